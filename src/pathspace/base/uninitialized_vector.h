// A std::vector whose resize() leaves new elements unwritten: for large buffers of which a pass
// writes only some entries (the vertex buffer's record slots, filters/vertex_buffer.h), so that the
// pages of entries never written are never touched (no zeroing pass, no page faults, no resident
// memory). Only for implicit-lifetime types (trivially copyable and destructible): storage from
// std::allocator<T>::allocate holds such objects without a constructor call (C++20, P0593). The
// caller must not read an entry before writing it.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace pathspace {

template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "UninitializedAllocator: only for implicit-lifetime types");
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  // resize(n) and the like: leave the entry as allocated.
  template <typename U>
  void construct(U*) noexcept {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace pathspace
