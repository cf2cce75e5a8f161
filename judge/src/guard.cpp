// Signals raised inside an in-process library call (an assert's abort, a segmentation fault)
// become a crash answer instead of ending the judge.

#include "collide/judge/adapter.hpp"

#include <csetjmp>
#include <csignal>
#include <cstring>

namespace collide::judge::detail {

namespace {

thread_local sigjmp_buf* g_jump = nullptr;
thread_local volatile sig_atomic_t g_signal = 0;

void on_signal(int sig) {
  if (g_jump == nullptr) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
  siglongjmp(*g_jump, 1);
}

constexpr int kSignals[] = {SIGABRT, SIGSEGV, SIGFPE, SIGBUS, SIGILL};

}  // namespace

bool run_guarded(void (*f)(void*), void* ctx, std::string& what) {
  static const bool installed = [] {
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_NODEFER | SA_ONSTACK;
    for (int s : kSignals) sigaction(s, &sa, nullptr);
    return true;
  }();
  (void)installed;
  sigjmp_buf jump;
  // Mask restored on the jump: the handler ran with the signal unblocked (SA_NODEFER) anyway.
  if (sigsetjmp(jump, 0) != 0) {
    g_jump = nullptr;
    what = std::string("signal ") + strsignal(g_signal) + " inside the library";
    return false;
  }
  g_jump = &jump;
  f(ctx);
  g_jump = nullptr;
  return true;
}

}  // namespace collide::judge::detail
