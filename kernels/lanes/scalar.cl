/* The lane-generic bodies at the widths the one-path-per-work-item kernels use: W = 1
 * (their scalar functions are these), and W = 4 for the sampler's hashes, which scramble a
 * dimension set's four coordinates in one uint4, and for the ray/triangle test, which meets
 * a leaf block's four triangles at once (kernels/trace/triangle.cl), and for the conductor's
 * Fresnel term, whose three channels fill a float4's lanes (kernels/bsdf/fresnel.cl).
 * kernels/lanes/packet.cl instantiates the same bodies at W = 8 or 16. */
#ifndef FACET_LANES_SCALAR_CL
#define FACET_LANES_SCALAR_CL

#include "kernels/lanes/lanes.cl"
#include "kernels/shared/render_layout.h"
#include "kernels/util/math.cl"
#include "kernels/util/sobol_table.cl"

#define FC_LW 1
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
#include "kernels/trace/sphere_lanes.cl"
#include "kernels/lights/area_lanes.cl"
#include "kernels/lanes/gather_lanes.cl"
#include "kernels/lights/light_pick_lanes.cl"
#include "kernels/lights/environment_lanes.cl"
#include "kernels/camera/filter_lanes.cl"
#include "kernels/camera/camera_lanes.cl"
#include "kernels/integrator/path_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

#define FC_LW 4
#include "kernels/lanes/lanes_open.cl"
#include "kernels/lanes/vec3_lanes.cl"
#include "kernels/util/hash_lanes.cl"
#include "kernels/bsdf/fresnel_lanes.cl"
#include "kernels/trace/triangle_lanes.cl"
#include "kernels/lanes/lanes_close.cl"

#endif
