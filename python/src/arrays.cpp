#include "arrays.h"

#include <cstring>

#include "pathspace/scene/scene_validation.h"

namespace pathspace::python {

static_assert(sizeof(Rgb) == 3 * sizeof(float), "Rgb must be three packed floats to be copied as (H, W, 3)");

py::array_t<float> array_of(const Image& image) {
  py::array_t<float> out({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(3)});
  if (image.size() > 0) std::memcpy(out.mutable_data(), image.pixels.data(), image.size() * sizeof(Rgb));
  return out;
}

Image image_of(const py::handle& object, const char* what) {
  const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(object);
  if (!array) throw py::type_error(std::string(what) + ": expected an array of numbers (height x width x 3)");
  const bool rgb = array.ndim() == 3 && array.shape(2) == 3;
  if (!rgb && array.ndim() != 2) {
    std::string shape;
    // Appended piecewise: `s += "x" + std::to_string(n)` trips GCC 12's false -Wstringop-overflow.
    for (py::ssize_t d = 0; d < array.ndim(); ++d) shape.append(d ? ", " : "").append(std::to_string(array.shape(d)));
    throw py::value_error(std::string(what) + ": expected shape (height, width, 3) or (height, width), got (" + shape + ")");
  }
  const py::ssize_t h = array.shape(0), w = array.shape(1);
  if (h < 1 || w < 1 || h > kMaxImageSide || w > kMaxImageSide)
    throw py::value_error(std::string(what) + ": each side must be 1 to " + std::to_string(kMaxImageSide) + " pixels");
  Image image{int(w), int(h)};
  const float* src = array.data();
  if (rgb) {
    std::memcpy(static_cast<void*>(image.pixels.data()), src, image.size() * sizeof(Rgb));
  } else {
    for (size_t i = 0; i < image.size(); ++i) image.pixels[i] = Rgb(src[i], src[i], src[i]);
  }
  return image;
}

}  // namespace pathspace::python
