// facet_film_ztest A.film B.film: are two independent renders of one scene (other seeds,
// other devices) estimates of the same image? Each film's two halves give each pixel's
// variance of the mean without a reference (film/error_metrics.hpp). Per channel:
//   z = sum(a - b) / sqrt(sum(var_a + var_b))   ~ N(0, 1) when both are unbiased,
//   r = sum((a - b)^2) / sum(var_a + var_b)     ~ 1.
// Fails (exit 1) when |z| > 4 for a channel or r > 1.5: a device computing another image.
// The GPU bundle (tools/bundle/run.sh) compares its renders with PoCL's by it.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "host/film/film_halves.hpp"
#include "host/film/film_merge.hpp"
#include "host/film/film_state.hpp"

int main(int argc, char** argv) {
    using namespace facet;
    if (argc != 3) {
        std::fprintf(stderr, "usage: facet_film_ztest A.film B.film\n");
        return 2;
    }
    try {
        const FilmState a = read_film(argv[1]), b = read_film(argv[2]);
        // The identity covers the seed (render/film_identity.hpp), which differs here by
        // design: the same scene file, size and path settings are required instead, and
        // equal identities where the seeds are equal too.
        const bool same_settings =
            std::filesystem::path(a.scene_path).filename() == std::filesystem::path(b.scene_path).filename() &&
            a.width == b.width && a.height == b.height && a.max_depth == b.max_depth && a.rr_depth == b.rr_depth &&
            a.strategy == b.strategy && a.sampler == b.sampler;
        if (!same_settings || (a.seed == b.seed && a.scene_hash != b.scene_hash))
            throw std::runtime_error(std::string(argv[2]) + " is not a render of the scene of " + argv[1] +
                                     " with the same settings");
        const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
        const FilmHalves ha = film_halves(a), hb = film_halves(b);
        const std::vector<float> ma = film_mean(ha), mb = film_mean(hb);
        auto variance = [](const FilmHalves& h, std::size_t i) {
            const double n0 = double(h.samples[0]), n1 = double(h.samples[1]), n = n0 + n1;
            const double d = double(h.rgb[0][i]) - double(h.rgb[1][i]);
            return d * d * n0 * n1 / (n * n);
        };
        const double inf = std::numeric_limits<double>::infinity();
        bool ok = true;
        for (int c = 0; c < 3; ++c) {
            double diff = 0.0, diff2 = 0.0, var = 0.0;
            for (std::size_t p = 0; p < pixels; ++p) {
                const std::size_t i = 3 * p + std::size_t(c);
                const double d = double(ma[i]) - double(mb[i]);
                diff += d;
                diff2 += d * d;
                var += variance(ha, i) + variance(hb, i);
            }
            const double z = var > 0.0 ? diff / std::sqrt(var) : (diff == 0.0 ? 0.0 : inf);
            const double r = var > 0.0 ? diff2 / var : (diff2 == 0.0 ? 1.0 : inf);
            const bool pass = std::abs(z) <= 4.0 && r <= 1.5;
            ok = ok && pass;
            std::printf("channel %c: z %+.3f, r %.3f  %s\n", "RGB"[c], z, r, pass ? "ok" : "FAIL");
        }
        std::printf("%s: %s and %s (%llu and %llu spp)\n", ok ? "same image" : "DIFFERENT images", argv[1], argv[2],
                    static_cast<unsigned long long>(a.spp), static_cast<unsigned long long>(b.spp));
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "facet_film_ztest: error: %s\n", e.what());
        return 2;
    }
}
