/* Camera and per-pass render parameters, passed to the kernels as one __constant
 * struct (kernels/integrator/path.cl). */
#ifndef FACET_SHARED_RENDER_H
#define FACET_SHARED_RENDER_H

#include "kernels/shared/types.h"
#include "kernels/shared/environment_layout.h"

#define FC_PROJECTION_PERSPECTIVE 0
#define FC_PROJECTION_ORTHOGRAPHIC 1

/* How light from area lights and the environment is estimated (punctual lights are
 * always sampled: nothing else can reach them), X(constant, name) in value order. MIS is
 * the default; the single strategies exist to measure and test them. */
#define FC_STRATEGY_LIST(X)                                                    \
    X(FC_STRATEGY_MIS, "mis")     /* light + BSDF sampling, power heuristic */ \
    X(FC_STRATEGY_LIGHT, "light") /* light sampling only */                    \
    X(FC_STRATEGY_BSDF, "bsdf")   /* BSDF sampling only */

/* Sample generators (kernels/util/sampler.cl), X(constant, name) in value order. */
#define FC_SAMPLER_LIST(X)                                                 \
    X(FC_SAMPLER_INDEPENDENT, "independent") /* uniform numbers (PCG32) */ \
    X(FC_SAMPLER_SOBOL, "sobol")             /* Owen-scrambled Sobol', shuffled per dimension set (Burley 2020) */

/* The constants: 0, 1, ... in list order (the values film files store). */
#define FC_RENDER_ENUM_VALUE(value, name) value,
enum { FC_STRATEGY_LIST(FC_RENDER_ENUM_VALUE) FC_STRATEGY_COUNT };
enum { FC_SAMPLER_LIST(FC_RENDER_ENUM_VALUE) FC_SAMPLER_COUNT };
#undef FC_RENDER_ENUM_VALUE

/* Pixel reconstruction filters (kernels/camera/filter.cl). */
#define FC_FILTER_BOX 0      /* uniform over the pixel (radius 0.5) or a wider square */
#define FC_FILTER_TENT 1     /* 1 - |x| / radius, separable */
#define FC_FILTER_GAUSSIAN 2 /* truncated Gaussian, sigma = radius / 3, separable */
#define FC_FILTER_MITCHELL 3 /* Mitchell-Netravali B = C = 1/3, negative lobes, separable */

/* The largest radiance one sample adds to a pixel, per channel (larger ones are
 * clamped to it), and the largest emission, light colour and environment radiance a
 * scene may give: 2^24 samples (the most a render takes) of it sum to 1.7e37, so the
 * float accumulation, the image and the report stay finite. */
#define FC_MAX_RADIANCE 1e30f
/* The largest r^2 + g^2 + b^2 one sample adds to its pixel's second moment (larger ones
 * are clamped to it): 2^24 samples of it sum to 1.7e37, finite like the sums. */
#define FC_MAX_SQUARE 1e30f
/* The most glass bounds caustic_guide.cl samples toward (host/scene/caustic_casters.cpp keeps the largest). */
#define FC_MAX_CASTERS 16u

/* Paths a work-item of packet_pass (kernels/integrator/packet_paths.cl) runs at once, in
 * lanes (it renders a multiple of as many pixels of a row: fc_packet_pixels): 8, or 16 on
 * CPUs whose native float vectors are 16 wide (AVX-512), where the host defines it in the
 * program's prelude (host/render/packet_paths.hpp, packet_width_for). */
#ifndef FC_PACKET_WIDTH
#define FC_PACKET_WIDTH 8
#endif

/* The least number of paths a packet_pass work-item's queue gives each lane. A lane idles
 * once the queue is empty, until the work-item's last path ends: with one path a lane (a
 * pass of one sample per pixel, as the progressive schedule's first passes are) the lanes
 * idle about half the time, waiting for the packet's longest path (docs/performance.md). */
#define FC_PACKET_PATHS_PER_LANE 16u

/* The pixels of a row one packet_pass work-item renders in a launch of `samples` samples per
 * pixel: `packet_width` times the least factor that gives every lane FC_PACKET_PATHS_PER_LANE
 * paths, but no more than the row holds (a row of `width` pixels). */
#if defined(__OPENCL_VERSION__) || defined(__OPENCL_C_VERSION__)
inline uint fc_packet_pixels(uint packet_width, uint width, uint samples)
#else
static inline fc_uint fc_packet_pixels(fc_uint packet_width, fc_uint width, fc_uint samples)
#endif
{
    const fc_uint s = samples > 0u ? samples : 1u;
    const fc_uint row = (width + packet_width - 1u) / packet_width;
    fc_uint m = (FC_PACKET_PATHS_PER_LANE + s - 1u) / s;
    if (m > row) m = row;
    if (m < 1u) m = 1u;
    return packet_width * m;
}

/* A pinhole, thin-lens or orthographic camera. `right` and `up` span half the image
 * plane: for a perspective camera at distance 1 along `forward` (so |up| =
 * tan(fov_y / 2)), for an orthographic camera in world units. Image x grows along
 * `right`, image y (row 0 at the top) against `up`. A perspective camera with
 * lens_radius > 0 is a thin lens focused at focus_distance along `forward`. */
typedef struct FcCamera {
    float eye[3];
    fc_int projection;
    float forward[3];
    float lens_radius; /* world units; 0: a pinhole */
    float right[3];
    float focus_distance; /* world units along `forward`, > 0 */
    float up[3];
    float pad2;
} FcCamera;

/* Parameters of one render pass. A pass adds samples [sample_begin, sample_begin +
 * sample_count) of every pixel to the accumulation buffer; the random stream of a
 * sample depends only on (seed, pixel, sample index), so an image does not depend
 * on how samples are split into passes. */
typedef struct FcRenderParams {
    FcCamera camera;
    fc_uint width;
    fc_uint height;
    fc_uint sample_begin;
    fc_uint sample_count;
    fc_uint seed;
    fc_uint max_depth;
    fc_uint rr_depth;
    fc_uint light_count;
    fc_uint row_begin;
    fc_uint row_count;
    fc_int environment_light; /* index of the FC_LIGHT_ENVIRONMENT light, or -1 */
    fc_uint strategy;         /* FC_STRATEGY_*: how direct light is estimated */
    fc_uint sampler;          /* FC_SAMPLER_*: where the sample values come from */
    fc_uint filter;           /* FC_FILTER_*: the pixel reconstruction filter */
    float filter_radius;      /* in pixels, > 0 */
    float clamp;              /* the largest contribution of one sample (its largest channel) */
    fc_uint caster_count;     /* glass bounds to sample toward (kernels/integrator/caustic_guide.cl) */
    float caster_fraction;    /* the share of Lambertian vertices' directions drawn toward them */
    float roulette_gain; /* Russian roulette's survival per unit of throughput (kernels/integrator/path_lanes.cl) */
    fc_uint pad3[1];
    FcEnvironment environment;
} FcRenderParams;

FC_STATIC_ASSERT(sizeof(FcCamera) == 64, "FcCamera is 64 bytes");
FC_STATIC_ASSERT(offsetof(FcCamera, up) == 48, "FcCamera offsets");
FC_STATIC_ASSERT(sizeof(FcRenderParams) == 224, "FcRenderParams is 224 bytes");
FC_STATIC_ASSERT(offsetof(FcRenderParams, width) == 64 && offsetof(FcRenderParams, row_count) == 100,
                 "FcRenderParams offsets");

#endif
