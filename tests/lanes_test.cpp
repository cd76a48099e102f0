// The lane-generic kernel bodies (kernels/lanes/lanes.cl, issue 29): each runs at W = 1 in
// the scalar kernels and at W = 8 in the packet form, and the two must compute the same
// bits, element for element, on ordinary and edge inputs (zeros, the disk's centre, signed
// zeros, infinite and zero densities, normals along the axes, points near the origin).
// The W = 8 sampler must also give the scalar sampler_get4's points (there the coordinates,
// not the paths, fill the lanes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "tests/cl_test_env.hpp"

namespace facet {
namespace {

struct LanesIn {
    float a[8], b[8], c[8], d[8];
    std::uint32_t k[8], m[8], n[8];
};
struct LanesOut {
    float one[4][8];
    float eight[4][8];
};

constexpr int kGroups = 1024;  // 8192 elements

// Fills every field; `edge` values go first, element by element, into field a..d.
std::vector<LanesIn> inputs(float lo, float hi, const std::vector<std::vector<float>>& edge = {}) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u(lo, hi);
    std::vector<LanesIn> in(kGroups);
    for (std::size_t e = 0; e < in.size() * 8; ++e) {
        LanesIn& g = in[e / 8];
        const std::size_t j = e % 8;
        float* f[4] = {&g.a[j], &g.b[j], &g.c[j], &g.d[j]};
        for (int v = 0; v < 4; ++v) *f[v] = u(rng);
        if (e < edge.size())
            for (std::size_t v = 0; v < edge[e].size() && v < 4; ++v) *f[v] = edge[e][v];
        g.k[j] = rng(), g.m[j] = rng(), g.n[j] = rng() % 100000u;
    }
    return in;
}

// Runs `kernel` and counts the elements whose W = 1 and W = 8 values differ in any bit.
int mismatches(const char* kernel, const std::vector<LanesIn>& in, int values) {
    std::vector<LanesOut> out = test::run_elementwise<LanesIn, LanesOut>("kernels/test/lanes_kernels.cl", kernel, in);
    int bad = 0;
    for (std::size_t g = 0; g < out.size(); ++g)
        for (int j = 0; j < 8; ++j)
            for (int v = 0; v < values; ++v) {
                std::uint32_t x, y;
                std::memcpy(&x, &out[g].one[v][j], 4);
                std::memcpy(&y, &out[g].eight[v][j], 4);
                if (x != y && bad++ < 5)
                    ADD_FAILURE() << kernel << " element " << g * 8 + j << " value " << v << ": W=1 "
                                  << out[g].one[v][j] << ", W=8 " << out[g].eight[v][j];
            }
    return bad;
}

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(Lanes, SincosTurnsSameBitsAtWidths1And8) {
    EXPECT_EQ(
        mismatches(
            "lanes_sincos_turns",
            inputs(-1.0f, 2.0f,
                   {{0.0f}, {-0.0f}, {0.25f}, {0.5f}, {0.75f}, {1.0f}, {0.125f}, {-0.375f}, {1e-30f}, {1.9999999f}}),
            2),
        0);
}

TEST(Lanes, CosineHemisphereSameBitsAtWidths1And8) {
    // a, b: the square; c: wo.z for the density
    EXPECT_EQ(mismatches("lanes_cosine_hemisphere",
                         inputs(0.0f, 1.0f,
                                {{0.5f, 0.5f, 1.0f},
                                 {0.0f, 0.0f, 0.5f},
                                 {0.5f, 0.0f, 0.5f},
                                 {0.0f, 0.5f, -0.5f},
                                 {0.9999999f, 0.5f, 0.0f},
                                 {0.25f, 0.75f, -0.0f}}),
                         4),
              0);
}

TEST(Lanes, TriangleAndAreaLightSameBitsAtWidths1And8) {
    // a, b: the square (and pick pdf, area); c: distance; d: cosine at the light
    EXPECT_EQ(mismatches("lanes_triangle_and_light",
                         inputs(-1.0f, 1.0f,
                                {{0.0f, 0.0f, 1.0f, 0.0f},
                                 {1.0f, 1.0f, 0.0f, -0.0f},
                                 {0.5f, 0.5f, 2.0f, -1.0f},
                                 {0.5f, 0.5f, 2.0f, 1e-30f}}),
                         4),
              0);
}

TEST(Lanes, FrameAndOffsetSameBitsAtWidths1And8) {
    // a, b, c: the normal (normalised below); d: the point's scale, near the origin and far
    std::vector<LanesIn> in = inputs(-1.0f, 1.0f,
                                     {{0.0f, 0.0f, 1.0f, 0.0f},
                                      {0.0f, 0.0f, -1.0f, 1e-3f},
                                      {1.0f, 0.0f, 0.0f, 1e4f},
                                      {0.0f, 1.0f, -0.0f, -1e4f},
                                      {0.0f, 0.0f, 0.0f, 0.03125f}});
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> scale(-6.0f, 6.0f);
    for (LanesIn& g : in)
        for (int j = 0; j < 8; ++j) {
            const float len = std::sqrt(g.a[j] * g.a[j] + g.b[j] * g.b[j] + g.c[j] * g.c[j]);
            if (len > 1e-3f) g.a[j] /= len, g.b[j] /= len, g.c[j] /= len;
        }
    for (std::size_t e = 5; e < in.size() * 8; ++e) in[e / 8].d[e % 8] = std::pow(10.0f, scale(rng));
    EXPECT_EQ(mismatches("lanes_frame_and_offset", in, 4), 0);
}

TEST(Lanes, PowerHeuristicSameBitsAtWidths1And8) {
    EXPECT_EQ(mismatches("lanes_power_heuristic",
                         inputs(0.0f, 10.0f,
                                {{0.0f, 0.0f},
                                 {kInf, 1.0f},
                                 {kInf, kInf},
                                 {1.0f, kInf},
                                 {0.0f, 2.0f},
                                 {3.0f, 0.0f},
                                 {1e30f, 1e30f},
                                 {1e-30f, 1e-30f}}),
                         1),
              0);
}

TEST(Lanes, PathWeightsSameBitsAtWidths1And8) {
    // a, b: the two densities (and throughput); c: throughput; d: eta scale; every strategy
    EXPECT_EQ(mismatches("lanes_path_weights",
                         inputs(0.0f, 4.0f,
                                {{0.0f, 0.0f},
                                 {kInf, 1.0f},
                                 {1.0f, kInf},
                                 {kInf, kInf},
                                 {0.0f, 3.0f},
                                 {0.0f, 0.0f},
                                 {kInf, 0.0f},
                                 {2.0f, 0.0f},
                                 {0.0f, 2.0f}}),
                         3),
              0);
}

// The microfacet bodies' inputs: a, b: the roughness (1e-4 added); c: wo's cosine + 0.1
// (normal incidence, grazing, below the horizon); d: its azimuth.
std::vector<LanesIn> microfacet_inputs() {
    return inputs(0.0f, 1.0f,
                  {{0.0f, 0.0f, 1.1f, 0.0f},
                   {1.0f, 1.0f, 1.1f, 0.3f},
                   {0.5f, 0.01f, 0.1f, 0.7f},
                   {0.2f, 0.2f, 0.0f, 0.1f},
                   {0.0f, 1.0f, 0.10001f, 0.25f}});
}

TEST(Lanes, GgxSameBitsAtWidths1And8) { EXPECT_EQ(mismatches("lanes_ggx", microfacet_inputs(), 4), 0); }

TEST(Lanes, BeckmannSameBitsAtWidths1And8) {
    // the visible-normal sampler's Newton iterations differ in number from lane to lane
    EXPECT_EQ(mismatches("lanes_beckmann", microfacet_inputs(), 4), 0);
}

TEST(Lanes, FresnelSameBitsAtWidths1And8) {
    // a: the cosine (normal incidence both ways, grazing, total internal reflection); b: the
    // index (1: no interface); c, d: Schlick's f0 and f90; the conductor's index b + i 5c
    EXPECT_EQ(
        mismatches("lanes_fresnel",
                   inputs(0.0f, 1.0f, {{1.0f, 0.1875f}, {0.0f, 0.1875f}, {0.5f, 0.5f}, {0.55f, 0.01f}, {0.45f, 1.0f}}),
                   3),
        0);
}

TEST(Lanes, PlainBaseSameBitsAtWidths1And8) {
    // each vector mixes GGX and Beckmann lanes, separable and height-correlated masking,
    // dielectrics and conductors, bases with and without a diffuse lobe, and both lobes' samples
    const std::vector<LanesIn> in = microfacet_inputs();
    EXPECT_EQ(mismatches("lanes_plain_base", in, 4), 0);
    // and most elements make a sample, of either lobe
    std::vector<LanesOut> out =
        test::run_elementwise<LanesIn, LanesOut>("kernels/test/lanes_kernels.cl", "lanes_plain_base", in);
    int made = 0;
    for (const LanesOut& o : out)
        for (int j = 0; j < 8; ++j) made += o.one[0][j] != -1.0f;
    EXPECT_GT(made, int(out.size() * 8) / 2);
}

TEST(Lanes, RoughDielectricSameBitsAsTheMaterialsFunctions) {
    // dielectric.cl's scalar functions of a material against the lanes' rough dielectric at
    // W = 8 (the packet paths' route): each vector mixes GGX and Beckmann lanes, separable and
    // height-correlated masking, F's own and the widened choice, compensated lanes, wo above and
    // below, indices above and below 1, reflections and refractions
    const std::vector<LanesIn> in = microfacet_inputs();
    EXPECT_EQ(mismatches("lanes_rough_dielectric", in, 4), 0);
    // most elements make a sample, and the second directions are evaluated on both sides
    std::vector<LanesOut> out =
        test::run_elementwise<LanesIn, LanesOut>("kernels/test/lanes_kernels.cl", "lanes_rough_dielectric", in);
    int made = 0, valued = 0;
    for (const LanesOut& o : out)
        for (int j = 0; j < 8; ++j) made += o.one[0][j] != -1.0f, valued += o.one[3][j] > 0.0f;
    EXPECT_GT(made, int(out.size() * 8) / 2);
    EXPECT_GT(valued, int(out.size() * 8) / 4);
}

TEST(Lanes, SphereSameBitsAtWidths1And8) {
    // a, b, c: the ray's origin and direction; d: the radius; with rays through the centre,
    // grazing, starting on the sphere and of zero length
    const std::vector<LanesIn> in = inputs(-1.0f, 1.0f,
                                           {{0.0f, 0.0f, 0.0f, 0.0f},
                                            {1.0f, 1.0f, 1.0f, 0.5f},
                                            {0.5f, -0.5f, 0.0f, -0.5f},
                                            {0.4f, 0.0f, -0.4f, 0.0f},
                                            {1.0f, 0.0f, 0.0f, 1.8f}});
    EXPECT_EQ(mismatches("lanes_sphere", in, 4), 0);
    // and the test meets the sphere often enough to matter
    std::vector<LanesOut> out =
        test::run_elementwise<LanesIn, LanesOut>("kernels/test/lanes_kernels.cl", "lanes_sphere", in);
    int hits = 0, misses = 0;
    for (const LanesOut& g : out)
        for (int j = 0; j < 8; ++j) (g.one[3][j] == 3.0f ? hits : misses) += 1;
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
}

TEST(Lanes, EnvironmentLocateSameBitsAtWidths1And8) {
    // a, b, c: a world direction (not unit: the angles do not need it); the axes, the poles
    // and signed zeros first
    EXPECT_EQ(mismatches("lanes_env_locate",
                         inputs(-1.0f, 1.0f,
                                {{0.0f, 0.0f, 0.0f},
                                 {0.0f, 1.0f, 0.0f},
                                 {0.0f, -1.0f, 0.0f},
                                 {-0.0f, -0.0f, 1.0f},
                                 {1.0f, 0.0f, -0.0f},
                                 {-1.0f, -0.0f, -0.0f},
                                 {0.5f, 0.5f, 0.5f}}),
                         4),
              0);
}

TEST(Lanes, EnvironmentDirectionSameBitsAtWidths1And8) {
    // a, b: the map's (u, v), with its corners and edges
    EXPECT_EQ(
        mismatches("lanes_env_uv_to_dir",
                   inputs(0.0f, 1.0f, {{0.0f, 0.0f}, {1.0f, 1.0f}, {0.5f, 0.0f}, {0.25f, 1.0f}, {0.75f, 0.5f}}), 3),
        0);
}

TEST(Lanes, FiltersSameBitsAtWidths1And8) {
    // a, b: the square's points for each of the four filters, with 0, 1/2 and the ends
    EXPECT_EQ(
        mismatches("lanes_filter",
                   inputs(0.0f, 1.0f, {{0.0f, 0.5f}, {0.5f, 0.0f}, {0.99999994f, 0.49999997f}, {0.25f, 0.75f}}), 4),
        0);
}

TEST(Lanes, CameraRaysSameBitsAtWidths1And8) {
    // a, b: the image position (corners and centre first); c, d: the lens
    EXPECT_EQ(
        mismatches("lanes_camera",
                   inputs(0.0f, 1.0f, {{0.0f, 0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.5f, 0.5f}, {0.5f, 0.5f, 1.0f, 0.0f}}),
                   4),
        0);
}

TEST(Lanes, SamplerGet4GivesTheScalarSamplersPoints) {
    EXPECT_EQ(mismatches("lanes_sampler_get4", inputs(0.0f, 1.0f), 4), 0);
}

TEST(Lanes, SamplerGet4At16LanesGivesTheScalarSamplersPoints) {
    // On AVX-512 CPUs the packets are 16 wide and the Sobol' chunks are indexed in registers.
    EXPECT_EQ(mismatches("lanes_sampler_get4_16", inputs(0.0f, 1.0f), 4), 0);
}

TEST(Lanes, HashesSameBitsAtWidths1And8) { EXPECT_EQ(mismatches("lanes_hashes", inputs(0.0f, 1.0f), 4), 0); }

TEST(Lanes, HashesSameBitsAtWidths1And4) { EXPECT_EQ(mismatches("lanes_hashes4", inputs(0.0f, 1.0f), 4), 0); }

}  // namespace
}  // namespace facet
