// The commands of the facet CLI.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/image/tonemap.hpp"

namespace facet {

struct RenderOptions {
    std::string scene;
    std::optional<int> spp, width, height, max_depth;
    std::optional<std::uint32_t> seed;
    std::optional<int> strategy;  // FC_STRATEGY_*
    std::optional<int> sampler;   // FC_SAMPLER_*
    std::optional<int> filter;    // FC_FILTER_*
    std::optional<float> filter_radius;
    // --env-sampling: 1 plain (no MIS compensation), 0 compensated
    std::optional<int> env_plain;
    // --env, --env-rotation, --env-strength (host/readers/default_lighting.hpp)
    std::string env;
    std::optional<float> env_rotation, env_strength;
    std::optional<float> smooth_normals;  // --smooth-normals [ANGLE]: crease angle (host/scene/smooth_normals.hpp)
    std::optional<float> clamp;           // the largest contribution of one sample (biased; off by default)
    std::optional<float> caustic_guide;   // the share of Lambertian directions drawn toward glass
    std::optional<float> roulette_gain;   // Russian roulette's survival per unit of throughput
    // The camera: --eye, --target, --up (3 numbers each), --fov, --aperture, --focus-distance.
    std::vector<float> eye, target, up;
    std::string camera;  // --camera NAME: a glTF file's camera by name
    std::optional<float> fov, aperture, focus_distance;
    std::optional<double> time_limit;
    std::optional<double> noise_threshold;  // stop once the half-buffer relMSE estimate is this low
    // --adaptive: the whole image at once, or per band of rows (render/session_tiles.hpp)
    enum class Adaptive { Global, Tiles } adaptive = Adaptive::Global;
    bool adaptive_tiles() const { return adaptive == Adaptive::Tiles; }
    std::string device;              // one selector or a list (ClContext::create_many)
    std::uint64_t samples_from = 0;  // --samples-from: the first sample index
    std::string out;
    std::string report;              // CSV; summary .json and plot .svg beside it
    std::string reference;           // image to measure the error against
    std::string film;                // --film: the accumulated samples, saved at the end (docs/film-format.md)
    std::string resume;              // --resume: a film to continue
    std::optional<double> snapshot;  // seconds between snapshots of the image so far
    float exposure = 0.0f;
    ToneMap tonemap = ToneMap::Clip;  // of the PNG
    std::vector<std::string> aov;     // --aov: extra EXR layers (albedo, normal, depth)
    std::string denoise = "none";     // --denoise: auto, facet, oidn or none (host/denoise/)
    std::string oidn;                 // --oidn: libOpenImageDenoise.so.2 to load (denoise/oidn.hpp)
    bool quiet = false;
    bool generic = false;  // build every kernel feature, not only the scene's
    bool strict = false;   // --strict: a missing or unreadable asset is an error, not a warning
};

struct CompareOptions {
    std::string image, reference;
};

struct SkyOptions {
    std::string out;
    int width = 2048;
    float elevation = 25.0f, azimuth = 40.0f, turbidity = 3.0f;
};

struct PlotOptions {
    std::string report, out;
};

struct InfoOptions {
    std::string scene;
};

// Exit statuses of `facet render` (documented in the README).
constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;          // bad command line (the message names the option)
constexpr int kExitInterrupted = 130;  // stopped by SIGINT/SIGTERM; the image so far was written

struct MergeOptions {
    std::vector<std::string> films;
    std::string out;   // the merged image (EXR; PNG beside it)
    std::string film;  // the merged film, if asked
    float exposure = 0.0f;
};

// `facet denoise IMAGE.exr`: an EXR with the albedo and normal layers (--aov), and its film
// for the half-images.
struct DenoiseOptions {
    std::string image;
    std::string film;               // --film: the render's film (the half-images)
    std::string out;                // default: IMAGE's stem + ".denoised.exr"
    std::string denoiser = "auto";  // --denoiser: auto, facet or oidn
    std::string oidn;               // --oidn LIBRARY
    std::string device;             // --device, for facet's denoiser
    float exposure = 0.0f;
};

int run_devices();
int run_info(const InfoOptions& opt);
int run_render(const RenderOptions& opt);
int run_merge(const MergeOptions& opt);
int run_denoise(const DenoiseOptions& opt);
int run_compare(const CompareOptions& opt);
int run_plot(const PlotOptions& opt);
int run_sky(const SkyOptions& opt);

// `facet --version`: version, commit, build type, and each OpenCL platform and device found
// (or that none was).
std::string version_report();

}  // namespace facet
