// The image files of an experiment, under <out>/images/: each cell's render (PNG, optionally EXR)
// with its false-colour relative-error map (error_colormap.h), and each scene's reference. Names are
// SCENE-EXPERIMENT-LABEL[-sSEED][-pPASSES] with the label as a slug ("PCLT plane" -> "pclt-plane").
#pragma once

#include <string>

#include "pathspace/film/image.h"

namespace pathspace::study {

// Lower-case letters and digits, everything else one '-': "PCLT 0.25x pixels" -> "pclt-0-25x-pixels".
std::string slug(const std::string& text);

struct ImageFiles {
  std::string png, error_png, exr;  // relative to the output folder; exr empty when not written
};

// Writes image (and, when reference is non-empty, its error map) as <out>/<base>.png, .err.png
// and with write_exr .exr; base is relative ("images/bs_c-fig1-pt").
ImageFiles write_images(const std::string& out_dir, const std::string& base, const Image& image, const Image& reference,
                        bool write_exr);

// Creates <out>/images; throws pathspace::Error when it cannot.
void create_image_folder(const std::string& out_dir);

}  // namespace pathspace::study
