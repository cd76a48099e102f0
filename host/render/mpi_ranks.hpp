// The MPI job this process belongs to: `mpirun -n N facet render ...` gives N ranks that
// render one image (render/device_group.hpp deals each pass's samples out between the
// ranks, then between each rank's devices, and reduces the films to rank 0). Started
// only when the process was launched by an MPI launcher (Open MPI's or a PMI/PMIx one)
// and facet was built with MPI (FACET_WITH_MPI, CMake option FACET_MPI, on when found);
// otherwise the job is this one process. Collective calls go from rank 0 outward and are
// made from the main thread only.
//
// Rank 0 waits for the others without blocking inside MPI (non-blocking calls, polled with
// short sleeps, so that a waiting rank leaves the CPU to the renderers), and records whom it
// is waiting for: waiting() tells another thread (render/device_group_watch.hpp) which
// ranks have not answered when a rank dies and mpirun ends the job.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace facet {

class Ranks {
public:
    // The job, started (MPI_Init) on first use when under an MPI launcher; MPI_Finalize
    // runs at exit.
    static Ranks& world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool leads() const { return rank_ == 0; }
    // "MPI rank 1 of 4 on node7" when an MPI launcher started this process, from the
    // launcher's environment (so without starting MPI: a rank that fails before the job
    // starts exits at once, and mpirun ends the job); empty otherwise.
    static std::string where();

    // Rank 0's `words` to every rank (the others' vectors are resized to match).
    void broadcast(std::vector<std::uint64_t>& words) const;
    // Every rank's `value`, at rank 0 in rank order (empty at the others).
    std::vector<double> gather(double value) const;
    // The element-wise sum of every rank's `in` (n floats), into `out` at rank 0, added
    // in the MPI library's reduction order.
    void reduce_sum(const float* in, float* out, std::size_t n) const;
    // True when `ok` holds at every rank.
    bool all(bool ok) const;
    // Ends the whole job (a rank that cannot go on while the others wait for it).
    [[noreturn]] void abort(int code) const;

    // What rank 0 is waiting for, as of now (safe from any thread).
    struct Wait {
        std::vector<int> ranks;  // the ranks not heard from yet (in the reduction: every other)
        bool reduction = false;  // in the films' reduction, where any of them may be missing
        double seconds = 0.0;    // since the call began
        bool waiting() const { return reduction || !ranks.empty(); }
    };
    Wait waiting() const;

private:
    Ranks() = default;
    void begin_wait(std::vector<int> ranks, bool reduction) const;
    void heard_from(int rank) const;
    void end_wait() const;

    int rank_ = 0;
    int size_ = 1;
    mutable std::mutex wait_mutex_;
    mutable Wait wait_;
    mutable double wait_start_ = 0.0;  // steady-clock seconds
};

// Throws facet::Error at every rank, before any sample, when a rank's scene identity
// (render/film_identity.hpp) or image size differs from rank 0's, naming the first such
// rank and both values: ranks of different scenes must not add up to one image. One
// process: nothing to check.
void check_ranks_agree(const Ranks& ranks, std::uint64_t identity, std::uint32_t width, std::uint32_t height);

}  // namespace facet
