// Image files: EXR (OpenEXR, linear float RGB), PFM (linear float, standard bottom-row-first order)
// and PNG (sRGB-encoded 8 bit, clamped). The format follows the file extension. Writes go to a
// temporary file in the same folder that is renamed into place, so a failure never leaves a
// half-written image. Errors are pathspace::Error naming the file.
#pragma once

#include <string>

#include "pathspace/film/image.h"

namespace pathspace {

enum class ImageFormat { exr, pfm, png };

// Format from the extension (case-insensitive); throws pathspace::Error for anything else.
ImageFormat image_format_from_path(const std::string& path);

void write_image(const std::string& path, const Image& image);
// Reads EXR, PFM, PNG (and what stb reads: JPG, HDR, TGA, BMP). LDR files are sRGB-decoded.
Image read_image(const std::string& path);

}  // namespace pathspace
