/* Every layout shared by host and kernels. */
#ifndef FACET_SHARED_ALL_H
#define FACET_SHARED_ALL_H
#include "types.h"
#include "bvh.h"
#include "scene.h"
#include "render.h"
#include "environment.h"
#include "features.h"
#endif
