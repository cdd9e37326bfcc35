// `pathspace study gallery DIR`: every scene under DIR that has a reference image beside it
// (TungstenRender.exr, as in Bitterli's scenes) is rendered at the reference's resolution for a fixed
// time and compared with it: the mean ratio per channel, relMSE, and the render, the reference and
// a relative-error map side by side on one HTML page (gallery.html, gallery.json; docs/cli.md,
// docs/scene-files.md "Gallery").
#pragma once

#include "studies/common/study_options.h"

namespace pathspace::studies {

// Renders and compares; a scene that fails to load or render is listed with its error. Throws
// UsageError for invalid options, pathspace::Error when nothing can be written.
int run_gallery_study(const GalleryOptions& o);

}  // namespace pathspace::studies
