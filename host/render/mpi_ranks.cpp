#include "host/render/mpi_ranks.hpp"

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <cstdlib>
#include <limits>
#include <thread>

#include <unistd.h>

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

// The tag of gather()'s point-to-point messages (collectives have their own context).
constexpr int kGatherTag = 17;

// Tests `requests` until all are done, calling done(i) as request i completes. Open MPI's
// blocking calls spin, taking the CPU from the renderers on an oversubscribed machine: this
// spins briefly, then sleeps 100 µs between tests.
template <typename F>
void poll(std::vector<MPI_Request>& requests, const char* what, F&& done) {
    std::vector<int> index(requests.size());
    std::size_t left = requests.size();
    int idle = 0;
    while (left > 0) {
        int count = 0;
        check(MPI_Testsome(int(requests.size()), requests.data(), &count, index.data(), MPI_STATUSES_IGNORE), what);
        if (count == MPI_UNDEFINED) return;
        for (int k = 0; k < count; ++k) done(std::size_t(index[std::size_t(k)]));
        left -= std::size_t(count);
        if (count > 0) idle = 0;
        else if (++idle < 64) std::this_thread::yield();
        else std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
}

void poll(MPI_Request request, const char* what) {
    std::vector<MPI_Request> one{request};
    poll(one, what, [](std::size_t) {});
}
#endif

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

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
    MPI_Request request{};
    check(MPI_Ibcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD, &request), "MPI_Ibcast");
    poll(request, "MPI_Ibcast");
    words.resize(n);
    check(MPI_Ibcast(words.data(), int(n), MPI_UINT64_T, 0, MPI_COMM_WORLD, &request), "MPI_Ibcast");
    poll(request, "MPI_Ibcast");
#endif
}

// Point to point, so that rank 0 knows whom it is still waiting for.
std::vector<double> Ranks::gather(double value) const {
    if (size_ == 1) return {value};
#if FACET_WITH_MPI
    if (!leads()) {
        MPI_Request request{};
        check(MPI_Isend(&value, 1, MPI_DOUBLE, 0, kGatherTag, MPI_COMM_WORLD, &request), "MPI_Isend");
        poll(request, "MPI_Isend");
        return {};
    }
    std::vector<double> all(std::size_t(size_), 0.0);
    all[0] = value;
    std::vector<MPI_Request> requests(std::size_t(size_ - 1));
    std::vector<int> ranks;
    for (int r = 1; r < size_; ++r) {
        check(MPI_Irecv(&all[std::size_t(r)], 1, MPI_DOUBLE, r, kGatherTag, MPI_COMM_WORLD,
                        &requests[std::size_t(r - 1)]),
              "MPI_Irecv");
        ranks.push_back(r);
    }
    begin_wait(std::move(ranks), false);
    poll(requests, "MPI_Irecv", [&](std::size_t i) { heard_from(int(i) + 1); });
    end_wait();
    return all;
#else
    return {value};
#endif
}

void Ranks::reduce_sum(const float* in, float* out, std::size_t n) const {
    if (size_ == 1) {
        for (std::size_t i = 0; i < n; ++i) out[i] = in[i];
        return;
    }
#if FACET_WITH_MPI
    for (std::size_t at = 0; at < n; at += kChunk) {
        const int count = int(std::min(kChunk, n - at));
        MPI_Request request{};
        check(
            MPI_Ireduce(in + at, leads() ? out + at : nullptr, count, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD, &request),
            "MPI_Ireduce");
        if (leads()) {
            std::vector<int> others;
            for (int r = 1; r < size_; ++r) others.push_back(r);
            begin_wait(std::move(others), true);
        }
        poll(request, "MPI_Ireduce");
        if (leads()) end_wait();
    }
#endif
}

bool Ranks::all(bool ok) const {
    if (size_ == 1) return ok;
#if FACET_WITH_MPI
    int mine = ok ? 1 : 0, every = 0;
    MPI_Request request{};
    check(MPI_Iallreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request), "MPI_Iallreduce");
    poll(request, "MPI_Iallreduce");
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

std::string Ranks::where() {
#if FACET_WITH_MPI
    auto first = [](std::initializer_list<const char*> names) -> const char* {
        for (const char* n : names)
            if (const char* v = std::getenv(n)) return v;
        return nullptr;
    };
    const char* rank = first({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"});
    const char* size = first({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"});
    if (!rank) return {};
    char host[256] = {};
    if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
    return fmt::format("MPI rank {}{} on {}", rank, size ? fmt::format(" of {}", size) : "",
                       host[0] ? host : "an unnamed host");
#else
    return {};
#endif
}

Ranks::Wait Ranks::waiting() const {
    std::lock_guard<std::mutex> lock(wait_mutex_);
    Wait w = wait_;
    if (w.waiting()) w.seconds = now_s() - wait_start_;
    return w;
}

void Ranks::begin_wait(std::vector<int> ranks, bool reduction) const {
    std::lock_guard<std::mutex> lock(wait_mutex_);
    wait_.ranks = std::move(ranks);
    wait_.reduction = reduction;
    wait_start_ = now_s();
}

void Ranks::heard_from(int rank) const {
    std::lock_guard<std::mutex> lock(wait_mutex_);
    std::erase(wait_.ranks, rank);
}

void Ranks::end_wait() const {
    std::lock_guard<std::mutex> lock(wait_mutex_);
    wait_ = Wait{};
}

void check_ranks_agree(const Ranks& ranks, std::uint64_t identity, std::uint32_t width, std::uint32_t height) {
    if (ranks.size() == 1) return;
    // Each value gathered as doubles (exact: the identity in two 32-bit halves).
    const std::vector<double> hi = ranks.gather(double(identity >> 32));
    const std::vector<double> lo = ranks.gather(double(identity & 0xffffffffu));
    const std::vector<double> w = ranks.gather(double(width)), h = ranks.gather(double(height));
    // Rank 0 finds the first rank that differs and tells every rank: [rank, identity, width, height].
    std::vector<std::uint64_t> verdict;
    if (ranks.leads()) {
        verdict.assign(4, 0);
        for (std::size_t r = 1; r < hi.size(); ++r)
            if (hi[r] != hi[0] || lo[r] != lo[0] || w[r] != w[0] || h[r] != h[0]) {
                verdict = {r, std::uint64_t(hi[r]) << 32 | std::uint64_t(lo[r]), std::uint64_t(w[r]),
                           std::uint64_t(h[r])};
                break;
            }
    }
    std::vector<std::uint64_t> first{identity, width, height};  // rank 0's
    ranks.broadcast(verdict);
    ranks.broadcast(first);
    if (verdict[0] == 0) return;
    if (verdict[2] != first[1] || verdict[3] != first[2])
        throw Error(
            fmt::format("MPI rank {} renders a {}x{} image, rank 0 a {}x{} one: every rank must render "
                        "the same scene and settings",
                        verdict[0], verdict[2], verdict[3], first[1], first[2]));
    throw Error(
        fmt::format("MPI rank {} renders another scene (identity {:016x}, rank 0 has {:016x}): every rank "
                    "must render the same scene and settings",
                    verdict[0], verdict[1], first[0]));
}

}  // namespace facet
