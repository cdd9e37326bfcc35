// Checked accessor reads (see gltf_accessors.h). Sizes are compared as differences, never as sums
// that could wrap around.
#include "pathspace/io/gltf/gltf_accessors.h"

#include <cmath>
#include <cstring>

namespace pathspace::gltf {

namespace {

size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

size_t components_of(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// Where the elements of an accessor lie: the first element's bytes and the distance between elements.
struct ElementSpan {
  const unsigned char* first = nullptr;
  size_t stride = 0, count = 0, element_size = 0;
  const unsigned char* at(size_t i) const { return first + i * stride; }
};

ElementSpan locate(const Context& c, int index, int type, const std::string& what) {
  const tinygltf::Model& m = c.model;
  check_index(c, index, m.accessors.size(), what);
  const std::string name = element("accessors", size_t(index));
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  if (a.type != type) c.fail(name + " (" + what + ") has the wrong type " + std::to_string(a.type));
  ElementSpan s;
  s.count = a.count;
  s.element_size = component_size(a.componentType) * components_of(a.type);
  if (s.element_size == 0) c.fail(name + " has an invalid componentType " + std::to_string(a.componentType));
  if (a.sparse.isSparse) c.warn(name + ".sparse is not supported; the base values are used");
  if (a.bufferView < 0) c.fail(name + " has no bufferView (accessors without data are not supported)");
  check_index(c, a.bufferView, m.bufferViews.size(), name + ".bufferView");
  const tinygltf::BufferView& v = m.bufferViews[size_t(a.bufferView)];
  const std::string view = element("bufferViews", size_t(a.bufferView));
  check_index(c, v.buffer, m.buffers.size(), view + ".buffer");
  const std::vector<unsigned char>& data = m.buffers[size_t(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
    c.fail(view + " (offset " + std::to_string(v.byteOffset) + ", length " + std::to_string(v.byteLength) + ") lies outside its buffer of " +
           std::to_string(data.size()) + " bytes");
  s.stride = v.byteStride != 0 ? v.byteStride : s.element_size;
  if (s.stride < s.element_size) c.fail(view + ".byteStride " + std::to_string(v.byteStride) + " is smaller than an element of " + name);
  if (s.count == 0) return s;
  // Last element's end: byteOffset + stride * (count - 1) + element_size <= byteLength.
  const size_t avail = v.byteLength;
  if (a.byteOffset > avail || s.element_size > avail - a.byteOffset ||
      s.count - 1 > (avail - a.byteOffset - s.element_size) / s.stride)
    c.fail(name + " (" + std::to_string(s.count) + " elements from offset " + std::to_string(a.byteOffset) + ") does not fit in " + view);
  s.first = data.data() + v.byteOffset + a.byteOffset;
  return s;
}

template <class T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // glTF data is little-endian, like every machine pathspace targets
  return v;
}

}  // namespace

std::vector<float> read_floats(const Context& c, int index, int type, bool allow_normalized, const std::string& what) {
  const ElementSpan s = locate(c, index, type, what);
  const tinygltf::Accessor& a = c.model.accessors[size_t(index)];
  const size_t n = components_of(type);
  const int ct = a.componentType;
  const bool normalized_ok = allow_normalized && a.normalized &&
                             (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (ct != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_ok)
    c.fail(element("accessors", size_t(index)) + " (" + what + ") has componentType " + std::to_string(ct) +
           (allow_normalized ? "; expected FLOAT or normalized unsigned byte/short" : "; expected FLOAT"));
  std::vector<float> out(s.count * n);
  for (size_t i = 0; i < s.count; ++i)
    for (size_t k = 0; k < n; ++k) {
      const unsigned char* p = s.at(i) + k * component_size(ct);
      float x = 0.f;
      if (ct == TINYGLTF_COMPONENT_TYPE_FLOAT) x = load<float>(p);
      else if (ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) x = float(*p) / 255.f;
      else x = float(load<uint16_t>(p)) / 65535.f;
      if (!std::isfinite(x)) c.fail(element("accessors", size_t(index)) + " (" + what + ") holds a NaN or infinite value");
      out[i * n + k] = x;
    }
  return out;
}

std::vector<uint32_t> read_unsigned(const Context& c, int index, int type, const std::string& what) {
  const ElementSpan s = locate(c, index, type, what);
  const int ct = c.model.accessors[size_t(index)].componentType;
  if (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    c.fail(element("accessors", size_t(index)) + " (" + what + ") has componentType " + std::to_string(ct) + "; expected an unsigned integer type");
  const size_t n = components_of(type), size = component_size(ct);
  std::vector<uint32_t> out(s.count * n);
  for (size_t i = 0; i < s.count; ++i)
    for (size_t k = 0; k < n; ++k) {
      const unsigned char* p = s.at(i) + k * size;
      out[i * n + k] = size == 1 ? *p : size == 2 ? load<uint16_t>(p) : load<uint32_t>(p);
    }
  return out;
}

std::vector<uint32_t> read_indices(const Context& c, int index, size_t vertex_count, const std::string& what) {
  const ElementSpan s = locate(c, index, TINYGLTF_TYPE_SCALAR, what);
  const int ct = c.model.accessors[size_t(index)].componentType;
  if (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    c.fail(element("accessors", size_t(index)) + " (" + what + ") has componentType " + std::to_string(ct) + "; expected an unsigned integer type");
  std::vector<uint32_t> out(s.count);
  for (size_t i = 0; i < s.count; ++i) {
    const unsigned char* p = s.at(i);
    const uint32_t v = ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? *p : ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? load<uint16_t>(p) : load<uint32_t>(p);
    if (v >= vertex_count)
      c.fail(what + ": index " + std::to_string(v) + " at position " + std::to_string(i) + " names no vertex (" + std::to_string(vertex_count) + " vertices)");
    out[i] = v;
  }
  return out;
}

}  // namespace pathspace::gltf
