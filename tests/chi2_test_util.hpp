// A chi-square goodness-of-fit harness for direction samplers (implementation in
// chi2_test_util.cpp).
//
// Method (after Mitsuba's chi2.py and pbrt-v4's bsdfs_test.cpp, adapted to narrow lobes):
//  1. Chart. The sphere is cut into n_theta x n_phi cells in spherical coordinates about
//     +z: theta in [0, pi], phi - phi0 in [0, 2pi). The cell edges are NOT uniform: they
//     are uniform in asinh((theta - theta_c) / w_theta) and asinh((phi - phi_c) / w_phi),
//     so the cells are a fraction of the lobe's width w around its axis (theta_c, phi_c)
//     (e.g. the mirror direction) and grow geometrically away from it. A lobe far
//     narrower than a uniform 64 x 128 cell (alpha = 0.002) is thus resolved, while the
//     cells still cover the whole sphere: there is no "outside" region to account for.
//     theta = pi/2 is always an edge (the nearest edge is moved onto it), so the horizon,
//     where reflection pdfs drop to 0, never cuts a cell.
//  2. Expected counts. Each cell's probability is the integral of the pdf over it, by
//     order x order Gauss-Legendre points in (theta, phi) with the sin(theta) Jacobian,
//     summed in double on the host from pdf values a kernel computes at the points. The
//     pdf is smooth inside every cell (step 1), so the rule is accurate to ~1e-6.
//  3. One more cell counts the samples the sampler refused (e.g. reflected below the
//     horizon); its expectation is N (1 - integral of the pdf over the sphere). Samples
//     that are not finite or fall outside the chart are "invalid": there must be none.
//  4. Cells with an expected count below 5 are pooled into one (merged with the smallest
//     remaining cell if the pool itself stays below 5). Chi-square statistic with
//     (cells - 1) degrees of freedom; p-value from the regularised upper incomplete gamma
//     function Q(dof/2, chi2/2) (series and continued fraction, Numerical Recipes 6.2).
//  5. Significance: 0.01 for the whole family of tests, Sidak-corrected: each test
//     rejects at 1 - (1 - 0.01)^(1/n_tests).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

namespace facet::test::chi2 {

struct Chart {
    std::vector<double> theta_edges;  // n_theta + 1 edges in [0, pi]
    std::vector<double> phi_edges;    // n_phi + 1 edges in [0, 2pi], relative to phi0
    double phi0 = 0.0;
    int n_theta() const { return int(theta_edges.size()) - 1; }
    int n_phi() const { return int(phi_edges.size()) - 1; }
    int cells() const { return n_theta() * n_phi(); }
};

// A chart about the axis (theta_c, phi_c) with widths w_theta, w_phi (radians; large
// widths give nearly uniform cells).
Chart make_chart(double theta_c, double phi_c, double w_theta, double w_phi, int n_theta = 64, int n_phi = 128);

// A chart for a lobe about direction `axis` (unit, local frame) of angular widths w_theta
// along theta and w_perp across it (w_phi = w_perp / sin(theta_c), at most pi). A
// reflection lobe of roughness alpha seen from wo has w_theta ~ 2 alpha and w_perp ~
// 2 alpha cos(theta_o): reflection about h scales tilts of h across the plane of
// incidence by 2 (wo.h), which is small at grazing angles.
Chart make_lobe_chart(const double axis[3], double w_theta, double w_perp, int n_theta = 64, int n_phi = 128);

struct Quadrature {
    std::vector<cl_float4> dirs;  // order^2 points per cell, cell-major
    std::vector<double> weights;  // solid-angle weight of each point
    int per_cell = 0;
};

Quadrature make_quadrature(const Chart& chart, int order = 4);

// The integral of the pdf over each cell, from the pdf's values at the quadrature points.
std::vector<double> cell_masses(const Quadrature& q, const std::vector<float>& pdf);

struct Result {
    bool ok = false;
    double chi2 = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double mass = 0.0;          // integral of the pdf over the sphere
    std::uint64_t refused = 0;  // samples the sampler refused
    std::uint64_t invalid = 0;
    std::string message;  // a one-line summary
};

// `hist`: chart.cells() counts, then refused, then invalid; `mass`: cell_masses();
// `n`: samples drawn; `level`: the per-test significance.
Result test(const std::vector<std::uint32_t>& hist, const std::vector<double>& mass, std::uint64_t n, double level);

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularised upper incomplete gamma function.
double gamma_q(double a, double x);

// The per-test significance that keeps the family's at `alpha` over n tests.
double sidak(double alpha, int n_tests);

}  // namespace facet::test::chi2
