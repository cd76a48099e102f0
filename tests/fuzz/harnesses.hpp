// The fuzz targets as plain functions, shared by the libFuzzer executables
// (fuzz_*.cpp, one call each) and by the regression test that replays every input in
// tests/fuzz/regressions/<harness>/ through the gcc build (tests/fuzz_regression_test.cpp).
// Each returns normally for a scene that loads and keeps the invariants of
// fuzz_util.hpp or for a facet::Error; anything else is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_transform.hpp>

#include "host/error.hpp"
#include "host/image/image_io.hpp"
#include "tests/fuzz/fuzz_util.hpp"
#include "host/readers/environment_file.hpp"
#include "host/scene/environment_map.hpp"
#include "host/readers/load_scene.hpp"
#include "host/readers/gltf_reader.hpp"
#include "host/readers/obj_reader.hpp"
#include "host/readers/ply_reader.hpp"

namespace facet::fuzz {

// --- scene file --------------------------------------------------------------------
// The input is written as scene.json in the private folder, which also holds a small
// mesh (mesh.obj + mesh.mtl) and environment map (env.hdr) for the input to name, so
// that meshes, materials and environments are reached too.
inline void scene_json(std::string_view input) {
    static const bool files = [] {
        write_file("mesh.obj",
                   "mtllib mesh.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                   "usemtl red\nf 1//1 2//1 3//1 4//1\nusemtl glow\nf 1 3 2\n");
        write_file("mesh.mtl", "newmtl red\nKd 0.8 0.1 0.1\nKs 0.2 0.2 0.2\nNs 50\nnewmtl glow\nKd 0 0 0\nKe 4 4 4\n");
        // A 4x2 Radiance .hdr, stored flat (scanlines shorter than 8 are not run-length encoded).
        std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
        for (int i = 0; i < 8; ++i) hdr += std::string{char(128), char(100 + 10 * i), char(60), char(129)};
        write_file("env.hdr", hdr);
        return true;
    }();
    (void)files;
    const std::string path = write_file("scene.json", input);
    try {
        check_scene(load_scene(path));
    } catch (const Error&) {
        // a clear error: the expected outcome of a bad file
    }
}

// --- OBJ + MTL ---------------------------------------------------------------------
// The input is the OBJ text; everything after a line "#--mtl--" is written as in.mtl
// beside it (seeds name it with "mtllib in.mtl"); without that line there is no in.mtl
// (a missing library). Loaded by load_scene (validation, tinyobjloader, conversion,
// default camera and light), then again by load_obj with a mirroring transform.
inline void obj_mtl(std::string_view input) {
    constexpr std::string_view kSeparator = "\n#--mtl--\n";
    const std::size_t cut = input.find(kSeparator);
    const std::string path = write_file("in.obj", input.substr(0, cut));
    if (cut != std::string_view::npos) {
        write_file("in.mtl", input.substr(cut + kSeparator.size()));
    } else {
        std::error_code ec;
        std::filesystem::remove(work_dir() + "/in.mtl", ec);
    }
    try {
        check_scene(load_scene(path));
        Scene scene;
        ObjLoadOptions options;
        options.transform = glm::scale(glm::mat4(1.0f), glm::vec3(-2.0f, 0.5f, 3.0f));
        load_obj(path, scene, options);
        build_lights(scene);
        scene.camera = frame_camera(scene);
        check_scene(scene);
    } catch (const Error&) {
        // a clear error: the expected outcome of a bad file
    }
}

// --- environment map ---------------------------------------------------------------
// The input is written as in.hdr when it starts like a Radiance file ("#?"), else as
// in.exr (OpenImageIO picks the reader by extension, then tries the others), and read
// by load_environment_map (OpenImageIO, facet's checks, sanitising, the distribution),
// then lights a one-quad scene. Images whose header claims more than 2^22 pixels are
// skipped: reading a valid one legitimately takes gigabytes (facet's own limit, 2^28
// pixels, is tested by Limits.HugeImageHeaderIsRejectedBeforeReading).
inline void env_map(std::string_view input) {
    const bool hdr = input.substr(0, 2) == "#?";
    const std::string path = write_file(hdr ? "in.hdr" : "in.exr", input);
    try {
        check_image_header(path);  // before OpenImageIO allocates from the header
    } catch (const Error&) {
        return;
    }
    {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
        if (!in) {
            (void)OIIO::geterror();  // clears the thread's error message
        } else if (std::int64_t(in->spec().width) * in->spec().height > (std::int64_t(1) << 22)) {
            return;
        }
    }
    std::vector<std::string> warnings;
    try {
        EnvironmentMap env = load_environment_map(path, glm::vec3(1.0f), glm::mat3(1.0f), warnings);
        Scene scene;
        add_quad(scene, glm::vec3(-1, 0, -1), glm::vec3(2, 0, 0), glm::vec3(0, 0, 2),
                 add_material(scene, default_material(), "floor"));
        scene.environment = std::move(env);
        build_lights(scene);
        check_scene(scene);
    } catch (const Error&) {
        // a clear error: the expected outcome of a bad file
    }
}

// --- glTF ------------------------------------------------------------------------------
// The input is written as in.glb when it starts with glTF's binary magic ("glTF"), else
// as in.gltf; beside it lies buf.bin (96 bytes: four VEC3 positions then six uint16
// indices and padding) for a .gltf to name. Loaded by load_scene (tinygltf, the accessor
// checks, materials, nodes, camera, lights, default light), then by load_gltf into a
// JSON-scene-like setting with a mirroring transform and forced smooth normals.
inline void gltf(std::string_view input) {
    static const bool files = [] {
        std::string bin;
        const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const std::uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
        bin.append(reinterpret_cast<const char*>(pos), sizeof pos);
        bin.append(reinterpret_cast<const char*>(idx), sizeof idx);
        bin.resize(96, '\0');
        write_file("buf.bin", bin);
        return true;
    }();
    (void)files;
    const bool glb = input.substr(0, 4) == "glTF";
    const std::string path = write_file(glb ? "in.glb" : "in.gltf", input);
    try {
        check_scene(load_scene(path));
        Scene scene;
        GltfLoadOptions options;
        options.mesh.transform = glm::scale(glm::mat4(1.0f), glm::vec3(-2.0f, 0.5f, 3.0f));
        options.mesh.normals = NormalRule::Smooth;
        options.take_camera = false;
        load_gltf(path, scene, options);
        build_lights(scene);
        scene.camera = frame_camera(scene);
        check_scene(scene);
    } catch (const Error&) {
        // a clear error: the expected outcome of a bad file
    }
}

// --- PLY -------------------------------------------------------------------------------
// The input is written as in.ply, or as in.ply.gz when it starts with gzip's magic bytes,
// and loaded by load_scene (the header check, Assimp, normals, default camera and light),
// then by load_ply with a mirroring transform.
inline void ply(std::string_view input) {
    const bool gz = input.size() >= 2 && static_cast<unsigned char>(input[0]) == 0x1f &&
                    static_cast<unsigned char>(input[1]) == 0x8b;
    const std::string path = write_file(gz ? "in.ply.gz" : "in.ply", input);
    try {
        check_scene(load_scene(path));
        Scene scene;
        MeshOptions options;
        options.transform = glm::scale(glm::mat4(1.0f), glm::vec3(-2.0f, 0.5f, 3.0f));
        load_ply(path, scene, options);
        build_lights(scene);
        scene.camera = frame_camera(scene);
        check_scene(scene);
    } catch (const Error&) {
        // a clear error: the expected outcome of a bad file
    }
}

}  // namespace facet::fuzz
