// A render session: what `facet render` does between loading the scene and writing the
// files, as Cycles keeps it in integrator/render_scheduler.cpp and Tungsten in its
// Renderer. Built from the scene and the session options, it opens the devices (each MPI
// rank its own), builds the BVH, renders the AOVs, compiles the device group
// (render/device_group.hpp), continues a film, and runs the progressive driver
// (render/progressive.hpp) with the stop rules (render/session_rules.hpp) and, in the
// tile mode, the band rounds (render/session_tiles.hpp). At ranks other than 0 it follows
// rank 0; at rank 0 of a job of several ranks a watch (render/device_group_watch.hpp)
// hands the film to the caller when a rank is lost. Writing files is the caller's.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/denoise/denoiser.hpp"
#include "host/film/film_state.hpp"
#include "host/render/aov.hpp"
#include "host/render/device_group.hpp"
#include "host/render/device_group_watch.hpp"
#include "host/render/session_rules.hpp"
#include "host/render/session_tiles.hpp"
#include "host/scene/device_scene.hpp"
#include "host/report/report.hpp"
#include "host/scene/scene.hpp"

namespace facet {

struct SessionOptions {
    StopRequest stop;
    std::string device;               // one selector or a list (ClContext::create_many)
    bool generic = false;             // the generic program, not one specialised to the scene
    std::uint64_t samples_from = 0;   // the first sample index
    bool aovs = false;                // render the AOVs (render/aov.hpp) before the image
    bool denoise = false;             // keep the first device for denoise() (the AOVs are rendered too)
    std::optional<FilmState> resume;  // a film to continue (checked against the scene)
    std::string resume_path;          // its file, for messages
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();  // for wall_s
    std::function<void(const std::string&)> warn;                                    // a device dropped
};

// After each pass (or round of the tile mode).
struct SessionPass {
    PassRecord record;         // pass, spp (the mean in the tile mode), times, the estimate
    std::uint64_t target_spp;  // 0: unbounded
    double remaining_s = 0.0;  // to the target or the time limit, at the measured rate
    double msamples_per_s = 0.0;
    bool last = false;
};

struct SessionHooks {
    std::function<int()> stop_signal;  // the first stop signal received, 0: none (any thread)
    std::function<void(const SessionPass&)> on_pass;
    // One sample per pixel takes more than the time limit (measured, not guessed): the
    // first pass's estimated seconds; the render goes on to finish that pass.
    std::function<void(double first_pass_s)> on_slow_first_pass;
    // At rank 0 of several ranks, when a rank is lost: saves what the film holds (the film
    // is held as of the last pass end) and returns the process's exit status.
    std::function<int(const DeviceGroupWatch::Lost&)> on_rank_lost;
};

struct SessionOutcome {
    int passes = 0;                // uniform passes and tile rounds
    std::uint64_t spp = 0;         // the fewest samples of any pixel
    double mean_spp = 0.0;         // the mean over the image (spp but in the tile mode)
    bool converged = false;        // the noise threshold was reached
    bool interrupted = false;      // a stop signal ended it
    std::optional<TileRun> tiles;  // the tile mode's bands and image
};

class RenderSession {
public:
    RenderSession(const Scene& scene, SessionOptions options);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    // At an MPI rank other than 0: renders what rank 0 deals out until its session ends,
    // then true; false at rank 0 (which runs the session).
    bool follow();
    SessionOutcome run(const SessionHooks& hooks);

    const StopRules& rules() const { return rules_; }
    const Bvh& bvh() const { return bvh_; }
    const DeviceGroup& group() const { return *group_; }
    const std::optional<AovImages>& aovs() const { return aovs_; }
    std::uint32_t aov_spp() const;
    // The kernels' build, and their first launch (the drivers' just-in-time compile).
    double compile_seconds() const { return group_->stats().compile_seconds + warmup_s_; }
    std::uint64_t spp() const { return group_->stats().samples_per_pixel; }
    // The image so far (the tile mode's once its rounds began) and the film of the
    // uniform passes (the tile mode has none: its bands hold different sample counts).
    std::vector<float> image(double* rejected_samples = nullptr) const;
    bool has_film() const { return !tiles_started_; }
    FilmState film() const;
    // The film so far denoised by facet's denoiser (denoise/denoiser.hpp) on the first
    // device, guided by the AOVs. Throws facet::Error when the session was not opened
    // with `denoise`, has no film (the tile mode) or a half holds no sample.
    DenoisedImage denoised(const DenoiseSettings& settings = {}) const;

private:
    void warm_up();
    PassRecord record(int pass, std::uint64_t spp, const ErrorMetrics& estimate) const;

    const Scene& scene_;
    SessionOptions options_;
    StopRules rules_;
    std::uint64_t film_identity_ = 0;
    Bvh bvh_;
    std::unique_ptr<DeviceScene> device_scene_;  // what every device and the AOV pass read
    std::optional<AovImages> aovs_;
    // facet's denoiser on the first device, its program built on a thread of its own while
    // the devices render (denoised() waits for it; a failed build is thrown there).
    std::shared_future<std::shared_ptr<const Denoiser>> denoiser_;
    std::unique_ptr<DeviceGroup> group_;
    double warmup_s_ = 0.0;
    bool tiles_started_ = false;
    std::optional<ResolvedBands> bands_;  // the tile mode's latest round
};

}  // namespace facet
