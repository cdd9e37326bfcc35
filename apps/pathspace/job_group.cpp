#include "job_group.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "pathspace/base/fnv1a.h"
#include "pathspace/options/usage_error.h"

#if PATHSPACE_HAVE_MPI
#include "mpi_process_group.h"
#endif

namespace pathspace::cli {

namespace {
// Set by the MPI launchers of Open MPI, MPICH / Slurm (PMI) and PMIx: a plain start stays MPI-free.
bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

#if !PATHSPACE_HAVE_MPI
// The launcher's process count where it says (Open MPI, PMI); 1 otherwise.
long launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::strtol(v, nullptr, 10);
  return 1;
}
#endif
}  // namespace

std::shared_ptr<ProcessGroup> job_group() {
#if PATHSPACE_HAVE_MPI
  static const std::shared_ptr<ProcessGroup> group = started_by_launcher() ? mpi_world() : nullptr;
  return group && group->size() > 1 ? group : nullptr;
#else
  // Without MPI every process of an mpirun job would render the whole image alone and write the same
  // files: refuse instead of doing that silently.
  if (started_by_launcher() && launched_processes() > 1)
    throw Error(fmt::format("started by an MPI launcher with {} processes, but this pathspace was built without MPI "
                            "(PATHSPACE_MPI off): run it without mpirun, or rebuild with Open MPI (docs/distributed.md)",
                            launched_processes()));
  return nullptr;
#endif
}

namespace {
bool g_error_printed_by_rank0 = false;
}  // namespace

bool error_printed_by_rank0() { return g_error_printed_by_rank0; }

void agreed_step(ProcessGroup* group, const std::function<void()>& step) {
  if (!group) return step();
  std::exception_ptr failure;
  uint64_t code = 0;  // 0: ok, 1: failure, 2: usage error
  std::string message;
  try {
    step();
  } catch (const UsageError& e) {
    failure = std::current_exception(), code = 2, message = e.what();
  } catch (const std::exception& e) {
    failure = std::current_exception(), code = 1, message = e.what();
  }
  const std::vector<uint64_t> codes = group->all_gather(code);
  int first = -1;
  for (size_t r = 0; r < codes.size() && first < 0; ++r)
    if (codes[r] != 0) first = int(r);
  if (first < 0) return;
  group->broadcast(first, &message);
  g_error_printed_by_rank0 = group->rank() != 0;
  if (first == group->rank()) std::rethrow_exception(failure);
  const std::string text = fmt::format("rank {}: {}", first, message);
  if (codes[size_t(first)] == 2) throw UsageError(text);
  throw Error(text);
}

void require_same_on_every_rank(ProcessGroup* group, const std::string& what, const std::string& text) {
  if (!group) return;
  const std::vector<uint64_t> all = group->all_gather(fnv1a64(text.data(), text.size()));
  for (size_t r = 1; r < all.size(); ++r)
    if (all[r] != all[0]) {
      g_error_printed_by_rank0 = group->rank() != 0;
      throw UsageError(fmt::format("distributed render: rank {} was started with other {} than rank 0 (this rank: {})", r, what, text),
                       "start every rank with the same options");
    }
}

void abort_job(const std::string& message, int exit_code) {
  fmt::print(stderr, "pathspace render: error: {}\n", message);
  std::fflush(stderr);
#if PATHSPACE_HAVE_MPI
  mpi_abort(exit_code);
#endif
  std::exit(exit_code);
}

std::string binary_identity() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return "binary=" + std::to_string(fnv1a64(bytes.data(), bytes.size())) + " size=" + std::to_string(bytes.size());
}

}  // namespace pathspace::cli
