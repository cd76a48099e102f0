#include "host/scene/texture_validate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "host/scene/normal_map_pyramid.hpp"
#include "host/scene/texture.hpp"

namespace facet {
namespace {

enum Role : unsigned { kFraction = 1, kEmission = 2, kNormal = 4 };

// What one texture's level-0 texels were changed by.
struct Changes {
    std::size_t texels = 0;
    float lo = std::numeric_limits<float>::infinity(), hi = -std::numeric_limits<float>::infinity();
    void saw(float v) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
};

void sanitise(TextureImage& t, unsigned roles, Changes& ch) {
    const std::size_t count = std::size_t(t.width) * std::size_t(t.height);
    for (std::size_t i = 0; i < count; ++i) {
        float* v = &t.texels[4 * i];
        bool changed = false;
        for (int c = 0; c < 3; ++c) {
            float x = v[c];
            if (roles & (kFraction | kNormal)) x = std::clamp(x, 0.0f, 1.0f);
            if (roles & kEmission) x = std::max(x, 0.0f);
            if (x != v[c]) {
                ch.saw(v[c]);
                v[c] = x;
                changed = true;
            }
        }
        if (roles & kNormal) {
            const float n[3] = {2.0f * v[0] - 1.0f, 2.0f * v[1] - 1.0f, 2.0f * v[2] - 1.0f};
            const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(std::fabs(len - 1.0f) <= 0.1f)) {
                for (int c = 0; c < 3; ++c) {
                    const float unit = len > 1e-6f ? n[c] / len : (c == 2 ? 1.0f : 0.0f);
                    v[c] = 0.5f * unit + 0.5f;
                }
                ch.saw(len);
                changed = true;
            }
        }
        if (changed) ++ch.texels;
    }
}

std::string role_names(unsigned roles) {
    std::string s;
    auto add = [&](const char* name) { s += (s.empty() ? "" : " and ") + std::string(name); };
    if (roles & kFraction) add("a reflectance or fraction (0 to 1)");
    if (roles & kEmission) add("an emission multiplier (at least 0)");
    if (roles & kNormal) add("a normal map (unit vectors)");
    return s;
}

}  // namespace

void sanitise_textures(Scene& scene) {
    std::vector<unsigned> roles(scene.textures.size(), 0u);
    auto bind = [&](int index, unsigned role) {
        if (index >= 0 && std::size_t(index) < roles.size()) roles[std::size_t(index)] |= role;
    };
    for (const Material& m : scene.materials) {
        const MaterialTextures& b = m.textures;
        bind(b.base_color, kFraction);
        bind(b.specular, kFraction);
        bind(b.roughness, kFraction);
        bind(b.metalness, kFraction);
        bind(b.emission, kEmission);
        bind(b.normal, kNormal);
        bind(b.clearcoat_normal, kNormal);
        for (int index : {b.clearcoat, b.clearcoat_roughness, b.sheen_color, b.sheen_roughness, b.specular_strength,
                          b.specular_color})
            bind(index, kFraction);
    }
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        TextureImage& t = scene.textures[i];
        if (roles[i] == 0 || t.width < 1 || t.height < 1) continue;
        Changes ch;
        sanitise(t, roles[i], ch);
        if (roles[i] & kNormal) build_normal_map_pyramid(t);  // the bumps' spread in alpha
        if (ch.texels == 0) continue;
        if (!(roles[i] & kNormal)) {
            std::vector<float> level0(
                t.texels.begin(), t.texels.begin() + std::ptrdiff_t(4 * std::size_t(t.width) * std::size_t(t.height)));
            TextureImage rebuilt = make_texture(t.width, t.height, std::move(level0), t.wrap_u, t.wrap_v);
            t.texels = std::move(rebuilt.texels);
            t.levels = rebuilt.levels;
        }
        scene.warnings.push_back(
            fmt::format("{}: {} of its {} texels were outside what the texture is read as, {} (values or lengths "
                        "from {:g} to {:g}), and were clamped to it",
                        t.path.empty() ? std::string("a texture") : t.path, ch.texels,
                        std::size_t(t.width) * std::size_t(t.height), role_names(roles[i]), ch.lo, ch.hi));
    }
}

}  // namespace facet
