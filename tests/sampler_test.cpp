// The path tracer's sample generator (kernels/util/sampler.cl) on the device: the
// scrambled Sobol' points keep their stratification, every coordinate is uniform, the
// two half-images of a pixel stay independent estimators (the error estimate needs
// it), different dimension sets are decorrelated, and integration error drops below
// the independent sampler's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "host/bvh/bvh.hpp"
#include "host/cl/runtime.hpp"
#include "host/render/renderer.hpp"
#include "host/readers/load_scene.hpp"
#include "kernels/shared/render_layout.h"
#include "tests/cl_test_env.hpp"
#include "tests/test_helpers.hpp"
#include "tests/test_paths.hpp"

namespace facet {
namespace {

// `samples` consecutive sample indices of each of `pixels` pixels: 4 floats a point.
std::vector<float> points(int kind, std::uint32_t seed, std::uint32_t pixels, std::uint32_t samples,
                          std::uint32_t set) {
    ClContext& ctx = test::context();
    const std::size_t n = std::size_t(pixels) * samples;
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, n * 4 * sizeof(float));
    cl::Kernel k(test::program("kernels/test/sampler_kernels.cl"), "sampler_points");
    k.setArg(0, std::uint32_t(kind)), k.setArg(1, seed), k.setArg(2, std::uint32_t(1000)), k.setArg(3, samples);
    k.setArg(4, set), k.setArg(5, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<float> v(n * 4);
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, v.size() * sizeof(float), v.data());
    return v;
}

// The points of one half of one pixel (samples half, half + 2, ...), coordinate c.
std::vector<float> half_coords(const std::vector<float>& v, std::uint32_t pixel, std::uint32_t samples, int half,
                               int c) {
    std::vector<float> out;
    for (std::uint32_t s = std::uint32_t(half); s < samples; s += 2)
        out.push_back(v[4 * (std::size_t(pixel) * samples + s) + c]);
    return out;
}

// Burley's sampler written plainly on the host (each scramble on its own, Sobol' points
// from the direction numbers of Joe & Kuo's new-joe-kuo-6.21201 table, as
// tests/tools/sobol_table.py), against which the kernel's chained formulation is checked
// bit for bit.
namespace burley {

std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::uint32_t reverse(std::uint32_t x) {
    std::uint32_t r = 0;
    for (int b = 0; b < 32; ++b) r |= ((x >> b) & 1u) << (31 - b);
    return r;
}

std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
    x = reverse(x) + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverse(x);
}

// Dimension d's direction numbers v[k] (bit k of the index, from the top bit down).
std::vector<std::uint32_t> directions(int d) {
    std::vector<std::uint32_t> v(32);
    if (d == 0) {
        for (int k = 0; k < 32; ++k) v[k] = 1u << (31 - k);
        return v;
    }
    const int s[] = {1, 2, 3}, a[] = {0, 1, 1};
    const std::vector<std::uint32_t> m[] = {{1}, {1, 3}, {1, 3, 1}};
    const int sd = s[d - 1], ad = a[d - 1];
    for (int k = 0; k < sd; ++k) v[k] = m[d - 1][k] << (31 - k);
    for (int k = sd; k < 32; ++k) {
        std::uint32_t x = v[k - sd] ^ (v[k - sd] >> sd);
        for (int j = 1; j < sd; ++j)
            if ((ad >> (sd - 1 - j)) & 1) x ^= v[k - j];
        v[k] = x;
    }
    return v;
}

std::uint32_t sobol(int d, std::uint32_t i) {
    static const std::vector<std::uint32_t> v[4] = {directions(0), directions(1), directions(2), directions(3)};
    std::uint32_t x = 0;
    for (int k = 0; k < 32; ++k)
        if ((i >> k) & 1u) x ^= v[d][k];
    return x;
}

std::uint32_t hash_pair(std::uint32_t a, std::uint32_t b) { return std::uint32_t(mix64((std::uint64_t(a) << 32) | b)); }

// Wellons' lowbias32: the coordinates' scramble seeds from the set's.
std::uint32_t lowbias32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

// Coordinate c of dimension set `set` of sample `sample` of `pixel`.
float point(std::uint32_t seed, std::uint32_t pixel, std::uint32_t sample, std::uint32_t set, int c) {
    const std::uint32_t half_seed = std::uint32_t(
        mix64(mix64(std::uint64_t(seed) ^ 0x5a17e5eedULL) ^ ((std::uint64_t(sample & 1u) << 32) | pixel)));
    const std::uint32_t set_seed = hash_pair(half_seed, set);
    const std::uint32_t i = nested_uniform_scramble(sample >> 1, set_seed);
    const std::uint32_t x =
        nested_uniform_scramble(sobol(c, i), lowbias32(set_seed + std::uint32_t(c + 1) * 0x9e3779b9u));
    return float(x >> 8) * 0x1p-24f;
}

}  // namespace burley

TEST(Sampler, SobolIsBurleysScramble) {
    const std::uint32_t samples = 64, seed = 5;
    for (std::uint32_t set : {0u, 1u, 2u, 7u, 40u}) {
        std::vector<float> v = points(FC_SAMPLER_SOBOL, seed, 3, samples, set);
        int wrong = 0;
        for (std::uint32_t g = 0; g < 3 * samples; ++g)
            for (int c = 0; c < 4; ++c)
                if (v[4 * g + c] != burley::point(seed, 1000 + g / samples, g % samples, set, c) && ++wrong < 5)
                    ADD_FAILURE() << "set " << set << ", pixel " << 1000 + g / samples << ", sample " << g % samples
                                  << ", coordinate " << c;
        EXPECT_EQ(wrong, 0) << "set " << set;
    }
}

TEST(Sampler, SobolHalvesAreZeroTwoNets) {
    // 2^m points of one half: in dimensions (0, 1) every elementary interval of area
    // 2^-m holds exactly one point (a (0, m, 2)-net), in every set; each coordinate
    // alone is stratified into 2^m intervals.
    const std::uint32_t m = 7, n = 1u << m, samples = 2 * n;
    for (std::uint32_t set : {0u, 1u, 2u, 9u}) {
        std::vector<float> v = points(FC_SAMPLER_SOBOL, 3, 4, samples, set);
        for (std::uint32_t pixel = 0; pixel < 4; ++pixel) {
            for (int half = 0; half < 2; ++half) {
                std::vector<float> x = half_coords(v, pixel, samples, half, 0);
                std::vector<float> y = half_coords(v, pixel, samples, half, 1);
                ASSERT_EQ(x.size(), n);
                for (std::uint32_t a = 0; a <= m; ++a) {
                    std::set<std::uint32_t> cells;
                    for (std::uint32_t i = 0; i < n; ++i)
                        cells.insert((std::uint32_t(x[i] * float(1u << a)) << (m - a)) |
                                     std::uint32_t(y[i] * float(1u << (m - a))));
                    EXPECT_EQ(cells.size(), n) << "set " << set << " pixel " << pixel << " half " << half
                                               << ": intervals 2^-" << a << " x 2^-" << (m - a);
                }
                for (int c = 0; c < 4; ++c) {
                    std::set<std::uint32_t> strata;
                    for (float u : half_coords(v, pixel, samples, half, c)) {
                        ASSERT_GE(u, 0.0f);
                        ASSERT_LT(u, 1.0f);
                        strata.insert(std::uint32_t(u * float(n)));
                    }
                    EXPECT_EQ(strata.size(), n) << "set " << set << " coordinate " << c;
                }
            }
        }
    }
}

// The error of estimating the integral of a smooth 4-D function, per pixel and half.
struct HalfErrors {
    std::vector<double> e[2];
};
HalfErrors half_errors(int kind, std::uint32_t pixels, std::uint32_t samples, std::uint32_t set) {
    std::vector<float> v = points(kind, 11, pixels, samples, set);
    // f = prod_c (1 + sin(2 pi u_c) / 2 + u_c - 1/2): integral 1 over [0,1]^4.
    auto f = [](const float* u) {
        double p = 1.0;
        for (int c = 0; c < 4; ++c) {
            const double x = double(u[c]);
            p *= 1.0 + 0.5 * std::sin(6.283185307179586 * x) + (x - 0.5);
        }
        return p;
    };
    HalfErrors h;
    for (std::uint32_t p = 0; p < pixels; ++p) {
        double sum[2] = {0.0, 0.0};
        for (std::uint32_t s = 0; s < samples; ++s) sum[s & 1] += f(&v[4 * (std::size_t(p) * samples + s)]);
        for (int k = 0; k < 2; ++k) h.e[k].push_back(sum[k] / double(samples / 2) - 1.0);
    }
    return h;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sab += a[i] * b[i], saa += a[i] * a[i], sbb += b[i] * b[i];
    return sab / std::sqrt(saa * sbb);
}

double rms(const std::vector<double>& a) {
    double s = 0.0;
    for (double x : a) s += x * x;
    return std::sqrt(s / double(a.size()));
}

TEST(Sampler, HalvesAreIndependentAndUnbiased) {
    // Across 4096 pixels the two halves' errors are uncorrelated (one interleaved
    // stratified sequence would make them strongly anti-correlated), and their mean
    // is zero within 5 standard errors.
    const std::uint32_t pixels = 4096;
    for (int kind : {FC_SAMPLER_SOBOL, FC_SAMPLER_INDEPENDENT}) {
        for (std::uint32_t samples : {2u, 16u, 64u}) {
            HalfErrors h = half_errors(kind, pixels, samples, 3);
            double r = correlation(h.e[0], h.e[1]);
            EXPECT_LT(std::fabs(r), 5.0 / std::sqrt(double(pixels))) << "kind " << kind << ", " << samples << " spp";
            for (int k = 0; k < 2; ++k) {
                double mean = 0.0;
                for (double e : h.e[k]) mean += e;
                mean /= double(pixels);
                EXPECT_LT(std::fabs(mean), 5.0 * rms(h.e[k]) / std::sqrt(double(pixels)))
                    << "kind " << kind << ", " << samples << " spp, half " << k;
            }
        }
    }
}

TEST(Sampler, SetsAreDecorrelated) {
    // The same coordinate of two dimension sets, over one pixel's samples: no
    // correlation beyond chance.
    const std::uint32_t samples = 4096;
    std::vector<float> a = points(FC_SAMPLER_SOBOL, 5, 1, samples, 1);
    std::vector<float> b = points(FC_SAMPLER_SOBOL, 5, 1, samples, 2);
    for (int c = 0; c < 4; ++c) {
        std::vector<double> x, y;
        for (std::uint32_t s = 0; s < samples; ++s)
            x.push_back(double(a[4 * s + c]) - 0.5), y.push_back(double(b[4 * s + c]) - 0.5);
        EXPECT_LT(std::fabs(correlation(x, y)), 5.0 / std::sqrt(double(samples))) << "coordinate " << c;
    }
}

TEST(Sampler, SobolBeatsIndependentOnSmoothIntegrand) {
    // 64 samples a pixel on a smooth 4-D integrand: the scrambled Sobol' error is
    // far below the independent sampler's (whose error falls as 1/sqrt(n)).
    const std::uint32_t pixels = 1024, samples = 64;
    double sobol = rms(half_errors(FC_SAMPLER_SOBOL, pixels, samples, 4).e[0]);
    double independent = rms(half_errors(FC_SAMPLER_INDEPENDENT, pixels, samples, 4).e[0]);
    EXPECT_LT(sobol, 0.5 * independent) << "sobol " << sobol << ", independent " << independent;
}

// The Cornell box rendered with each sampler: the two images agree in mean. The test
// is a z-test of their difference, per 8x8-pixel block and over the whole image, with
// variances estimated from each render's own two halves.
TEST(Sampler, RenderMatchesIndependentInMean) {
    // Per pixel the statistic is the sum of the three channels and its variance is read
    // from that sum's two halves, (a - b)^2 / 4: the channels of one pixel share their
    // paths, so summing the channels' variances instead would leave out their covariance
    // and understate the variance (z-scores spread about twice as wide as N(0, 1)).
    Scene scene = load_scene(test::scenes_dir() + "/cornell_box.json");
    scene.settings.width = scene.settings.height = 32;
    const std::uint32_t spp = 128;
    Bvh bvh = build_bvh(scene.vertices);
    struct Sums {
        std::vector<double> mean, var;
    };
    auto render = [&](int sampler) {
        scene.settings.sampler = sampler;
        Renderer r(test::context(), scene, bvh);
        r.render(spp);
        const Renderer::Halves h = r.halves();
        Sums out;
        for (std::size_t p = 0; 3 * p < h.rgb[0].size(); ++p) {
            double a = 0.0, b = 0.0;
            for (int c = 0; c < 3; ++c) a += double(h.rgb[0][3 * p + c]), b += double(h.rgb[1][3 * p + c]);
            out.mean.push_back(0.5 * (a + b));
            out.var.push_back(0.25 * (a - b) * (a - b));
        }
        return out;
    };
    const Sums a = render(FC_SAMPLER_SOBOL), b = render(FC_SAMPLER_INDEPENDENT);
    const int w = scene.settings.width, blocks = w / 8;
    double total_d = 0.0, total_v = 0.0, worst = 0.0;
    for (int by = 0; by < blocks; ++by) {
        for (int bx = 0; bx < blocks; ++bx) {
            double d = 0.0, v = 0.0;
            for (int y = 8 * by; y < 8 * by + 8; ++y)
                for (int x = 8 * bx; x < 8 * bx + 8; ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    d += a.mean[i] - b.mean[i];
                    v += a.var[i] + b.var[i];
                }
            total_d += d, total_v += v;
            if (v > 0.0) worst = std::max(worst, std::fabs(d) / std::sqrt(v));
        }
    }
    EXPECT_LT(worst, 4.5) << "the worst 8x8 block's z-score";
    EXPECT_LT(std::fabs(total_d) / std::sqrt(total_v), 4.0) << "the whole image's z-score";
}

}  // namespace
}  // namespace facet
