#include "host/cli/stop_signals.hpp"

#include <atomic>

namespace facet {
namespace {

std::atomic<int> g_first{0};
std::atomic<int> g_count{0};
static_assert(std::atomic<int>::is_always_lock_free, "signal handlers need a lock-free atomic");

extern "C" void on_stop_signal(int sig) {
    int none = 0;
    g_first.compare_exchange_strong(none, sig);
    g_count.fetch_add(1);
}

void install(int sig, void (*handler)(int), struct sigaction* old) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;  // the OpenCL runtime's waits carry on
    sigaction(sig, &sa, old);
}

}  // namespace

StopSignals::StopSignals() {
    g_first.store(0);
    g_count.store(0);
    install(SIGINT, on_stop_signal, &old_int_);
    install(SIGTERM, on_stop_signal, &old_term_);
    install(SIGHUP, on_stop_signal, &old_hup_);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
    sigaction(SIGHUP, &old_hup_, nullptr);
}

SigpipeIgnored::SigpipeIgnored() { install(SIGPIPE, SIG_IGN, &old_); }

SigpipeIgnored::~SigpipeIgnored() { sigaction(SIGPIPE, &old_, nullptr); }

int StopSignals::first() const { return g_first.load(); }
int StopSignals::count() const { return g_count.load(); }

}  // namespace facet
