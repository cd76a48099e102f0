// The chi-square harness of chi2_test_util.hpp: its implementation, a helper source of
// facet_tests (the harness's own checks are Microfacet.Chi2Harness in microfacet_test.cpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "tests/chi2_test_util.hpp"

namespace facet::test::chi2 {
namespace {

constexpr double kPi = std::numbers::pi;

// Edges uniform in asinh((x - c) / w) over [lo, hi].
std::vector<double> warped_edges(double lo, double hi, double c, double w, int n) {
    double a = std::asinh((lo - c) / w);
    double b = std::asinh((hi - c) / w);
    std::vector<double> e(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) e[std::size_t(i)] = c + w * std::sinh(a + (b - a) * i / n);
    e.front() = lo;
    e.back() = hi;
    return e;
}

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n, Numerical Recipes 4.6).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(std::size_t(n), 0.0);
    w.assign(std::size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = 0.0;
            for (int k = 1; k <= n; ++k) {
                double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            double dz = p0 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-15) break;
        }
        x[std::size_t(i)] = z;
        w[std::size_t(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}

}  // namespace

Chart make_chart(double theta_c, double phi_c, double w_theta, double w_phi, int n_theta, int n_phi) {
    Chart c;
    c.theta_edges = warped_edges(0.0, kPi, theta_c, w_theta, n_theta);
    // The horizon on an edge: move the nearest inner edge onto pi/2.
    int best = 1;
    for (int i = 1; i < n_theta; ++i)
        if (std::abs(c.theta_edges[std::size_t(i)] - kPi / 2) < std::abs(c.theta_edges[std::size_t(best)] - kPi / 2))
            best = i;
    c.theta_edges[std::size_t(best)] = kPi / 2;
    c.phi0 = phi_c - kPi;
    c.phi_edges = warped_edges(0.0, 2.0 * kPi, kPi, std::min(w_phi, kPi), n_phi);
    return c;
}

Chart make_lobe_chart(const double axis[3], double w_theta, double w_perp, int n_theta, int n_phi) {
    double theta_c = std::atan2(std::hypot(axis[0], axis[1]), axis[2]);
    double phi_c = std::atan2(axis[1], axis[0]);
    double s = std::sin(theta_c);
    double w_phi = (s * kPi > w_perp) ? w_perp / s : kPi;
    return make_chart(theta_c, phi_c, w_theta, w_phi, n_theta, n_phi);
}

Quadrature make_quadrature(const Chart& chart, int order) {
    std::vector<double> gx, gw;
    gauss_legendre(order, gx, gw);
    Quadrature q;
    q.per_cell = order * order;
    std::size_t total = std::size_t(chart.cells()) * std::size_t(q.per_cell);
    q.dirs.reserve(total);
    q.weights.reserve(total);
    for (int a = 0; a < chart.n_theta(); ++a) {
        double t0 = chart.theta_edges[std::size_t(a)], t1 = chart.theta_edges[std::size_t(a) + 1];
        for (int b = 0; b < chart.n_phi(); ++b) {
            double p0 = chart.phi_edges[std::size_t(b)], p1 = chart.phi_edges[std::size_t(b) + 1];
            for (int i = 0; i < order; ++i) {
                double theta = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * gx[std::size_t(i)];
                double st = std::sin(theta), ct = std::cos(theta);
                for (int j = 0; j < order; ++j) {
                    double phi = chart.phi0 + 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * gx[std::size_t(j)];
                    cl_float4 d;
                    d.s[0] = float(st * std::cos(phi));
                    d.s[1] = float(st * std::sin(phi));
                    d.s[2] = float(ct);
                    d.s[3] = 0.0f;
                    q.dirs.push_back(d);
                    q.weights.push_back(0.25 * (t1 - t0) * (p1 - p0) * gw[std::size_t(i)] * gw[std::size_t(j)] * st);
                }
            }
        }
    }
    return q;
}

std::vector<double> cell_masses(const Quadrature& q, const std::vector<float>& pdf) {
    std::vector<double> m(q.dirs.size() / std::size_t(q.per_cell), 0.0);
    for (std::size_t i = 0; i < pdf.size(); ++i) m[i / std::size_t(q.per_cell)] += q.weights[i] * double(pdf[i]);
    return m;
}

Result test(const std::vector<std::uint32_t>& hist, const std::vector<double>& mass, std::uint64_t n, double level) {
    Result r;
    std::size_t cells = mass.size();
    r.refused = hist[cells];
    r.invalid = hist[cells + 1];
    for (double m : mass) r.mass += m;
    // Observed / expected per cell, the refused cell last.
    std::vector<std::pair<double, double>> oe;
    oe.reserve(cells + 1);
    for (std::size_t i = 0; i < cells; ++i) oe.emplace_back(double(hist[i]), mass[i] * double(n));
    oe.emplace_back(double(r.refused), std::max(0.0, 1.0 - r.mass) * double(n));
    std::sort(oe.begin(), oe.end(), [](auto& a, auto& b) { return a.second < b.second; });
    // Pool the cells expected below 5.
    double po = 0.0, pe = 0.0;
    std::size_t k = 0;
    while (k < oe.size() && oe[k].second < 5.0) {
        po += oe[k].first;
        pe += oe[k].second;
        ++k;
    }
    std::vector<std::pair<double, double>> kept(oe.begin() + std::ptrdiff_t(k), oe.end());
    if (pe > 0.0 || po > 0.0) {
        if (pe < 5.0 && !kept.empty()) {
            kept.front().first += po;
            kept.front().second += pe;
        } else {
            kept.emplace_back(po, pe);
        }
    }
    bool impossible = false;
    for (auto& [o, e] : kept) {
        if (e <= 0.0) {
            if (o > 0.0) impossible = true;
            continue;
        }
        r.chi2 += (o - e) * (o - e) / e;
        ++r.dof;
    }
    r.dof -= 1;
    r.p_value = (impossible || r.dof < 1) ? 0.0 : gamma_q(0.5 * r.dof, 0.5 * r.chi2);
    r.ok = r.invalid == 0 && !impossible && r.dof >= 1 && r.p_value >= level;
    std::ostringstream s;
    s << "chi2 = " << r.chi2 << ", dof = " << r.dof << ", p = " << r.p_value << " (level " << level
      << "), pdf mass = " << r.mass << ", refused = " << r.refused << "/" << n << ", invalid = " << r.invalid
      << (impossible ? ", samples where the pdf is 0" : "");
    r.message = s.str();
    return r;
}

double gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    double gln = std::lgamma(a);
    if (x < a + 1.0) {
        // Series for P(a, x) (Numerical Recipes 6.2.5).
        double ap = a, sum = 1.0 / a, del = sum;
        for (int n = 0; n < 100000; ++n) {
            ap += 1.0;
            del *= x / ap;
            sum += del;
            if (std::abs(del) < std::abs(sum) * 1e-15) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(-x + a * std::log(x) - gln));
    }
    // Continued fraction for Q(a, x), modified Lentz (Numerical Recipes 6.2.7).
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (std::abs(del - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - gln) * h;
}

double sidak(double alpha, int n_tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / n_tests); }

}  // namespace facet::test::chi2
