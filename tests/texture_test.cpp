// Image textures (docs/textures.md): lookups through the real kernels against closed
// forms (bilinear weights, wrap modes, mip levels), sRGB decoding, normal-map frames,
// renders of textured surfaces, and the readers' bindings (JSON, MTL, glTF) and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "host/bvh/bvh.hpp"
#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "host/readers/load_scene.hpp"
#include "host/readers/obj_reader.hpp"
#include "host/render/aov.hpp"
#include "host/render/features.hpp"
#include "host/render/progressive.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "kernels/shared/feature_flags.h"
#include "tests/cl_test_env.hpp"
#include "tests/texture_test_util.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the system's temporary one.
fs::path temp_dir(const std::string& name) {
    fs::path d = fs::temp_directory_path() / ("facet_texture_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// Writes RGB floats (top row first) as a little-endian PFM, which every build reads.
void write_pfm(const fs::path& path, int w, int h, const std::vector<float>& rgb) {
    std::ofstream out(path, std::ios::binary);
    out << "PF\n" << w << " " << h << "\n-1.0\n";
    for (int y = h - 1; y >= 0; --y)  // PFM rows go from the bottom
        out.write(reinterpret_cast<const char*>(&rgb[std::size_t(y) * std::size_t(w) * 3u]),
                  std::streamsize(std::size_t(w) * 3u * sizeof(float)));
}

std::vector<float> rgba_of(const std::vector<float>& rgb) {
    std::vector<float> out;
    for (std::size_t i = 0; i < rgb.size(); i += 3) out.insert(out.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 1.0f});
    return out;
}

// The closed form: wrap an integer coordinate, then bilinear weights around uv * size - 0.5.
int wrap(int i, int n, int mode) {
    if (mode == FC_WRAP_CLAMP) return std::clamp(i, 0, n - 1);
    if (mode == FC_WRAP_MIRROR) {
        int m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return m < n ? m : 2 * n - 1 - m;
    }
    return ((i % n) + n) % n;
}

float bilinear(const std::vector<float>& rgb, int w, int h, int mode, double u, double v, int c) {
    const double x = u * w - 0.5, y = v * h - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double ax = x - x0, ay = y - y0;
    auto at = [&](int xi, int yi) {
        return double(rgb[(std::size_t(wrap(yi, h, mode)) * std::size_t(w) + std::size_t(wrap(xi, w, mode))) * 3u +
                          std::size_t(c)]);
    };
    return float((1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) +
                 ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1)));
}

std::vector<float> random_rgb(int w, int h, unsigned seed, float lo = 0.0f, float hi = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> d(lo, hi);
    std::vector<float> rgb(std::size_t(w) * std::size_t(h) * 3u);
    for (float& v : rgb) v = d(rng);
    return rgb;
}

TEST(Texture, BilinearAndWrapModesMatchClosedForm) {
    const int w = 5, h = 3;
    const std::vector<float> rgb = random_rgb(w, h, 7);
    for (int mode : {FC_WRAP_REPEAT, FC_WRAP_CLAMP, FC_WRAP_MIRROR}) {
        TextureImage t = make_texture(w, h, rgba_of(rgb), mode, mode);
        std::vector<cl_float4> uvl;
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> d(-2.5f, 3.5f);
        // texel centres first (exact texel values), then anywhere, inside and outside [0, 1]
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) uvl.push_back({{(x + 0.5f) / w, (y + 0.5f) / h, 0.0f, 0.0f}});
        for (int i = 0; i < 400; ++i) uvl.push_back({{d(rng), d(rng), 0.0f, 0.0f}});
        const std::vector<cl_float4> got = test::texture_lookup(t, uvl);
        for (std::size_t i = 0; i < uvl.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                const float want = bilinear(rgb, w, h, mode, uvl[i].s[0], uvl[i].s[1], c);
                if (i < std::size_t(w * h)) {
                    ASSERT_NEAR(got[i].s[c], rgb[3 * i + std::size_t(c)], 1e-6f) << "texel centre " << i;
                }
                ASSERT_NEAR(got[i].s[c], want, 2e-5f) << "mode " << mode << " uv " << uvl[i].s[0] << "," << uvl[i].s[1];
            }
    }
}

TEST(Texture, MipLevelsAreBoxFilteredAndTrilinear) {
    const int w = 8, h = 4;
    const std::vector<float> rgb = random_rgb(w, h, 3);
    TextureImage t = make_texture(w, h, rgba_of(rgb));
    ASSERT_EQ(t.levels, 4);  // 8x4, 4x2, 2x1, 1x1
    double mean[3] = {0, 0, 0};
    for (std::size_t i = 0; i < rgb.size(); ++i) mean[i % 3] += double(rgb[i]) / double(w * h);
    // The last level is the image's mean; level 1's texel (0, 0) the mean of its 2x2 block.
    const std::vector<cl_float4> got = test::texture_lookup(
        t, {{{0.3f, 0.6f, 3.0f, 0.0f}}, {{0.125f, 0.25f, 1.0f, 0.0f}}, {{0.3f, 0.6f, 2.5f, 0.0f}}});
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[0].s[c], mean[c], 1e-5) << "1x1 level";
        const std::size_t c3 = std::size_t(c);
        const float block = (rgb[c3] + rgb[3 + c3] + rgb[3 * w + c3] + rgb[3 * w + 3 + c3]) / 4.0f;
        EXPECT_NEAR(got[1].s[c], block, 1e-5) << "level 1 texel centre";
    }
    // lod 2.5: halfway between level 2 (2x1) and level 3 (1x1).
    const std::vector<cl_float4> l2 = test::texture_lookup(t, {{{0.3f, 0.6f, 2.0f, 0.0f}}});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[2].s[c], 0.5 * (double(l2[0].s[c]) + mean[c]), 1e-5);
}

TEST(Texture, SrgbDecodedForColourNotForData) {
    const fs::path dir = temp_dir("srgb");
    // An 8-bit PNG: write_png clips and sRGB-encodes, so byte = round(255 encode(x)).
    std::vector<float> rgb = {0.0f, 0.05f, 0.2f, 0.5f, 0.8f, 1.0f};
    const std::string png = (dir / "ramp.png").string();
    write_png(png, 2, 1, rgb);
    TextureImage color, data;
    try {
        color = load_texture(png, TextureSpace::Color, "test");
        data = load_texture(png, TextureSpace::Data, "test");
    } catch (const Error& e) {
        GTEST_SKIP() << "this build does not read PNG: " << e.what();
    }
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const std::size_t t = (i / 3) * 4 + i % 3;
        const float x = rgb[i];
        const float encoded = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
        const float byte = std::round(255.0f * encoded) / 255.0f;
        const float decoded = byte <= 0.04045f ? byte / 12.92f : std::pow((byte + 0.055f) / 1.055f, 2.4f);
        EXPECT_NEAR(color.texels[t], decoded, 1e-5f) << "colour: sRGB decoded";
        EXPECT_NEAR(data.texels[t], byte, 1e-5f) << "data: the stored value";
    }
    fs::remove_all(dir);
}

// A binary PPM (P6) of w x h pixels with 8-bit (maxval 255) or 16-bit (maxval 65535,
// big-endian) codes, which OpenImageIO reads as an sRGB integer image.
void write_ppm(const fs::path& path, int w, int h, int maxval, const std::vector<int>& codes) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << w << " " << h << "\n" << maxval << "\n";
    for (int c : codes) {
        if (maxval > 255) out.put(char(c >> 8));
        out.put(char(c & 0xff));
    }
}

// 8-bit images are stored in 4 bytes a texel (sRGB colours decoded on the device through
// the table, data as unorm), 16-bit ones as half floats: at texel centres the kernels
// read what the host decoded (exactly for 8 bits, to half precision for 16).
TEST(Texture, CompactFormatsAtTexelCentres) {
    const fs::path dir = temp_dir("formats");
    const int w = 5, h = 3;
    std::mt19937 rng(3);
    std::vector<int> c8, c16;
    for (int i = 0; i < w * h * 3; ++i) {
        c8.push_back(int(rng() % 256));
        c16.push_back(int(rng() % 65536));
    }
    c8[0] = 0;  // the ends of both ranges
    c8[1] = 255;
    c16[0] = 0;
    c16[1] = 65535;
    write_ppm(dir / "b8.ppm", w, h, 255, c8);
    write_ppm(dir / "b16.ppm", w, h, 65535, c16);
    struct Case {
        std::string file;
        TextureSpace space;
        int format;
        std::uint32_t words;  // per texel
        float tolerance;      // relative
    };
    const Case cases[] = {{"b8.ppm", TextureSpace::Color, FC_TEXEL_RGBA8_SRGB, 1, 2e-6f},
                          {"b8.ppm", TextureSpace::Data, FC_TEXEL_RGBA8, 1, 2e-6f},
                          {"b16.ppm", TextureSpace::Color, FC_TEXEL_RGBA16F, 2, 1e-3f},
                          {"b16.ppm", TextureSpace::Data, FC_TEXEL_RGBA16F, 2, 1e-3f}};
    for (const Case& k : cases) {
        SCOPED_TRACE(k.file + (k.space == TextureSpace::Color ? " colour" : " data"));
        TextureImage t;
        try {
            t = load_texture((dir / k.file).string(), k.space, "test");
        } catch (const Error& e) {
            GTEST_SKIP() << "this build does not read PPM: " << e.what();
        }
        EXPECT_EQ(t.format, k.format);
        std::vector<cl_float4> uvl;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) uvl.push_back({{(x + 0.5f) / w, (y + 0.5f) / h, 0.0f, 0.0f}});
        const std::vector<cl_float4> got = test::texture_lookup(t, uvl);
        for (std::size_t i = 0; i < uvl.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                const float want = t.texels[4 * i + std::size_t(c)];
                ASSERT_NEAR(got[i].s[c], want, k.tolerance * want + 1e-7f) << "texel " << i << " channel " << c;
            }
        // The device's bytes: the 256-word sRGB table, then the pyramid in the format.
        Scene scene;
        scene.textures.push_back(t);
        Material m = default_material();
        m.textures.base_color = 0;
        scene.materials.push_back(m);
        scene.shading.push_back(FcTriShading{});
        const std::size_t level0 = std::size_t(w * h), smaller = t.texels.size() / 4u - level0;
        EXPECT_EQ(t.mip_format, FC_TEXEL_RGBA16F);  // the smaller levels in half floats
        EXPECT_EQ(compile_textures(scene).texels.size(), FC_SRGB_TABLE_WORDS + level0 * k.words + smaller * 2u);
    }
    fs::remove_all(dir);
}

// A fine dark checker of sRGB codes 10 and 11 (8 bits): its level 1 is the linear mean of
// the two, which no 8-bit code holds. Re-quantised to 8 bits it read as code 11, 4.9 % too
// bright (issue 28: mip levels "re-quantised to 8 bits with upward rounding"); kept in half
// floats it is within 0.1 %.
TEST(Texture, MipLevelsKeepTheirPrecision) {
    const fs::path dir = temp_dir("mip_precision");
    const int w = 8, h = 8;
    std::vector<int> codes;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) codes.push_back((x + y) % 2 == 0 ? 10 : 11);
    write_ppm(dir / "checker.ppm", w, h, 255, codes);
    TextureImage t;
    try {
        t = load_texture((dir / "checker.ppm").string(), TextureSpace::Color, "test");
    } catch (const Error& e) {
        GTEST_SKIP() << "this build does not read PPM: " << e.what();
    }
    ASSERT_EQ(t.format, FC_TEXEL_RGBA8_SRGB);
    auto decode = [](int code) {
        const float e = float(code) / 255.0f;
        return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
    };
    const float want = 0.5f * (decode(10) + decode(11));
    std::vector<cl_float4> uvl;
    for (int level = 1; level <= 3; ++level) {
        const int n = w >> level;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) uvl.push_back({{(x + 0.5f) / n, (y + 0.5f) / n, float(level), 0.0f}});
    }
    const std::vector<cl_float4> got = test::texture_lookup(t, uvl);
    for (std::size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[i].s[c], want, 1e-3f * want) << "lookup " << i << " channel " << c;
    fs::remove_all(dir);
}

TEST(Texture, NormalMapFrames) {
    ClContext& ctx = test::context();
    const float s = std::sin(0.3f), c = std::cos(0.3f);
    // flat; tilted 0.3 rad toward the tangent (+x); toward the image's top (+y here); scaled by 0
    std::vector<cl_float4> in = {{{0.5f, 0.5f, 1.0f, 1.0f}},
                                 {{0.5f + 0.5f * s, 0.5f, 0.5f + 0.5f * c, 1.0f}},
                                 {{0.5f, 0.5f + 0.5f * s, 0.5f + 0.5f * c, 1.0f}},
                                 {{0.9f, 0.1f, 0.8f, 0.0f}}};
    cl::Kernel k(test::program("kernels/test/texture_kernels.cl"), "normal_map_batch");
    cl::Buffer ib(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(cl_float4), in.data());
    cl::Buffer ob(ctx.context(), CL_MEM_WRITE_ONLY, in.size() * sizeof(cl_float4));
    k.setArg(0, ib);
    k.setArg(1, ob);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(in.size()));
    std::vector<cl_float4> out(in.size());
    ctx.queue().enqueueReadBuffer(ob, CL_TRUE, 0, out.size() * sizeof(cl_float4), out.data());
    EXPECT_EQ(out[0].s[0], 0.0f);
    EXPECT_EQ(out[0].s[1], 0.0f);
    EXPECT_EQ(out[0].s[2], 1.0f) << "a flat normal map changes nothing";
    EXPECT_NEAR(std::atan2(out[1].s[0], out[1].s[2]), 0.3, 1e-5) << "tilted toward dp/du";
    EXPECT_NEAR(out[1].s[1], 0.0f, 1e-6f);
    EXPECT_NEAR(std::atan2(out[2].s[1], out[2].s[2]), 0.3, 1e-5) << "tilted toward the image's top (-dp/dv)";
    EXPECT_NEAR(out[3].s[2], 1.0f, 1e-6f) << "scale 0: the x and y of the map ignored";
}

// A unit-albedo-scale quad [-1, 1]^2 at z = 0 filling an orthographic image, under a
// constant white environment, direct light only: each pixel's expectation is the
// diffuse albedo averaged over it.
Scene lit_quad(int size) {
    Scene scene;
    Material m = make_material("lambert");
    m.diffuse = glm::vec3(1.0f);
    scene.materials.push_back(m);
    scene.material_names.push_back("quad");
    add_quad(scene, glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f), 0);
    scene.environment = constant_environment(glm::vec3(1.0f));
    build_lights(scene);
    scene.camera.eye = glm::vec3(0.0f, 0.0f, 5.0f);
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.projection = FC_PROJECTION_ORTHOGRAPHIC;
    scene.camera.ortho_height = 2.0f;
    scene.settings.width = scene.settings.height = size;
    scene.settings.max_depth = 1;
    return scene;
}

Renderer::Halves render_halves(const Scene& scene, std::uint32_t spp) {
    Bvh bvh = build_bvh(scene.vertices);
    Renderer r(test::context(), scene, bvh);
    render_fixed(r, spp);
    return r.halves();
}

// Per channel: the image's mean and its standard error from the two halves of each pixel.
void image_mean(const Renderer::Halves& h, double mean[3], double sd[3]) {
    const double na = double(h.samples[0]), nb = double(h.samples[1]), nt = na + nb;
    const std::size_t n = h.rgb[0].size() / 3;
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0, var = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = h.rgb[0][3 * i + std::size_t(c)], b = h.rgb[1][3 * i + std::size_t(c)];
            sum += (na * a + nb * b) / nt;
            var += (a - b) * (a - b) * na * nb / (nt * nt);
        }
        mean[c] = sum / double(n);
        sd[c] = std::sqrt(var) / double(n);
    }
}

TEST(Texture, TexturedQuadMeanIsTextureMean) {
    Scene scene = lit_quad(32);
    const std::vector<float> rgb = random_rgb(8, 8, 5, 0.1f, 0.9f);
    scene.textures.push_back(make_texture(8, 8, rgba_of(rgb)));
    scene.materials[0].textures.base_color = 0;
    double want[3] = {0, 0, 0};
    for (std::size_t i = 0; i < rgb.size(); ++i) want[i % 3] += double(rgb[i]) / 64.0;
    double mean[3], sd[3];
    image_mean(render_halves(scene, 64), mean, sd);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(sd[c], 0.0);
        EXPECT_LT(std::fabs(mean[c] - want[c]), 4.0 * sd[c] + 1e-4)
            << "channel " << c << ": mean " << mean[c] << " vs the texture's " << want[c] << " (sd " << sd[c] << ")";
    }
    // Not the factor alone: the texture's mean is far from the untextured albedo 1.
    for (int c = 0; c < 3; ++c) EXPECT_LT(want[c], 0.8);
}

// The albedo AOV of a textured quad is the texture: a 2 x 1 clamped texture, red left
// and blue right, over an orthographic view of the quad.
TEST(Texture, AlbedoAovShowsTheTexture) {
    Scene scene = lit_quad(16);
    const std::vector<float> rgb = {0.8f, 0.1f, 0.1f, 0.1f, 0.2f, 0.7f};
    scene.textures.push_back(make_texture(2, 1, rgba_of(rgb), FC_WRAP_CLAMP, FC_WRAP_CLAMP));
    scene.materials[0].textures.base_color = 0;
    Bvh bvh = build_bvh(scene.vertices);
    const AovImages a = render_aovs(test::context(), scene, bvh, 4);
    for (int y : {2, 8, 13}) {
        const std::size_t left = std::size_t(y) * 16 + 1, right = std::size_t(y) * 16 + 14;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.albedo[3 * left + std::size_t(c)], rgb[std::size_t(c)], 1e-4f) << "left, channel " << c;
            EXPECT_NEAR(a.albedo[3 * right + std::size_t(c)], rgb[3 + std::size_t(c)], 1e-4f) << "right, channel " << c;
        }
    }
}

TEST(Texture, FlatNormalMapEqualsUnmapped) {
    Scene plain = lit_quad(24);
    Material& m = plain.materials[0];
    m = make_material("ggx");
    m.alpha_x = m.alpha_y = 0.2f;
    plain.camera.projection = FC_PROJECTION_PERSPECTIVE;
    plain.camera.eye = glm::vec3(0.5f, 0.3f, 2.0f);
    plain.settings.max_depth = 3;
    Scene mapped = plain;
    std::vector<float> flat;
    for (int i = 0; i < 16; ++i) flat.insert(flat.end(), {0.5f, 0.5f, 1.0f});
    mapped.textures.push_back(make_texture(4, 4, rgba_of(flat)));
    mapped.materials[0].textures.normal = 0;
    const Renderer::Halves a = render_halves(plain, 16), b = render_halves(mapped, 16);
    std::size_t differ = 0;
    for (int k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < a.rgb[k].size(); ++i)
            if (std::fabs(a.rgb[k][i] - b.rgb[k][i]) > 1e-4f * (1.0f + std::fabs(a.rgb[k][i]))) ++differ;
    EXPECT_EQ(differ, 0u) << "pixels that a flat normal map changed";
}

TEST(Texture, MtlMapKdOnObj) {
    const fs::path dir = temp_dir("mtl");
    // A 2x1 texture: left red, right green; the quad's u runs along x.
    write_pfm(dir / "rg.pfm", 2, 1, {0.8f, 0.1f, 0.1f, 0.1f, 0.8f, 0.1f});
    std::ofstream(dir / "quad.mtl") << "newmtl tex\nKd 1 1 1\nmap_Kd -clamp on rg.pfm\n";
    std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl tex\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    Scene scene;
    load_obj((dir / "quad.obj").string(), scene, glm::mat4(1.0f));
    ASSERT_EQ(scene.textures.size(), 1u);
    const std::size_t tex = std::size_t(scene.shading[0].material);
    ASSERT_EQ(scene.material_names[tex], "tex");
    EXPECT_EQ(scene.materials[tex].textures.base_color, 0);
    for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("ignored"), std::string::npos) << w;
    // OBJ's v runs up the image: flipped.
    ASSERT_EQ(scene.texcoords.size(), 2u);
    EXPECT_EQ(scene.texcoords[0].uv[0][1], 1.0f);
    Scene lit = lit_quad(16);
    lit.vertices = scene.vertices;
    lit.shading = scene.shading;
    for (FcTriShading& sh : lit.shading) sh.material = 0;
    lit.texcoords = scene.texcoords;
    lit.textures = scene.textures;
    lit.materials[0].textures = scene.materials[tex].textures;
    build_lights(lit);
    const Renderer::Halves h = render_halves(lit, 16);
    // The left column red, the right green (clamped: no blending across the edge).
    const std::size_t left = 8 * 16 + 0, right = 8 * 16 + 15;
    EXPECT_GT(h.rgb[0][3 * left], 3.0f * h.rgb[0][3 * left + 1]);
    EXPECT_GT(h.rgb[0][3 * right + 1], 3.0f * h.rgb[0][3 * right]);
    fs::remove_all(dir);
}

TEST(Texture, GltfBoxTexturedRendersWithItsTexture) {
    const std::string box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
    if (!fs::exists(box)) GTEST_SKIP() << box << " is missing (Debian's assimp-testmodels)";
    Scene scene = load_scene(box);
    for (const std::string& w : scene.warnings)
        EXPECT_EQ(w.find("baseColorTexture"), std::string::npos) << "no texture ignored: " << w;
    ASSERT_EQ(scene.textures.size(), 1u);
    const TextureImage& t = scene.textures[0];
    double tex[3] = {0, 0, 0};
    for (std::size_t i = 0; i < std::size_t(t.width) * std::size_t(t.height); ++i)
        for (int c = 0; c < 3; ++c) tex[c] += double(t.texels[4 * i + std::size_t(c)]) / double(t.width * t.height);
    // Lit by a directional light from the camera, on black: the box's pixels are those lit.
    scene.environment = no_environment();
    scene.punctual_lights.clear();
    PunctualLight sun;
    sun.type = FC_LIGHT_DIRECTIONAL;
    sun.direction = scene.camera.target - scene.camera.eye;
    scene.punctual_lights.push_back(sun);
    build_lights(scene);
    scene.settings.width = scene.settings.height = 32;
    scene.settings.max_depth = 1;
    Scene plain = scene;
    for (Material& m : plain.materials) m.textures = MaterialTextures{};
    const Renderer::Halves ht = render_halves(scene, 4), hp = render_halves(plain, 4);
    double a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
    for (std::size_t i = 0; i < hp.rgb[0].size(); i += 3) {
        if (!(hp.rgb[0][i] > 0.0f)) continue;  // the background
        for (int c = 0; c < 3; ++c) {
            a[c] += double(ht.rgb[0][i + std::size_t(c)]);
            b[c] += double(hp.rgb[0][i + std::size_t(c)]);
        }
    }
    ASSERT_GT(b[0], 0.0) << "the box is seen";
    // Textured over untextured follows the texture's colour (the white specular layer
    // makes it less saturated): darker in every channel, the same order of channels.
    double ratio[3];
    for (int c = 0; c < 3; ++c) {
        ratio[c] = a[c] / b[c];
        EXPECT_LT(ratio[c], 1.0) << "channel " << c;
        EXPECT_GT(ratio[c], 0.05) << "channel " << c;
    }
    for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
            if (tex[c] > tex[d] + 0.05) {
                EXPECT_GT(ratio[c], ratio[d]) << "channels " << c << " and " << d;
            }
}

TEST(Texture, JsonTexturesAndMissingImagesAreCheckersOrStrictErrors) {
    const fs::path dir = temp_dir("json");
    write_pfm(dir / "grey.pfm", 1, 1, {0.25f, 0.5f, 0.75f});
    auto scene_with = [&](const std::string& textures) {
        const fs::path p = dir / "scene.json";
        std::ofstream(p)
            << R"({"materials": {"wood": {"model": "ggx", "textures": )" << textures
            << R"(}}, "shapes": [{"type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0], "edge2": [0, 2, 0], "material": "wood"}]})";
        return p.string();
    };
    Scene ok = load_scene(scene_with(
        R"({"diffuse": "grey.pfm", "roughness": {"file": "grey.pfm", "channel": "g", "wrap": "mirror"}, "normal_scale": 0.5})"));
    ASSERT_EQ(ok.textures.size(), 2u) << "one image, read as colour and as data";
    EXPECT_EQ(ok.materials[0].textures.roughness_channel, 1);
    EXPECT_EQ(ok.textures[1].wrap_u, FC_WRAP_MIRROR);
    EXPECT_EQ(scene_features(ok) & (1u << 9), 1u << 9) << "the textures feature";
    // A missing or corrupt image is a warning naming it and its material: a colour shows
    // the magenta and black checker, data (a normal map) is left out; --strict refuses both.
    auto warnings_of = [](const Scene& s) {
        std::string all;
        for (const std::string& w : s.warnings) all += w + "\n";
        return all;
    };
    const Scene missing = load_scene(scene_with(R"({"diffuse": "no_such.png"})"));
    ASSERT_EQ(missing.textures.size(), 1u);
    EXPECT_EQ(missing.materials[0].textures.base_color, 0);
    EXPECT_EQ(missing.textures[0].texels[0], 1.0f) << "magenta";
    EXPECT_EQ(missing.textures[0].texels[1], 0.0f);
    std::string w = warnings_of(missing);
    EXPECT_NE(w.find("no_such.png"), std::string::npos) << w;
    EXPECT_NE(w.find("wood"), std::string::npos) << w;
    EXPECT_NE(w.find("checker"), std::string::npos) << w;
    try {
        load_scene(scene_with(R"({"diffuse": "no_such.png"})"), "", true);
        FAIL() << "a missing image must fail with --strict";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no_such.png"), std::string::npos) << what;
        EXPECT_NE(what.find("--strict"), std::string::npos) << what;
    }
    std::ofstream(dir / "corrupt.pfm") << "PF\n4 4\n-1.0\nshort";
    const Scene corrupt = load_scene(scene_with(R"({"normal": "corrupt.pfm"})"));
    EXPECT_EQ(corrupt.materials[0].textures.normal, -1) << "left out";
    EXPECT_NE(warnings_of(corrupt).find("corrupt.pfm"), std::string::npos) << warnings_of(corrupt);
    std::ofstream(dir / "m.mtl") << "newmtl cow\nmap_Kd missing.png\n";
    std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl cow\nf 1 2 3\n";
    w = warnings_of(load_scene((dir / "m.obj").string()));
    EXPECT_NE(w.find("missing.png"), std::string::npos) << w;
    EXPECT_NE(w.find("cow"), std::string::npos) << w;
    EXPECT_NE(w.find("m.mtl:2"), std::string::npos) << w;
    try {
        load_scene((dir / "m.obj").string(), "", true);
        FAIL() << "a missing map_Kd must fail with --strict";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
    }
    // A missing material library, only a warning before, is refused too.
    std::ofstream(dir / "nolib.obj") << "mtllib absent.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_NE(warnings_of(load_scene((dir / "nolib.obj").string())).find("absent.mtl"), std::string::npos);
    try {
        load_scene((dir / "nolib.obj").string(), "", true);
        FAIL() << "a missing MTL must fail with --strict";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("absent.mtl"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

TEST(Texture, SpecialisedProgramWithoutTexturesLeavesThemOut) {
    Scene plain = lit_quad(4);
    EXPECT_EQ(scene_features(plain) & (1u << 9), 0u);
    Bvh bvh = build_bvh(plain.vertices);
    Renderer r(test::context(), plain, bvh);
    EXPECT_NE(r.build().source.text.find("#define FC_HAS_TEXTURES 0\n"), std::string::npos);
    DeviceTextures d = compile_textures(plain);
    EXPECT_EQ(d.texcoords.size(), 1u) << "no uvs uploaded for a scene without textures";
}

TEST(Texture, TooLargeForTheDeviceIsRefused) {
    Scene scene = lit_quad(4);
    const int side = 1200;  // 1200^2 x 16 bytes x 4/3: 30 MiB of texels
    scene.textures.push_back(make_texture(side, side, std::vector<float>(std::size_t(side) * side * 4u, 0.5f)));
    scene.materials[0].textures.base_color = 0;
    Bvh bvh = build_bvh(scene.vertices);
    const char* sel = std::getenv("FACET_TEST_DEVICE");
    ::setenv("FACET_DEVICE_MEMORY_MIB", "16", 1);
    ClContext small = ClContext::create(sel ? sel : "");
    ::unsetenv("FACET_DEVICE_MEMORY_MIB");
    try {
        Renderer r(small, scene, bvh);
        FAIL() << "a texture larger than the device's memory must be refused";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("textures"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("MiB"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace facet
