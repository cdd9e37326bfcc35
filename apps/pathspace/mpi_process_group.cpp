#include "mpi_process_group.h"

#include <mpi.h>

#include <cstdlib>
#include <limits>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace::cli {

namespace {

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw Error(std::string("MPI: ") + what + " failed");
}

// MPI counts are ints: a message of 2 GiB or more would need splitting, which no film slice needs
// below 16k x 16k pixels per rank.
int count_of(size_t bytes) {
  if (bytes > size_t(std::numeric_limits<int>::max())) throw Error("MPI: a message of more than 2 GiB");
  return int(bytes);
}

class MpiWorld final : public ProcessGroup {
 public:
  MpiWorld() {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiWorld() override {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void all_to_all(const std::vector<std::vector<uint8_t>>& send, std::vector<std::vector<uint8_t>>* received) override {
    const size_t n = static_cast<size_t>(size_);
    std::vector<int> send_counts(n), send_offsets(n), recv_counts(n), recv_offsets(n);
    std::vector<uint8_t> send_bytes;
    for (int d = 0; d < size_; ++d) {
      send_offsets[size_t(d)] = count_of(send_bytes.size());
      send_counts[size_t(d)] = count_of(send[size_t(d)].size());
      send_bytes.insert(send_bytes.end(), send[size_t(d)].begin(), send[size_t(d)].end());
    }
    check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Alltoall");
    size_t total = 0;
    for (int s = 0; s < size_; ++s) recv_offsets[size_t(s)] = count_of(total), total += size_t(recv_counts[size_t(s)]);
    std::vector<uint8_t> recv_bytes(total);
    check(MPI_Alltoallv(send_bytes.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, recv_bytes.data(), recv_counts.data(),
                        recv_offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    received->assign(size_t(size_), {});
    for (int s = 0; s < size_; ++s) {
      const auto begin = recv_bytes.begin() + recv_offsets[size_t(s)];
      (*received)[size_t(s)].assign(begin, begin + recv_counts[size_t(s)]);
    }
  }

  std::vector<std::vector<uint8_t>> gather(const std::vector<uint8_t>& bytes) override {
    const int mine = count_of(bytes.size());
    const size_t n = static_cast<size_t>(size_);
    std::vector<int> counts(n), offsets(n);
    check(MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    size_t total = 0;
    if (rank_ == 0)
      for (int s = 0; s < size_; ++s) offsets[size_t(s)] = count_of(total), total += size_t(counts[size_t(s)]);
    std::vector<uint8_t> all(total);
    check(MPI_Gatherv(bytes.data(), mine, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD), "MPI_Gatherv");
    std::vector<std::vector<uint8_t>> out;
    if (rank_ != 0) return out;
    for (int s = 0; s < size_; ++s) {
      const auto begin = all.begin() + offsets[size_t(s)];
      out.emplace_back(begin, begin + counts[size_t(s)]);
    }
    return out;
  }

  std::vector<uint64_t> all_gather(uint64_t value) override {
    std::vector<uint64_t> all(static_cast<size_t>(size_));
    check(MPI_Allgather(&value, 1, MPI_UINT64_T, all.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD), "MPI_Allgather");
    return all;
  }

  void all_max(std::vector<uint64_t>* values) override {
    check(MPI_Allreduce(MPI_IN_PLACE, values->data(), count_of(values->size()), MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  }

  void all_sum(std::vector<uint64_t>* values) override {
    // Unsigned addition wraps modulo 2^64 in any order, like the fixed-point sums it adds.
    check(MPI_Allreduce(MPI_IN_PLACE, values->data(), count_of(values->size()), MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  }

  void broadcast(int root, std::string* text) override {
    uint64_t size = text->size();
    check(MPI_Bcast(&size, 1, MPI_UINT64_T, root, MPI_COMM_WORLD), "MPI_Bcast");
    text->resize(size_t(size));
    check(MPI_Bcast(text->data(), count_of(size_t(size)), MPI_CHAR, root, MPI_COMM_WORLD), "MPI_Bcast");
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::shared_ptr<ProcessGroup> mpi_world() {
  static const std::shared_ptr<ProcessGroup> world = std::make_shared<MpiWorld>();
  return world;
}

void mpi_abort(int exit_code) {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Abort(MPI_COMM_WORLD, exit_code);
}

}  // namespace pathspace::cli
