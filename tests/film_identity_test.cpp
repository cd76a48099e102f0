// FilmIdentity.*: the film's scene identity from the compiled device scene
// (host/render/film_identity.hpp): resume and merge refuse samples of another scene, and
// accept those of the same scene compiled again.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "host/film/film_layout.hpp"
#include "host/bvh/bvh.hpp"
#include "host/cl/kernel_source.hpp"
#include "host/film/film_merge.hpp"
#include "host/render/film_identity.hpp"
#include "host/render/renderer.hpp"
#include "host/scene/texture.hpp"
#include "tests/lit_scene.hpp"
#include "tests/test_helpers.hpp"
#include "tests/test_paths.hpp"

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
            EXPECT_NE(msg.find("the film was rendered from another scene"), std::string::npos) << what << ": " << msg;
    }
}

// Settings the film does not list (it names size, seed, depths, strategy and sampler) are in the
// parameter block the identity hashes: a film of another Russian roulette gain, clamp or pixel
// filter is refused, and the message names such settings as a cause.
TEST(FilmIdentity, RefusesOtherRouletteGainClampOrFilter) {
    const Scene base = textured_scene();
    std::vector<std::pair<const char*, Scene>> changes;
    Scene gain = base;
    gain.settings.roulette_gain = 1.0f;
    changes.push_back({"roulette gain", gain});
    Scene clamp = base;
    clamp.settings.clamp = 10.0f;
    changes.push_back({"clamp", clamp});
    Scene filter = base;
    filter.settings.filter = FC_FILTER_TENT;
    changes.push_back({"filter", filter});
    const std::uint64_t id = identity(base);
    const std::vector<float> sums(film_floats(36), 1.0f);
    const FilmState film = make_film(base, id, SampleRanges{{0, 4}}, 1.0, sums);
    for (const auto& [what, changed] : changes) {
        const std::uint64_t other = identity(changed);
        EXPECT_NE(other, id) << what;
        const std::string msg = error_of([&] { check_film_matches(film, "g.film", changed, other); });
        EXPECT_NE(msg.find("or with other settings than its size, seed, depths, strategy and sampler"),
                  std::string::npos)
            << what << ": " << msg;
        EXPECT_NE(msg.find("--roulette-gain"), std::string::npos) << what << ": " << msg;
    }
}

// The identity covers the render kernels' code: the digest of the render program's sources
// (every file path.cl includes) ignores where they were read from (#line directives) and
// changes with any other line; a film of the same scene and settings whose identity differs
// (another facet's kernels) is refused, and the message says that kernels may be why.
TEST(FilmIdentity, CoversTheRenderKernelsCode) {
    EXPECT_EQ(kernel_code_digest("#line 1 \"kernels/a.cl\"\nfloat x;\n"),
              kernel_code_digest("#line 7 \"/tmp/elsewhere/kernels/a.cl\"\nfloat x;\n"));
    EXPECT_NE(kernel_code_digest("float x;\n"), kernel_code_digest("float y;\n"));
    EXPECT_NE(kernel_code_digest("a\nb\n"), kernel_code_digest("ab\n"));

    const std::uint64_t embedded = kernel_code_digest(assemble_program(kRenderProgram).text);
    EXPECT_EQ(render_kernel_digest(), embedded);
    // The same sources read from the checkout (FACET_KERNEL_DIR) give the same digest.
    const std::string kernels = (std::filesystem::path(test::scenes_dir()).parent_path() / "kernels").string();
    const char* before = std::getenv("FACET_KERNEL_DIR");
    const std::string saved = before ? before : "";
    ::setenv("FACET_KERNEL_DIR", kernels.c_str(), 1);
    const AssembledSource from_disk = assemble_program(kRenderProgram);
    if (saved.empty()) ::unsetenv("FACET_KERNEL_DIR");
    else ::setenv("FACET_KERNEL_DIR", saved.c_str(), 1);
    EXPECT_NE(from_disk.origin, "embedded");
    EXPECT_GT(from_disk.files.size(), 20u) << "path.cl and what it includes";
    EXPECT_EQ(kernel_code_digest(from_disk.text), embedded) << "the checkout's kernels are the embedded ones";

    const Scene s = textured_scene();
    const std::uint64_t id = identity(s);
    const DeviceScene compiled = compile(s, build_bvh(s.vertices));
    EXPECT_EQ(film_identity(compiled, render_kernel_digest()), id);
    EXPECT_NE(film_identity(compiled, embedded ^ 1u), id) << "another facet's kernels, the same scene";
    const std::vector<float> sums(film_floats(36), 1.0f);
    const FilmState other_kernels = make_film(s, id ^ 1u, SampleRanges{{0, 4}}, 1.0, sums);
    const std::string msg = error_of([&] { check_film_matches(other_kernels, "k.film", s, id); });
    EXPECT_NE(msg.find("--resume k.film: the film was rendered from another scene, or by a facet whose render kernels "
                       "differ from this one's, or with other settings"),
              std::string::npos)
        << msg;
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
