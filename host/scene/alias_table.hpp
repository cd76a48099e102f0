// Alias tables (Walker 1977, built by Vose's method, "A Linear Algorithm for Generating
// Random Numbers with a Given Distribution", IEEE TSE 17(9), 1991; pbrt-v4's AliasTable):
// O(1) sampling of a discrete distribution over n bins. Bin i = floor(u n) is taken with
// probability q[i], its alias otherwise, so the probability of index k is
//   P(k) = (q[k] + sum over bins j != k with alias[j] == k of (1 - q[j])) / n.
// The kernel side is env_alias_pick in kernels/lights/environment.cl.
#pragma once

#include <cstdint>
#include <vector>

namespace facet {

struct AliasTable {
    std::vector<float> q;             // threshold of each bin, in [0, 1]
    std::vector<std::int32_t> alias;  // the index a bin hands over to above its threshold
    // P(k) as the stored (float) table samples it, in double: the probabilities the
    // kernels report as the density.
    std::vector<double> probability;
};

// The table of `weights` (finite, >= 0, at least one). A zero weight is never picked; all
// zero weights give the uniform distribution.
AliasTable build_alias_table(const std::vector<double>& weights);

// P(k) of a stored table by the formula above (double arithmetic on the float thresholds).
std::vector<double> alias_table_probabilities(const std::vector<float>& q, const std::vector<std::int32_t>& alias);

}  // namespace facet
