// Signals raised inside an in-process library call (an assert's abort, a segmentation fault)
// become a crash answer instead of ending the judge; a call that never returns is abandoned by
// the watchdog's timer signal the same way.

#include "collide/judge/adapter.hpp"

#include <cmath>
#include <csetjmp>
#include <csignal>
#include <cstring>
#include <sys/time.h>

namespace collide::judge::detail {

namespace {

thread_local sigjmp_buf* g_jump = nullptr;
thread_local volatile sig_atomic_t g_signal = 0;

// The watchdog's state: calls started (the handler sees progress when it changes), the count the
// handler last saw, its ticks without progress, and the ticks that make a hang (0: disarmed).
volatile sig_atomic_t g_calls = 0;
volatile sig_atomic_t g_seen = 0;
volatile sig_atomic_t g_stuck = 0;
volatile sig_atomic_t g_limit_ticks = 0;
constexpr int kTicksPerLimit = 10;

void on_signal(int sig) {
  if (g_jump == nullptr) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
  siglongjmp(*g_jump, 1);
}

// A tick: progress since the last one resets the count; a call outstanding for the whole limit
// is abandoned. Outside a guarded call the tick does nothing.
void on_tick(int) {
  if (g_limit_ticks == 0 || g_jump == nullptr) return;
  if (g_calls != g_seen) {
    g_seen = g_calls;
    g_stuck = 0;
    return;
  }
  g_stuck = g_stuck + 1;
  if (g_stuck < g_limit_ticks) return;
  g_signal = SIGALRM;
  siglongjmp(*g_jump, 1);
}

constexpr int kSignals[] = {SIGABRT, SIGSEGV, SIGFPE, SIGBUS, SIGILL};

// What the watchdog replaced (a host's own SIGALRM handler and timer), restored when disarmed.
struct sigaction g_old_action {};
itimerval g_old_timer{};

}  // namespace

Watchdog::Watchdog(double limit_seconds) {
  struct sigaction sa {};
  sa.sa_handler = on_tick;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_NODEFER | SA_RESTART;
  sigaction(SIGALRM, &sa, &g_old_action);
  g_stuck = 0;
  g_seen = g_calls;
  g_limit_ticks = kTicksPerLimit;
  const double period = limit_seconds / kTicksPerLimit, whole = std::floor(period);
  itimerval t{};
  t.it_interval.tv_sec = static_cast<time_t>(whole);
  t.it_interval.tv_usec = static_cast<suseconds_t>((period - whole) * 1e6);
  t.it_value = t.it_interval;
  setitimer(ITIMER_REAL, &t, &g_old_timer);
}

Watchdog::~Watchdog() {
  g_limit_ticks = 0;
  setitimer(ITIMER_REAL, &g_old_timer, nullptr);
  sigaction(SIGALRM, &g_old_action, nullptr);
}

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
    what = g_signal == SIGALRM ? std::string("hang: the library call ran past the time-out")
                               : std::string("signal ") + strsignal(g_signal) + " inside the library";
    return false;
  }
  g_calls = g_calls + 1;
  g_jump = &jump;
  f(ctx);
  g_jump = nullptr;
  return true;
}

}  // namespace collide::judge::detail
