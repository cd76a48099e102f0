// Alias tables by Vose's method (alias_table.hpp).
#include "host/scene/alias_table.hpp"

#include <algorithm>
#include <cstddef>

namespace facet {

AliasTable build_alias_table(const std::vector<double>& weights) {
    const std::size_t n = weights.size();
    AliasTable t;
    t.q.assign(n, 1.0f);
    t.alias.resize(n);
    for (std::size_t i = 0; i < n; ++i) t.alias[i] = std::int32_t(i);
    double sum = 0.0;
    for (double w : weights) sum += w;
    if (sum > 0.0) {
        // scaled weights (mean 1): the bins below 1 take their remainder from one above
        std::vector<double> p(n);
        std::vector<std::size_t> small, large;
        for (std::size_t i = 0; i < n; ++i) {
            p[i] = weights[i] * double(n) / sum;
            (p[i] < 1.0 ? small : large).push_back(i);
        }
        while (!small.empty() && !large.empty()) {
            const std::size_t s = small.back(), l = large.back();
            small.pop_back();
            large.pop_back();
            t.q[s] = float(p[s]);
            t.alias[s] = std::int32_t(l);
            p[l] = (p[l] + p[s]) - 1.0;
            (p[l] < 1.0 ? small : large).push_back(l);
        }
        // what is left is 1 up to rounding: its own bin entirely; a zero weight left over
        // (rounding only) hands its whole bin to the heaviest index
        const std::size_t heaviest = std::size_t(std::max_element(weights.begin(), weights.end()) - weights.begin());
        for (std::size_t s : small)
            if (!(weights[s] > 0.0)) t.q[s] = 0.0f, t.alias[s] = std::int32_t(heaviest);
    }
    t.probability = alias_table_probabilities(t.q, t.alias);
    return t;
}

std::vector<double> alias_table_probabilities(const std::vector<float>& q, const std::vector<std::int32_t>& alias) {
    const std::size_t n = q.size();
    std::vector<double> p(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        p[j] += double(q[j]);
        if (q[j] < 1.0f) p[std::size_t(alias[j])] += 1.0 - double(q[j]);
    }
    for (double& x : p) x /= double(n);
    return p;
}

}  // namespace facet
