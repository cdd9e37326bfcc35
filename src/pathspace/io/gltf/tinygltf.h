// tinygltf (Debian libtinygltf-dev, header-only 2.7) with the configuration pathspace compiles it in:
// every file that includes tiny_gltf.h must see the same macros, so they live here.
// * Its implementation is compiled into pathspace_io (tinygltf_implementation.cpp), not taken from
//   Debian's libtinygltf.so: the fuzz and sanitizer builds then instrument the parser too.
// * No stb inside tinygltf (TINYGLTF_NO_STB_IMAGE*): images are kept as encoded bytes by our own
//   callback and decoded by io/image_io (sRGB or linear as the glTF texture slot needs). External
//   image files are not read by tinygltf (TINYGLTF_NO_EXTERNAL_IMAGE); the loader reads them.
// * JSON through nlohmann (Debian nlohmann-json3-dev, /usr/include/nlohmann/json.hpp).
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop
