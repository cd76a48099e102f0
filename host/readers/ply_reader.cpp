// PLY through Assimp: the file is read (and inflated when gzip'd) here, checked to be a
// PLY, then handed to Assimp's PLY importer from memory without post-processing: Assimp
// 5.2's triangulation aborts the process (an ai_assert) and another post-process step
// crashes on some malformed files (found by tests/fuzz/fuzz_ply). So every array and
// index it returns is checked here, points and lines are skipped here, and polygons are
// split into fans here.
#include "host/readers/ply_reader.hpp"

#include <cmath>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/gzip_file.hpp"
#include "host/readers/ply_header.hpp"

namespace facet {
namespace {

// The mesh's triangles, its positions and (when it has them) normals; points and lines
// (which Assimp sorts out) are skipped.
std::size_t convert(const std::string& path, const aiMesh& m, IndexedMesh& out) {
    if (m.mNumVertices > 0 && !m.mVertices) throw Error(fmt::format("{}: the PLY file has no vertex positions", path));
    if (m.mNumFaces > 0 && !m.mFaces) throw Error(fmt::format("{}: the PLY file's faces could not be read", path));
    out.positions.resize(m.mNumVertices);
    for (unsigned i = 0; i < m.mNumVertices; ++i) {
        out.positions[i] = glm::vec3(m.mVertices[i].x, m.mVertices[i].y, m.mVertices[i].z);
        // Not dropped later as "zero area": a NaN or infinite vertex is a broken file.
        if (!std::isfinite(out.positions[i].x) || !std::isfinite(out.positions[i].y) ||
            !std::isfinite(out.positions[i].z))
            throw Error(fmt::format("{}: element 'vertex' {} is ({}, {}, {}): not finite", path, i, out.positions[i].x,
                                    out.positions[i].y, out.positions[i].z));
    }
    if (m.mNormals) {
        out.normals.resize(m.mNumVertices);
        for (unsigned i = 0; i < m.mNumVertices; ++i)
            out.normals[i] = glm::vec3(m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z);
    }
    if (m.mTextureCoords[0]) {  // (u, v) or (s, t), v up the image as in OBJ: flipped
        out.texcoords.resize(m.mNumVertices);
        for (unsigned i = 0; i < m.mNumVertices; ++i)
            out.texcoords[i] = glm::vec2(m.mTextureCoords[0][i].x, 1.0f - m.mTextureCoords[0][i].y);
    }
    std::size_t skipped = 0;
    out.indices.reserve(std::size_t(m.mNumFaces) * 3);
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        if (face.mNumIndices < 3 || !face.mIndices) {
            ++skipped;
            continue;
        }
        for (unsigned c = 0; c < face.mNumIndices; ++c)
            if (face.mIndices[c] >= m.mNumVertices)
                throw Error(fmt::format("{}: face {} names vertex {}, but there are {} vertices", path, f,
                                        face.mIndices[c], m.mNumVertices));
        for (unsigned c = 1; c + 1 < face.mNumIndices; ++c) {  // a fan: faces of any size, convex as PLY's are
            out.indices.push_back(face.mIndices[0]);
            out.indices.push_back(face.mIndices[c]);
            out.indices.push_back(face.mIndices[c + 1]);
        }
    }
    return skipped;
}

}  // namespace

void load_ply(const std::string& path, Scene& scene, const MeshOptions& options) {
    std::string bytes = read_maybe_gzipped(path, "PLY file");
    const PlyHeader header = check_ply_header(path, bytes);
    // Assimp 5.2 drops a binary body's first byte when it is 0x0A, taking it for the end of
    // an "end_header\r\n" line; after "end_header\n" that byte is data (the first vertex's,
    // one file in 256), and every value after it was read one byte out of step. Handing
    // Assimp the "\r\n" it expects keeps the body as written (PlyValues.BinaryBody...).
    if (header.binary && header.body_offset >= 2 && bytes[header.body_offset - 2] != '\r')
        bytes.insert(header.body_offset - 1, 1, '\r');
    if (!header.ascii_body.empty()) {  // the header kept, the body as rewritten
        bytes.resize(header.body_offset);
        bytes += header.ascii_body;
    }
    Assimp::Importer importer;
    const aiScene* ai = nullptr;
    try {
        ai = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, "ply");
    } catch (const std::exception& e) {  // Assimp catches its own; this is for allocation failures
        throw Error(fmt::format("{}: cannot read the PLY file: {}", path, e.what()));
    }
    if (!ai || !ai->mRootNode)
        throw Error(fmt::format("{}: cannot read the PLY file: {}", path, importer.GetErrorString()));
    if (ai->mNumMeshes == 0) throw Error(fmt::format("{}: the PLY file has no faces", path));
    int material = options.material_override;
    if (material < 0) material = add_material(scene, default_material(), "default");
    MeshTally tally;
    std::size_t skipped = 0;
    for (unsigned i = 0; i < ai->mNumMeshes; ++i) {
        if (!ai->mMeshes || !ai->mMeshes[i]) throw Error(fmt::format("{}: cannot read the PLY file's mesh", path));
        IndexedMesh mesh;
        skipped += convert(path, *ai->mMeshes[i], mesh);
        add_indexed_mesh(mesh, options.transform, material, options.normals, true, scene, tally);
    }
    if (skipped > 0)
        scene.warnings.push_back(fmt::format("{}: {} faces with fewer than 3 vertices were skipped", path, skipped));
    finish_mesh_file(path, tally, options.normals, "area-weighted vertex normals: the PLY has none", "no usable normal",
                     scene);
}

}  // namespace facet
