// Embree (Intel's CPU ray tracer, Debian's libembree-dev) on the same ray batches as
// facet's trace kernel: the reference the trace figures are ratios against. Built
// only when CMake finds Embree 3 (FACET_HAVE_EMBREE); otherwise available() is false
// and the bench says why.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "bench/bench.hpp"

namespace facet {

// Whether this facet_bench was built with Embree; when not, `why` says so.
bool embree_available(std::string* why);

struct EmbreeTimes {
    double build_s = 0.0;  // rtcCommitScene, one build thread, medium quality
    // Best-of-reps wall and CPU seconds for the whole batch; [0] one thread, [1] `threads` threads.
    Timing closest1[2];  // rtcIntersect1
    Timing closestP[2];  // rtcIntersect<packet> (width in packet_width)
    Timing closestS[2];  // rtcIntersect1M stream
    Timing any1[2];      // rtcOccluded1
    Timing anyP[2];      // rtcOccluded<packet>
    int packet_width = 0;
    int threads = 1;
    std::size_t hit_mismatches = 0;  // rays where Embree's hit/miss differs from facet's
    std::size_t t_mismatches = 0;    // hits whose distance differs by more than 1e-3 relative
};

// Builds Embree's BVH over `vertices` (3 per triangle) and traces `rays` closest-hit
// and any-hit with each variant. `facet_t` (facet's distances, -1 on a miss) is
// compared against Embree's closest hits.
EmbreeTimes bench_embree_trace(const std::vector<glm::vec3>& vertices, const RayBatch& rays, int threads, int reps,
                               const std::vector<float>& facet_t);

}  // namespace facet
