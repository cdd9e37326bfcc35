// VertexBuffer: the selected vertices of one sample pass in structure-of-arrays form (Binder et al.
// 2021, sec. 3: "the first phase generates paths and stores all necessary information"). Record r of
// path p is slot r * paths + p, r < count[p] (VertexBufferView::slot); each path writes only its own
// slots, so filling is race-free and the layout is independent of the thread schedule.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/base/uninitialized_vector.h"
#include "pathspace/filters/path_sample.h"
#include "pathspace/filters/vertex_buffer_view.h"

namespace pathspace {

// One value per record slot, e.g. a filter's output: like the buffer's own slot arrays, the entries
// of slots that hold no record are left unwritten (and unread).
using SlotValues = UninitializedVector<Rgb>;

class VertexBuffer {
 public:
  // Keeps the arrays' contents where the layout is unchanged (slots beyond a path's count are never
  // read), so a buffer resized for a smaller last batch and back costs no clearing pass. New slots
  // are left unwritten (UninitializedVector): a path writes only its records, and the blocks of
  // the rarer records (camera-side branches, second layers) are mostly never touched, so their
  // memory is never paged in. Only the first block is zeroed, since readers that walk every path
  // read its first slot whether or not it holds a record (filters/hashed/voxel_key_blocks.h).
  void resize(size_t paths, int records_per_path);
  size_t paths() const { return prefix.size(); }
  int records_per_path() const { return records_per_path_; }
  size_t slot(size_t path, int record) const { return size_t(record) * paths() + path; }
  size_t total_records() const;  // valid records (sum of count)

  // Stores one path's sample (drops records beyond records_per_path; the caller sizes it right):
  // VertexBufferView::store, the one implementation the GPU uses too.
  void store(size_t path, uint32_t pixel_index, const PathSample& s) { view().store(path, pixel_index, s); }
  // Raw pointers to the arrays (valid until the next resize). The const form is for readers: the
  // view's pointers are not const so that one type serves writers and readers on both sides.
  VertexBufferView view();
  VertexBufferView view() const { return const_cast<VertexBuffer*>(this)->view(); }
  // The record in slot i as the kernel produced it.
  FilterVertex record(size_t i) const;
  // out sized to every slot, each record's own contribution in its slot (what a filter hands on
  // unfiltered).
  void copy_contributions(SlotValues* out) const;

  // One vector per field of filters/vertex_fields.h: per path, then per record slot (a slot holds
  // whatever was last written there, or nothing, unless it is one of its path's count records).
#define PATHSPACE_HOST_PATH_FIELD(T, name, what) std::vector<T> name;
#define PATHSPACE_HOST_SLOT_FIELD(T, name, member, what) UninitializedVector<T> name;
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_HOST_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_HOST_SLOT_FIELD)
#undef PATHSPACE_HOST_PATH_FIELD
#undef PATHSPACE_HOST_SLOT_FIELD

  // Bytes one path and one record slot take (the batch budget of a filter counts them).
  static size_t bytes_per_path();
  static size_t bytes_per_slot();

 private:
  int records_per_path_ = 0;
};

// Slots per path for a vertex selection (vertices per path times layers).
int records_per_path(const VertexSelection& selection);

}  // namespace pathspace
