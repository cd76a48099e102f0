#include "host/render/mpi_ranks.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "host/error.hpp"

#if FACET_WITH_MPI
// The C API only: the deprecated C++ bindings need a library facet does not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace facet {
namespace {

#if FACET_WITH_MPI
// Whether an MPI launcher started this process: initialising MPI otherwise (a "singleton")
// is slow and fails in some containers, and one process needs no MPI.
bool under_mpi_launcher() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(v)) return true;
    return false;
}

void check(int status, const char* what) {
    if (status != MPI_SUCCESS) throw Error(fmt::format("MPI error {} in {}", status, what));
}

// MPI counts are ints: long arrays go in chunks.
constexpr std::size_t kChunk = std::size_t(std::numeric_limits<int>::max() / 2);
#endif

}  // namespace

Ranks& Ranks::world() {
    static Ranks* job = [] {
        static Ranks r;
#if FACET_WITH_MPI
        if (under_mpi_launcher()) {
            int initialised = 0;
            MPI_Initialized(&initialised);
            if (!initialised) {
                check(MPI_Init(nullptr, nullptr), "MPI_Init");
                std::atexit([] {
                    int finalised = 0;
                    MPI_Finalized(&finalised);
                    if (!finalised) MPI_Finalize();
                });
            }
            MPI_Comm_rank(MPI_COMM_WORLD, &r.rank_);
            MPI_Comm_size(MPI_COMM_WORLD, &r.size_);
        }
#endif
        return &r;
    }();
    return *job;
}

void Ranks::broadcast(std::vector<std::uint64_t>& words) const {
    if (size_ == 1) return;
#if FACET_WITH_MPI
    std::uint64_t n = words.size();
    check(MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
    words.resize(n);
    check(MPI_Bcast(words.data(), int(n), MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
#endif
}

std::vector<double> Ranks::gather(double value) const {
    if (size_ == 1) return {value};
    std::vector<double> all(leads() ? std::size_t(size_) : 0);
#if FACET_WITH_MPI
    check(MPI_Gather(&value, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD), "MPI_Gather");
#endif
    return all;
}

void Ranks::reduce_sum(const float* in, float* out, std::size_t n) const {
    if (size_ == 1) {
        for (std::size_t i = 0; i < n; ++i) out[i] = in[i];
        return;
    }
#if FACET_WITH_MPI
    for (std::size_t at = 0; at < n; at += kChunk) {
        const int count = int(std::min(kChunk, n - at));
        check(MPI_Reduce(in + at, leads() ? out + at : nullptr, count, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD),
              "MPI_Reduce");
    }
#endif
}

bool Ranks::all(bool ok) const {
    if (size_ == 1) return ok;
#if FACET_WITH_MPI
    int mine = ok ? 1 : 0, every = 0;
    check(MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD), "MPI_Allreduce");
    return every == 1;
#else
    return ok;
#endif
}

void Ranks::abort(int code) const {
#if FACET_WITH_MPI
    if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::exit(code);
}

}  // namespace facet
