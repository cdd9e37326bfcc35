// Scene parser entry points for fuzzing and corpus replay (see fuzz_inputs.h).
#include "fuzz/fuzz_inputs.h"

#include <filesystem>
#include <fstream>
#include <vector>

#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/io/ply_reader.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/image_texture.h"
#if PATHSPACE_HAS_MITSUBA
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#endif

namespace pathspace::fuzz {

namespace {

constexpr std::string_view kMtlMarker = "#--- scene.mtl ---\n";

void write_file(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

Scene load(Format format, std::string_view bytes, const std::string& folder) {
  std::vector<std::string> warnings;
  LoadWarnings w(&warnings);
  SceneFileSettings settings;
  const SceneLoadOptions options;
  switch (format) {
    case Format::pbrt:
      return pbrt::load_pbrt_string(std::string(bytes), "fuzz.pbrt", folder, options, &w, &settings);
    case Format::ply: {
      // The reader alone: a PlyMesh is not a Scene, but must be valid when it comes back.
      const PlyMesh mesh = parse_ply(std::string(bytes), "fuzz.ply");
      for (uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) throw std::logic_error("PLY reader returned an out-of-range index");
      return Scene();
    }
    case Format::obj: {
      const size_t split = bytes.find(kMtlMarker);
      const std::string obj = folder + "/scene.obj", mtl = folder + "/scene.mtl";
      write_file(obj, bytes.substr(0, split));
      std::error_code ec;
      if (split == std::string_view::npos) std::filesystem::remove(mtl, ec);
      else write_file(mtl, bytes.substr(split + kMtlMarker.size()));
      return load_scene(obj, options, &warnings);
    }
    case Format::gltf: {
      const std::string path = folder + "/scene.gltf";
      write_file(path, bytes);
      Scene scene = load_scene(path, options, &warnings);
      // An animated file is also sampled between and after its keys (the still scene is at 0 s).
      if (const auto scene_at = load_scene_animation(path, options, &warnings))
        for (const double seconds : {0.37, 1e6}) scene_at(seconds);
      return scene;
    }
    case Format::image: {
      if (bytes.empty()) throw Error(FileLoc{"fuzz.img"}, "empty input");
      static const char* const kNames[4] = {"fuzz.exr", "fuzz.pfm", "fuzz.png", "fuzz.hdr"};
      const std::string name = kNames[uint8_t(bytes[0]) % 4];
      try {
        const Image image = decode_image(name, std::string(bytes.substr(1)));
        if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * size_t(image.height))
          throw std::logic_error("image reader returned an inconsistent image");
        // The same bytes as a scalar texture (alpha, or the mean colour: cutout opacity) must decode to
        // the same size, every texel one value in all three channels (NaN excepted: it differs from itself).
        const Image scalar = decode_image(name, std::string(bytes.substr(1)), LdrEncoding::linear, ImageContent::scalar);
        if (scalar.width != image.width || scalar.height != image.height || scalar.pixels.size() != image.pixels.size())
          throw std::logic_error("the scalar read of an image has another size");
        for (const Rgb& t : scalar.pixels)
          if ((t.r == t.r) && (t.g != t.r || t.b != t.r)) throw std::logic_error("a scalar texel differs between channels");
        // An 8-bit file read as bytes (textures kept as 8 bits) is the same image: each byte's table
        // value is the float the colour read gave.
        if (const auto b = decode_image_bytes(name, std::string(bytes.substr(1)))) {
          if (b->width != image.width || b->height != image.height || b->rgb.size() != 3 * image.pixels.size())
            throw std::logic_error("the byte read of an image has another size");
          const float* value = texture_byte_values(ByteEncoding::srgb);
          for (size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
              if (value[b->rgb[3 * i + size_t(c)]] != image.pixels[i][c]) throw std::logic_error("the byte read differs from the float read");
        }
      } catch (const Error& e) {
        // The readers name the file at the start of the message; the fuzz contract wants it as a location.
        if (std::string_view(e.what()).substr(0, name.size()) != name) throw std::logic_error(std::string("image error without its file: ") + e.what());
        throw Error(FileLoc{name}, e.what());
      }
      return Scene();
    }
    case Format::mitsuba:
#if PATHSPACE_HAS_MITSUBA
      return mitsuba::load_mitsuba_string(std::string(bytes), "fuzz.xml", folder, options, &w, &settings);
#else
      throw std::logic_error("this build has no Mitsuba loader");
#endif
  }
  return Scene();
}

}  // namespace

const char* format_name(Format f) {
  switch (f) {
    case Format::pbrt: return "pbrt";
    case Format::ply: return "ply";
    case Format::obj: return "obj";
    case Format::mitsuba: return "mitsuba";
    case Format::gltf: return "gltf";
    case Format::image: return "image";
  }
  return "";
}

bool format_available(Format f) {
#if PATHSPACE_HAS_MITSUBA
  (void)f;
  return true;
#else
  return f != Format::mitsuba;
#endif
}

InputFolder::InputFolder() : dir_("fuzz"), path_(dir_.path.string()) {
  write_file(dir_.file("inc.pbrt"), "Material \"diffuse\" \"rgb reflectance\" [ 0.2 0.3 0.4 ]\n");
  write_file(dir_.file("mesh.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  // A 1x1 RGB PFM (little-endian: negative scale) of value 0.25.
  const float px[3] = {0.25f, 0.25f, 0.25f};
  write_file(dir_.file("tex.pfm"), std::string("PF\n1 1\n-1.0\n") + std::string(reinterpret_cast<const char*>(px), sizeof px));
}

Outcome load_bytes(Format format, std::string_view bytes, const InputFolder& folder) {
  Outcome o;
  try {
    load(format, bytes, folder.path());
    o.loaded = true;
  } catch (const Error& e) {
    o.error = e.what();
    o.location = e.location();
  }
  return o;
}

}  // namespace pathspace::fuzz
