// Intel Open Image Denoise through host/denoise/oidn.hpp: found where asked, refused
// with the library named when it cannot be loaded, and, where it is installed (pyoidn,
// or $FACET_OIDN), denoising each half of a noisy flat image. Suite Oidn.
#include <gtest/gtest.h>

#include <random>

#include "host/denoise/oidn.hpp"
#include "host/error.hpp"

#include "tests/denoise_test_util.hpp"

namespace facet {
namespace {

constexpr std::uint32_t kSize = 64;
constexpr std::size_t kPixels = std::size_t(kSize) * kSize;

AovImages flat_features() { return test::flat_features(kPixels); }

FilmHalves noisy_flat(float sigma) {
    std::mt19937 rng(3);
    std::normal_distribution<float> noise(0.0f, sigma);
    FilmHalves h;
    h.samples[0] = h.samples[1] = 8;
    for (int k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < 3 * kPixels; ++i) h.rgb[k].push_back(0.5f + noise(rng));
    return h;
}

TEST(Oidn, GivenLibraryIsTaken) {
    EXPECT_EQ(find_oidn("/some/libOpenImageDenoise.so.2"), "/some/libOpenImageDenoise.so.2");
}

TEST(Oidn, UnloadableLibraryIsNamed) {
    try {
        denoise_oidn("/nonexistent/libOpenImageDenoise.so.2", kSize, kSize, noisy_flat(0.1f), flat_features());
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/libOpenImageDenoise.so.2: cannot load"), std::string::npos)
            << e.what();
    }
}

TEST(Oidn, DenoisesEachHalfWhereInstalled) {
    const std::string library = find_oidn("");
    if (library.empty()) GTEST_SKIP() << "Intel Open Image Denoise not installed (pip install pyoidn, or FACET_OIDN)";
    const FilmHalves h = noisy_flat(0.1f);
    const DenoisedImage d = denoise_oidn(library, kSize, kSize, h, flat_features());
    ASSERT_EQ(d.rgb.size(), 3 * kPixels);
    double noisy = 0.0, denoised = 0.0;
    for (std::size_t i = 0; i < 3 * kPixels; ++i) {
        noisy += double(h.rgb[0][i] - 0.5f) * double(h.rgb[0][i] - 0.5f);
        denoised += double(d.half[0][i] - 0.5f) * double(d.half[0][i] - 0.5f);
    }
    EXPECT_LT(denoised, noisy / 10.0);
}

}  // namespace
}  // namespace facet
