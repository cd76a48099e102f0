// Alias tables (host/scene/alias_table.hpp) and the environment's tables built from them
// (host/scene/environment_map.hpp): the probabilities a stored table samples, by
// P(k) = (q[k] + sum over bins j aliased to k of (1 - q[j])) / n, reproduce the weights
// (exactly when the scaled weights are floats; to float rounding otherwise), a zero weight
// is never picked, and the density the kernels read is what the tables sample. The device
// sampling itself is tested against that density by tests/environment_chi2_test.cpp.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "host/scene/alias_table.hpp"
#include "host/scene/environment_map.hpp"
#include "host/scene/sky.hpp"

namespace facet {
namespace {

// Independent of build_alias_table's own probability: from the stored bins.
std::vector<double> implied(const AliasTable& t) {
    std::vector<double> p(t.q.size(), 0.0);
    for (std::size_t j = 0; j < t.q.size(); ++j) {
        EXPECT_GE(t.q[j], 0.0f);
        EXPECT_LE(t.q[j], 1.0f);
        EXPECT_GE(t.alias[j], 0);
        EXPECT_LT(std::size_t(t.alias[j]), t.q.size());
        p[j] += double(t.q[j]);
        p[std::size_t(t.alias[j])] += 1.0 - double(t.q[j]);
    }
    for (double& x : p) x /= double(t.q.size());
    return p;
}

TEST(AliasTable, ReproducesProbabilitiesExactly) {
    // n w / sum are dyadic: every threshold is a float, every probability exact
    const std::vector<double> w = {1.0, 2.0, 3.0, 0.0, 2.0, 8.0, 0.0, 0.0};
    const AliasTable t = build_alias_table(w);
    const std::vector<double> p = implied(t);
    ASSERT_EQ(p.size(), w.size());
    for (std::size_t k = 0; k < w.size(); ++k) {
        EXPECT_EQ(p[k], w[k] / 16.0) << "index " << k;
        EXPECT_EQ(t.probability[k], p[k]) << "index " << k;
    }
}

TEST(AliasTable, ReproducesRandomWeightsToFloatRounding) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n : {1, 2, 3, 17, 1000, 4096}) {
        std::vector<double> w(static_cast<std::size_t>(n));
        double sum = 0.0;
        for (double& x : w) {
            const double r = u(rng);
            x = r < 0.2 ? 0.0 : r < 0.25 ? 1e3 * r : r * r * r;  // zeros, a few peaks, a tail
            sum += x;
        }
        if (!(sum > 0.0)) w[0] = sum = 1.0;
        const AliasTable t = build_alias_table(w);
        const std::vector<double> p = implied(t);
        for (std::size_t k = 0; k < w.size(); ++k) {
            EXPECT_EQ(t.probability[k], p[k]) << "n " << n << ", index " << k;
            if (w[k] == 0.0) {
                EXPECT_EQ(p[k], 0.0) << "a zero weight is never picked (n " << n << ")";
            } else {
                EXPECT_NEAR(p[k], w[k] / sum, 1e-6 * (w[k] / sum) + 1e-7 / n) << "n " << n << ", index " << k;
            }
        }
        for (std::size_t j = 0; j < w.size(); ++j)
            if (t.q[j] < 1.0f) {
                EXPECT_GT(w[std::size_t(t.alias[j])], 0.0) << "an alias has weight";
            }
    }
}

TEST(AliasTable, AllZeroIsUniform) {
    const AliasTable t = build_alias_table(std::vector<double>(5, 0.0));
    for (double p : implied(t)) EXPECT_EQ(p, 0.2);
}

// The environment's distribution: each texel's stored density is W H P(row) P(column | row)
// of the stored tables, and close to the texel weights'; the same for MIS compensation's.
TEST(AliasTable, EnvironmentDensityIsWhatTheTablesSample) {
    SunSkyParams sp;
    const EnvironmentMap sky = sun_sky_environment(sp, 256);
    for (bool compensated : {false, true}) {
        const std::vector<float> d = compensated ? compensated_environment_distribution(sky) : sky.distribution;
        const int w = sky.params.width, h = sky.params.height;
        const std::size_t texels = std::size_t(w) * h;
        ASSERT_EQ(d.size(), 2 * std::size_t(h) + 3 * texels);
        auto table = [&](std::size_t at, int n) {
            AliasTable t;
            for (int i = 0; i < n; ++i) {
                t.q.push_back(d[at + 2 * std::size_t(i)]);
                t.alias.push_back(std::bit_cast<std::int32_t>(d[at + 2 * std::size_t(i) + 1]));
            }
            return t;
        };
        const std::vector<double> rows = implied(table(0, h));
        double sum = 0.0;
        for (int y = 0; y < h; ++y) {
            const std::vector<double> cols = implied(table(2 * std::size_t(h) + 2 * std::size_t(y) * w, w));
            for (int x = 0; x < w; ++x) {
                const double want = rows[y] * cols[x] * double(texels);
                const float got = d[2 * std::size_t(h) + 2 * texels + std::size_t(y) * w + x];
                EXPECT_EQ(got, float(want))
                    << "texel (" << x << ", " << y << ")" << (compensated ? ", compensated" : "");
                sum += double(got);
            }
        }
        EXPECT_NEAR(sum / double(texels), 1.0, 1e-5);
    }
}

}  // namespace
}  // namespace facet
