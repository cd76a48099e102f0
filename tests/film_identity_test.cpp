// FilmIdentity.*: the film's scene identity from the compiled device scene
// (host/render/film_identity.hpp): resume and merge refuse samples of another scene, and
// accept those of the same scene compiled again.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/film/film_layout.hpp"
#include "host/bvh/bvh.hpp"
#include "host/film/film_merge.hpp"
#include "host/render/film_identity.hpp"
#include "host/scene/texture.hpp"
#include "tests/lit_scene.hpp"
#include "tests/test_helpers.hpp"

namespace facet {
namespace {

using test::error_of;

// The lit scene with a sphere and a textured floor (a 2x2 base-colour texture).
Scene textured_scene() {
    Scene s = test::lit_scene(6);
    s.spheres.push_back(FcSphere{{0.2f, 0.3f, 0.1f}, 0.25f, 0, -1, 0, 0});
    s.textures.push_back(make_texture(
        2, 2, {0.2f, 0.4f, 0.6f, 1.0f, 0.9f, 0.1f, 0.3f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f, 0.7f, 0.2f, 0.8f, 1.0f}));
    for (Material& m : s.materials) m.textures.base_color = 0;
    s.texcoords.assign(s.triangle_count(), FcTriTexcoords{});
    return s;
}

std::uint64_t identity(const Scene& s) { return film_identity(s, build_bvh(s.vertices)); }

// The messages of --resume and of a merge of a film of `base` with one of `changed`.
std::vector<std::string> refusals(const Scene& base, const Scene& changed) {
    const std::vector<float> sums(film_floats(36), 1.0f);
    const FilmState a = make_film(base, identity(base), SampleRanges{{0, 4}}, 1.0, sums);
    const FilmState b = make_film(changed, identity(changed), SampleRanges{{4, 8}}, 1.0, sums);
    return {error_of([&] { check_film_matches(a, "a.film", changed, identity(changed)); }), error_of([&] {
                merge_films({a, b}, {"a.film", "b.film"});
            })};
}

TEST(FilmIdentity, AcceptsTheSameSceneCompiledAgain) {
    ASSERT_TRUE(scene_uses_textures(textured_scene()));
    EXPECT_EQ(identity(textured_scene()), identity(textured_scene()));
    for (const std::string& msg : refusals(textured_scene(), textured_scene())) EXPECT_EQ(msg, "");
}

TEST(FilmIdentity, RefusesAnotherSphereTextureOrUvScale) {
    const Scene base = textured_scene();
    std::vector<std::pair<const char*, Scene>> changes;
    Scene moved = base;
    moved.spheres[0].center[0] += 0.01f;
    changes.push_back({"moved sphere", moved});
    Scene radius = base;
    radius.spheres[0].radius = 0.26f;
    changes.push_back({"sphere radius", radius});
    Scene texel = base;
    texel.textures[0].texels[0] = 0.21f;
    changes.push_back({"texel", texel});
    Scene uv = base;
    for (Material& m : uv.materials) m.textures.uv_transform[0] = 2.0f;
    changes.push_back({"uv scale", uv});
    for (const auto& [what, changed] : changes) {
        EXPECT_NE(identity(changed), identity(base)) << what;
        for (const std::string& msg : refusals(base, changed))
            EXPECT_NE(msg.find("the film was rendered from another scene (identity "), std::string::npos)
                << what << ": " << msg;
    }
}

// The identity leaves out the trees' layout (the node width each device picks) but not
// what they are built from.
TEST(FilmIdentity, SameAcrossTreeWidths) {
    const Scene s = textured_scene();
    BvhOptions wide;
    wide.width = 8;
    EXPECT_EQ(film_identity(s, build_bvh(s.vertices)), film_identity(s, build_bvh(s.vertices, wide)));
    Scene moved = s;
    moved.vertices[0].x += 0.01f;
    EXPECT_NE(film_identity(moved, build_bvh(moved.vertices)), film_identity(s, build_bvh(s.vertices)));
}

}  // namespace
}  // namespace facet
