// film/film_validate.hpp: a film whose checksum holds but whose samples no render can
// have written (NaN, a negative image, counts that do not add up) is refused by
// read_film, naming the film and the pixel; a film ending at sample 2^32 reads back.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "host/film/film_layout.hpp"
#include "host/film/film_state.hpp"
#include "host/film/film_validate.hpp"
#include "host/render/film_identity.hpp"
#include "host/bvh/bvh.hpp"
#include "host/scene/scene.hpp"
#include "tests/lit_scene.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

using test::error_of;

// A 4x3 film of samples 0-5 (3 in each half), every channel 1 and nothing rejected.
FilmState plain_film(SampleRanges samples = {{0, 6}}) {
    Scene scene = test::lit_scene(4);
    scene.settings.height = 3;
    std::vector<float> sums(film_floats(12), 1.0f);
    for (std::size_t i = 3; i < film_rgba_floats(12); i += 4) sums[i] = 0.0f;
    return make_film(scene, film_identity(scene, build_bvh(scene.vertices)), samples, 1.0, sums);
}

// The message read_film gives for `film` written to a file (empty when it reads).
std::string read_error(const FilmState& film) {
    test::TempDir dir;
    const std::string path = dir.path("bad.film");
    write_film(path, film);
    return error_of([&] { read_film(path); });
}

TEST(FilmValidate, AcceptsWhatARenderWrites) {
    EXPECT_EQ(read_error(plain_film()), "");
    FilmState f = plain_film();
    f.sums[4 * 5] = -0.5f;     // a Mitchell filter's negative lobe darkens one pixel below zero
    f.sums[4 * 5 + 3] = 2.0f;  // two of its three even samples rejected
    EXPECT_EQ(read_error(f), "");
}

TEST(FilmValidate, RefusesNanNegativeAndInconsistentCounts) {
    FilmState nan = plain_film();
    nan.sums[4 * 6 + 1] = std::numeric_limits<float>::quiet_NaN();
    std::string msg = read_error(nan);
    EXPECT_NE(msg.find("bad.film: pixel (2, 1) of the even-sample half has the green nan: not a finite number"),
              std::string::npos)
        << msg;

    FilmState inf = plain_film();
    inf.sums[12 * 4 + 0] = std::numeric_limits<float>::infinity();
    msg = read_error(inf);
    EXPECT_NE(msg.find("odd-sample half has the red inf"), std::string::npos) << msg;

    FilmState negative = plain_film();
    for (std::size_t i = 0; i < 12; ++i) negative.sums[4 * i + 2] = -1.0f;
    msg = read_error(negative);
    EXPECT_NE(msg.find("bad.film: the even-sample half's blue light adds up to -12, below zero"), std::string::npos)
        << msg;

    FilmState too_many = plain_film();
    too_many.sums[3] = 4.0f;  // 4 rejected of the 3 even samples
    msg = read_error(too_many);
    EXPECT_NE(msg.find("more than the 3 samples the half holds"), std::string::npos) << msg;

    FilmState fraction = plain_film();
    fraction.sums[3] = 0.5f;
    EXPECT_NE(read_error(fraction).find("a non-negative whole number"), std::string::npos);

    FilmState empty_half = plain_film({{0, 1}});  // sample 0 only: the odd half holds none
    msg = read_error(empty_half);
    EXPECT_NE(msg.find("odd-sample half has the red 1: but the half holds no samples"), std::string::npos) << msg;

    // The second moments (film_layout.hpp): sums of squares
    FilmState square = plain_film();
    square.sums[film_rgba_floats(12) + 12 + 5] = -2.0f;  // the odd half's pixel (1, 1)
    msg = read_error(square);
    EXPECT_NE(msg.find("bad.film: pixel (1, 1) of the odd-sample half has the second moment -2: a sum of squares"),
              std::string::npos)
        << msg;
    square.sums[film_rgba_floats(12) + 12 + 5] = std::numeric_limits<float>::infinity();
    EXPECT_NE(read_error(square).find("second moment inf"), std::string::npos);
}

TEST(FilmValidate, FilmEndingAtSample2To32ReadsBack) {
    const std::uint64_t end = std::uint64_t(1) << 32;
    EXPECT_EQ(read_error(plain_film({{end - 6, end}})), "");
    EXPECT_NE(read_error(plain_film({{end - 5, end + 1}})).find("sample range"), std::string::npos);
}

}  // namespace
}  // namespace facet
