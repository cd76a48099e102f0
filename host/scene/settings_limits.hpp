// The ranges of the render settings: one table for the scene file's "render" section
// (host/readers/json_scene.cpp) and the command line's options (host/cli/cli.cpp).
#pragma once

#include <cstdint>
#include <string>

#include <fmt/format.h>

namespace facet {

struct SettingRange {
    std::int64_t lo, hi;  // inclusive
    bool contains(std::int64_t v) const { return v >= lo && v <= hi; }
    // "an integer in [1, 16384]", for messages.
    std::string words() const { return fmt::format("an integer in [{}, {}]", lo, hi); }
};

namespace limits {
inline constexpr SettingRange kWidth{1, 16384};
inline constexpr SettingRange kHeight{1, 16384};
inline constexpr SettingRange kSpp{1, std::int64_t{1} << 24};
inline constexpr SettingRange kMaxDepth{1, 1024};
inline constexpr SettingRange kRrDepth{0, 1024};
inline constexpr SettingRange kSeed{0, 0xffffffffLL};
// The time limit (--time) is a finite number of seconds > 0.
inline constexpr const char* kTimeWords = "a finite number of seconds > 0";
// The share of Lambertian vertices' directions drawn toward glass (caustic_guide): at most
// 0.9, so that the BSDF keeps sampling every direction often.
inline constexpr double kMaxCausticGuide = 0.9;
// Russian roulette's gain (roulette_gain): in (0, kMaxRouletteGain]. A large gain is nearly no
// roulette: survival 0.95 wherever gain times the throughput reaches it.
inline constexpr double kMaxRouletteGain = 1e6;
}  // namespace limits

}  // namespace facet
