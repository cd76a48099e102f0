// film/film_state.hpp and Renderer::restore: a film saved and read back is the same
// film, a corrupt or foreign one is refused, and N/2 samples + a resume of N/2 more
// give the image of one uninterrupted render of N samples.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "host/film/film_layout.hpp"
#include "host/bvh/bvh.hpp"
#include "host/error.hpp"
#include "host/film/film_state.hpp"
#include "host/render/film_identity.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/scene.hpp"
#include "tests/cl_test_env.hpp"
#include "tests/lit_scene.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

using test::error_of;
using test::lit_scene;

FilmState some_film(int w, int h) {
    Scene scene = lit_scene(w);
    scene.settings.height = h;
    std::vector<float> sums(film_floats(std::size_t(w) * std::size_t(h)));
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i] = i % 4 == 3 ? 0.0f : float(i) * 0.25f;  // none rejected
    return make_film(scene, film_identity(scene, build_bvh(scene.vertices)), 7, 1.5, sums);
}

TEST(FilmState, RoundTrip) {
    test::TempDir dir;
    FilmState a = some_film(5, 3);
    a.seed = 99;
    write_film(dir.path("a.film"), a);
    FilmState b = read_film(dir.path("a.film"));
    EXPECT_EQ(b.scene_path, a.scene_path);
    EXPECT_EQ(b.scene_hash, a.scene_hash);
    EXPECT_EQ(b.width, 5);
    EXPECT_EQ(b.height, 3);
    EXPECT_EQ(b.seed, 99u);
    EXPECT_EQ(b.max_depth, a.max_depth);
    EXPECT_EQ(b.rr_depth, a.rr_depth);
    EXPECT_EQ(b.strategy, a.strategy);
    EXPECT_EQ(b.sampler, a.sampler);
    EXPECT_EQ(b.spp, 7u);
    EXPECT_EQ(b.render_seconds, 1.5);
    ASSERT_EQ(b.sums.size(), a.sums.size());
    EXPECT_EQ(0, std::memcmp(a.sums.data(), b.sums.data(), a.sums.size() * sizeof(float)));
}

TEST(FilmState, RefusesCorruptTruncatedAndForeignFiles) {
    test::TempDir dir;
    const std::string path = dir.path("a.film");
    write_film(path, some_film(4, 4));
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::string flipped = bytes;
    flipped[flipped.size() - 5] ^= 0x40;
    EXPECT_NE(error_of([&] { read_film(dir.write("flip.film", flipped)); }).find("checksum"), std::string::npos);
    EXPECT_NE(error_of([&] { read_film(dir.write("cut.film", bytes.substr(0, bytes.size() - 8))); }).find("truncated"),
              std::string::npos);
    EXPECT_NE(error_of([&] { read_film(dir.write("text.film", "hello, world\n")); }).find("not a facet film"),
              std::string::npos);
    EXPECT_NE(error_of([&] { read_film(dir.path("none.film")); }).find("none.film"), std::string::npos);
    EXPECT_NE(error_of([&] { read_film("/dev/zero"); }).find("not a regular file"), std::string::npos);
}

TEST(FilmState, RefusesAnotherSceneOrSettings) {
    Scene scene = lit_scene(6);
    const std::uint64_t hash = film_identity(scene, build_bvh(scene.vertices));
    FilmState film = make_film(scene, hash, 4, 0.1, std::vector<float>(film_floats(36)));
    EXPECT_EQ(error_of([&] { check_film_matches(film, "f.film", scene, hash); }), "");

    Scene other = scene;
    other.camera.eye.x += 0.01f;
    EXPECT_NE(film_identity(other, build_bvh(other.vertices)), hash);
    EXPECT_NE(error_of([&] {
                  check_film_matches(film, "f.film", other, film_identity(other, build_bvh(other.vertices)));
              }).find("another scene"),
              std::string::npos);
    other = scene;
    other.materials[0].diffuse[0] = 0.5f;
    EXPECT_NE(film_identity(other, build_bvh(other.vertices)), hash);
    for (auto change :
         {+[](RenderSettings& s) { s.width = 7; }, +[](RenderSettings& s) { s.seed = 3; },
          +[](RenderSettings& s) { s.max_depth = 2; }, +[](RenderSettings& s) { s.strategy = FC_STRATEGY_BSDF; },
          +[](RenderSettings& s) { s.sampler = FC_SAMPLER_INDEPENDENT; }}) {
        Scene changed = scene;
        change(changed.settings);
        const std::string msg = error_of([&] { check_film_matches(film, "f.film", changed, hash); });
        EXPECT_NE(msg.find("f.film"), std::string::npos) << msg;
    }
}

TEST(FilmState, ResumeEqualsOneUninterruptedRender) {
    test::TempDir dir;
    Scene scene = lit_scene(16);
    Bvh bvh = build_bvh(scene.vertices);
    const std::uint64_t hash = film_identity(scene, build_bvh(scene.vertices));

    Renderer whole(test::context(), scene, bvh);
    whole.render(3);
    whole.render(5);
    std::vector<float> want = whole.image();

    {
        Renderer first(test::context(), scene, bvh);
        first.render(3);
        write_film(dir.path("half.film"), make_film(scene, hash, first.stats().samples_per_pixel,
                                                    first.stats().render_seconds, first.accumulation()));
    }
    FilmState film = read_film(dir.path("half.film"));
    check_film_matches(film, "half.film", scene, hash);
    Renderer second(test::context(), scene, bvh);
    second.restore(film.sums, film.spp, film.render_seconds);
    second.render(5);
    EXPECT_EQ(second.stats().samples_per_pixel, 8u);
    std::vector<float> got = second.image();
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got[i], want[i], 1e-5f * std::max(1.0f, want[i])) << i;
    Renderer::Halves h = second.halves();
    EXPECT_EQ(h.samples[0], 4u);
    EXPECT_EQ(h.samples[1], 4u);
    // New sample indices: continuing at index 0 would repeat samples 0..2 and differ.
    Renderer repeated(test::context(), scene, bvh);
    repeated.restore(film.sums, 0, 0.0);
    repeated.render(5);
    std::vector<float> wrong = repeated.image();
    double worst = 0.0;
    for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(double(wrong[i]) - double(want[i])));
    EXPECT_GT(worst, 1e-3) << "the test scene is too smooth to tell sample indices apart";
}

}  // namespace
}  // namespace facet
