#!/usr/bin/env python3
"""Issue 29's packet prototype: how much faster PoCL runs shading work written over eight
lanes per work-item than over one, from one source (bench/packet/README.md).

shade_template.cl is compiled at width 1 (float: the GPU form) and width 8 (float8), the
two forms alternated for --rounds rounds; the medians give paths per second and the
ratios. The per-work-item sums of the two forms must agree (same operations, only the
order of the final sum differs), and the lane occupancy shows what divergent path
lengths cost with and without regeneration.

Needs pyopencl and numpy from PyPI and an OpenCL driver (PoCL here): pip install pyopencl numpy
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

# Lane types and gathers per width. A gather at width 8 reads each lane's element in turn
# (PoCL 3.1 emits no vgatherdps for these), as a product version would.
WIDTH_1 = """
#define REAL float
#define UINT uint
#define INT int
#define FN(name) name##_w1
#define V3 V3_w1
#define LANES 1u
#define LANE_IDS 0u
#define TRUE_MASK 1
#define CONVERT_REAL convert_float
#define CONVERT_INT convert_int
#define AS_UINT as_uint
#define ANY(x) (x)
#define COUNT(x) ((x) ? 1u : 0u)
#define HSUM(x) (x)
#define CHUNKS(t, r) (t[(r) & 15u] ^ t[16u + (((r) >> 4) & 15u)] ^ t[32u + (((r) >> 8) & 15u)] ^ \\
    t[48u + (((r) >> 12) & 15u)] ^ t[64u + (((r) >> 16) & 15u)] ^ t[80u + (((r) >> 20) & 15u)] ^ \\
    t[96u + (((r) >> 24) & 15u)] ^ t[112u + ((r) >> 28)])
#define GATHER_TABLE(t, r, c) do { uint4 q_ = CHUNKS(t, r); c[0] = q_.x; c[1] = q_.y; c[2] = q_.z; c[3] = q_.w; } while (0)
#define GATHER_LIGHT(L, i, v0, e1, e2, ln, le, area) do { __global const float* l_ = (L) + 16 * (i); \\
    v0 = FN(v3)(l_[0], l_[1], l_[2]); e1 = FN(v3)(l_[3], l_[4], l_[5]); e2 = FN(v3)(l_[6], l_[7], l_[8]); \\
    ln = FN(v3)(l_[9], l_[10], l_[11]); le = FN(v3)(l_[12], l_[13], l_[14]); area = l_[15]; } while (0)
#define GATHER_POINT(P, k, p, n) do { __global const float* q_ = (P) + 8 * (k); \\
    p = FN(v3)(q_[0], q_[1], q_[2]); n = FN(v3)(q_[4], q_[5], q_[6]); } while (0)
"""

WIDTH_8 = """
#define REAL float8
#define UINT uint8
#define INT int8
#define FN(name) name##_w8
#define V3 V3_w8
#define LANES 8u
#define LANE_IDS ((uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u))
#define TRUE_MASK -1
#define CONVERT_REAL convert_float8
#define CONVERT_INT convert_int8
#define AS_UINT as_uint8
#define ANY(x) any(x)
#define COUNT(x) ((uint)(-((x).s0 + (x).s1 + (x).s2 + (x).s3 + (x).s4 + (x).s5 + (x).s6 + (x).s7)))
#define HSUM(x) ((x).s0 + (x).s1 + (x).s2 + (x).s3 + (x).s4 + (x).s5 + (x).s6 + (x).s7)
#define EACH_LANE(M, ...) M(0, __VA_ARGS__) M(1, __VA_ARGS__) M(2, __VA_ARGS__) M(3, __VA_ARGS__) \\
    M(4, __VA_ARGS__) M(5, __VA_ARGS__) M(6, __VA_ARGS__) M(7, __VA_ARGS__)
#define TABLE_LANE(j, t, r, c) { uint r_ = (r).s##j; uint4 q_ = t[r_ & 15u] ^ t[16u + ((r_ >> 4) & 15u)] ^ \\
    t[32u + ((r_ >> 8) & 15u)] ^ t[48u + ((r_ >> 12) & 15u)] ^ t[64u + ((r_ >> 16) & 15u)] ^ \\
    t[80u + ((r_ >> 20) & 15u)] ^ t[96u + ((r_ >> 24) & 15u)] ^ t[112u + (r_ >> 28)]; \\
    c[0].s##j = q_.x; c[1].s##j = q_.y; c[2].s##j = q_.z; c[3].s##j = q_.w; }
#define GATHER_TABLE(t, r, c) do { EACH_LANE(TABLE_LANE, t, r, c) } while (0)
#define SET3(v, j, a, b, c) { (v).x.s##j = (a); (v).y.s##j = (b); (v).z.s##j = (c); }
#define LIGHT_LANE(j, L, i, v0, e1, e2, ln, le, area) { __global const float* l_ = (L) + 16 * (i).s##j; \\
    SET3(v0, j, l_[0], l_[1], l_[2]) SET3(e1, j, l_[3], l_[4], l_[5]) SET3(e2, j, l_[6], l_[7], l_[8]) \\
    SET3(ln, j, l_[9], l_[10], l_[11]) SET3(le, j, l_[12], l_[13], l_[14]) (area).s##j = l_[15]; }
#define GATHER_LIGHT(L, i, v0, e1, e2, ln, le, area) do { EACH_LANE(LIGHT_LANE, L, i, v0, e1, e2, ln, le, area) } while (0)
#define POINT_LANE(j, P, k, p, n) { __global const float* q_ = (P) + 8 * (k).s##j; \\
    SET3(p, j, q_[0], q_[1], q_[2]) SET3(n, j, q_[4], q_[5], q_[6]) }
#define GATHER_POINT(P, k, p, n) do { EACH_LANE(POINT_LANE, P, k, p, n) } while (0)
"""

NAMES = ("REAL UINT INT FN V3 LANES LANE_IDS TRUE_MASK CONVERT_REAL CONVERT_INT AS_UINT ANY COUNT HSUM "
         "CHUNKS GATHER_TABLE GATHER_LIGHT GATHER_POINT EACH_LANE TABLE_LANE SET3 LIGHT_LANE POINT_LANE").split()


def program_source(samples):
    template = open(os.path.join(HERE, "shade_template.cl")).read()
    common = f"#define SAMPLES_PER_ITEM {samples}u\n"
    undef = "".join(f"#undef {n}\n" for n in NAMES)
    return common + WIDTH_1 + template + undef + WIDTH_8 + template


def scene_data():
    """Two area-light triangles under the Cornell box's ceiling and 1024 wall points."""
    rng = np.random.default_rng(0)
    table = rng.integers(0, 2**32, size=(128, 4), dtype=np.uint32)
    lights = np.zeros((2, 16), np.float32)
    for i in range(2):
        lights[i, 0:3] = (213 + 130 * i, 548.7, 227 + 105 * i)
        lights[i, 3:6] = (130 * (1 - 2 * i), 0, 0)
        lights[i, 6:9] = (0, 0, 105 * (1 - 2 * i))
        lights[i, 9:12] = (0, -1, 0)
        lights[i, 12:15] = (18.4, 11.0, 2.75)
        lights[i, 15] = 0.5 * 130 * 105
    points = np.zeros((1024, 8), np.float32)
    points[:, 0:3] = rng.uniform(0, 548, (1024, 3))
    n = rng.normal(size=(1024, 3))
    points[:, 4:7] = n / np.linalg.norm(n, axis=1)[:, None]
    return table, lights, points


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--items", type=int, default=65536, help="work-items (pixels; default 256 x 256)")
    ap.add_argument("--samples", type=int, default=64, help="paths per work-item (default 64)")
    ap.add_argument("--max-depth", type=int, default=16, help="bounces at most (default 16, facet's)")
    ap.add_argument("--rounds", type=int, default=5, help="alternated rounds (default 5)")
    a = ap.parse_args()
    if a.samples % 8:
        raise SystemExit("packet_prototype.py: --samples must be a multiple of 8")
    try:
        import pyopencl as cl
    except ImportError:
        print("pyopencl not installed: pip install pyopencl numpy; skipping the packet prototype")
        return 0
    ctx = cl.create_some_context(interactive=False)
    device = ctx.devices[0]
    queue = cl.CommandQueue(ctx)
    program = cl.Program(ctx, program_source(a.samples)).build()
    table, lights, points = scene_data()
    mf = cl.mem_flags
    bufs = [cl.Buffer(ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=x) for x in (table, lights, points)]
    out = cl.Buffer(ctx, mf.WRITE_ONLY, 4 * a.items)
    slots = cl.Buffer(ctx, mf.WRITE_ONLY, 8 * a.items)
    forms = {"width 1": "paths_w1", "width 8": "paths_w8", "width 8, regenerated": "paths_regenerated_w8",
             "width 1, regenerated": "paths_regenerated_w1"}
    kernels = {k: cl.Kernel(program, v) for k, v in forms.items()}
    times = {k: [] for k in forms}
    sums, occupancy = {}, {}
    for rnd in range(a.rounds + 1):   # round 0 warms up and is not counted
        for name, k in kernels.items():
            k.set_args(*bufs, out, slots, np.uint32(a.max_depth))
            t0 = time.perf_counter()
            cl.enqueue_nd_range_kernel(queue, k, (a.items,), (64,))
            queue.finish()
            dt = time.perf_counter() - t0
            if rnd:
                times[name].append(dt)
            s = np.empty(a.items, np.float32)
            cl.enqueue_copy(queue, s, out)
            st = np.empty(2 * a.items, np.uint32)
            cl.enqueue_copy(queue, st, slots)
            sums[name] = s
            occupancy[name] = st[1::2].sum(dtype=np.float64) / st[0::2].sum(dtype=np.float64)
    paths = a.items * a.samples
    base = statistics.median(times["width 1"])
    print(f"packet prototype on {device.name.strip()} ({device.platform.name.strip()}), {a.items} work-items x "
          f"{a.samples} paths, max depth {a.max_depth}, {a.rounds} alternated rounds, load {os.getloadavg()[0]:.1f}")
    print("| form | median s | M paths/s | × width 1 | lane occupancy | max rel. diff. of sums vs width 1 |")
    print("|---|---|---|---|---|---|")
    ref = sums["width 1"].astype(np.float64)
    for name in forms:
        med = statistics.median(times[name])
        diff = np.max(np.abs(sums[name] - ref) / np.maximum(np.abs(ref), 1e-30))
        print(f"| {name} | {med:.3f} | {paths / med * 1e-6:.2f} | {base / med:.2f} | {occupancy[name]:.3f} | {diff:.2g} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
