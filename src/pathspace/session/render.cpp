#include "pathspace/session/render.h"

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"

#ifndef PATHSPACE_BUILD_TYPE
#define PATHSPACE_BUILD_TYPE "unknown"
#endif

namespace pathspace {

const char* build_type() { return PATHSPACE_BUILD_TYPE; }

RenderSnapshot render(const Scene& scene, const Accel& accel, const RenderConfig& config, const RunLimit& limit) {
  if (limit.passes == 0 && !(limit.seconds > 0.0)) throw Error("render() needs a pass count or a time budget");
  // Non-owning handles: the caller keeps scene and accel alive for this call.
  RenderSession session(std::shared_ptr<const Scene>(std::shared_ptr<void>(), &scene),
                        std::shared_ptr<const Accel>(std::shared_ptr<void>(), &accel), config);
  session.run(limit);
  return session.snapshot();
}

}  // namespace pathspace
