#include "pathspace/study/image_files.h"

#include <cctype>
#include <filesystem>
#include <system_error>

#include "pathspace/base/error.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"
#include "pathspace/study/error_colormap.h"

namespace pathspace::study {

std::string slug(const std::string& text) {
  std::string s;
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      s += char(std::tolower(u));
    else if (!s.empty() && s.back() != '-')
      s += '-';
  }
  while (!s.empty() && s.back() == '-') s.pop_back();
  return s;
}

ImageFiles write_images(const std::string& out_dir, const std::string& base, const Image& image, const Image& reference,
                        bool write_exr) {
  ImageFiles f;
  f.png = base + ".png";
  write_image(out_dir + "/" + f.png, image);
  if (reference.size() > 0) {
    f.error_png = base + ".err.png";
    write_image(out_dir + "/" + f.error_png, colour_error_map(rel_error_map(image, reference)));
  }
  if (write_exr) {
    f.exr = base + ".exr";
    write_image(out_dir + "/" + f.exr, image);
  }
  return f;
}

void create_image_folder(const std::string& out_dir) {
  std::error_code ec;
  if (std::filesystem::exists(out_dir, ec) && !std::filesystem::is_directory(out_dir, ec))
    throw Error("cannot write to '" + out_dir + "': it is not a folder");
  std::filesystem::create_directories(std::filesystem::path(out_dir) / "images", ec);
  if (ec) throw Error("cannot create '" + out_dir + "/images': " + ec.message());
}

}  // namespace pathspace::study
