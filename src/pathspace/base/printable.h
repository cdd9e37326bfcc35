// Text from input (file contents, names, command-line words) shown in a message: control bytes and
// bytes that are not valid UTF-8 become \xNN escapes, so a binary file's bytes never reach the
// terminal raw (no escape sequences, no broken lines). Valid UTF-8 stays as it is.
#pragma once

#include <string>
#include <string_view>

namespace pathspace {

std::string printable(std::string_view text);

}  // namespace pathspace
