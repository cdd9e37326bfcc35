// DeviceScene: a Scene's SceneView copied to device memory, every array it points to included
// (geometry, materials, textures and their texels, lights, the light and environment
// distributions), so kernels take a SceneView whose pointers are device pointers. Uploaded once per
// scene; the device arrays live as long as the object. CUDA builds only.
#pragma once

#include <vector>

#include "pathspace/parallel/device_buffer.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace::gpu {

class DeviceScene {
 public:
  explicit DeviceScene(const Scene& scene);
  // The view with device pointers (host-side struct: pass it to kernels by value).
  const SceneView& view() const { return view_; }
  size_t bytes() const { return bytes_; }

 private:
  // Uploads n elements and returns the device pointer (null for n == 0 or a null source).
  template <typename T>
  const T* upload(const T* host, size_t n);

  SceneView view_;
  size_t bytes_ = 0;
  std::vector<DeviceBuffer<unsigned char>> arrays_;  // every uploaded array, owned here
};

}  // namespace pathspace::gpu
