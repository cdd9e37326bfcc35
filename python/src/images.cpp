// Image files and error metrics for Python: read_image, write_image (EXR, PFM, PNG; written
// atomically, like every pathspace output) and compare, the metrics of `pathspace compare`.
#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "arrays.h"
#include "bindings.h"
#include "pathspace/film/block_metrics.h"
#include "pathspace/film/flip.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"

namespace pathspace::python {

namespace {

std::string path_argument(const py::handle& value) { return py::str(py::module_::import("os").attr("fspath")(value)); }

// The image file at a path (str or os.PathLike), read without the GIL.
Image read_path(const py::handle& path) {
  const std::string p = path_argument(path);
  py::gil_scoped_release release;
  return read_image(p);
}

// A path is read from its file; anything else is taken as an array.
Image image_argument(const py::handle& value, const char* what) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) return read_path(value);
  return image_of(value, what);
}

}  // namespace

void bind_images(py::module_& m) {
  m.def(
      "read_image",
      [](const py::object& path) { return array_of(read_path(path)); },
      py::arg("path"),
      "Reads an image file (EXR, PFM, PNG; also JPG, HDR, TGA, BMP) as a float32 array (height, width, 3) of linear RGB "
      "(8-bit files are sRGB-decoded). Raises pathspace.Error naming the file.");
  m.def(
      "write_image",
      [](const py::object& path, const py::object& array) {
        const std::string p = path_argument(path);
        const Image image = image_of(array, "write_image");
        py::gil_scoped_release release;
        image_format_from_path(p);  // an unknown extension fails before anything is written
        write_image(p, image);
      },
      py::arg("path"), py::arg("image"),
      "Writes a (height, width, 3) or (height, width) array as EXR or PFM (linear float) or PNG (sRGB, 8 bit, clamped), by "
      "the extension. The file is written under a temporary name and renamed, so it is never left half-written.");
  m.def(
      "compare",
      [](const py::object& test, const py::object& reference, const py::object& reference_variance, int block,
         double flip_ppd) {
        if (block < 1) throw py::value_error("compare: block must be at least 1, not " + std::to_string(block));
        if (!(flip_ppd > 0.0) || !std::isfinite(flip_ppd))
          throw py::value_error("compare: flip_ppd must be a positive number of pixels per degree");
        const Image t = image_argument(test, "test"), r = image_argument(reference, "reference");
        Image v;
        const bool has_variance = !reference_variance.is_none();
        if (has_variance) v = image_argument(reference_variance, "reference_variance");
        auto size = [](const Image& i) { return std::to_string(i.width) + "x" + std::to_string(i.height); };
        if (t.width != r.width || t.height != r.height) throw py::value_error("compare: the images differ in size (" + size(t) + " and " + size(r) + ")");
        if (has_variance && (v.width != r.width || v.height != r.height))
          throw py::value_error("compare: reference_variance is " + size(v) + ", the reference " + size(r));
        ImageError e;
        BlockError b;
        FlipResult f;
        {
          py::gil_scoped_release release;
          e = image_error(t, r, has_variance ? &v : nullptr);
          b = block_error(t, r, block);
          f = flip(t, r, flip_ppd);
        }
        py::dict d;
        d["mse"] = e.mse;
        d["rel_mse"] = e.rel_mse;
        d["mean_image"] = e.mean_image;
        d["mean_reference"] = e.mean_reference;
        d["block"] = block;
        d["block_rel_mse"] = b.block_rel_mse;
        d["blotched_share"] = b.blotched_share;
        d["flip"] = f.mean;
        return d;
      },
      py::arg("test"), py::arg("reference"), py::arg("reference_variance") = py::none(),
      py::arg("block") = kDefaultMetricBlock, py::arg("flip_ppd") = kFlipPixelsPerDegree,
      "The metrics of `pathspace compare`: mse, rel_mse (per channel (I - R)^2 / (R^2 + 0.01), averaged; the "
      "reference's own noise removed when its variance-of-the-mean image is given), mean_image and mean_reference; "
      "block_rel_mse (rel_mse of the two images averaged over block x block pixel blocks, partial blocks at the right "
      "and bottom edges over the pixels they have), blotched_share (the share of blocks whose mean Rec. 709 luminance "
      "differs from the reference block's by more than 0.25 x its luminance + 0.02) and block; flip, the mean LDR FLIP "
      "(Andersson et al. 2020; the images clamped to [0, 1]) at flip_ppd pixels per degree (67: 0.7 m from a 0.7 m "
      "wide 3840-pixel monitor). Each image argument is an array or an image file's path.");
}

}  // namespace pathspace::python
