// The MPI job this process belongs to: `mpirun -n N facet render ...` gives N ranks that
// render one image (render/device_group.hpp deals each pass's samples out between the
// ranks, then between each rank's devices, and reduces the films to rank 0). Started
// only when the process was launched by an MPI launcher (Open MPI's or a PMI/PMIx one)
// and facet was built with MPI (FACET_WITH_MPI, CMake option FACET_MPI, on when found);
// otherwise the job is this one process. Collective calls go from rank 0 outward and are
// made from the main thread only.
#pragma once

#include <cstddef>
#include <cstdint>
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

private:
    Ranks() = default;
    int rank_ = 0;
    int size_ = 1;
};

}  // namespace facet
