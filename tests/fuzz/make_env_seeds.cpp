// Writes small environment-map seeds for fuzz_env_map into a folder: generated EXR
// files (several compressions, pixel types and channel counts) and Radiance .hdr files
// (flat and run-length encoded), and, for each map given after the folder, a copy
// shrunk to 16x8 texels (box filter), e.g. from ../shared/assets.
//   make_env_seeds OUT_DIR [map.exr|map.hdr ...]
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "host/error.hpp"
#include "host/image/image_io.hpp"

namespace {

bool write(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type, const char* compression,
           const std::vector<float>& px) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return false;
    OIIO::ImageSpec spec(w, h, channels, type);
    if (compression) spec.attribute("compression", compression);
    return out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close();
}

std::vector<float> gradient(int w, int h, int channels) {
    std::vector<float> px(std::size_t(w) * h * channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                px[(std::size_t(y) * w + x) * channels + c] = float(x + 1) / float(w) * float(c + 1) + 0.1f * float(y);
    return px;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: make_env_seeds OUT_DIR [maps...]\n");
        return 2;
    }
    const std::string dir = argv[1];
    int failures = 0;
    auto check = [&](bool ok, const std::string& what) {
        if (!ok) {
            std::fprintf(stderr, "make_env_seeds: %s failed: %s\n", what.c_str(), OIIO::geterror().c_str());
            ++failures;
        }
    };
    struct Exr {
        const char* name;
        int w, h, channels;
        OIIO::TypeDesc type;
        const char* compression;
    };
    const Exr exrs[] = {
        {"gen_8x4_rgb_half_zip.exr", 8, 4, 3, OIIO::TypeDesc::HALF, "zip"},
        {"gen_8x4_rgba_float_none.exr", 8, 4, 4, OIIO::TypeDesc::FLOAT, "none"},
        {"gen_16x8_rgb_half_piz.exr", 16, 8, 3, OIIO::TypeDesc::HALF, "piz"},
        {"gen_4x2_y_float_rle.exr", 4, 2, 1, OIIO::TypeDesc::FLOAT, "rle"},
        {"gen_6x2_rgb_half_zips.exr", 6, 2, 3, OIIO::TypeDesc::HALF, "zips"},
        {"gen_1x1_rgb_float_none.exr", 1, 1, 3, OIIO::TypeDesc::FLOAT, "none"},
    };
    for (const Exr& e : exrs)
        check(write(dir + "/" + e.name, e.w, e.h, e.channels, e.type, e.compression, gradient(e.w, e.h, e.channels)),
              e.name);
    // Radiance: 4 wide is stored flat, 16 wide run-length encoded.
    check(write(dir + "/gen_4x2.hdr", 4, 2, 3, OIIO::TypeDesc::FLOAT, nullptr, gradient(4, 2, 3)), "gen_4x2.hdr");
    check(write(dir + "/gen_16x8.hdr", 16, 8, 3, OIIO::TypeDesc::FLOAT, nullptr, gradient(16, 8, 3)), "gen_16x8.hdr");
    // Special values: negative, NaN and infinite texels (sanitised by facet).
    std::vector<float> odd = gradient(8, 4, 3);
    odd[0] = -1.0f;
    odd[4] = NAN;
    odd[8] = INFINITY;
    check(write(dir + "/gen_8x4_special_float.exr", 8, 4, 3, OIIO::TypeDesc::FLOAT, "none", odd), "special");

    for (int i = 2; i < argc; ++i) {
        const std::string src = argv[i];
        try {
            facet::ImageRGB img = facet::read_image(src);
            const int w = 16, h = 8;
            std::vector<float> small(std::size_t(w) * h * 3, 0.0f);
            std::vector<int> count(std::size_t(w) * h, 0);
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x) {
                    const std::size_t d = std::size_t(y * h / img.height) * w + std::size_t(x * w / img.width);
                    for (int c = 0; c < 3; ++c) small[3 * d + c] += img.rgb[(std::size_t(y) * img.width + x) * 3 + c];
                    ++count[d];
                }
            for (std::size_t d = 0; d < count.size(); ++d)
                for (int c = 0; c < 3; ++c) small[3 * d + c] /= float(std::max(count[d], 1));
            std::string base = src.substr(src.find_last_of('/') + 1);
            const bool hdr = base.size() > 4 && base.substr(base.size() - 4) == ".hdr";
            const std::string out = dir + "/asset_" + base;
            check(write(out, w, h, 3, hdr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF, hdr ? nullptr : "zip", small),
                  out);
        } catch (const facet::Error& e) {
            std::fprintf(stderr, "make_env_seeds: skipping %s: %s\n", src.c_str(), e.what());
        }
    }
    return failures == 0 ? 0 : 1;
}
