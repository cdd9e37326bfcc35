#include "interrupt_handler.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

#include "pathspace/io/atomic_file.h"
#include "pathspace/session/render_session.h"

namespace pathspace::cli {

namespace {

std::atomic<int> g_signal{0};
std::atomic<RenderSession*> g_session{nullptr};
std::atomic<bool> g_speaks{true};  // false on the ranks of a distributed render other than 0
constexpr const char* kRenderMessage =
    "\npathspace render: interrupted: finishing the pass in flight, then writing the outputs (again to stop at once)\n";
std::atomic<const char*> g_first_message{kRenderMessage};
struct sigaction g_previous_int, g_previous_term;

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<RenderSession*>::is_always_lock_free && std::atomic<bool>::is_always_lock_free &&
                  std::atomic<const char*>::is_always_lock_free,
              "the signal handler may only touch lock-free atomics");

void say(const char* text) {
  if (!g_speaks.load()) return;
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

// Async-signal-safe: lock-free atomics, RenderSession::cancel() (an atomic store), write, unlink, _exit.
extern "C" void on_signal(int sig) {
  int none = 0;
  if (g_signal.compare_exchange_strong(none, sig)) {
    if (RenderSession* s = g_session.load()) s->cancel();
    say(g_first_message.load());
    return;
  }
  remove_unfinished_temporaries();
  say("\npathspace render: stopped at once; no file is half-written\n");
  ::_exit(128 + g_signal.load());
}

}  // namespace

InterruptHandler::InterruptHandler(bool speaks, const char* first_signal_message) {
  g_speaks.store(speaks);
  g_first_message.store(first_signal_message ? first_signal_message : kRenderMessage);
  g_signal.store(0);
  g_session.store(nullptr);
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptHandler::~InterruptHandler() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
  g_session.store(nullptr);
}

void InterruptHandler::watch(RenderSession* session) {
  g_session.store(session);
  if (session && g_signal.load() != 0) session->cancel();
}

int InterruptHandler::signal() const { return g_signal.load(); }

int InterruptHandler::exit_code() const { return signal() ? 128 + signal() : 0; }

}  // namespace pathspace::cli
