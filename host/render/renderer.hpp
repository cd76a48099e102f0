// The progressive renderer: the scene and its BVH uploaded once, the render program
// built once, and passes of samples added to a float accumulation buffer on the device.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/cl/runtime.hpp"
#include "host/film/film_halves.hpp"
#include "host/render/pass_target.hpp"
#include "host/render/scene_buffers.hpp"
#include "host/scene/scene.hpp"

namespace facet {

// The render program: path.cl and what it includes (its render_pass kernel).
inline constexpr const char* kRenderProgram = "kernels/integrator/path.cl";

struct RenderStats {
    std::uint64_t samples_per_pixel = 0;  // samples added to every pixel so far
    double compile_seconds = 0.0;         // building the render program
    std::uint32_t features = 0;           // the program's features (FeatureMask)
    bool packet_paths = false;            // packet_pass renders, not render_pass
    std::uint32_t packet_width = 0;       // its paths a work-item (8 or 16), with packet_paths
    double upload_seconds = 0.0;
    double render_seconds = 0.0;  // time inside render passes
};

class Renderer : public PassTarget {
public:
    // Uploads `scene` (with its `bvh`) and builds the render program: specialised to
    // the features the scene uses (render/features.hpp), or with every feature when
    // `generic`. The image size, depth and seed come from scene.settings.
    // `extra_prelude` lines go before the program (the bench uses them to defeat the
    // driver's cache).
    Renderer(ClContext& ctx, const Scene& scene, const Bvh& bvh, bool generic = false,
             const std::vector<std::string>& extra_prelude = {});
    // The same with the scene already compiled (`dev`, of `scene` and `bvh`): a render
    // compiles it once for all its devices (render/device_group.hpp) and the AOV pass.
    Renderer(ClContext& ctx, const Scene& scene, const Bvh& bvh, const DeviceScene& dev, bool generic = false,
             const std::vector<std::string>& extra_prelude = {});

    // Adds `count` samples to every pixel, split into launches of at most
    // `max_rows_per_launch` rows (0: the whole image). Renders run through the
    // progressive driver (render/progressive.hpp), which bounds every launch.
    void render(std::uint32_t count, std::uint32_t max_rows_per_launch = 0);

    // PassTarget: one launch over a band of rows, and the bookkeeping of a finished pass.
    std::uint32_t target_width() const override { return std::uint32_t(width_); }
    std::uint32_t target_height() const override { return std::uint32_t(height_); }
    std::uint64_t finished_spp() const override { return stats_.samples_per_pixel; }
    void launch(std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count) override;
    // One launch of the samples [first, first + count) over a band of rows, whatever
    // finished_spp() is (a device of a DeviceGroup renders its own share of a pass).
    void launch_samples(std::uint64_t first, std::uint32_t count, std::uint32_t row_begin, std::uint32_t row_count);
    void end_pass(std::uint32_t count, double seconds) override;

    // The mean radiance so far, linear RGB, row-major from the top row, 3 floats a
    // pixel. `rejected_samples` receives the number of samples the kernel dropped as
    // NaN, infinite or negative (0 for a correct renderer).
    std::vector<float> image(double* rejected_samples = nullptr) const;

    // The two independent half-images: samples with even index and with odd index,
    // each averaged over its own count (for error estimation without a reference).
    using Halves = FilmHalves;
    Halves halves() const;

    // Clears the accumulated samples.
    void reset() override;

    // The accumulation buffer as the kernel holds it, for a film (film/film_state.hpp):
    // 2 * pixel_count() RGBA sums, the even-sample half then the odd-sample half.
    std::vector<float> accumulation() const;
    // The same into `into` (resized to fit), which keeps its memory from pass to pass.
    void read_accumulation(std::vector<float>& into) const;

    // Continues an earlier render: loads `sums` (from accumulation(), of the same scene
    // and settings) holding `spp` samples per pixel rendered in `render_seconds`; the
    // next render() starts at sample index `spp`.
    void restore(const std::vector<float>& sums, std::uint64_t spp, double render_seconds);

    const RenderStats& stats() const { return stats_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const ClContext& context() const { return ctx_; }
    const ProgramBuild& build() const { return build_; }
    std::size_t pixel_count() const { return std::size_t(width_) * std::size_t(height_); }

private:
    ClContext& ctx_;
    int width_;
    int height_;
    FcRenderParams params_{};
    std::size_t local_size_ = 64;  // work-group size of every launch
    ProgramBuild build_;
    cl::Program program_;
    cl::Kernel kernel_;   // render_pass, or packet_pass (stats_.packet_paths)
    SceneBuffers scene_;  // the parameter block and the scene's arrays
    cl::Buffer accum_;
    RenderStats stats_;
};

}  // namespace facet
