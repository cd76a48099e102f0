// At rank 0 of an MPI job: a thread that saves the job's work when the job is ending
// without rank 0's consent. Open MPI 4.1 cannot survive a rank's death (no ULFM): mpirun
// sends every other rank SIGTERM and, odls_base_sigkill_timeout seconds later (1 by
// default), SIGKILL, while rank 0 waits for the dead rank inside a gather or the films'
// reduction and never reaches its final writes. The watch sees the stop signal (the
// render's StopSignals) and, when the main thread has not begun its final writes within
// 0.3 of the kill timeout (OMPI_MCA_odls_base_sigkill_timeout), calls `save` with the film
// held as of the last pass end (DeviceGroup::hold_film) and ends the process with the exit
// status `save` returns. A rank that has not answered
// for FACET_RANK_TIMEOUT seconds (default 300: a hung device, or an mpirun run with
// --enable-recovery that does not end the job) is handled alike.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "host/render/device_group.hpp"

namespace facet {

// The job lost a rank; rank 0 wrote the samples every rank had finished.
constexpr int kExitRankLost = 3;

class DeviceGroupWatch {
public:
    struct Lost {
        std::string why;         // "MPI rank 1 did not answer: ...", for the message
        std::vector<int> ranks;  // the ranks rank 0 was waiting for (empty: unknown or none)
        bool waiting = false;    // rank 0 was waiting for a rank (false: Ctrl-C in mid-pass, or
                                 // a rank died while rank 0 rendered its own share)
    };
    // `stop_signal` is the first stop signal received (0: none), read from the watch's
    // thread; `save` runs in it, with the film held, and the process then exits with the
    // status it returns.
    DeviceGroupWatch(const DeviceGroup& group, std::function<int()> stop_signal, std::function<int(const Lost&)> save);
    ~DeviceGroupWatch();
    DeviceGroupWatch(const DeviceGroupWatch&) = delete;
    DeviceGroupWatch& operator=(const DeviceGroupWatch&) = delete;

    // The main thread is about to write its final files: the watch ends. Should the watch
    // already be saving, this blocks until the process exits.
    void stand_down();

    // Seconds from the stop signal to the watch's save, and its rank timeout.
    double grace_s() const { return grace_s_; }
    double rank_timeout_s() const { return rank_timeout_s_; }

private:
    void watch();

    const DeviceGroup& group_;
    std::function<int()> stop_signal_;
    std::function<int(const Lost&)> save_;
    double grace_s_ = 0.3;
    double rank_timeout_s_ = 300.0;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stood_down_ = false;
    std::thread thread_;
};

}  // namespace facet
