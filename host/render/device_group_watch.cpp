#include "host/render/device_group_watch.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "host/error.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// A positive number of seconds from the environment, else `fallback`.
double seconds_from_env(const char* name, double fallback) {
    const char* v = std::getenv(name);
    if (!v || !*v) return fallback;
    char* end = nullptr;
    const double s = std::strtod(v, &end);
    if (end == v || *end != '\0' || !(s > 0.0))
        throw Error(fmt::format("{}={}: expected a positive number of seconds", name, v));
    return s;
}

std::string rank_list(const std::vector<int>& ranks) {
    std::string s;
    for (int r : ranks) s += (s.empty() ? "" : ", ") + std::to_string(r);
    return s;
}

}  // namespace

DeviceGroupWatch::DeviceGroupWatch(const DeviceGroup& group, std::function<int()> stop_signal,
                                   std::function<int(const Lost&)> save)
    : group_(group), stop_signal_(std::move(stop_signal)), save_(std::move(save)) {
    grace_s_ = 0.3 * seconds_from_env("OMPI_MCA_odls_base_sigkill_timeout", 1.0);
    rank_timeout_s_ = seconds_from_env("FACET_RANK_TIMEOUT", 300.0);
    thread_ = std::thread([this] { watch(); });
}

DeviceGroupWatch::~DeviceGroupWatch() {
    stand_down();
    if (thread_.joinable()) thread_.join();
}

void DeviceGroupWatch::stand_down() {
    const std::lock_guard<std::mutex> lock(mutex_);  // held by a saving watch until the exit
    stood_down_ = true;
    wake_.notify_all();
}

void DeviceGroupWatch::watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    Clock::time_point signalled{};
    bool seen = false;
    for (;;) {
        wake_.wait_for(lock, std::chrono::milliseconds(20));
        if (stood_down_) return;
        const Ranks::Wait wait = group_.ranks().waiting();
        const int sig = stop_signal_();
        if (sig != 0 && !seen) {
            seen = true;
            signalled = Clock::now();
        }
        const bool ending = seen && std::chrono::duration<double>(Clock::now() - signalled).count() >= grace_s_;
        const bool silent = wait.waiting() && wait.seconds >= rank_timeout_s_;
        if (!ending && !silent) continue;

        Lost lost;
        lost.ranks = wait.ranks;
        lost.waiting = wait.waiting();
        // In the reduction, one of the ranks (exactly one when there are two ranks).
        const std::string whom =
            wait.ranks.empty() ? std::string("an MPI rank")
            : wait.ranks.size() < 2
                ? fmt::format("MPI rank {}", wait.ranks[0])
                : fmt::format("{}MPI ranks {}", wait.reduction ? "one of " : "", rank_list(wait.ranks));
        if (silent) {
            lost.why =
                fmt::format("{} did not answer for {:.0f} s (FACET_RANK_TIMEOUT); the job is lost", whom, wait.seconds);
        } else if (wait.waiting()) {
            lost.why = fmt::format(
                "the job is ending (signal {} from mpirun) while rank 0 waits for {}{}: {} died or was killed", sig,
                whom, wait.reduction ? " in the films' reduction" : "",
                wait.ranks.size() > 1 ? (wait.reduction ? "one of them" : "they") : "that rank");
        } else {
            lost.why =
                fmt::format("the job is ending (signal {} from mpirun: a rank died, or Ctrl-C) in mid-pass", sig);
        }
        int status = kExitRankLost;
        try {
            const std::unique_lock<std::mutex> film = group_.hold_film();
            status = save_(lost);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "facet: error: saving the job's film: %s\n", e.what());
        }
        std::fflush(stdout);
        std::fflush(stderr);
        std::_Exit(status);
    }
}

}  // namespace facet
