// The one check every input file of pathspace passes (io/file_bytes.h reads through it): what is
// not a regular file is refused before a read could block on it (a FIFO is opened without
// blocking, so a FIFO with no writer cannot hang the process deaf to SIGTERM) or run without end
// (/dev/zero). Errors name the file and what it is: "PATH: file not found", "PATH: is a directory,
// not a file", "PATH: is a FIFO (named pipe), not a regular file", a character or block device, a
// socket, or "PATH: cannot open: <reason>".
#pragma once

#include <string>

namespace pathspace {

// The bytes of the regular file `path`, as stored (images, checkpoints, content hashes, camera
// paths, glTF buffers; io/file_bytes.h's read_file_bytes adds gzip and the byte-order mark).
std::string read_file_as_stored(const std::string& path);

// The check alone, for readers with streams of their own (the vertex buffer file's).
void require_regular_file(const std::string& path);

// Both note the file in every open InputFileLog (base/input_file_log.h); this read does not.
std::string read_file_as_stored_unlogged(const std::string& path);

}  // namespace pathspace
