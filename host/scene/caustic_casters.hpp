// The glass that caustics come through, as bounding spheres: what the kernels sample toward
// at Lambertian vertices (kernels/integrator/caustic_guide.cl).
#pragma once

#include <vector>

#include "host/scene/scene.hpp"

namespace facet {

// The bounding spheres of the scene's dielectric objects, 4 floats each (centre, radius):
// each analytic sphere of a dielectric material as it is; for triangles, each run of
// consecutive triangles of one dielectric material (a mesh as the readers add it), in the
// world and in each shared mesh, placed by each of its instances. At most FC_MAX_CASTERS,
// the largest kept; none when settings.caustic_guide is 0 or no material is Lambertian or
// a rough microfacet one.
// Bounds are a matter of efficiency only: the kernels' estimate is unbiased for any.
std::vector<float> caustic_casters(const Scene& scene);

}  // namespace facet
