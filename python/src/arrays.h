// Images as numpy arrays: float32, height x width x 3, row 0 at the top, linear RGB. An array
// returned to Python owns a copy of the pixels (it shares no memory with the renderer).
#pragma once

#include <pybind11/numpy.h>

#include "bindings.h"
#include "pathspace/film/image.h"

namespace pathspace::python {

py::array_t<float> array_of(const Image& image);
// From anything numpy can turn into a float32 array of shape (H, W, 3) or (H, W) (grey, copied into
// each channel); raises ValueError for other shapes. `what` names the argument in messages.
Image image_of(const py::handle& array, const char* what);

}  // namespace pathspace::python
