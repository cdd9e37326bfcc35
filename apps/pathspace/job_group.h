// The process group of a `pathspace render` started by mpirun or srun (docs/distributed.md), and the
// CLI's rules for failures in one: a step every rank runs (reading the scene) ends with an agreement,
// so one rank's error stops all of them with its message; a failure after that aborts the job.
// Built without MPI (PATHSPACE_MPI off) or started alone, there is no group and nothing changes.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "pathspace/parallel/process_group.h"

namespace pathspace::cli {

// Null unless this process is one of several started by an MPI launcher (MPI is initialised on the
// first call and finalised at exit).
std::shared_ptr<ProcessGroup> job_group();

// Runs `step` on every rank, then agrees (collectively) whether it failed anywhere: every rank then
// throws the error of the lowest failing rank (a UsageError stays one), prefixed with its rank.
void agreed_step(ProcessGroup* group, const std::function<void()>& step);
// True on the ranks other than 0 once agreed_step threw: rank 0 prints that error for the job
// (with the failing rank's number), the others only exit with its status.
bool error_printed_by_rank0();

// Collective: throws on every rank when `text` differs between ranks, naming the first rank that
// differs from rank 0 and `what` the text holds (the run options that decide how much is rendered,
// which RenderSession::join's fingerprint of the image options leaves out).
void require_same_on_every_rank(ProcessGroup* group, const std::string& what, const std::string& text);

// A failure on this rank alone while the others may be waiting for it: prints the message and ends
// the whole job (MPI_Abort), so nothing hangs.
[[noreturn]] void abort_job(const std::string& message, int exit_code);

// A fingerprint of this executable's bytes (the options and the scene are compared by
// RenderSession::join): ranks running different builds are refused at start-up.
std::string binary_identity();

}  // namespace pathspace::cli
