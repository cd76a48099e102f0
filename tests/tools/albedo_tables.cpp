// Writes the albedo tables of kernels/bsdf/ that the energy compensation of
// kernels/bsdf/energy_compensation.cl reads, one file per family:
// - albedo_tables_conductor.cl: the directional albedo E(mu) (F = 1) of the
//   single-scattering GGX and Beckmann lobes with height-correlated Smith G and its
//   cosine-weighted average (Kulla-Conty's compensation lobe);
// - albedo_tables_schlick.cl: E5(mu) (F = (1 - wo.h)^5) and its average, for the Schlick
//   form of the specular layer's albedo (the diffuse coupling);
// - albedo_tables_dielectric.cl: the rough dielectric's energy albedo E_R + E_T for
//   Turquin 2019's albedo scaling (from inside divided by E: energy_compensation.cl).
// The albedos are integrated on the kernels themselves (kernels/test/albedo_kernels.cl)
// with 2^16 visible-normal samples per node; the averages 2 int E(mu) mu dmu are the
// exact integrals of the piecewise-linear interpolant the kernels use, so the compensated
// lobes' albedo integrates to exactly 1 at F = 1 whatever the table's resolution.
//
// - albedo_tables_sheen.cl: the directional albedo E_sheen(mu, r) of the Charlie sheen lobe
//   (kernels/bsdf/sheen.cl), whose albedo scaling weights the layer below it.
//
// Usage (from the repository root, after building the target facet_albedo_tables):
//   ./build/tests/facet_albedo_tables kernels/bsdf [sheen] && make format
// (`sheen`: only albedo_tables_sheen.cl).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/cl_test_env.hpp"
#include "kernels/shared/material_layout.h"

namespace {

constexpr int kNMu = 32;
constexpr int kNR = 32;
constexpr unsigned kSamples = 1u << 16;

// E and E5 at every node of one NDF, [r][mu].
std::vector<cl_float2> integrate(int ndf) {
    using namespace facet::test;
    const std::size_t n = std::size_t(kNMu) * kNR;
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float2));
    cl::Kernel k(program("kernels/test/albedo_kernels.cl"), "albedo_table");
    k.setArg(0, ndf);
    k.setArg(1, kNMu);
    k.setArg(2, kNR);
    k.setArg(3, kSamples);
    k.setArg(4, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<cl_float2> v(n);
    context().queue().enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(cl_float2), v.data());
    return v;
}

// The rough dielectric's energy albedo E_R + E_T of one NDF and side, [x][r][mu]; from
// inside (side 1) divided by the F = 1 albedo E_c that the kernels read from `e` (the
// fc_albedo_E table) at the same (mu, r). The index axis is uniform in sqrt(x), x = (eta -
// 1) / (eta + 1) up to eta = 100, the largest ior the readers accept: fine near eta = 1,
// where the critical angle moves as sqrt(eta - 1), and as fine as the old uniform axis
// over x in 1.2..2.5. Stored as half floats (vload_half) to stay in constant memory.
constexpr int kDMu = 16;
constexpr int kDR = 12;
constexpr int kDX = 16;
constexpr float kDXMax = 99.0f / 101.0f;
constexpr unsigned kDSamples = 1u << 16;

std::vector<float> integrate_dielectric(int ndf, int side, const std::vector<float>& e) {
    using namespace facet::test;
    const std::size_t n = std::size_t(kDMu) * kDR * kDX;
    cl::Buffer table(context().context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, e.size() * sizeof(float),
                     const_cast<float*>(e.data()));
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, n * sizeof(cl_float2));
    cl::Kernel k(program("kernels/test/albedo_kernels.cl"), "albedo_dielectric_table");
    k.setArg(0, ndf);
    k.setArg(1, side);
    k.setArg(2, kDMu);
    k.setArg(3, kDR);
    k.setArg(4, kDX);
    k.setArg(5, kDXMax);
    k.setArg(6, kDSamples);
    k.setArg(7, table);
    k.setArg(8, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<cl_float2> t(n);
    context().queue().enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(cl_float2), t.data());
    std::vector<float> v(n);
    for (int x = 0; x < kDX; ++x)
        for (int j = 0; j < kDR; ++j)
            for (int i = 0; i < kDMu; ++i) {
                const std::size_t id = (std::size_t(x) * kDR + j) * kDMu + i;
                // alpha = 0 does not scatter: E = 1 exactly (eta -> 1 does: node x = 0 is
                // integrated at x = 1e-3, the limit of a rough interface)
                const float ed = j == 0 ? 1.0f : t[id].s[0];
                v[id] = side == 1 ? ed / t[id].s[1] : ed;
            }
    return v;
}

// The sheen lobe's albedo at every node, [r][mu].
constexpr int kSMu = 32;
constexpr int kSR = 32;
constexpr unsigned kSSamples = 1u << 16;

std::vector<double> integrate_sheen() {
    using namespace facet::test;
    const std::size_t n = std::size_t(kSMu) * kSR;
    cl::Buffer out(context().context(), CL_MEM_WRITE_ONLY, n * sizeof(float));
    cl::Kernel k(program("kernels/test/albedo_kernels.cl"), "albedo_sheen_table");
    k.setArg(0, kSMu);
    k.setArg(1, kSR);
    k.setArg(2, kSSamples);
    k.setArg(3, out);
    context().queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<float> v(n);
    context().queue().enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(float), v.data());
    return std::vector<double>(v.begin(), v.end());
}

// 2 int_0^1 E(mu) mu dmu of the piecewise-linear interpolant of row[0..kNMu).
double average(const std::vector<double>& row) {
    const double h = 1.0 / (kNMu - 1);
    double s = 0.0;
    for (int i = 0; i + 1 < kNMu; ++i) {
        const double mu = i * h;
        s += 2.0 * h * (row[i] * (mu / 2.0 + h / 6.0) + row[i + 1] * (mu / 2.0 + h / 3.0));
    }
    return s;
}

// A float literal of OpenCL C: 7 significant digits, always with a point ("1.0f", not "1f").
std::string literal(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7g", x);
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s + "f";
}

// The IEEE 754 binary16 bits of a float of the normal half range (round to nearest even),
// as vload_half reads them. Throws for a value it cannot hold.
unsigned short half_bits(float v) {
    if (v == 0.0f) return 0;
    std::uint32_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    const int e = int((b >> 23) & 0xffu) - 127 + 15;
    if (!std::isfinite(v) || e <= 0 || e >= 31) throw std::runtime_error("table value out of half range");
    const std::uint32_t m = b & 0x7fffffu;
    std::uint32_t h = (std::uint32_t(e) << 10) | (m >> 13);
    const std::uint32_t rest = m & 0x1fffu;
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;  // a carry rounds into the exponent
    return static_cast<unsigned short>(((b >> 16) & 0x8000u) | h);
}

void print_half_array(std::FILE* f, const char* name, const std::vector<double>& v, int per_line) {
    std::fprintf(f, "__constant ushort %s[%zu] = {\n", name, v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        std::fprintf(f, "%s0x%04x,%s", i % per_line == 0 ? "    " : " ", unsigned(half_bits(float(v[i]))),
                     (i + 1) % per_line == 0 ? "\n" : "");
    std::fprintf(f, "};\n");
}

void print_array(std::FILE* f, const char* name, const std::vector<double>& v, int per_line) {
    std::fprintf(f, "__constant float %s[%zu] = {\n", name, v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        std::fprintf(f, "%s%s,%s", i % per_line == 0 ? "    " : " ", literal(v[i]).c_str(),
                     (i + 1) % per_line == 0 ? "\n" : "");
    std::fprintf(f, "};\n");
}

// One generated kernel file: opens dir/name (throws naming it), writes the common
// header line, then `body`, then closes it (throws on a write error).
template <class Body>
void write_file(const std::string& dir, const char* name, Body body) {
    const std::string path = dir + "/" + name;
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw std::runtime_error("cannot write " + path);
    std::fprintf(f, "/* Generated by tests/tools/albedo_tables.cpp (facet_albedo_tables): do not edit.\n");
    body(f);
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) throw std::runtime_error("write error on " + path);
    std::fprintf(stderr, "wrote %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && !(argc == 3 && std::string(argv[2]) == "sheen")) {
        std::fprintf(stderr, "usage: facet_albedo_tables OUT_DIR [sheen]  (from the repository root: kernels/bsdf)\n");
        return 2;
    }
    const std::string dir = argv[1];
    try {
        const std::vector<double> sheen = integrate_sheen();
        write_file(dir, "albedo_tables_sheen.cl", [&](std::FILE* f) {
            std::fprintf(f,
                         " * The directional albedo E_sheen(mu, r) of the Charlie sheen lobe (sheen.cl, colour 1),\n"
                         " * integrated on the kernels with %u cosine samples per node: fc_albedo_sheen[r][mu] at\n"
                         " * mu = i / %d and sheen roughness r = j / %d (clamped below as sheen.cl clamps it). */\n",
                         kSSamples, kSMu - 1, kSR - 1);
            std::fprintf(f, "#ifndef FACET_BSDF_ALBEDO_TABLES_SHEEN_CL\n#define FACET_BSDF_ALBEDO_TABLES_SHEEN_CL\n\n");
            std::fprintf(f, "#define FC_SHEEN_N_MU %d\n#define FC_SHEEN_N_R %d\n\n", kSMu, kSR);
            print_array(f, "fc_albedo_sheen", sheen, 8);
            std::fprintf(f, "\n#endif\n");
        });
        if (argc == 3) return 0;
        // [ndf][r][mu] in FC_NDF order: Beckmann (0), GGX (1).
        static_assert(FC_NDF_BECKMANN == 0 && FC_NDF_GGX == 1, "albedo tables are indexed by ndf");
        std::vector<double> e, e5, e_avg, e5_avg;
        for (int ndf : {FC_NDF_BECKMANN, FC_NDF_GGX}) {
            std::vector<cl_float2> t = integrate(ndf);
            for (int j = 0; j < kNR; ++j) {
                std::vector<double> row(kNMu), row5(kNMu);
                for (int i = 0; i < kNMu; ++i) {
                    // alpha = 0 is the mirror: E = 1 and E5 = (1 - mu)^5 exactly
                    const double mu = double(i) / (kNMu - 1);
                    row[i] = j == 0 ? 1.0 : double(t[j * kNMu + i].s[0]);
                    row5[i] = j == 0 ? (1.0 - mu) * (1.0 - mu) * (1.0 - mu) * (1.0 - mu) * (1.0 - mu)
                                     : double(t[j * kNMu + i].s[1]);
                }
                e.insert(e.end(), row.begin(), row.end());
                e5.insert(e5.end(), row5.begin(), row5.end());
                e_avg.push_back(average(row));
                e5_avg.push_back(average(row5));
            }
        }
        // the dielectric divides by E as the kernels will read it: the float literals
        std::vector<float> e_float;
        for (double v : e) e_float.push_back(std::stof(literal(v)));
        std::vector<double> d;
        for (int ndf : {FC_NDF_BECKMANN, FC_NDF_GGX})
            for (int side : {0, 1})
                for (float v : integrate_dielectric(ndf, side, e_float)) d.push_back(double(v));

        write_file(dir, "albedo_tables_conductor.cl", [&](std::FILE* f) {
            std::fprintf(f,
                         " * The directional albedo of the single-scattering GGX and Beckmann lobes with F = 1 and\n"
                         " * height-correlated Smith G, integrated on the kernels with %u visible-normal samples per\n"
                         " * node: fc_albedo_E[ndf][r][mu] at mu = i / %d and r = sqrt(alpha) = j / %d (ndf: 0\n"
                         " * Beckmann, 1 GGX), and its average 2 int E(mu) mu dmu over the linear interpolant,\n"
                         " * fc_albedo_E_avg[ndf][r]. */\n",
                         kSamples, kNMu - 1, kNR - 1);
            std::fprintf(
                f, "#ifndef FACET_BSDF_ALBEDO_TABLES_CONDUCTOR_CL\n#define FACET_BSDF_ALBEDO_TABLES_CONDUCTOR_CL\n\n");
            std::fprintf(f, "#define FC_ALBEDO_N_MU %d\n#define FC_ALBEDO_N_R %d\n\n", kNMu, kNR);
            print_array(f, "fc_albedo_E", e, 8);
            print_array(f, "fc_albedo_E_avg", e_avg, 8);
            std::fprintf(f, "\n#endif\n");
        });
        write_file(dir, "albedo_tables_schlick.cl", [&](std::FILE* f) {
            std::fprintf(f,
                         " * The directional albedo of the same lobes with F = (1 - wo.h)^5 (Schlick's F is F0 E +\n"
                         " * (1 - F0) E5), on the grid of albedo_tables_conductor.cl, %u samples per node:\n"
                         " * fc_albedo_E5[ndf][r][mu] and its average fc_albedo_E5_avg[ndf][r]. */\n",
                         kSamples);
            std::fprintf(
                f, "#ifndef FACET_BSDF_ALBEDO_TABLES_SCHLICK_CL\n#define FACET_BSDF_ALBEDO_TABLES_SCHLICK_CL\n\n");
            std::fprintf(f, "#include \"kernels/bsdf/albedo_tables_conductor.cl\"\n\n");
            print_array(f, "fc_albedo_E5", e5, 8);
            print_array(f, "fc_albedo_E5_avg", e5_avg, 8);
            std::fprintf(f, "\n#endif\n");
        });
        write_file(dir, "albedo_tables_dielectric.cl", [&](std::FILE* f) {
            std::fprintf(f,
                         " * The rough dielectric's energy albedo E_R + E_T (transmission times etap^2, exact\n"
                         " * Fresnel) seen from wo, %u samples per node: fc_albedo_dielectric[ndf][side][x][r][mu]\n"
                         " * at mu = i / %d, r = j / %d and x = (eta - 1) / (eta + 1) = %.6g (k / %d)^2 (k = 0 at x =\n"
                         " * 1e-3), eta the relative index n_far / n_near (side 0) or its inverse (side 1, leaving\n"
                         " * the denser medium), as IEEE half floats (read with vload_half). Side 1 holds E / E_c,\n"
                         " * E_c = fc_albedo_E (albedo_tables_conductor.cl) interpolated at the node. */\n",
                         kDSamples, kDMu - 1, kDR - 1, double(kDXMax), kDX - 1);
            std::fprintf(
                f,
                "#ifndef FACET_BSDF_ALBEDO_TABLES_DIELECTRIC_CL\n#define FACET_BSDF_ALBEDO_TABLES_DIELECTRIC_CL\n\n");
            std::fprintf(f, "#define FC_ALBEDO_D_N_MU %d\n#define FC_ALBEDO_D_N_R %d\n#define FC_ALBEDO_D_N_X %d\n",
                         kDMu, kDR, kDX);
            std::fprintf(f, "#define FC_ALBEDO_D_X_MAX %s\n\n", literal(kDXMax).c_str());
            print_half_array(f, "fc_albedo_dielectric", d, 12);
            std::fprintf(f, "\n#endif\n");
        });
        return 0;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "facet_albedo_tables: %s\n", ex.what());
        return 1;
    }
}
