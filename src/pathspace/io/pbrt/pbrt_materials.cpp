// pbrt-v4 materials, textures and spectra (see pbrt_materials.h). Roughness follows pbrt-v4:
// alpha = sqrt(roughness) when "remaproughness" is true (the default), else alpha = roughness;
// alpha < 1e-3 counts as perfectly smooth, as in pbrt's TrowbridgeReitz::EffectivelySmooth.
#include "pathspace/io/pbrt/pbrt_materials.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "pathspace/io/image_io.h"
#include "pathspace/io/named_spectra.h"
#include "pathspace/io/pbrt/pbrt_paths.h"
#include "pathspace/io/spectrum/cie_tables.h"

namespace pathspace::pbrt {

namespace {

Rgb lookup_texture(const Param& p, const TextureTable& textures) {
  if (p.strings.size() != 1) throw Error(p.loc, "texture parameter '" + p.name + "' must name one texture");
  const auto it = textures.values.find(p.strings[0]);
  if (it == textures.values.end()) throw Error(p.loc, "texture '" + p.strings[0] + "' is not defined");
  return it->second;
}

// A spectrum parameter as samples: inline pairs, an .spd file (relative to the file that names it,
// then to the main file's folder, as other files are found), a CIE illuminant by name or a
// blackbody temperature.
SampledSpectrum sampled_spectrum_param(const Param& p, const TextureTable& textures) {
  if (p.type == "blackbody") {
    if (p.numbers.size() != 1) throw Error(p.loc, "blackbody parameter '" + p.name + "' needs one temperature (kelvin)");
    return blackbody_spectrum(p.numbers[0], BlackbodyUnit::peak_normalised, p.loc);
  }
  if (p.strings.empty()) return spectrum_from_pairs(p.numbers, p.loc, "spectrum '" + p.name + "'");
  if (p.strings.size() != 1) throw Error(p.loc, "spectrum '" + p.name + "' names more than one spectrum");
  const std::string& name = p.strings[0];
  if (name == "stdillum-D65" || name == "stdillum-A") {
    SampledSpectrum s;
    for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += kCieStepNm) {
      s.nm.push_back(nm);
      s.value.push_back(name == "stdillum-D65" ? cie_at(nm).d65 : cie_illuminant_a(nm));
    }
    return s;
  }
  const std::filesystem::path path =
      resolve_scene_file(name, std::filesystem::path(p.loc.file).parent_path().string(), textures.main_folder);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(p.loc, "unknown named spectrum or spectrum file '" + name + "' (looked for " + path.string() + ")");
  return read_spd_file(path.string());
}

float alpha_from(const Statement& st, LoadWarnings* w) {
  double u = st.get_float("roughness", 0.0), v = u;
  u = st.get_float("uroughness", u);
  v = st.get_float("vroughness", v);
  if (u != v) w->add(st.loc, st.title() + ": anisotropic roughness approximated by sqrt(uroughness * vroughness)");
  const double r = std::sqrt(std::max(0.0, u) * std::max(0.0, v));
  const bool remap = st.get_bool("remaproughness", true);
  return float(remap ? std::sqrt(r) : r);
}

float eta_from(const Statement& st, const TextureTable& textures, LoadWarnings* w, const std::string& name = "eta") {
  const Param* p = st.find(name);
  if (!p) return 1.5f;
  if (p->type == "float" && p->numbers.size() == 1) return float(p->numbers[0]);
  if (p->type == "spectrum" && p->strings.size() == 1) {
    Rgb named;
    if (find_named_spectrum(p->strings[0], &named)) return named.g;
  }
  if (p->type == "spectrum") {
    // A dispersive index becomes one: its y-bar weighted mean (the luminance of the unbounded
    // conversion), which is close to the index at 555 nm.
    const SampledSpectrum s = sampled_spectrum_param(*p, textures);
    w->add(p->loc, "dispersive eta approximated by one index, its y-bar weighted mean");
    return float(y_bar_weighted_mean(s));
  }
  throw Error(p->loc, "parameter '" + name + "' must be a float or a spectrum");
}

}  // namespace

Rgb spectrum_param(const Statement& st, const std::string& name, const Rgb& fallback, const TextureTable& textures,
                   LoadWarnings* w, SpectrumUse use) {
  const Param* p = st.find(name);
  if (!p) return fallback;
  if (p->type == "rgb" || p->type == "color") {
    if (p->numbers.size() != 3) throw Error(p->loc, "rgb parameter '" + name + "' needs 3 values");
    return Rgb(float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2]));
  }
  if (p->type == "texture") return lookup_texture(*p, textures);
  if (p->type == "float" && p->numbers.size() == 1) return Rgb(float(p->numbers[0]));
  if (p->type == "spectrum" && p->strings.size() == 1) {
    Rgb named;
    if (find_named_spectrum(p->strings[0], &named)) return named;
    if (p->strings[0].rfind("stdillum-", 0) == 0 && p->strings[0] != "stdillum-D65" && p->strings[0] != "stdillum-A") {
      w->add(p->loc, "illuminant spectrum '" + p->strings[0] + "' taken as white (1, 1, 1)");
      return Rgb(1.f);
    }
  }
  if (p->type == "spectrum" || p->type == "blackbody") return spectrum_to_rgb(sampled_spectrum_param(*p, textures), use);
  throw Error(p->loc, "parameter '" + name + "' has an unsupported type '" + p->type + "'");
}

namespace {

const ImageTextureRef* image_param(const Statement& st, const std::string& name, const TextureTable& textures) {
  const Param* p = st.find(name);
  if (!p || p->type != "texture" || p->strings.size() != 1) return nullptr;
  const auto it = textures.images.find(p->strings[0]);
  return it == textures.images.end() ? nullptr : &it->second;
}

// An imagemap Texture: its mean colour (the constant stand-in, returned) and, for spectrum textures
// in a scene, the image itself (bilinear or point, repeat or clamp, uscale/vscale/udelta/vdelta,
// sRGB or linear).
Rgb add_image_texture(const Statement& st, const std::string& folder, TextureTable* textures, LoadWarnings* w) {
  const std::string& name = st.strings[0];
  const Param* file = st.find("filename");
  if (!file || file->strings.size() != 1) throw Error(st.loc, "imagemap texture '" + name + "' needs a filename");
  std::filesystem::path path(file->strings[0]);
  if (path.is_relative()) path = std::filesystem::path(folder) / path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(file->loc, "texture file '" + file->strings[0] + "' not found (looked for " + path.string() + ")");
  const std::string encoding = st.get_string("encoding", "sRGB");
  if (encoding != "sRGB" && encoding != "linear")
    w->add(st.find("encoding")->loc, "imagemap encoding \"" + encoding + "\" approximated by sRGB");
  const LdrEncoding ldr = encoding == "linear" ? LdrEncoding::linear : LdrEncoding::srgb;
  const TextureUvTransform uv{float(st.get_float("uscale", 1.0)), float(st.get_float("vscale", 1.0)),
                              float(st.get_float("udelta", 0.0)), float(st.get_float("vdelta", 0.0))};
  const std::string filter = st.get_string("filter", "bilinear");
  const std::string wrap = st.get_string("wrap", "repeat");
  TextureSampling sampling;  // "point" and "clamp" as pbrt-v4; the rest approximated (warnings below)
  sampling.nearest = filter == "point";
  if (wrap == "clamp") sampling.wrap = TextureWrap::clamp;
  const std::string mapping = st.get_string("mapping", "uv");
  st.ignore({"maxanisotropy"});
  const float scale = float(st.get_float("scale", 1.0));
  const bool invert = st.get_bool("invert", false);
  const bool image = st.strings[1] == "spectrum" && textures->scene && !invert && mapping == "uv";

  uint32_t index = 0;
  Rgb value;
  if (image) {
    index = textures->files.add(textures->scene, path.string(), ldr, uv, ImageContent::color, sampling);
    value = textures->scene->textures[index].mean();
  } else {
    ImageTexture t;
    t.texels = read_image(path.string(), ldr).pixels;
    value = t.mean();
  }
  if (!all_finite(value)) throw Error(file->loc, "texture file '" + file->strings[0] + "' holds NaN or infinite values");
  if (st.strings[1] == "float") value = Rgb(average(value));
  value *= scale;
  if (invert) value = Rgb(1.f) - value;
  const bool float_image = st.strings[1] == "float" && textures->scene && !invert && mapping == "uv";
  if (float_image) textures->float_images[name] = {path.string(), ldr, uv, scale};
  if (image) {
    textures->images[name] = {index, Rgb(scale)};
    if (filter != "bilinear" && filter != "point")
      w->add(st.loc, "imagemap filter \"" + filter + "\" approximated by bilinear filtering (no MIP maps)");
    if (wrap != "repeat" && wrap != "clamp") w->add(st.loc, "imagemap wrap \"" + wrap + "\" approximated by repeat");
  } else {
    w->add(st.loc, "image texture '" + name + "' approximated by its mean colour (" +
                       std::string(invert ? "invert" : mapping != "uv" ? "mapping \"" + mapping + "\"" : st.strings[1] == "float" ? "float textures" : "no scene") +
                       " not supported" + (float_image ? "; a shape's \"alpha\" uses the image itself" : "") + ")");
  }
  return value;
}

// pbrt-v4's 2D checkerboard: tex1 where floor(s) + floor(t) is even, tex2 elsewhere, with
// s = u uscale + udelta, t = v vscale + vdelta. Baked into 2x2 texels looked up by nearest texel,
// with the uv transform halved (one texel per check). Returns the mean (the constant fallback).
Rgb add_checkerboard_texture(const Statement& st, TextureTable* textures, LoadWarnings* w) {
  const std::string& name = st.strings[0];
  if (st.get_int("dimension", 2) != 2) throw Error(st.find("dimension")->loc, "checkerboard: only dimension 2 is supported");
  if (image_param(st, "tex1", *textures) || image_param(st, "tex2", *textures))
    w->add(st.loc, "checkerboard '" + name + "': image textures as checks approximated by their mean colours");
  Rgb t1 = spectrum_param(st, "tex1", Rgb(1.f), *textures, w), t2 = spectrum_param(st, "tex2", Rgb(0.f), *textures, w);
  if (st.strings[1] == "float") t1 = Rgb(average(t1)), t2 = Rgb(average(t2));
  const std::string mapping = st.get_string("mapping", "uv");
  const Rgb mean = (t1 + t2) * 0.5f;
  if (st.strings[1] != "spectrum" || !textures->scene || mapping != "uv") {
    w->add(st.loc, "checkerboard '" + name + "' approximated by its mean colour (" +
                       (mapping != "uv" ? "mapping \"" + mapping + "\"" : std::string("float textures")) + " not supported)");
    return mean;
  }
  ImageTexture t;
  t.name = "checkerboard '" + name + "'";
  t.width = t.height = 2;
  t.texels = {t2, t1, t1, t2};  // top row: t odd; bottom row: t even (v = 0 is the bottom)
  t.uscale = float(st.get_float("uscale", 1.0)) * 0.5f;
  t.vscale = float(st.get_float("vscale", 1.0)) * 0.5f;
  t.udelta = float(st.get_float("udelta", 0.0)) * 0.5f;
  t.vdelta = float(st.get_float("vdelta", 0.0)) * 0.5f;
  t.nearest = true;
  textures->images[name] = {textures->scene->add_texture(std::move(t)), Rgb(1.f)};
  return mean;
}

}  // namespace

Rgb reflectance_param(const Statement& st, const std::string& name, const Rgb& fallback, const TextureTable& textures,
                      LoadWarnings* w, int32_t* texture) {
  *texture = -1;
  if (const ImageTextureRef* ref = image_param(st, name, textures)) {
    st.find(name)->used = true;
    *texture = int32_t(ref->texture);
    return ref->scale;
  }
  return spectrum_param(st, name, fallback, textures, w);
}

float float_texture_param(const Statement& st, const std::string& name, float fallback, TextureTable* textures,
                          LoadWarnings* w, int32_t* texture) {
  *texture = -1;
  const Param* p = st.find(name);
  if (p && p->type == "texture" && p->strings.size() == 1) {
    const auto it = textures->float_images.find(p->strings[0]);
    if (it != textures->float_images.end()) {
      p->used = true;
      const FloatImageFile& f = it->second;
      try {
        *texture = int32_t(textures->files.add(textures->scene, f.path, f.ldr, f.uv, ImageContent::scalar));
      } catch (const Error& e) {
        throw Error(p->loc, std::string("float texture '") + p->strings[0] + "': " + e.what());
      }
      return f.scale;
    }
  }
  return average(spectrum_param(st, name, Rgb(fallback), *textures, w));
}

void add_texture(const Statement& st, const std::string& folder, TextureTable* textures, LoadWarnings* w) {
  const std::string& name = st.strings[0];
  const std::string& cls = st.strings[2];
  Rgb value(0.5f);
  if (cls == "constant") {
    value = spectrum_param(st, "value", Rgb(1.f), *textures, w);
  } else if (cls == "imagemap") {
    value = add_image_texture(st, folder, textures, w);
  } else if (cls == "scale") {
    value = spectrum_param(st, "tex", Rgb(1.f), *textures, w) * spectrum_param(st, "scale", Rgb(1.f), *textures, w);
    // An image times a constant stays an image texture.
    const ImageTextureRef* tex = image_param(st, "tex", *textures);
    const ImageTextureRef* scale = image_param(st, "scale", *textures);
    if (tex && !scale) textures->images[name] = {tex->texture, tex->scale * spectrum_param(st, "scale", Rgb(1.f), *textures, w)};
    if (scale && !tex) textures->images[name] = {scale->texture, scale->scale * spectrum_param(st, "tex", Rgb(1.f), *textures, w)};
    if (tex && scale) w->add(st.loc, "scale texture '" + name + "' of two image textures approximated by their mean colours' product");
  } else if (cls == "checkerboard") {
    value = add_checkerboard_texture(st, textures, w);
  } else if (cls == "mix") {
    // pbrt-v4: (1 - amount) tex1 + amount tex2; exact for constants, image inputs by their means.
    if (image_param(st, "tex1", *textures) || image_param(st, "tex2", *textures) || image_param(st, "amount", *textures))
      w->add(st.loc, "mix texture '" + name + "': image inputs approximated by their mean colours");
    const float amount = average(spectrum_param(st, "amount", Rgb(0.5f), *textures, w));
    value = spectrum_param(st, "tex1", Rgb(0.f), *textures, w) * (1.f - amount) + spectrum_param(st, "tex2", Rgb(1.f), *textures, w) * amount;
  } else {
    w->add(st.loc, "texture class '" + cls + "' not supported; texture '" + name + "' taken as constant 0.5");
    for (const Param& p : st.params) p.used = true;
  }
  textures->values[name] = value;
}

namespace {

// The slab of pbrt-v4's coated materials: thickness (mean free paths), albedo, g, maxdepth, nsamples.
void read_coat_slab(const Statement& st, const TextureTable& textures, LoadWarnings* w, Material* m) {
  const double thickness = st.get_float("thickness", 0.01);
  if (!(thickness >= 0.0) || !std::isfinite(thickness)) throw Error(st.find("thickness")->loc, "thickness must be >= 0");
  m->thickness = float(std::max(thickness, 1e-30));  // pbrt-v4: at least the smallest float
  const double g = st.get_float("g", 0.0);
  if (!(g > -1.0 && g < 1.0)) throw Error(st.find("g")->loc, "g (Henyey-Greenstein asymmetry) must lie in (-1, 1)");
  m->g = float(g);
  const Rgb albedo = spectrum_param(st, "albedo", Rgb(0.f), textures, w);
  for (int c = 0; c < 3; ++c) m->medium_albedo[c] = std::clamp(albedo[c], 0.f, 1.f);  // pbrt-v4 clamps it too
  const int max_depth = st.get_int("maxdepth", 10), n_samples = st.get_int("nsamples", 1);
  if (max_depth < 1 || max_depth > 65535) throw Error(st.find("maxdepth")->loc, "maxdepth must lie in [1, 65535]");
  if (n_samples < 1 || n_samples > 65535) throw Error(st.find("nsamples")->loc, "nsamples must lie in [1, 65535]");
  m->max_depth = uint16_t(max_depth);
  m->n_samples = uint16_t(n_samples);
  if (m->type == MaterialType::coated_conductor && m->alpha < 1e-3f && m->base_alpha < 1e-3f && !is_black(m->medium_albedo))
    w->add(st.loc, "coatedconductor: a smooth coat over a smooth conductor is a mirror here; the slab's scattering (albedo) is ignored");
  st.ignore({"displacement"});
}

}  // namespace

Material make_material(const std::string& type, const Statement& st, const TextureTable& tex, LoadWarnings* w) {
  // pbrt's BSDFs are two-sided; pathspace's diffuse/Phong lobes are one-sided unless told.
  Material m;
  m.two_sided = true;
  st.ignore({"type"});
  if (type == "diffuse") {
    m.diffuse = reflectance_param(st, "reflectance", Rgb(0.5f), tex, w, &m.diffuse_texture);
  } else if (type == "conductor" || type == "coatedconductor") {
    const std::string prefix = type == "coatedconductor" ? "conductor." : "";
    Rgb eta = spectrum_param(st, prefix + "eta", Rgb(0.200438f, 0.924033f, 1.102212f), tex, w, SpectrumUse::unbounded);
    Rgb k = spectrum_param(st, prefix + "k", Rgb(3.912949f, 2.452848f, 2.142188f), tex, w, SpectrumUse::unbounded);
    if (st.find("reflectance")) {  // pbrt: eta = 1, k = 2 sqrt(r) / sqrt(1 - r)
      const Rgb r = spectrum_param(st, "reflectance", Rgb(), tex, w);
      eta = Rgb(1.f);
      for (int i = 0; i < 3; ++i) {
        const float ri = std::clamp(r[i], 0.f, 0.9999f);
        k[i] = 2.f * std::sqrt(ri) / std::sqrt(1.f - ri);
      }
    }
    if (type == "coatedconductor") {
      // pbrt-v4: the conductor lies in the coat, so its eta and k are relative to the coat's index.
      Statement conductor = st, coat = st;
      for (Param& p : conductor.params)
        if (p.name.rfind("conductor.", 0) == 0) p.name = p.name.substr(10);
      for (Param& p : coat.params)
        if (p.name.rfind("interface.", 0) == 0) p.name = p.name.substr(10);
      m.type = MaterialType::coated_conductor;
      m.ior = eta_from(st, tex, w, "interface.eta");
      if (!(m.ior > 0.f)) m.ior = 1.f;  // pbrt: an index of 0 means 1
      m.eta = eta * (1.f / m.ior);
      m.k = k * (1.f / m.ior);
      m.base_alpha = alpha_from(conductor, w);
      m.alpha = alpha_from(coat, w);
      m.distribution = MicrofacetDistribution::ggx;
      read_coat_slab(st, tex, w, &m);
      st.ignore({"interface.roughness", "interface.uroughness", "interface.vroughness", "conductor.roughness",
                 "conductor.uroughness", "conductor.vroughness", "remaproughness"});
      m.two_sided = true;
    } else {
      m = make_rough_conductor(alpha_from(st, w), eta, k);
      m.two_sided = true;
    }
  } else if (type == "dielectric" || type == "thindielectric") {
    const float eta = eta_from(st, tex, w);
    const float alpha = type == "dielectric" ? alpha_from(st, w) : 0.f;
    if (type == "thindielectric") w->add(st.loc, "thindielectric approximated by a smooth dielectric slab surface");
    m = alpha < 1e-3f ? make_glass(eta) : make_rough_dielectric(alpha, eta);
  } else if (type == "coateddiffuse") {
    m.type = MaterialType::coated_diffuse;
    m.diffuse = reflectance_param(st, "reflectance", Rgb(0.5f), tex, w, &m.diffuse_texture);
    m.ior = eta_from(st, tex, w);
    m.alpha = alpha_from(st, w);
    read_coat_slab(st, tex, w, &m);
  } else if (type == "diffusetransmission") {
    m.diffuse = reflectance_param(st, "reflectance", Rgb(0.25f), tex, w, &m.diffuse_texture);
    w->add(st.loc, "diffusetransmission approximated as diffuse reflection only (transmission dropped)");
    for (const Param& p : st.params) p.used = true;
  } else {
    w->add(st.loc, "material type '" + type + "' not supported; using grey diffuse 0.5");
    m.diffuse = Rgb(0.5f);
    for (const Param& p : st.params) p.used = true;
  }
  return m;
}

SubsurfaceMaterial make_subsurface(const Statement& st, const TextureTable& textures, LoadWarnings* w) {
  for (const char* refused : {"name", "reflectance", "mfp"})
    if (const Param* p = st.find(refused))
      throw Error(p->loc, std::string("subsurface material: \"") + refused +
                              "\" is not supported; give \"sigma_a\" and \"sigma_s\" (docs/media.md)");
  SubsurfaceMaterial r;
  const float eta = st.find("eta") ? eta_from(st, textures, w, "eta") : 1.33f;  // pbrt-v4's default
  const float alpha = alpha_from(st, w);
  r.boundary = alpha < 1e-3f ? make_glass(eta) : make_rough_dielectric(alpha, eta);
  const double scale = st.get_float("scale", 1.0);
  if (!(scale >= 0.0) || !std::isfinite(scale)) throw Error(st.find("scale")->loc, "subsurface \"scale\" must be finite and >= 0");
  r.sigma_a = spectrum_param(st, "sigma_a", Rgb(0.0011f, 0.0024f, 0.014f), textures, w, SpectrumUse::unbounded) * float(scale);
  r.sigma_s = spectrum_param(st, "sigma_s", Rgb(2.55f, 3.21f, 3.77f), textures, w, SpectrumUse::unbounded) * float(scale);
  r.g = float(st.get_float("g", 0.0));
  return r;
}

}  // namespace pathspace::pbrt
