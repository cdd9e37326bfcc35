// PLACEHOLDER: being implemented.
#include "pathspace/io/image_io.h"

#include "pathspace/base/error.h"

namespace pathspace {
ImageFormat image_format_from_path(const std::string&) { throw Error("image io not implemented"); }
void write_image(const std::string&, const Image&) { throw Error("image io not implemented"); }
Image read_image(const std::string&) { throw Error("image io not implemented"); }
}  // namespace pathspace
