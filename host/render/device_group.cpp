#include "host/render/device_group.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <thread>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/film/film_layout.hpp"
#include "host/render/film_identity.hpp"
#include "host/util/clock.hpp"

namespace facet {
namespace {

std::string message_of(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "unknown error";
    }
}

// Runs f(i) for i in [0, n) on threads (inline for one), and returns each one's exception.
template <typename F>
std::vector<std::exception_ptr> for_each_concurrently(std::size_t n, F&& f) {
    std::vector<std::exception_ptr> errors(n);
    auto guarded = [&](std::size_t i) {
        try {
            f(i);
        } catch (...) {
            errors[i] = std::current_exception();
        }
    };
    if (n == 1) {
        guarded(0);
        return errors;
    }
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < n; ++i) threads.emplace_back(guarded, i);
    for (std::thread& t : threads) t.join();
    return errors;
}

}  // namespace

// `count` dealt out in proportion to `rates` (equal until every rate is measured),
// rounded by largest remainder so that the shares add up to `count`.
std::vector<std::uint32_t> shares_by_rate(std::uint32_t count, const std::vector<double>& rates) {
    const bool measured = std::all_of(rates.begin(), rates.end(), [](double r) { return r > 0.0; });
    double total = 0.0;
    for (double r : rates) total += measured ? r : 1.0;
    std::vector<std::uint32_t> share(rates.size());
    std::vector<std::pair<double, std::size_t>> remainder;
    std::uint32_t dealt = 0;
    for (std::size_t k = 0; k < rates.size(); ++k) {
        const double exact = double(count) * (measured ? rates[k] : 1.0) / total;
        share[k] = std::uint32_t(std::floor(exact));
        dealt += share[k];
        remainder.push_back({exact - std::floor(exact), k});
    }
    std::stable_sort(remainder.begin(), remainder.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t r = 0; dealt < count; ++r, ++dealt) share[remainder[r % remainder.size()].second] += 1;
    return share;
}

DeviceGroup::DeviceGroup(std::vector<ClContext> contexts, const Scene& scene, const Bvh& bvh, bool generic,
                         std::uint64_t first_sample, Warn warn)
    : DeviceGroup(std::move(contexts), scene, bvh, compile(scene, bvh), generic, first_sample, std::move(warn)) {}

DeviceGroup::DeviceGroup(std::vector<ClContext> contexts, const Scene& scene, const Bvh& bvh, const DeviceScene& dev,
                         bool generic, std::uint64_t first_sample, Warn warn)
    : width_(int(dev.params.width)), height_(int(dev.params.height)), warn_(std::move(warn)),
      first_sample_(first_sample), next_(first_sample) {
    if (contexts.empty()) throw Error("no OpenCL device to render on");
    // Every rank renders the same scene at the same size, or none starts (render/mpi_ranks.hpp).
    check_ranks_agree(ranks_, film_identity(dev), dev.params.width, dev.params.height);
    const std::size_t n = contexts.size();
    for (ClContext& c : contexts) contexts_.push_back(std::make_unique<ClContext>(std::move(c)));
    renderers_.resize(n);
    shares_.resize(n);
    rate_.assign(n, 0.0);
    committed_.assign(n, std::vector<float>(film_floats(pixel_count()), 0.0f));
    // One program per device, built concurrently.
    std::vector<std::exception_ptr> errors = for_each_concurrently(n, [&](std::size_t i) {
        shares_[i].desc = contexts_[i]->desc();
        renderers_[i] = std::make_unique<Renderer>(*contexts_[i], scene, bvh, dev, generic);
    });
    const bool none = std::all_of(errors.begin(), errors.end(), [](const std::exception_ptr& e) { return bool(e); });
    // Every rank has a device, or none renders (the others would wait for it).
    if (!ranks_.all(!none)) {
        if (none) std::rethrow_exception(errors[0]);
        throw Error("another MPI rank has no device that could build the program; see its message");
    }
    for (std::size_t i = 0; i < n; ++i)
        if (errors[i]) drop(i, message_of(errors[i]));
    rank_rate_.assign(std::size_t(ranks_.size()), 0.0);
    rank_pixel_samples_.assign(std::size_t(ranks_.size()), 0);
    for (std::size_t i : live()) {
        const RenderStats& s = renderers_[i]->stats();
        shares_[i].build_s = s.compile_seconds;
        stats_.compile_seconds = std::max(stats_.compile_seconds, s.compile_seconds);
        stats_.upload_seconds = std::max(stats_.upload_seconds, s.upload_seconds);
        stats_.features = s.features;
        stats_.packet_paths = stats_.packet_paths || s.packet_paths;
        stats_.packet_width = std::max(stats_.packet_width, s.packet_width);
    }
}

std::vector<std::size_t> DeviceGroup::live() const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < renderers_.size(); ++i)
        if (renderers_[i]) out.push_back(i);
    return out;
}

void DeviceGroup::drop(std::size_t device, const std::string& why) {
    DeviceShare& s = shares_[device];
    s.dropped = true;
    s.error = why;
    renderers_[device].reset();
    if (warn_)
        warn_(fmt::format("device [{}] {} / {} failed and is dropped; the other devices render its samples: {}",
                          s.desc.index, s.desc.platform, s.desc.name, why));
}

std::vector<DeviceGroup::Job> DeviceGroup::deal(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin,
                                                std::uint32_t row_count) const {
    const std::vector<std::size_t> devices = live();
    if (devices.empty()) throw Error("every OpenCL device failed; see the warnings above");
    std::vector<double> rates;
    for (std::size_t i : devices) rates.push_back(rate_[i]);
    const std::vector<std::uint32_t> share = shares_by_rate(count, rates);
    std::vector<Job> jobs;
    std::uint64_t at = first;
    for (std::size_t k = 0; k < devices.size(); ++k) {
        if (share[k] == 0) continue;
        jobs.push_back({devices[k], at, share[k], row_begin, row_count});
        at += share[k];
    }
    return jobs;
}

void DeviceGroup::run(std::vector<Job> jobs) {
    while (!jobs.empty()) {
        std::vector<double> seconds(jobs.size(), 0.0);
        std::vector<std::exception_ptr> errors = for_each_concurrently(jobs.size(), [&](std::size_t j) {
            const Job& job = jobs[j];
            if (before_launch) before_launch(job.device);
            const auto start = Clock::now();
            renderers_[job.device]->launch_samples(job.first, job.count, job.row_begin, job.row_count);
            seconds[j] = seconds_since(start);
        });
        std::vector<Job> again;
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const Job& job = jobs[j];
            if (errors[j]) {
                if (!renderers_[job.device]) continue;  // already dropped (two jobs of one device)
                drop(job.device, message_of(errors[j]));
                // Its buffer is lost since the last pass end: every job it had in this pass again.
                for (const Job& done : pass_jobs_)
                    if (done.device == job.device) again.push_back(done);
                continue;
            }
            const double pixel_samples = double(job.count) * double(job.row_count) * double(width_);
            shares_[job.device].pixel_samples += std::uint64_t(pixel_samples);
            shares_[job.device].busy_s += seconds[j];
            rate_[job.device] = pixel_samples / std::max(seconds[j], 1e-9);
            pass_jobs_.push_back(job);
        }
        // Jobs of dropped devices (those that failed now, and any done before in this pass).
        for (const Job& j : jobs)
            if (!renderers_[j.device]) again.push_back(j);
        std::erase_if(pass_jobs_, [&](const Job& j) { return !renderers_[j.device]; });
        jobs.clear();
        std::sort(again.begin(), again.end(), [](const Job& a, const Job& b) {
            return a.first < b.first || (a.first == b.first && a.row_begin < b.row_begin);
        });
        again.erase(std::unique(again.begin(), again.end(),
                                [](const Job& a, const Job& b) {
                                    return a.first == b.first && a.count == b.count && a.row_begin == b.row_begin &&
                                           a.row_count == b.row_count;
                                }),
                    again.end());
        for (const Job& j : again) {
            std::vector<Job> dealt = deal(j.first, j.count, j.row_begin, j.row_count);
            jobs.insert(jobs.end(), dealt.begin(), dealt.end());
        }
    }
}

void DeviceGroup::commit() {
    // Each device's sums read back; a device failing here loses its pass, dealt again.
    for (;;) {
        const std::vector<std::size_t> devices = live();
        read_.resize(committed_.size());
        std::vector<std::exception_ptr> errors = for_each_concurrently(
            devices.size(), [&](std::size_t k) { renderers_[devices[k]]->read_accumulation(read_[devices[k]]); });
        std::vector<Job> again;
        for (std::size_t k = 0; k < devices.size(); ++k) {
            if (!errors[k]) continue;
            drop(devices[k], message_of(errors[k]));
            for (const Job& j : pass_jobs_)
                if (j.device == devices[k]) again.push_back(j);
        }
        if (again.empty()) {
            for (std::size_t k = 0; k < devices.size(); ++k) committed_[devices[k]].swap(read_[devices[k]]);
            return;
        }
        std::erase_if(pass_jobs_, [&](const Job& j) { return !renderers_[j.device]; });
        std::vector<Job> jobs;
        for (const Job& j : again) {
            std::vector<Job> dealt = deal(j.first, j.count, j.row_begin, j.row_count);
            jobs.insert(jobs.end(), dealt.begin(), dealt.end());
        }
        run(jobs);
    }
}

void DeviceGroup::local_reset() {
    const std::unique_lock<std::mutex> film = hold_film();
    for (std::size_t i : live()) renderers_[i]->reset();
    for (std::vector<float>& c : committed_) std::fill(c.begin(), c.end(), 0.0f);
    if (!reduced_.empty()) std::fill(reduced_.begin(), reduced_.end(), 0.0f);
    pass_jobs_.clear();
    samples_ = base_samples_;
    next_ = std::max(first_sample_, next_sample(base_samples_));
    stats_.samples_per_pixel = sample_count(samples_);
    stats_.render_seconds = base_seconds_;
}

void DeviceGroup::restore(const std::vector<float>& sums, const SampleRanges& samples, double render_seconds,
                          bool second_moments) {
    if (sums.size() != film_floats(pixel_count()))
        throw Error(fmt::format("a film of {} values does not fit a {}x{} image", sums.size(), width_, height_));
    if (first_sample_ > 0 && first_sample_ < next_sample(samples))
        throw Error(fmt::format("the film holds samples {}: samples from {} would repeat some of them",
                                describe(samples), first_sample_));
    {
        const std::unique_lock<std::mutex> film = hold_film();
        // Rank 0 holds the film; the other ranks add new samples only.
        if (ranks_.leads()) base_ = sums;
        base_samples_ = normalized(samples);
        base_seconds_ = render_seconds;
        second_moments_ = second_moments;
    }
    local_reset();
}

std::vector<float> DeviceGroup::accumulation() const {
    std::vector<float> sums = base_.empty() ? std::vector<float>(film_floats(pixel_count()), 0.0f) : base_;
    if (ranks_.size() > 1) {
        for (std::size_t k = 0; k < reduced_.size(); ++k) sums[k] += reduced_[k];
        return sums;
    }
    for (const std::vector<float>& c : committed_)
        for (std::size_t k = 0; k < sums.size(); ++k) sums[k] += c[k];
    return sums;
}

FilmHalves DeviceGroup::halves() const { return film_halves(accumulation(), pixel_count(), samples_, second_moments_); }

ErrorMetrics DeviceGroup::estimate() const {
    // The films accumulation() adds, in its order.
    std::vector<const std::vector<float>*> films;
    if (!base_.empty()) films.push_back(&base_);
    if (ranks_.size() > 1) {
        if (!reduced_.empty()) films.push_back(&reduced_);
    } else {
        for (const std::vector<float>& c : committed_) films.push_back(&c);
    }
    return estimate_film_error(films, pixel_count(), samples_);
}

std::vector<float> DeviceGroup::image(double* rejected_samples) const {
    // The means alone: no second moments
    const FilmHalves h = film_halves(accumulation(), pixel_count(), samples_, false);
    if (rejected_samples) *rejected_samples = h.rejected;
    return film_mean(h);
}

std::string DeviceGroup::description() const {
    std::string s;
    for (const DeviceShare& d : shares_) s += (s.empty() ? "" : " + ") + d.desc.platform + " / " + d.desc.name;
    if (ranks_.size() > 1) s += fmt::format(" (rank 0 of {} MPI ranks)", ranks_.size());
    return s;
}

}  // namespace facet
