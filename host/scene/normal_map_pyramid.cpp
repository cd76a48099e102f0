// Normal-map pyramids with the normals' spread in alpha (normal_map_pyramid.hpp).
#include "host/scene/normal_map_pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "host/scene/texture.hpp"

namespace facet {

void build_normal_map_pyramid(TextureImage& t) {
    const std::size_t count = std::size_t(t.width) * std::size_t(t.height);
    if (t.width < 1 || t.height < 1 || t.texels.size() < 4 * count) return;
    std::vector<float> unit(4 * count);
    for (std::size_t i = 0; i < count; ++i) {
        double n[3], len2 = 0.0;
        for (int c = 0; c < 3; ++c) {
            n[c] = 2.0 * double(t.texels[4 * i + std::size_t(c)]) - 1.0;
            len2 += n[c] * n[c];
        }
        const double len = std::sqrt(len2);
        for (int c = 0; c < 3; ++c)
            unit[4 * i + std::size_t(c)] = len > 1e-6 ? float(n[c] / len) : (c == 2 ? 1.0f : 0.0f);
        unit[4 * i + 3] = 1.0f;
    }
    // Box-filtered means of the unit normals, level by level (texture.hpp's make_texture).
    const TextureImage means = make_texture(t.width, t.height, std::move(unit), t.wrap_u, t.wrap_v);
    std::vector<float> texels(t.texels.begin(), t.texels.begin() + std::ptrdiff_t(4 * count));
    for (std::size_t i = 0; i < count; ++i) texels[4 * i + 3] = 1.0f;
    texels.resize(means.texels.size());
    for (std::size_t i = count; i < means.texels.size() / 4; ++i) {
        const double m[3] = {double(means.texels[4 * i]), double(means.texels[4 * i + 1]),
                             double(means.texels[4 * i + 2])};
        const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        for (int c = 0; c < 3; ++c)
            texels[4 * i + std::size_t(c)] = len > 1e-6 ? float(0.5 * m[c] / len + 0.5) : (c == 2 ? 1.0f : 0.5f);
        texels[4 * i + 3] = float(std::min(len, 1.0));
    }
    t.texels = std::move(texels);
    t.levels = means.levels;
}

}  // namespace facet
