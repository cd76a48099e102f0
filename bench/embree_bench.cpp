// Embree on facet's ray batches: see embree_bench.hpp.
#include "bench/embree_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#ifdef FACET_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#include "host/error.hpp"

namespace facet {

#ifndef FACET_HAVE_EMBREE

bool embree_available(std::string* why) {
    if (why) *why = "facet_bench was built without Embree (install libembree-dev and reconfigure)";
    return false;
}

EmbreeTimes bench_embree_trace(const std::vector<glm::vec3>&, const RayBatch&, int, int, const std::vector<float>&) {
    throw Error("facet_bench was built without Embree");
}

#else

namespace {

using Clock = std::chrono::steady_clock;

RTCRayHit make_rayhit(const RayBatch& b, std::size_t i) {
    RTCRayHit rh;
    rh.ray.org_x = b.origins[i].s[0], rh.ray.org_y = b.origins[i].s[1], rh.ray.org_z = b.origins[i].s[2];
    rh.ray.dir_x = b.dirs[i].s[0], rh.ray.dir_y = b.dirs[i].s[1], rh.ray.dir_z = b.dirs[i].s[2];
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = b.dirs[i].s[3];
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

template <int N>
void fill_packet(RTCRayHitNt<N>& p, int* valid, const RayBatch& b, std::size_t first, std::size_t n) {
    for (int k = 0; k < N; ++k) {
        std::size_t i = first + std::size_t(k);
        valid[k] = i < n ? -1 : 0;
        std::size_t j = i < n ? i : first;
        p.ray.org_x[k] = b.origins[j].s[0], p.ray.org_y[k] = b.origins[j].s[1], p.ray.org_z[k] = b.origins[j].s[2];
        p.ray.dir_x[k] = b.dirs[j].s[0], p.ray.dir_y[k] = b.dirs[j].s[1], p.ray.dir_z[k] = b.dirs[j].s[2];
        p.ray.tnear[k] = 0.0f;
        p.ray.tfar[k] = b.dirs[j].s[3];
        p.ray.time[k] = 0.0f;
        p.ray.mask[k] = 0xFFFFFFFFu;
        p.ray.id[k] = 0;
        p.ray.flags[k] = 0;
        p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        p.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
}

void intersectN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<4>& p) {
    rtcIntersect4(valid, s, c, reinterpret_cast<RTCRayHit4*>(&p));
}
void intersectN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<8>& p) {
    rtcIntersect8(valid, s, c, reinterpret_cast<RTCRayHit8*>(&p));
}
void intersectN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<16>& p) {
    rtcIntersect16(valid, s, c, reinterpret_cast<RTCRayHit16*>(&p));
}
void occludedN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<4>& p) {
    rtcOccluded4(valid, s, c, reinterpret_cast<RTCRay4*>(&p.ray));
}
void occludedN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<8>& p) {
    rtcOccluded8(valid, s, c, reinterpret_cast<RTCRay8*>(&p.ray));
}
void occludedN(const int* valid, RTCScene s, RTCIntersectContext* c, RTCRayHitNt<16>& p) {
    rtcOccluded16(valid, s, c, reinterpret_cast<RTCRay16*>(&p.ray));
}

// Runs f(begin, end) over [0, n) split into `threads` contiguous chunks; returns the
// best wall time and the best CPU time of `reps` runs (after one warm-up).
template <typename F>
Timing timed(std::size_t n, int threads, int reps, F&& f) {
    Timing best{1e30, 1e30};
    for (int r = 0; r < reps + 1; ++r) {
        auto start = Clock::now();
        double cpu0 = process_cpu_seconds();
        if (threads <= 1) {
            f(std::size_t(0), n);
        } else {
            std::vector<std::thread> pool;
            std::size_t chunk = (n + std::size_t(threads) - 1) / std::size_t(threads);
            for (int k = 0; k < threads; ++k) {
                std::size_t b = std::min(n, std::size_t(k) * chunk), e = std::min(n, b + chunk);
                pool.emplace_back([&f, b, e] { f(b, e); });
            }
            for (auto& t : pool) t.join();
        }
        double cpu = process_cpu_seconds() - cpu0;
        double s = std::chrono::duration<double>(Clock::now() - start).count();
        if (r > 0) best.wall = std::min(best.wall, s), best.cpu = std::min(best.cpu, cpu);
    }
    return best;
}

template <int N>
void packet_runs(RTCScene scene, const RayBatch& rays, int threads, int reps, EmbreeTimes& out) {
    const std::size_t n = rays.origins.size();
    // Packets of N rays through rtcIntersectN (closest) or rtcOccludedN (any hit).
    auto run = [&](int th, bool any) {
        return timed(n, th, reps, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            alignas(64) RTCRayHitNt<N> p;
            alignas(64) int valid[N];
            for (std::size_t i = b; i < e; i += N) {
                fill_packet<N>(p, valid, rays, i, e);
                if (any) occludedN(valid, scene, &ctx, p);
                else intersectN(valid, scene, &ctx, p);
            }
        });
    };
    for (int ti = 0; ti < 2; ++ti) {
        const int th = ti == 0 ? 1 : threads;
        out.closestP[ti] = run(th, false);
        out.anyP[ti] = run(th, true);
    }
}

}  // namespace

bool embree_available(std::string*) { return true; }

EmbreeTimes bench_embree_trace(const std::vector<glm::vec3>& vertices, const RayBatch& rays, int threads, int reps,
                               const std::vector<float>& facet_t) {
    EmbreeTimes out;
    out.threads = std::max(1, threads);
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) throw Error("Embree: rtcNewDevice failed");
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t tris = vertices.size() / 3;
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), vertices.size()));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
    for (std::size_t i = 0; i < vertices.size(); ++i)
        vb[3 * i] = vertices[i].x, vb[3 * i + 1] = vertices[i].y, vb[3 * i + 2] = vertices[i].z;
    for (std::size_t i = 0; i < 3 * tris; ++i) ib[i] = unsigned(i);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    auto start = Clock::now();
    rtcCommitScene(scene);
    out.build_s = std::chrono::duration<double>(Clock::now() - start).count();

    const std::size_t n = rays.origins.size();
    // Agreement with facet, from one closest-hit pass.
    for (std::size_t i = 0; i < n; ++i) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh = make_rayhit(rays, i);
        rtcIntersect1(scene, &ctx, &rh);
        bool eh = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        bool fh = i < facet_t.size() && facet_t[i] >= 0.0f;
        if (eh != fh) ++out.hit_mismatches;
        else if (eh && std::fabs(rh.ray.tfar - facet_t[i]) > 1e-3f * std::max(1.0f, rh.ray.tfar)) ++out.t_mismatches;
    }

    for (int ti = 0; ti < 2; ++ti) {
        int th = ti == 0 ? 1 : out.threads;
        out.closest1[ti] = timed(n, th, reps, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t i = b; i < e; ++i) {
                RTCRayHit rh = make_rayhit(rays, i);
                rtcIntersect1(scene, &ctx, &rh);
            }
        });
        out.any1[ti] = timed(n, th, reps, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            for (std::size_t i = b; i < e; ++i) {
                RTCRayHit rh = make_rayhit(rays, i);
                rtcOccluded1(scene, &ctx, &rh.ray);
            }
        });
        out.closestS[ti] = timed(n, th, reps, [&](std::size_t b, std::size_t e) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
            constexpr std::size_t M = 256;
            RTCRayHit stream[M];
            for (std::size_t i = b; i < e; i += M) {
                std::size_t m = std::min(M, e - i);
                for (std::size_t k = 0; k < m; ++k) stream[k] = make_rayhit(rays, i + k);
                rtcIntersect1M(scene, &ctx, stream, unsigned(m), sizeof(RTCRayHit));
            }
        });
    }
    if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) {
        out.packet_width = 16;
        packet_runs<16>(scene, rays, out.threads, reps, out);
    } else if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) {
        out.packet_width = 8;
        packet_runs<8>(scene, rays, out.threads, reps, out);
    } else {
        out.packet_width = 4;
        packet_runs<4>(scene, rays, out.threads, reps, out);
    }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return out;
}

#endif

}  // namespace facet
