// pbrt-v4 materials, textures and spectra mapped onto pathspace's materials (materials/material.h).
// diffuse, conductor and dielectric map directly; coateddiffuse and a few others are approximated,
// always with a warning that says how. Spectra become linear sRGB: RGB values directly, named metal
// and glass spectra through a small table of RGB fits, image textures through their mean colour.
#pragma once

#include <map>
#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_statement.h"
#include "pathspace/materials/material.h"

namespace pathspace::pbrt {

// Constant stand-ins for named textures ("Texture" statements).
struct TextureTable {
  std::map<std::string, Rgb> values;  // float textures store the value in all three channels
};

// Evaluates a Texture statement (imagemap files are resolved against `folder`; a missing file is an
// Error at the statement) and stores its constant stand-in.
void add_texture(const Statement& st, const std::string& folder, TextureTable* textures, LoadWarnings* warnings);

// Converts Material / MakeNamedMaterial parameters of the given pbrt type.
Material make_material(const std::string& type, const Statement& st, const TextureTable& textures, LoadWarnings* warnings);

// A spectrum-valued parameter (rgb, spectrum, blackbody or texture) as linear sRGB; `fallback` when absent.
Rgb spectrum_param(const Statement& st, const std::string& name, const Rgb& fallback, const TextureTable& textures,
                   LoadWarnings* warnings);

}  // namespace pathspace::pbrt
