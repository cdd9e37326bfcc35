// Mitsuba `bitmap` textures bound as real scene image textures (scene/image_texture.h) where a
// material can use one: diffuse's `reflectance` and plastic's `diffuse_reflectance`. Elsewhere a
// texture stays its mean colour (Object::get_rgb, with a warning).
//
// Mitsuba's uv has v = 0 at the image's top row (its OBJ loader flips v for this); pathspace's has
// v = 0 at the bottom. The shapes convert their uvs (mitsuba_shapes.cpp: v_pathspace = 1 - v_mitsuba),
// and `to_uv` = (scale a, b; offset c, d) becomes uscale a, udelta c, vscale b, vdelta 1 - b - d,
// which looks up the same texel as Mitsuba.
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_object.h"
#include "pathspace/io/texture_file.h"

namespace pathspace::mitsuba {

// Where bound textures go: the scene being built (each file read once per encoding and to_uv).
struct TextureBinding {
  Scene* scene = nullptr;
  TextureFiles files;
};

// The colour property `name` of `o`: for a bitmap texture (nested, or a <ref> to a top-level one)
// and a non-null `binding`, returns white and sets *texture to the bound texture's index; otherwise
// Object::get_rgb's value and *texture = -1. ImageContent::scalar reads the bitmap as a float
// texture (a mask's opacity: io/image_io.h).
Rgb textured_rgb(const Object& o, const std::string& name, const Rgb& fallback, const std::string& folder,
                 TextureBinding* binding, LoadWarnings* w, int32_t* texture, ImageContent content = ImageContent::color);

}  // namespace pathspace::mitsuba
