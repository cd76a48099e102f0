// facet's own sun-and-sky environment: a stiff image-based-lighting case without
// third-party data (docs/environment.md).
//
// Sky: the analytic model of Preetham, Shirley and Smits 1999, "A Practical Analytic
// Model for Daylight" (SIGGRAPH 99): Perez et al.'s luminance distribution with
// turbidity-dependent coefficients, zenith luminance and zenith chromaticity (their
// appendix A.2), xyY converted to linear Rec. 709 RGB.
// Sun: a disk of angular radius 0.2666 deg whose luminance is the luminous solar constant
// (128 klx) over the disk's solid angle, attenuated per channel along Kasten and Young's
// 1989 air mass by Rayleigh scattering and Angstrom aerosol extinction (Preetham's
// appendix A.1, after Iqbal 1983). It is drawn area-weighted (supersampled) into the few
// texels it covers, then renormalised so that its power in the map is exactly that of
// the disk above the horizon.
// Ground: a grey Lambertian plane of albedo `ground_albedo` lit by the map's upper
// hemisphere (sun included): radiance albedo * E / pi.
// Units: luminance in kcd/m^2 (a clear midday zenith is ~5, the sun ~1e6), i.e. the RGB
// values are radiance in units where Rec. 709 luminance Y = 1 means 1000 cd/m^2.
// Below the horizon (elevation < 0.5 deg) Preetham's model does not apply: the sky is
// that of a sun at 0.5 deg dimmed by 10^(elevation / 2.5 deg), a rough fit of twilight's
// fall of about a decade per 2.5 deg of depression, and the sun is hidden.
#pragma once

#include <string>
#include <vector>

#include "host/scene/environment_map.hpp"

namespace facet {

struct SunSkyParams {
    double elevation_degrees = 25.0;  // sun above the horizon, [-10, 90]
    // sun direction around the vertical: degrees to the right of the map's centre (+z) as
    // seen from inside, i.e. the sun's column is u = 0.5 + azimuth / 360
    double azimuth_degrees = 40.0;
    double turbidity = 3.0;  // [1.7, 10]: 2 very clear, 3 clear, 6 hazy
    double ground_albedo = 0.1;
    double sun_radius_degrees = 0.2666;
};

struct SunSkyImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;                     // 3 floats a texel, top row first
    double sun_power_fraction = 0.0;            // share of the sun in the map's luminance x solid angle
    double sun_direction[3] = {0.0, 1.0, 0.0};  // map frame
};

// Renders the map, width x width / 2 texels (width even, >= 8). Throws facet::Error on
// parameters out of range.
SunSkyImage render_sun_sky(const SunSkyParams& params, int width);

// Writes the map as a 32-bit float EXR with the parameters as metadata.
void write_sun_sky_exr(const std::string& path, int width, const SunSkyParams& params);

// The map as an environment (identity rotation, scale 1).
EnvironmentMap sun_sky_environment(const SunSkyParams& params, int width);

}  // namespace facet
