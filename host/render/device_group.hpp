// Several OpenCL devices rendering one image: one Renderer (program and scene) per
// device, built concurrently; every launch of a pass deals the pass's sample indices out
// between the devices in contiguous shares sized by each device's measured speed, so that
// they finish together; at the end of a pass each device's accumulation is read back and
// the films are summed on the host in device order. A device that fails is dropped with a
// warning: the samples it finished in earlier passes are kept, and its shares of the
// current pass are rendered again by the others. One device is the plain case.
//
// In an MPI job (render/mpi_ranks.hpp) every rank builds its own group; rank 0 runs the
// progressive driver and each of its calls goes to every rank: a launch's samples are
// dealt out between the ranks by their measured speeds (then between each rank's
// devices), and at the end of a pass the films are summed to rank 0 (MPI_Reduce), whose
// accumulation(), halves() and image() then describe the whole job. The other ranks
// call follow() instead of rendering.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/cl/runtime.hpp"
#include "host/film/film_halves.hpp"
#include "host/film/sample_ranges.hpp"
#include "host/render/mpi_ranks.hpp"
#include "host/render/pass_target.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// What one device did.
struct DeviceShare {
    DeviceDesc desc;
    double build_s = 0.0;             // its program build
    std::uint64_t pixel_samples = 0;  // samples it added, over all pixels
    double busy_s = 0.0;              // seconds in its launches
    bool dropped = false;             // failed and dropped
    std::string error;                // why
    double samples_per_s() const { return busy_s > 0.0 ? double(pixel_samples) / busy_s : 0.0; }
};

// `count` samples dealt out in proportion to `rates` (equal shares until every rate is
// measured), rounded by largest remainder so that the shares add up to `count`.
std::vector<std::uint32_t> shares_by_rate(std::uint32_t count, const std::vector<double>& rates);

class DeviceGroup : public PassTarget {
public:
    using Warn = std::function<void(const std::string&)>;

    // One renderer per context (render/renderer.hpp), built concurrently from one compiled scene. A device whose
    // program or upload fails is dropped through `warn`; when all fail, the first error
    // is thrown. The first pass starts at sample index `first_sample` (--samples-from).
    DeviceGroup(std::vector<ClContext> contexts, const Scene& scene, const Bvh& bvh, bool generic = false,
                std::uint64_t first_sample = 0, Warn warn = {});
    // The same with the scene compiled once by the caller (`dev`, of `scene` and `bvh`):
    // every device uploads this one DeviceScene. In an MPI job every rank's scene identity
    // (render/film_identity.hpp) and image size are checked against rank 0's first.
    DeviceGroup(std::vector<ClContext> contexts, const Scene& scene, const Bvh& bvh, const DeviceScene& dev,
                bool generic = false, std::uint64_t first_sample = 0, Warn warn = {});
    ~DeviceGroup() override;
    DeviceGroup(const DeviceGroup&) = delete;
    DeviceGroup& operator=(const DeviceGroup&) = delete;

    // PassTarget.
    std::uint32_t target_width() const override { return std::uint32_t(width_); }
    std::uint32_t target_height() const override { return std::uint32_t(height_); }
    std::uint64_t finished_spp() const override { return stats_.samples_per_pixel; }
    void launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) override;
    void end_pass(std::uint32_t count, double seconds) override;
    void reset() override;

    // Adaptive sampling (render/session_tiles.hpp): samples [first, first + count) of a band
    // of rows, dealt out to this process's devices; end_pass(0, seconds) then ends the
    // round. One process only (facet::Error with several MPI ranks).
    void launch_band(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count);

    // Continues a film (film/film_state.hpp) of the same scene and settings: its sums and
    // samples are kept and rendering goes on after its last sample index (or at
    // first_sample when that is later; earlier is refused, as it would repeat samples).
    // `second_moments`: whether the film's sums hold its samples' second moments
    // (film_layout.hpp; films written before format version 3 do not), and so the result's.
    void restore(const std::vector<float>& sums, const SampleRanges& samples, double render_seconds,
                 bool second_moments = true);
    bool second_moments() const { return second_moments_; }

    // As of the last finished pass: the sums (film layout), their sample indices, the
    // half-images and the image (3 floats a pixel; `rejected_samples` as Renderer's).
    std::vector<float> accumulation() const;
    const SampleRanges& samples() const { return samples_; }
    FilmHalves halves() const;
    std::vector<float> image(double* rejected_samples = nullptr) const;
    // estimate_error of halves(), without building them (film_halves.hpp's
    // estimate_film_error): the progressive render's estimate after each pass.
    ErrorMetrics estimate() const;

    // samples_per_pixel and render_seconds of the whole group (a restored film's too);
    // compile and upload seconds of the slowest device; features of the program.
    const RenderStats& stats() const { return stats_; }
    const std::vector<DeviceShare>& devices() const { return shares_; }
    // "platform / name", joined by " + " for several devices.
    std::string description() const;
    // MPI: the job's ranks, each rank's share of the samples (at rank 0), and the seconds
    // spent summing the films to rank 0.
    const Ranks& ranks() const { return ranks_; }
    const std::vector<std::uint64_t>& rank_pixel_samples() const { return rank_pixel_samples_; }
    double reduce_seconds() const { return reduce_seconds_; }
    // At ranks other than 0: does what rank 0's calls ask until its group ends.
    void follow();
    // Held while the film (accumulation(), samples(), halves(), image(), stats()) changes
    // at a pass end, reset or restore: a thread holding it reads one consistent film, as
    // of the last pass end (render/device_group_watch.hpp saves it when a rank dies).
    std::unique_lock<std::mutex> hold_film() const { return std::unique_lock<std::mutex>(film_mutex_); }
    // Called in a device's thread before each of its launches; an exception from it
    // counts as that device failing (the tests inject failures with it).
    std::function<void(std::size_t device)> before_launch;

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixel_count() const { return std::size_t(width_) * std::size_t(height_); }

private:
    struct Job {
        std::size_t device;
        std::uint64_t first;
        std::uint32_t count, row_begin, row_count;
    };
    std::vector<std::size_t> live() const;
    // Deals samples [first, first + count) of a band of rows out to the live devices.
    std::vector<Job> deal(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin,
                          std::uint32_t row_count) const;
    // Runs the jobs concurrently; a device that fails is dropped and every job it had in
    // this pass is dealt again to the others, until all are done.
    void run(std::vector<Job> jobs);
    void drop(std::size_t device, const std::string& why);
    // What every rank does for rank 0's launch, end of pass and reset.
    void rank_launch(const std::vector<std::uint64_t>& command);
    void rank_end_pass(std::uint32_t count, double seconds);
    void local_reset();
    void commit();

    int width_ = 0, height_ = 0;
    Warn warn_;
    std::vector<std::unique_ptr<ClContext>> contexts_;
    std::vector<std::unique_ptr<Renderer>> renderers_;  // null once dropped
    std::vector<DeviceShare> shares_;
    std::vector<double> rate_;                   // pixel samples per second, as last measured
    std::vector<std::vector<float>> committed_;  // each device's sums at the last pass end
    std::vector<std::vector<float>> read_;       // each device's sums as read at this pass end (then swapped
                                                 // with committed_): memory kept from pass to pass
    std::vector<float> base_;                    // a restored film's sums
    SampleRanges base_samples_;
    double base_seconds_ = 0.0;
    bool second_moments_ = true;  // false once a film without them is restored
    SampleRanges samples_;        // of the film: base and finished passes
    std::uint64_t first_sample_ = 0;
    std::uint64_t next_ = 0;      // the index of the current pass's first sample
    std::vector<Job> pass_jobs_;  // the current pass's jobs, to deal again if a device fails
    RenderStats stats_;
    const Ranks& ranks_ = Ranks::world();
    std::vector<double> rank_rate_;                  // at rank 0: each rank's pixel samples per second
    std::vector<std::uint64_t> rank_pixel_samples_;  // at rank 0
    std::vector<float> reduced_;                     // at rank 0: every rank's sums
    std::vector<float> reduced_next_, rank_local_;   // the next pass's reduction and this rank's sum
    double reduce_seconds_ = 0.0;
    bool followers_stopped_ = false;
    mutable std::mutex film_mutex_;
};

}  // namespace facet
