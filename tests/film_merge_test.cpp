// film/sample_ranges.hpp, film/film_merge.hpp and --samples-from: films of disjoint
// sample ranges add up to the film of one render of all the samples; overlapping
// ranges, other scenes and other settings are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "host/bvh/bvh.hpp"
#include "host/film/film_halves.hpp"
#include "host/film/film_layout.hpp"
#include "host/film/film_merge.hpp"
#include "host/render/film_identity.hpp"
#include "host/render/device_group.hpp"
#include "host/render/progressive.hpp"
#include "host/util/fnv.hpp"
#include "tests/lit_scene.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

using test::error_of;

// A film of `scene` holding samples [first, first + spp), rendered on the default device.
FilmState render_film(const Scene& scene, const Bvh& bvh, std::uint64_t first, std::uint64_t spp, std::uint32_t pass) {
    const char* sel = std::getenv("FACET_TEST_DEVICE");
    DeviceGroup group({ClContext::create(sel ? sel : "")}, scene, bvh, false, first);
    render_fixed(group, spp, pass);
    return make_film(scene, film_identity(scene, build_bvh(scene.vertices)), group.samples(),
                     group.stats().render_seconds, group.accumulation());
}

std::vector<float> image_of(const FilmState& f) { return film_mean(film_halves(f)); }

TEST(FilmMerge, SampleRangesCountHalvesAndOverlaps) {
    const SampleRanges r{{8, 12}, {0, 3}, {3, 5}};
    EXPECT_EQ(sample_count(r), 9u);
    EXPECT_EQ(even_samples(r), 5u);  // 0 2 4 8 10
    EXPECT_EQ(odd_samples(r), 4u);   // 1 3 9 11
    EXPECT_EQ(normalized(r), (SampleRanges{{0, 5}, {8, 12}}));
    EXPECT_EQ(describe(r), "0-4, 8-11");
    EXPECT_EQ(next_sample(r), 12u);
    EXPECT_FALSE(first_overlap(r));
    EXPECT_EQ(first_overlap(SampleRanges{{0, 5}, {8, 12}, {4, 6}}), 4u);
    EXPECT_EQ(describe({}), "none");
}

TEST(FilmMerge, MergedPartialRendersEqualOneRender) {
    test::TempDir dir;
    const Scene scene = test::lit_scene(16);
    const Bvh bvh = build_bvh(scene.vertices);
    const FilmState whole = render_film(scene, bvh, 0, 12, 3);
    // Three tasks of a farm, written and read back as files, merged out of order.
    write_film(dir.path("a.film"), render_film(scene, bvh, 0, 5, 2));
    write_film(dir.path("b.film"), render_film(scene, bvh, 5, 4, 4));
    write_film(dir.path("c.film"), render_film(scene, bvh, 9, 3, 1));
    const std::vector<std::string> paths{dir.path("c.film"), dir.path("a.film"), dir.path("b.film")};
    std::vector<FilmState> films;
    for (const std::string& p : paths) films.push_back(read_film(p));
    const FilmState merged = merge_films(films, paths);
    EXPECT_EQ(merged.spp, 12u);
    EXPECT_EQ(merged.samples, (SampleRanges{{0, 12}}));
    const std::vector<float> want = image_of(whole), got = image_of(merged);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got[i], want[i], 1e-5f * std::max(1.0f, want[i])) << i;
    const FilmHalves hw = film_halves(whole), hm = film_halves(merged);
    EXPECT_EQ(hm.samples[0], hw.samples[0]);
    EXPECT_EQ(hm.samples[1], hw.samples[1]);
    // A part alone is another image: the ranges hold different samples.
    double worst = 0.0;
    const std::vector<float> part = image_of(films[1]);
    for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(double(part[i]) - double(want[i])));
    EXPECT_GT(worst, 1e-3);
}

TEST(FilmMerge, RefusesOverlapsOtherScenesAndSettings) {
    const Scene scene = test::lit_scene(6);
    const std::uint64_t hash = film_identity(scene, build_bvh(scene.vertices));
    const std::vector<float> sums(film_floats(36), 1.0f);
    const FilmState a = make_film(scene, hash, SampleRanges{{0, 8}}, 1.0, sums);
    const FilmState b = make_film(scene, hash, SampleRanges{{6, 10}}, 1.0, sums);
    std::string msg = error_of([&] { merge_films({a, b}, {"a.film", "b.film"}); });
    EXPECT_NE(msg.find("a.film and b.film both hold sample 6"), std::string::npos) << msg;
    FilmState other = make_film(scene, hash ^ 1, SampleRanges{{8, 10}}, 1.0, sums);
    msg = error_of([&] { merge_films({a, other}, {"a.film", "o.film"}); });
    EXPECT_NE(msg.find("o.film: the film was rendered from another scene (identity "), std::string::npos) << msg;
    for (auto change : {+[](FilmState& f) { f.seed += 1; }, +[](FilmState& f) { f.max_depth += 1; },
                        +[](FilmState& f) { f.rr_depth += 1; }, +[](FilmState& f) { f.strategy += 1; },
                        +[](FilmState& f) { f.sampler += 1; }}) {
        FilmState c = make_film(scene, hash, SampleRanges{{8, 10}}, 1.0, sums);
        change(c);
        msg = error_of([&] { merge_films({a, c}, {"a.film", "c.film"}); });
        EXPECT_NE(msg.find("cannot be combined"), std::string::npos) << msg;
    }
    Scene wide = scene;
    wide.settings.width = 7;
    FilmState w = make_film(wide, hash, SampleRanges{{8, 10}}, 1.0, std::vector<float>(film_floats(42)));
    EXPECT_NE(error_of([&] { merge_films({a, w}, {"a.film", "w.film"}); }).find("size of 7x6"), std::string::npos);
    EXPECT_EQ(error_of([&] {
                  merge_films({a, make_film(scene, hash, SampleRanges{{8, 10}}, 1.0, sums)}, {"a", "b"});
              }),
              "");
}

// The bytes of `film` in an older format: version 1 (no "samples") or 2, both without
// second moments (RGBA sums only).
std::string legacy_film_bytes(const FilmState& film, std::uint32_t version) {
    test::TempDir dir;
    write_film(dir.path("f.film"), film);
    std::string bytes;
    {
        std::ifstream in(dir.path("f.film"), std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::uint32_t header_bytes = 0;
    std::memcpy(&header_bytes, bytes.data() + 12, 4);
    nlohmann::json header = nlohmann::json::parse(bytes.substr(16, header_bytes));
    if (version == 1) header.erase("samples");
    header.erase("second_moments");
    const std::size_t floats = film_rgba_floats(std::size_t(film.width) * std::size_t(film.height));
    Fnv1a hash;
    hash.bytes(film.sums.data(), floats * sizeof(float));
    header["payload_floats"] = floats;
    header["payload_fnv1a64"] = fmt::format("{:016x}", hash.h);
    const std::string text = header.dump() + "\n";
    const std::uint32_t words[2] = {version, std::uint32_t(text.size())};
    return bytes.substr(0, 8) + std::string(reinterpret_cast<const char*>(words), 8) + text +
           std::string(reinterpret_cast<const char*>(film.sums.data()), floats * sizeof(float));
}

TEST(FilmMerge, RangesSurviveTheFileAndVersionOneReadsAsFromZero) {
    test::TempDir dir;
    const Scene scene = test::lit_scene(4);
    FilmState f = make_film(scene, 1, SampleRanges{{10, 14}, {20, 21}}, 1.0, std::vector<float>(film_floats(16)));
    write_film(dir.path("f.film"), f);
    const FilmState g = read_film(dir.path("f.film"));
    EXPECT_EQ(g.samples, (SampleRanges{{10, 14}, {20, 21}}));
    EXPECT_EQ(g.spp, 5u);
    // A version 1 film (no "samples"): indices [0, spp).
    const FilmState old = read_film(dir.write("v1.film", legacy_film_bytes(f, 1)));
    EXPECT_EQ(old.samples, (SampleRanges{{0, 5}}));
}

// Films of versions 1 and 2 hold no second moments: they read with zeros there and
// say so, and so does a merge with one of them (the denoiser then reads the pair's
// variance: denoise/denoise_variance.hpp); a version 3 film keeps its own.
TEST(FilmMerge, SecondMomentsAreKeptOrKnownMissing) {
    test::TempDir dir;
    const Scene scene = test::lit_scene(4);
    std::vector<float> sums(film_floats(16), 1.0f);
    for (std::size_t i = 3; i < film_rgba_floats(16); i += 4) sums[i] = 0.0f;
    const FilmState a = make_film(scene, 1, SampleRanges{{4, 8}}, 1.0, sums);
    const FilmState b = make_film(scene, 1, SampleRanges{{0, 4}}, 1.0, sums);  // as version 1 reads it
    write_film(dir.path("a.film"), a);
    const FilmState a3 = read_film(dir.path("a.film"));
    EXPECT_TRUE(a3.second_moments);
    EXPECT_EQ(a3.sums, sums);
    EXPECT_EQ(film_halves(a3).square[1], std::vector<float>(16, 0.5f));  // 2 odd samples summing to 1
    for (std::uint32_t version : {1u, 2u}) {
        const FilmState old = read_film(dir.write("old.film", legacy_film_bytes(b, version)));
        EXPECT_FALSE(old.second_moments) << "version " << version;
        ASSERT_EQ(old.sums.size(), film_floats(16));
        EXPECT_TRUE(
            std::equal(old.sums.begin(), old.sums.begin() + std::ptrdiff_t(film_rgba_floats(16)), sums.begin()));
        EXPECT_TRUE(std::all_of(old.sums.begin() + std::ptrdiff_t(film_rgba_floats(16)), old.sums.end(),
                                [](float v) { return v == 0.0f; }));
        EXPECT_TRUE(film_halves(old).square[0].empty());
        const FilmState merged = merge_films({a3, old}, {"a.film", "old.film"});
        EXPECT_FALSE(merged.second_moments);
        EXPECT_TRUE(film_halves(merged).square[0].empty());
    }
    EXPECT_TRUE(merge_films({a3, b}, {"a.film", "b.film"}).second_moments);
}

}  // namespace
}  // namespace facet
