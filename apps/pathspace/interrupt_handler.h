// Ctrl-C (SIGINT) and SIGTERM during `pathspace render`: the first signal lets the pass in flight
// finish; the render then writes its outputs and checkpoint from every completed pass and exits with
// 128 + the signal (130 for SIGINT, 143 for SIGTERM; docs/checkpoints.md, "Interrupting"). A second
// signal ends the process at once with the same code, after removing the temporary files being
// written, so no output is ever half-written.
#pragma once

namespace pathspace {
class RenderSession;
}

namespace pathspace::cli {

class InterruptHandler {
 public:
  // Installs the handlers (one InterruptHandler at a time); the destructor restores the previous ones.
  // `speaks`: print what a signal does (rank 0 of a distributed render only: mpirun signals every rank).
  // `first_signal_message`: what the first signal prints (a string literal); nullptr: the render's.
  explicit InterruptHandler(bool speaks = true, const char* first_signal_message = nullptr);
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

  // The first signal cancels `session` (at once when it came already); nullptr: none.
  void watch(RenderSession* session);
  // The first signal received (SIGINT or SIGTERM), 0 while none.
  int signal() const;
  // 128 + signal(): the exit status of an interrupted render.
  int exit_code() const;
};

}  // namespace pathspace::cli
