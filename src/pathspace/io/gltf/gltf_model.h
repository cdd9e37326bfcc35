// A glTF file (.gltf with external or data-uri buffers, binary .glb: the format follows the content,
// GLB files start with "glTF") parsed by tinygltf, images kept as encoded bytes (gltf_textures.h).
// Syntax errors and extensionsRequired that pathspace does not support are a pathspace::Error naming
// the file; tinygltf's warnings and unsupported extensionsUsed are warnings.
#pragma once

#include <string>

#include "pathspace/io/gltf/tinygltf.h"
#include "pathspace/io/load_warnings.h"

namespace pathspace::gltf {

void read_model(const std::string& path, tinygltf::Model* model, LoadWarnings* warnings);

}  // namespace pathspace::gltf
