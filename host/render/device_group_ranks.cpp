// DeviceGroup across MPI ranks (render/device_group.hpp, render/mpi_ranks.hpp): rank 0's
// launches, pass ends and resets go to every rank as commands, the other ranks follow.
#include <algorithm>
#include <chrono>
#include <exception>

#include <fmt/format.h>

#include "host/film/film_layout.hpp"
#include "host/render/device_group.hpp"

#include "host/error.hpp"
#include "host/util/clock.hpp"

namespace facet {
namespace {

// Rank 0's commands to the other ranks: the first word, then its arguments.
enum Command : std::uint64_t { kLaunch = 1, kEndPass = 2, kReset = 3, kStop = 4 };

}  // namespace

DeviceGroup::~DeviceGroup() {
    if (ranks_.size() > 1 && ranks_.leads() && !followers_stopped_) {
        try {
            std::vector<std::uint64_t> stop{kStop};
            ranks_.broadcast(stop);
        } catch (...) {  // the job is ending either way
        }
    }
}

void DeviceGroup::follow() {
    if (ranks_.leads()) return;
    try {
        for (;;) {
            std::vector<std::uint64_t> command;
            ranks_.broadcast(command);
            if (command.empty() || command[0] == kStop) return;
            if (command[0] == kLaunch) rank_launch(command);
            if (command[0] == kEndPass) rank_end_pass(std::uint32_t(command[1]), 0.0);
            if (command[0] == kReset) local_reset();
        }
    } catch (const std::exception& e) {
        // Rank 0 waits for this rank: nothing can go on without it.
        fmt::print(stderr, "facet: error: MPI rank {}: {}\n", ranks_.rank(), e.what());
        ranks_.abort(1);
    }
}

void DeviceGroup::launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) {
    if (count == 0 || row_begin >= std::uint32_t(height_)) return;
    row_count = std::min(row_count, std::uint32_t(height_) - row_begin);
    if (ranks_.size() == 1) {
        run(deal(next_, count, row_begin, row_count));
        return;
    }
    // The band's samples dealt out between the ranks: [kLaunch, rows, (first, count) per rank].
    std::vector<std::uint64_t> command{kLaunch, row_begin, row_count};
    std::uint64_t at = next_;
    for (std::uint32_t share : shares_by_rate(count, rank_rate_)) {
        command.push_back(at);
        command.push_back(share);
        at += share;
    }
    ranks_.broadcast(command);
    rank_launch(command);
}

void DeviceGroup::launch_band(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin,
                              std::uint32_t row_count) {
    if (ranks_.size() > 1) throw Error("adaptive bands of rows are rendered by one process, not by MPI ranks");
    if (count == 0 || row_begin >= std::uint32_t(height_)) return;
    run(deal(first, count, row_begin, std::min(row_count, std::uint32_t(height_) - row_begin)));
}

void DeviceGroup::rank_launch(const std::vector<std::uint64_t>& command) {
    const std::uint32_t row_begin = std::uint32_t(command[1]), row_count = std::uint32_t(command[2]);
    const std::size_t mine = 3 + 2 * std::size_t(ranks_.rank());
    const std::uint64_t first = command[mine];
    const std::uint32_t count = std::uint32_t(command[mine + 1]);
    const auto start = Clock::now();
    if (count > 0) run(deal(first, count, row_begin, row_count));
    const std::vector<double> seconds = ranks_.gather(seconds_since(start));
    for (std::size_t r = 0; r < seconds.size(); ++r) {
        const double pixel_samples = double(command[3 + 2 * r + 1]) * double(row_count) * double(width_);
        if (pixel_samples == 0.0) continue;
        rank_rate_[r] = pixel_samples / std::max(seconds[r], 1e-9);
        rank_pixel_samples_[r] += std::uint64_t(pixel_samples);
    }
}

void DeviceGroup::end_pass(std::uint32_t count, double seconds) {
    if (ranks_.size() > 1) {
        std::vector<std::uint64_t> command{kEndPass, count};
        ranks_.broadcast(command);
    }
    rank_end_pass(count, seconds);
}

void DeviceGroup::rank_end_pass(std::uint32_t count, double seconds) {
    commit();
    if (ranks_.size() > 1) {
        // Every rank says it has its pass (so that rank 0 knows whom it waits for), then
        // the films of every rank are summed to rank 0, through buffers kept from pass to
        // pass (at 1024² a fresh 40 MB each pass costs its page faults again).
        const auto start = Clock::now();
        ranks_.gather(0.0);
        rank_local_.assign(film_floats(pixel_count()), 0.0f);
        for (const std::vector<float>& c : committed_)
            for (std::size_t k = 0; k < rank_local_.size(); ++k) rank_local_[k] += c[k];
        if (ranks_.leads()) reduced_next_.assign(rank_local_.size(), 0.0f);
        ranks_.reduce_sum(rank_local_.data(), reduced_next_.data(), rank_local_.size());
        reduce_seconds_ += seconds_since(start);
    }
    const std::unique_lock<std::mutex> film = hold_film();
    if (ranks_.size() > 1 && ranks_.leads()) reduced_.swap(reduced_next_);
    pass_jobs_.clear();
    samples_.push_back({next_, next_ + count});
    samples_ = normalized(samples_);
    next_ += count;
    stats_.samples_per_pixel = sample_count(samples_);
    stats_.render_seconds += seconds;
}

void DeviceGroup::reset() {
    if (ranks_.size() > 1) {
        std::vector<std::uint64_t> command{kReset};
        ranks_.broadcast(command);
    }
    local_reset();
}

}  // namespace facet
