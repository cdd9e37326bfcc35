// The processes that render one image together (docs/distributed.md): the few collective operations
// a distributed RenderSession needs, as an interface, so that the library does not depend on MPI.
// The CLI provides the MPI implementation (apps/pathspace/mpi_process_group.h); a render without one
// is a single process and exchanges nothing. Every operation is collective: all ranks call it, in
// the same order, or the job hangs (the CLI aborts the job when one rank fails alone).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pathspace {

class ProcessGroup {
 public:
  virtual ~ProcessGroup() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Rank r sends send[d] to rank d and receives into (*received)[s] what rank s sent it.
  virtual void all_to_all(const std::vector<std::vector<uint8_t>>& send, std::vector<std::vector<uint8_t>>* received) = 0;
  // Rank 0 receives every rank's bytes in rank order (its own included); the others get nothing.
  virtual std::vector<std::vector<uint8_t>> gather(const std::vector<uint8_t>& bytes) = 0;
  // Every rank's value, in rank order, on every rank.
  virtual std::vector<uint64_t> all_gather(uint64_t value) = 0;
  // Element-wise maximum over the ranks, on every rank (the stop agreement).
  virtual void all_max(std::vector<uint64_t>* values) = 0;
  // Element-wise sum modulo 2^64 over the ranks, on every rank (fixed-point sums: any order gives the same).
  virtual void all_sum(std::vector<uint64_t>* values) = 0;
  // Rank `root`'s text on every rank.
  virtual void broadcast(int root, std::string* text) = 0;
};

}  // namespace pathspace
