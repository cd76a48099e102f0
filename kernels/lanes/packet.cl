/* The lane-generic bodies at W = FC_PACKET_WIDTH (8, or 16 on AVX-512 CPUs): that many paths a
 * work-item in float8 or float16 lanes (issue 29's
 * packet paths, kernels/integrator/packet_paths.cl), the same source the scalar
 * kernels run at W = 1 (kernels/lanes/scalar.cl). The sampler's lane form reads the Sobol'
 * table of kernels/util/sampler.cl. */
#ifndef FACET_LANES_PACKET_CL
#define FACET_LANES_PACKET_CL

#include "kernels/lanes/scalar.cl"
#include "kernels/shared/render_layout.h"
#include "kernels/util/sampler.cl"

#define FC_LW FC_PACKET_WIDTH
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/vec3_lanes.cl"
#include "kernels/util/hash_lanes.cl"
#include "kernels/util/trig_lanes.cl"
#include "kernels/util/warp_lanes.cl"
#include "kernels/util/frame_lanes.cl"
#include "kernels/util/mis_lanes.cl"
#include "kernels/util/exp_lanes.cl"
#include "kernels/bsdf/fresnel_lanes.cl"
#include "kernels/bsdf/ggx_lanes.cl"
#include "kernels/bsdf/beckmann_lanes.cl"
#include "kernels/bsdf/energy_compensation_lanes.cl"
#include "kernels/bsdf/refraction_lanes.cl"
#include "kernels/bsdf/dielectric_lanes.cl"
#include "kernels/bsdf/plain_base_lanes.cl"
#include "kernels/trace/ray_lanes.cl"
#include "kernels/trace/triangle_lanes.cl"
#include "kernels/trace/sphere_lanes.cl"
#include "kernels/lights/area_lanes.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/light_pick_lanes.cl"
#include "kernels/lights/environment_lanes.cl"
#include "kernels/camera/filter_lanes.cl"
#include "kernels/camera/camera_lanes.cl"
#include "kernels/integrator/path_lanes.cl"
#include "kernels/util/sampler_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

#endif
