// Bitmap texture binding for the Mitsuba loader (see mitsuba_textures.h).
#include "pathspace/io/mitsuba/mitsuba_textures.h"

#include <cmath>
#include <filesystem>

namespace pathspace::mitsuba {

namespace {

// to_uv as scale and offset; anything else (rotation, shear) keeps only those parts, with a warning.
TextureUvTransform uv_transform(const Object& tex, LoadWarnings* w) {
  const Mat4 m = tex.get_transform("to_uv");
  const double a = m.m[0][0], b = m.m[1][1], c = m.m[0][3], d = m.m[1][3];
  if (m.m[0][1] != 0.0 || m.m[1][0] != 0.0)
    w->add(tex.loc(), tex.title() + ": to_uv other than scale and translate: only its scale and offset are used");
  TextureUvTransform uv{float(a), float(b), float(c), float(1.0 - b - d)};
  if (!std::isfinite(uv.uscale) || !std::isfinite(uv.vscale) || !std::isfinite(uv.udelta) || !std::isfinite(uv.vdelta))
    throw Error(tex.loc(), tex.title() + ": to_uv must be finite");
  return uv;
}

int32_t bind_bitmap(const Object& tex, const std::string& folder, TextureBinding* binding, LoadWarnings* w,
                    ImageContent content) {
  const FileLoc loc = tex.loc();
  const std::string file = tex.get_string("filename", "");
  const std::filesystem::path path = tex.doc().resolve_file(file, folder);
  std::error_code ec;
  if (file.empty() || !std::filesystem::is_regular_file(path, ec))
    throw Error(loc, "texture file '" + file + "' not found (looked for " + path.string() + ")");
  // raw: 8-bit data is linear (Mitsuba's default decodes sRGB); float images are always linear.
  const LdrEncoding ldr = tex.get_bool("raw", false) ? LdrEncoding::linear : LdrEncoding::srgb;
  TextureSampling sampling;
  const std::string filter = tex.get_string("filter_type", "bilinear");
  if (filter != "bilinear" && filter != "nearest") throw Error(loc, tex.title() + ": filter_type must be bilinear or nearest, not '" + filter + "'");
  sampling.nearest = filter == "nearest";
  const std::string wrap = tex.get_string("wrap_mode", "repeat");
  if (wrap == "mirror") sampling.wrap = TextureWrap::mirror;
  else if (wrap == "clamp") sampling.wrap = TextureWrap::clamp;
  else if (wrap != "repeat") throw Error(loc, tex.title() + ": wrap_mode must be repeat, mirror or clamp, not '" + wrap + "'");
  const TextureUvTransform uv = uv_transform(tex, w);
  tex.ignore({"format"});
  tex.warn_unused(w);
  uint32_t index = 0;
  try {
    index = binding->files.add(binding->scene, path.string(), ldr, uv, content, sampling);
  } catch (const Error& e) {
    throw Error(loc, "bitmap texture: " + std::string(e.what()));
  }
  if (!all_finite(binding->scene->textures[index].mean()))
    throw Error(loc, "bitmap texture '" + file + "' holds NaN or infinite values");
  return int32_t(index);
}

}  // namespace

Rgb textured_rgb(const Object& o, const std::string& name, const Rgb& fallback, const std::string& folder,
                 TextureBinding* binding, LoadWarnings* w, int32_t* texture, ImageContent content) {
  *texture = -1;
  const Property* p = o.find(name);
  if (binding && binding->scene && p && (p->tag == "texture" || p->tag == "ref")) {
    pugi::xml_node node = p->node;
    if (p->tag == "ref") node = o.doc().texture(o.doc().attr(p->node, "id"));
    if (node) {
      const Object tex(o.doc(), node);
      if (tex.type() == "bitmap") {
        *texture = bind_bitmap(tex, folder, binding, w, content);
        return Rgb(1.f);
      }
    }
  }
  return o.get_rgb(name, fallback, folder, w);  // also the errors for a bad <ref>
}

}  // namespace pathspace::mitsuba
