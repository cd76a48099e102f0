// Environment maps: sanitising and the sampling distribution
// (environment.hpp documents the buffers, docs/environment.md the reasons).
#include "host/scene/environment_map.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <new>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/util/color.hpp"
#include "host/util/math.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {
namespace {

// Solid angle of one texel of row y (all texels of a row are equal).
double texel_solid_angle(int y, int width, int height) {
    return 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
}

void check_scale(const glm::vec3& s, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(s[c]) || s[c] < 0.0f)
            throw Error(
                fmt::format("{}: the environment's scale ({}, {}, {}) must be finite and >= 0", what, s.x, s.y, s.z));
}

// Sets negative, NaN and infinite channels to 0; warns with the count and the change
// in energy (luminance x solid angle) relative to the map after the change.
void sanitise(int width, int height, std::vector<float>& rgb, const std::string& name,
              std::vector<std::string>& warnings) {
    long long bad = 0, non_finite = 0;
    double removed = 0.0, kept = 0.0;
    for (int y = 0; y < height; ++y) {
        const double omega = texel_solid_angle(y, width, height);
        for (int x = 0; x < width; ++x) {
            float* t = &rgb[3 * (std::size_t(y) * width + x)];
            bool changed = false, inf_nan = false;
            for (int c = 0; c < 3; ++c) {
                if (std::isfinite(t[c]) && t[c] >= 0.0f) {
                    kept += kLuminanceWeights[c] * double(t[c]) * omega;
                    continue;
                }
                if (std::isfinite(t[c])) removed += kLuminanceWeights[c] * -double(t[c]) * omega;
                else inf_nan = true;
                t[c] = 0.0f;
                changed = true;
            }
            bad += changed ? 1 : 0;
            non_finite += inf_nan ? 1 : 0;
        }
    }
    if (bad == 0) return;
    std::string msg = fmt::format(
        "{}: {} texels were negative, NaN or infinite and were set to 0 ({:.3g}% of the "
        "map's energy changed",
        name, bad, kept > 0.0 ? 100.0 * removed / kept : 100.0);
    if (non_finite > 0) msg += fmt::format("; {} of them NaN or infinite, not counted in the energy", non_finite);
    warnings.push_back(msg + ")");
}

}  // namespace

void set_environment_rotation(FcEnvironment& params, const glm::mat3& m) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) params.to_map[r][c] = m[c][r];  // glm is column-major
        params.to_map[r][3] = 0.0f;
    }
}

void set_environment_rotation(EnvironmentMap& env, const glm::mat3& world_to_map) {
    set_environment_rotation(env.params, world_to_map);
}

void set_environment_filter(EnvironmentMap& env, int filter) {
    if (filter != FC_ENV_FILTER_NEAREST && filter != FC_ENV_FILTER_BILINEAR)
        throw Error(fmt::format("environment: unknown filter {}", filter));
    env.params.filter = filter;
    build_environment_distribution(env);
}

void set_environment_scale(EnvironmentMap& env, const glm::vec3& scale) {
    check_scale(scale, "environment");
    for (int c = 0; c < 3; ++c) env.params.scale[c] *= scale[c];
    build_environment_distribution(env);
}

EnvironmentMap no_environment() {
    EnvironmentMap env;
    env.params.enabled = 0;
    set_environment_rotation(env.params, glm::mat3(1.0f));
    return env;
}

EnvironmentMap constant_environment(const glm::vec3& radiance) {
    check_scale(radiance, "constant environment");
    EnvironmentMap env;
    env.params.enabled = 1;
    for (int c = 0; c < 3; ++c) env.params.scale[c] = radiance[c];
    set_environment_rotation(env.params, glm::mat3(1.0f));
    build_environment_distribution(env);
    return env;
}

namespace {

// The luminance (scale included) of each texel as the kernels look it up: the texel's
// own, or for the bilinear lookup its mean over the texel's (u, v) square, which the
// interpolation between the surrounding centres makes (1/8, 3/4, 1/8) in each direction
// over the 3 x 3 texels around it (wrapping around in u, the edge rows repeated in v as
// the lookup clamps them). Every weight is positive, so a texel whose square sees any
// light has a positive weight: light sampling alone still covers the whole map.
std::vector<double> texel_luminance(const EnvironmentMap& env) {
    const FcEnvironment& p = env.params;
    const double sr = double(p.scale[0]), sg = double(p.scale[1]), sb = double(p.scale[2]);
    const int w = p.width, h = p.height;
    std::vector<double> lum(std::size_t(w) * h);
    for (std::size_t i = 0; i < lum.size(); ++i) {
        const float* t = &env.texels[4 * i];
        lum[i] = luminance(double(t[0]) * sr, double(t[1]) * sg, double(t[2]) * sb);
    }
    if (p.filter != FC_ENV_FILTER_BILINEAR) return lum;
    constexpr double k[3] = {0.125, 0.75, 0.125};
    std::vector<double> across(lum.size());  // filtered in u
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double* row = &lum[std::size_t(y) * w];
            across[std::size_t(y) * w + x] = k[0] * row[(x + w - 1) % w] + k[1] * row[x] + k[2] * row[(x + 1) % w];
        }
    for (int y = 0; y < h; ++y) {
        const double* up = &across[std::size_t(std::max(y - 1, 0)) * w];
        const double* mid = &across[std::size_t(y) * w];
        const double* down = &across[std::size_t(std::min(y + 1, h - 1)) * w];
        for (int x = 0; x < w; ++x) lum[std::size_t(y) * w + x] = k[0] * up[x] + k[1] * mid[x] + k[2] * down[x];
    }
    return lum;
}

// Appends to `dist` the guide table of the cdf of `n` intervals at `cdf_at`: entry k of
// env_guide_size(n) + 1 the interval holding k / g (the largest i < n with cdf[i] <= k / g,
// as env_find_interval finds it), stored as the bits of a uint.
void append_guide(std::vector<float>& dist, std::size_t cdf_at, int n) {
    const std::uint32_t g = env_guide_size(std::uint32_t(n));
    std::vector<float> guide(g + 1);
    for (std::uint32_t k = 0; k <= g; ++k) {
        const float t = float(k) / float(g);  // exact: g is a power of two
        const float* cdf = dist.data() + cdf_at;
        const auto i = std::uint32_t(std::upper_bound(cdf, cdf + n, t) - cdf - 1);
        guide[k] = std::bit_cast<float>(i);
    }
    dist.insert(dist.end(), guide.begin(), guide.end());
}

// The guide tables of the marginal cdf and of each row's conditional cdf, in that order.
void append_guides(std::vector<float>& dist, int w, int h) {
    append_guide(dist, 0, h);
    for (int y = 0; y < h; ++y) append_guide(dist, std::size_t(h + 1) + std::size_t(y) * (w + 1), w);
}

// Appends to `dist` each row's largest conditional probability, the largest step of its
// conditional cdf as the kernels take it (a float difference of two entries): with the row's
// own probability it bounds the density of every direction in the row (env_row_pdf_bound).
void append_row_bounds(std::vector<float>& dist, int w, int h) {
    std::vector<float> bound(h, 0.0f);
    for (int y = 0; y < h; ++y) {
        const float* cond = dist.data() + std::size_t(h + 1) + std::size_t(y) * (w + 1);
        for (int x = 0; x < w; ++x) bound[y] = std::max(bound[y], cond[x + 1] - cond[x]);
    }
    dist.insert(dist.end(), bound.begin(), bound.end());
}

// Fills `dist` (the layout of EnvironmentMap::distribution) with the cdfs of texel weights
// max(luminance - subtract, 0) * sin(theta), the luminance as texel_luminance gives it,
// and returns their sum; `mean` gets the integral of the luminance over the sphere.
double build_cdfs(const EnvironmentMap& env, double subtract, std::vector<float>& dist, double* mean) {
    const FcEnvironment& p = env.params;
    const int w = p.width, h = p.height;
    const std::vector<double> texel_lum = texel_luminance(env);
    dist.assign(std::size_t(h + 1) + std::size_t(h) * (w + 1), 0.0f);
    float* marginal = dist.data();
    std::vector<double> row_sum(h, 0.0), f(w);
    *mean = 0.0;
    for (int y = 0; y < h; ++y) {
        const double sin_theta = std::sin(kPi * (y + 0.5) / h);
        const double omega = texel_solid_angle(y, w, h);
        float* cond = marginal + (h + 1) + std::size_t(y) * (w + 1);
        double sum = 0.0;
        for (int x = 0; x < w; ++x) {
            const double lum = texel_lum[std::size_t(y) * w + x];
            *mean += lum * omega;
            f[x] = std::max(lum - subtract, 0.0) * sin_theta;
            sum += f[x];
        }
        // conditional cdf of the row (uniform when the row is black: never picked)
        double acc = 0.0;
        for (int x = 0; x < w; ++x) {
            cond[x] = sum > 0.0 ? float(acc / sum) : float(double(x) / w);
            acc += f[x];
        }
        cond[w] = 1.0f;
        row_sum[y] = sum;
    }
    double total = 0.0;
    for (int y = 0; y < h; ++y) total += row_sum[y];
    double acc = 0.0;
    for (int y = 0; y < h; ++y) {
        marginal[y] = total > 0.0 ? float(acc / total) : float(double(y) / h);
        acc += row_sum[y];
    }
    marginal[h] = 1.0f;
    append_guides(dist, w, h);
    append_row_bounds(dist, w, h);
    return total;
}

}  // namespace

void build_environment_distribution(EnvironmentMap& env) {
    FcEnvironment& p = env.params;
    if (p.width == 0) {
        env.distribution.assign(1, 0.0f);
        p.total = 0.0f;
        env.mean_luminance = p.enabled ? luminance(double(p.scale[0]), double(p.scale[1]), double(p.scale[2])) : 0.0;
        return;
    }
    // The bilinear lookup's texels carry their mean luminance (scale included) in the fourth
    // float: env_sample spreads a picked texel's samples in proportion to the interpolated
    // luminance, and env_pdf divides by this mean (kernels/lights/environment.cl).
    const std::vector<double> lum = texel_luminance(env);
    for (std::size_t i = 0; i < lum.size(); ++i)
        env.texels[4 * i + 3] = p.filter == FC_ENV_FILTER_BILINEAR ? float(lum[i]) : 0.0f;
    double mean = 0.0;
    const double total = build_cdfs(env, 0.0, env.distribution, &mean);
    p.total = float(total / (double(p.width) * p.height));
    env.mean_luminance = p.enabled ? mean / (4.0 * kPi) : 0.0;
}

std::vector<float> compensated_environment_distribution(const EnvironmentMap& env, double fraction) {
    if (env.params.width == 0 || !env.params.enabled || !(env.params.total > 0.0f) || !(fraction > 0.0))
        return env.distribution;
    std::vector<float> dist;
    double mean = 0.0;
    // Karlik et al.'s max(0, L - mean): texels at or below the mean get probability 0 and
    // are left to BSDF sampling (env_pdf 0 there: the MIS weight of an escaped ray is 1,
    // and a light sample that rounds into one is dropped). A floor of L / 10, L / 20 or
    // L / 4 kept on them measured worse (docs/sampling.md). The subtracted level sits a hair
    // above the mean so that a constant map, whose texels round around the mean, leaves
    // nothing and falls back to the plain distribution.
    const double level = fraction * env.mean_luminance * (1.0 + 1e-6);
    const double total = build_cdfs(env, level, dist, &mean);
    if (!(total > 0.0)) return env.distribution;
    return dist;
}

std::vector<float> environment_sampling_distribution(const EnvironmentMap& env, int strategy) {
    if (env.sampling == EnvironmentSampling::compensated && strategy == FC_STRATEGY_MIS)
        return compensated_environment_distribution(env);
    return env.distribution;
}

EnvironmentMap environment_from_pixels(int width, int height, std::vector<float> rgb, const glm::vec3& scale,
                                       const glm::mat3& world_to_map, const std::string& name,
                                       std::vector<std::string>& warnings) {
    check_scale(scale, name);
    if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * height * 3)
        throw Error(fmt::format("{}: an environment map needs width x height x 3 floats (got {}x{}, {} floats)", name,
                                width, height, rgb.size()));
    if (std::size_t(width) * height > (std::size_t(1) << 28))
        throw Error(fmt::format("{}: the map is {}x{}: at most 2^28 texels are supported", name, width, height));
    sanitise(width, height, rgb, name, warnings);

    EnvironmentMap env;
    env.params.enabled = 1;
    set_environment_rotation(env.params, world_to_map);
    for (int c = 0; c < 3; ++c) env.params.scale[c] = scale[c];
    if (width == 1 && height == 1) {
        // one texel: the constant environment of its radiance (sampled uniformly)
        for (int c = 0; c < 3; ++c) env.params.scale[c] = scale[c] * rgb[c];
    } else {
        if (width != 2 * height)
            warnings.push_back(
                fmt::format("{}: the map is {}x{}, not 2:1: it is stretched onto the sphere", name, width, height));
        env.params.width = width;
        env.params.height = height;
        env.texels.assign(std::size_t(width) * height * 4, 0.0f);
        for (std::size_t i = 0; i < std::size_t(width) * height; ++i)
            for (int c = 0; c < 3; ++c) env.texels[4 * i + c] = rgb[3 * i + c];
    }
    build_environment_distribution(env);
    const bool black = env.params.width == 0 ? env.mean_luminance <= 0.0 : !(env.params.total > 0.0f);
    if (black) warnings.push_back(fmt::format("{}: the map is black: it lights nothing", name));
    return env;
}

}  // namespace facet
