// The sun-and-sky environment (sky.hpp gives the models and their sources).
#include "host/scene/sky.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/util/color.hpp"
#include "host/util/math.hpp"

namespace facet {
namespace {

constexpr double kDeg = kPi / 180.0;

struct Vec {
    double x, y, z;
};
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The map's convention (kernels/shared/environment_layout.h): phi = 2 pi u, theta = pi v.
Vec direction(double theta, double phi) {
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// Perez et al. 1993 luminance distribution, as parameterised by Preetham et al. 1999.
struct Perez {
    double a, b, c, d, e;
    double operator()(double cos_theta, double gamma) const {
        const double ct = std::max(cos_theta, 1e-3);
        const double cg = std::cos(gamma);
        return (1.0 + a * std::exp(b / ct)) * (1.0 + c * std::exp(d * gamma) + e * cg * cg);
    }
};

// Preetham 1999, appendix A.2: the distribution coefficients for Y, x and y.
Perez perez_Y(double t) {
    return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
}
Perez perez_x(double t) {
    return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
            -0.0033 * t + 0.0452};
}
Perez perez_y(double t) {
    return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
            -0.0109 * t + 0.0529};
}

// Zenith chromaticity: [T^2 T 1] M [theta_s^3 theta_s^2 theta_s 1]^T.
double zenith_chroma(const double m[3][4], double t, double ts) {
    const double tv[3] = {t * t, t, 1.0}, sv[4] = {ts * ts * ts, ts * ts, ts, 1.0};
    double r = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) r += tv[i] * m[i][j] * sv[j];
    return r;
}
constexpr double kZenithX[3][4] = {
    {0.00166, -0.00375, 0.00209, 0.0}, {-0.02903, 0.06377, -0.03202, 0.00394}, {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {
    {0.00275, -0.00610, 0.00317, 0.0}, {-0.04214, 0.08970, -0.04153, 0.00516}, {0.15346, -0.26756, 0.06670, 0.26688}};

// CIE xyY to linear Rec. 709 RGB (IEC 61966-2-1 matrix), negatives clipped.
void xyY_to_rgb(double x, double y, double Y, float out[3]) {
    const double X = y > 0.0 ? x * Y / y : 0.0, Z = y > 0.0 ? (1.0 - x - y) * Y / y : 0.0;
    const double rgb[3] = {3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
                           -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
                           0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z};
    for (int c = 0; c < 3; ++c) out[c] = float(std::max(rgb[c], 0.0));
}

double texel_solid_angle(int y, int w, int h) {
    return 2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
}

}  // namespace

SunSkyImage render_sun_sky(const SunSkyParams& p, int width) {
    if (width < 8 || width % 2 != 0 || width > 65536)
        throw Error(fmt::format("sun and sky: the width must be even, in [8, 65536] (got {})", width));
    if (!(p.elevation_degrees >= -10.0 && p.elevation_degrees <= 90.0) ||
        !(p.turbidity >= 1.7 && p.turbidity <= 10.0) || !(p.ground_albedo >= 0.0 && p.ground_albedo <= 1.0) ||
        !(p.sun_radius_degrees > 0.0 && p.sun_radius_degrees < 5.0) || !std::isfinite(p.azimuth_degrees))
        throw Error(
            fmt::format("sun and sky: parameters out of range (elevation {} in [-10, 90], turbidity {} in "
                        "[1.7, 10], ground albedo {} in [0, 1], sun radius {} in (0, 5) degrees)",
                        p.elevation_degrees, p.turbidity, p.ground_albedo, p.sun_radius_degrees));
    const int w = width, h = width / 2;
    SunSkyImage img;
    img.width = w;
    img.height = h;
    img.rgb.assign(std::size_t(w) * h * 3, 0.0f);

    // the sun the sky is evaluated for (Preetham needs it above the horizon) and twilight
    const double elev = std::max(p.elevation_degrees, 0.5) * kDeg;
    const double dim = p.elevation_degrees < 0.5 ? std::pow(10.0, (p.elevation_degrees - 0.5) / 2.5) : 1.0;
    const double theta_s = kPi / 2.0 - elev, phi_s = kPi + p.azimuth_degrees * kDeg;
    const Vec sun = direction(theta_s, phi_s);

    // sky: Y from the zenith luminance (kcd/m^2), x and y from the zenith chromaticity
    const double t = p.turbidity;
    const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta_s);
    const double Yz = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
    const double xz = zenith_chroma(kZenithX, t, theta_s), yz = zenith_chroma(kZenithY, t, theta_s);
    const Perez fY = perez_Y(t), fx = perez_x(t), fy = perez_y(t);
    const double nY = fY(1.0, theta_s), nx = fx(1.0, theta_s), ny = fy(1.0, theta_s);
    const int sky_rows = h / 2;  // rows whose centre is above the horizon
    for (int y = 0; y < sky_rows; ++y)
        for (int x = 0; x < w; ++x) {
            const Vec d = direction(kPi * (y + 0.5) / h, 2.0 * kPi * (x + 0.5) / w);
            const double gamma = std::acos(std::clamp(dot(d, sun), -1.0, 1.0));
            xyY_to_rgb(xz * fx(d.y, gamma) / nx, yz * fy(d.y, gamma) / ny, dim * Yz * fY(d.y, gamma) / nY,
                       &img.rgb[3 * (std::size_t(y) * w + x)]);
        }

    // sun: luminous solar constant over the disk, attenuated along the air mass
    const double r = p.sun_radius_degrees * kDeg, cos_r = std::cos(r);
    const double disk_omega = 2.0 * kPi * (1.0 - cos_r);
    const Vec disk = direction(kPi / 2.0 - p.elevation_degrees * kDeg, phi_s);  // the true sun
    const double zen_deg = 90.0 - std::max(p.elevation_degrees, 0.0);
    const double air_mass = 1.0 / (std::cos(zen_deg * kDeg) + 0.50572 * std::pow(96.07995 - zen_deg, -1.6364));
    const double beta = 0.04608 * t - 0.04586, lambda[3] = {0.612, 0.549, 0.465};  // um
    double sun_rgb[3];
    for (int c = 0; c < 3; ++c)
        sun_rgb[c] = 128.0 / disk_omega *
                     std::exp(-air_mass * (0.008735 * std::pow(lambda[c], -4.08) + beta * std::pow(lambda[c], -1.3)));
    // area-weighted coverage of each texel near the disk (16 x 16 points, sin(theta) weights)
    struct Cover {
        std::size_t texel;
        double fraction;
    };
    std::vector<Cover> covers;
    double disk_in_map = 0.0;
    const double reach = r + std::hypot(2.0 * kPi / w, kPi / h);
    const int n = 16;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Vec c = direction(kPi * (y + 0.5) / h, 2.0 * kPi * (x + 0.5) / w);
            if (dot(c, disk) < std::cos(reach)) continue;
            double in = 0.0, all = 0.0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double th = kPi * (y + (j + 0.5) / n) / h;
                    const Vec d = direction(th, 2.0 * kPi * (x + (i + 0.5) / n) / w);
                    all += std::sin(th);
                    in += dot(d, disk) >= cos_r ? std::sin(th) : 0.0;
                }
            if (in <= 0.0) continue;
            disk_in_map += in / all * texel_solid_angle(y, w, h);
            if (y < sky_rows) covers.push_back({std::size_t(y) * w + x, in / all});
        }
    img.sun_direction[0] = disk.x;
    img.sun_direction[1] = disk.y;
    img.sun_direction[2] = disk.z;
    // renormalise: the disk's power in the map is exactly L_sun * disk_omega
    double sun_lum_omega = 0.0;
    for (const Cover& cv : covers) {
        const double f = cv.fraction * disk_omega / disk_in_map;
        float add[3];
        for (int c = 0; c < 3; ++c) {
            add[c] = float(sun_rgb[c] * f);
            img.rgb[3 * cv.texel + c] += add[c];
        }
        sun_lum_omega += luminance(add) * texel_solid_angle(int(cv.texel / std::size_t(w)), w, h);
    }

    // ground: albedo * E / pi with E the irradiance from the upper hemisphere
    double e[3] = {0.0, 0.0, 0.0};
    for (int y = 0; y < sky_rows; ++y) {
        const double wgt = std::cos(kPi * (y + 0.5) / h) * texel_solid_angle(y, w, h);
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) e[c] += double(img.rgb[3 * (std::size_t(y) * w + x) + c]) * wgt;
    }
    for (int y = sky_rows; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) img.rgb[3 * (std::size_t(y) * w + x) + c] = float(p.ground_albedo * e[c] / kPi);

    double total = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            total += luminance(&img.rgb[3 * (std::size_t(y) * w + x)]) * texel_solid_angle(y, w, h);
    img.sun_power_fraction = total > 0.0 ? sun_lum_omega / total : 0.0;
    return img;
}

void write_sun_sky_exr(const std::string& path, int width, const SunSkyParams& params) {
    SunSkyImage img = render_sun_sky(params, width);
    ImageMetadata meta;
    meta.strings.push_back({"facet:environment", "Preetham et al. 1999 sky with sun disk, kcd/m^2"});
    meta.floats.push_back({"facet:sun_elevation_degrees", float(params.elevation_degrees)});
    meta.floats.push_back({"facet:sun_azimuth_degrees", float(params.azimuth_degrees)});
    meta.floats.push_back({"facet:turbidity", float(params.turbidity)});
    meta.floats.push_back({"facet:ground_albedo", float(params.ground_albedo)});
    meta.floats.push_back({"facet:sun_power_fraction", float(img.sun_power_fraction)});
    write_exr(path, img.width, img.height, img.rgb, meta);
}

EnvironmentMap sun_sky_environment(const SunSkyParams& params, int width) {
    SunSkyImage img = render_sun_sky(params, width);
    std::vector<std::string> warnings;
    return environment_from_pixels(img.width, img.height, std::move(img.rgb), glm::vec3(1.0f), glm::mat3(1.0f),
                                   "sun and sky", warnings);
}

}  // namespace facet
