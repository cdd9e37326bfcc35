// pbrt-v4 materials, textures and spectra mapped onto pathspace's materials (materials/material.h).
// diffuse, conductor and dielectric map directly; coateddiffuse and a few others are approximated,
// always with a warning that says how. Spectra become linear sRGB: RGB values directly, named metal
// and glass spectra through a small table of RGB fits, sampled spectra and blackbodies through the
// CIE 1931 observer (io/spectrum/spectrum_to_rgb.h). Spectrum imagemap textures (and constant
// scales of them) bind real image textures to reflectances; elsewhere they stand in by their mean.
#pragma once

#include <map>
#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_statement.h"
#include "pathspace/io/spectrum/spectrum_to_rgb.h"
#include "pathspace/io/texture_file.h"
#include "pathspace/materials/material.h"

namespace pathspace::pbrt {

// An image texture bound by name: texels scene->textures[texture], times `scale`.
struct ImageTextureRef {
  uint32_t texture = 0;
  Rgb scale{1.f, 1.f, 1.f};
};

// Named textures ("Texture" statements): a constant stand-in for every texture, and for spectrum
// image textures also the image itself. Images are read into *scene when it is set (the scene
// builder sets it); without a scene every imagemap is its mean colour.
// A float imagemap texture, read as a scalar image where it is used as one (a shape's alpha).
struct FloatImageFile {
  std::string path;
  LdrEncoding ldr = LdrEncoding::srgb;
  TextureUvTransform uv;
  float scale = 1.f;
};

struct TextureTable {
  std::map<std::string, Rgb> values;  // float textures store the value in all three channels
  std::map<std::string, ImageTextureRef> images;
  std::map<std::string, FloatImageFile> float_images;
  Scene* scene = nullptr;
  TextureFiles files;
  std::string main_folder;  // where .spd files are looked for when not beside the file naming them
};

// Evaluates a Texture statement (imagemap files are resolved against `folder`; a missing file is an
// Error at the statement) and stores its constant stand-in.
void add_texture(const Statement& st, const std::string& folder, TextureTable* textures, LoadWarnings* warnings);

// pbrt-v4's "subsurface" material as what it models: a dielectric boundary (eta, roughness) around a
// homogeneous medium of sigma_a and sigma_s (times "scale"; pbrt-v4's defaults, in mm^-1, when not
// given) with Henyey-Greenstein g, rendered by the integrators' volumetric random walk instead of
// pbrt's BSSRDF (docs/media.md). Measured presets ("name") and the "reflectance"/"mfp" form are
// errors at the parameter.
struct SubsurfaceMaterial {
  Material boundary;
  Rgb sigma_a, sigma_s;
  float g = 0.f;
};
SubsurfaceMaterial make_subsurface(const Statement& st, const TextureTable& textures, LoadWarnings* warnings);

// Converts Material / MakeNamedMaterial parameters of the given pbrt type.
Material make_material(const std::string& type, const Statement& st, const TextureTable& textures, LoadWarnings* warnings);

// A reflectance that may be textured: a texture parameter naming an image texture returns its scale
// and sets *texture to the image's index; otherwise spectrum_param's value and *texture = -1.
Rgb reflectance_param(const Statement& st, const std::string& name, const Rgb& fallback, const TextureTable& textures,
                      LoadWarnings* warnings, int32_t* texture);

// A float parameter that may name a float image texture (pbrt-v4's shape "alpha"): for such a
// texture, binds its scalar image (io/image_io.h, ImageContent::scalar) into textures->scene,
// sets *texture to its index and returns its scale; otherwise the constant value (a float or a
// constant texture) and *texture = -1.
float float_texture_param(const Statement& st, const std::string& name, float fallback, TextureTable* textures,
                          LoadWarnings* warnings, int32_t* texture);

// A spectrum-valued parameter (rgb, spectrum, blackbody or texture) as linear sRGB; `fallback` when absent.
// RGB values pass as given; spectra (inline pairs, .spd files, CIE illuminants, blackbodies) are
// converted as `use` says (spectrum_to_rgb.h). Named metal and glass spectra come from named_spectra.h.
Rgb spectrum_param(const Statement& st, const std::string& name, const Rgb& fallback, const TextureTable& textures,
                   LoadWarnings* warnings, SpectrumUse use = SpectrumUse::reflectance);

}  // namespace pathspace::pbrt
