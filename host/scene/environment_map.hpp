// The environment light on the host: constant radiance or an equirectangular map
// (read from a file by host/readers/environment_file.hpp), sanitised, with
// the sampling distribution the kernels use (kernels/lights/environment.cl). The
// direction <-> texel convention is the comment of kernels/shared/environment_layout.h;
// docs/environment.md explains units, sanitising and the distribution.
//
// Buffers uploaded to the device:
//  - texels: 4 floats a texel (R, G, B, m), linear radiance before `scale`, top row
//    (theta = 0) first, width x height texels (one zero texel when width == 0); m is 0
//    for the nearest lookup and, for the bilinear one, the mean over the texel's square of
//    the interpolated luminance (scale included), which env_sample and env_pdf divide by
//    (build_environment_distribution writes it).
//  - distribution (floats), for a map of W x H texels:
//      [0, H]                              the marginal cdf over rows: H + 1 entries,
//                                          cdf[0] = 0, cdf[H] = 1
//      [H + 1 + y (W + 1), ... + W]        the conditional cdf of row y: W + 1 entries,
//                                          0 ... 1 (uniform for a row with no energy)
//      then the guide tables (Chen & Asau 1974) of the marginal cdf and of each row's
//      conditional cdf in turn, g + 1 entries each for a cdf of n intervals, g =
//      env_guide_size(n) (kernels/shared/environment_layout.h): entry k is the interval
//      holding k / g, the bits of a uint; env_sample bisects only between entries k and
//      k + 1 (kernels/lights/environment.cl, env_find_interval)
//      then H floats, each row's largest conditional probability (the largest step of its
//      conditional cdf): the bound of a row's densities that glass's choice reads first
//      (kernels/lights/environment.cl, env_row_pdf_bound)
//    Texel (x, y) weighs f = luminance(texel * scale) * sin(theta of row y's centre) (for
//    the bilinear lookup, the luminance is its mean over the texel's square); a
//    texel's probability is the product of its two cdf steps. params.total is the
//    integral of f over the (u, v) square: sum(f) / (W H); 0 for a black map, whose
//    pdf is then 0 everywhere. A constant environment has a one-float distribution (an
//    OpenCL buffer cannot be empty).
//    With MIS compensation (opt-in, under the MIS strategy) the renderer uploads
//    instead the same layout built from max(luminance - mean, 0) * sin(theta)
//    (environment_sampling_distribution; docs/sampling.md, "MIS compensation").
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "kernels/shared/environment_layout.h"

namespace facet {

// How next-event estimation samples a map: MIS compensation (Karlik, Sik, Vevoda,
// Skrivan, Krivanek 2019) or the plain luminance distribution.
enum class EnvironmentSampling { compensated, plain };

// The fraction of the mean luminance that MIS compensation subtracts from each texel.
constexpr double kEnvironmentCompensation = 1.0;

struct EnvironmentMap {
    FcEnvironment params{};
    std::vector<float> texels = std::vector<float>(4, 0.0f);  // 4 floats a texel
    std::vector<float> distribution = std::vector<float>(1, 0.0f);
    // (1 / 4pi) * integral of the luminance of the radiance (scale included) over the
    // sphere: the mean luminance, for light selection by power.
    double mean_luminance = 0.0;
    EnvironmentSampling sampling = EnvironmentSampling::compensated;  // scene "sampling", --env-sampling
};

// Stores the world-to-map rotation in params.to_map (rows).
void set_environment_rotation(FcEnvironment& params, const glm::mat3& world_to_map);
void set_environment_rotation(EnvironmentMap& env, const glm::mat3& world_to_map);

// How the kernels look the map up, FC_ENV_FILTER_NEAREST (the default) or
// FC_ENV_FILTER_BILINEAR (the scene's "filter": "bilinear"); rebuilds the distribution, whose
// texel weights follow the lookup. Throws facet::Error on another value.
void set_environment_filter(EnvironmentMap& env, int filter);

// Multiplies the radiance by `scale` (finite, >= 0) and rebuilds the distribution.
void set_environment_scale(EnvironmentMap& env, const glm::vec3& scale);

// No environment: escaped rays see black, nothing is sampled.
EnvironmentMap no_environment();

// Radiance `radiance` (linear RGB, >= 0) from every direction.
EnvironmentMap constant_environment(const glm::vec3& radiance);

// A map from linear RGB pixels (3 floats a pixel, top row first). `name` prefixes the
// warnings: texels with negative, NaN or infinite channels are set to 0 (the warning
// says how many and how much of the energy changed); a map that is not 2:1 is stretched
// onto the sphere (warning); a black map lights nothing (warning, pdf 0); a 1 x 1 map
// becomes the constant environment of its texel. Throws facet::Error on a bad scale or
// size.
EnvironmentMap environment_from_pixels(int width, int height, std::vector<float> rgb, const glm::vec3& scale,
                                       const glm::mat3& world_to_map, const std::string& name,
                                       std::vector<std::string>& warnings);

// Builds params.total, the distribution and mean_luminance from the texels and scale.
void build_environment_distribution(EnvironmentMap& env);

// MIS compensation's distribution (Karlik et al. 2019), in the layout of `distribution`:
// texel weights max(luminance - fraction * mean_luminance, 0) * sin(theta), since BSDF
// sampling already covers the smooth part (texels at or below the mean get probability 0:
// environment_map.cpp). It is the density of light sampling on both
// sides of MIS (env_sample and env_pdf read the cdfs only), so the estimator stays
// unbiased as long as BSDF sampling also runs. Returns the plain distribution when
// nothing remains (a constant map, where every texel is the mean) and for a constant or
// black environment.
std::vector<float> compensated_environment_distribution(const EnvironmentMap& env,
                                                        double fraction = kEnvironmentCompensation);

// The distribution the renderer uploads for render strategy `strategy` (FC_STRATEGY_*):
// the compensated one when env.sampling asks for it and the strategy is MIS, else the
// plain one (light sampling alone must reach every texel; BSDF sampling alone never reads it).
std::vector<float> environment_sampling_distribution(const EnvironmentMap& env, int strategy);

}  // namespace facet
