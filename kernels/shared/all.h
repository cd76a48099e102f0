/* Every layout shared by host and kernels. */
#ifndef FACET_SHARED_ALL_H
#define FACET_SHARED_ALL_H
#include "kernels/shared/types.h"
#include "kernels/shared/bvh_layout.h"
#include "kernels/shared/scene_layout.h"
#include "kernels/shared/sphere_layout.h"
#include "kernels/shared/instance_layout.h"
#include "kernels/shared/render_layout.h"
#include "kernels/shared/environment_layout.h"
#include "kernels/shared/texture_layout.h"
#include "kernels/shared/feature_flags.h"
#include "kernels/shared/denoise_layout.h"
#endif
