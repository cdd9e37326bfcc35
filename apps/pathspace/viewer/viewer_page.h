// The page `pathspace view` serves (docs/viewer.md): static HTML, CSS and JavaScript compiled into
// the binary, no network resource of its own.
#pragma once

namespace pathspace::viewer {

extern const char* const kViewerPage;

}  // namespace pathspace::viewer
