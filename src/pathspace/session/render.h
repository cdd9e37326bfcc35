// render(): the one-call convenience over RenderSession for callers that own the scene and its
// acceleration structure and want a finished render (tests, benchmarks).
#pragma once

#include "pathspace/session/render_session.h"

namespace pathspace {

// Renders with `config` until `limit` in a session that borrows scene and accel; returns the
// images, statistics and AOVs.
RenderSnapshot render(const Scene& scene, const Accel& accel, const RenderConfig& config, const RunLimit& limit);

// "release", "debug", ... as configured at build time.
const char* build_type();

}  // namespace pathspace
