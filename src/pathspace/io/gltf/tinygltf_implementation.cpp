// The one translation unit that compiles tinygltf's implementation (see tinygltf.h for why here and
// with which options). Its own warnings are not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#define TINYGLTF_IMPLEMENTATION
#include "pathspace/io/gltf/tinygltf.h"
#pragma GCC diagnostic pop
