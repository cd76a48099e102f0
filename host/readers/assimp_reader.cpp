// Models through Assimp. The file passes facet's input checks first; Assimp then reads it
// (and any file it names) through AssimpFiles (assimp_io.hpp). Post-processing runs only
// after Assimp's own validation of the scene (aiProcess_ValidateDataStructure) has passed,
// since its steps trust the arrays they are given (the PLY reader met an abort in the
// triangulation of a malformed file); every array and index used here is checked again.
// The node hierarchy is applied here (each mesh placed once per node naming it), as
// aiProcess_PreTransformVertices would, so that a node's mesh keeps its own material.
#include "host/readers/assimp_reader.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <set>
#include <utility>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "host/error.hpp"
#include "host/readers/assimp_io.hpp"
#include "host/readers/assimp_material.hpp"
#include "host/readers/text_parse.hpp"
#include "host/util/input_file.hpp"

namespace facet {
namespace {

// The most meshes the node hierarchy may place (a tree of nodes naming the same mesh many
// times over would otherwise multiply it without bound).
constexpr std::size_t kMaxPlacedMeshes = 1000000;

glm::mat4 to_glm(const aiMatrix4x4& a) {
    glm::mat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = a[r][c];  // glm is column-major, aiMatrix4x4 row-major
    return m;
}

// The mesh's triangles with positions, normals and uvs (the first set); points and
// lines are counted in `skipped`, polygons split into fans (Triangulate has run).
IndexedMesh convert(const std::string& path, const aiMesh& m, std::size_t& skipped) {
    if (m.mNumVertices > 0 && !m.mVertices) throw Error(fmt::format("{}: a mesh has no vertex positions", path));
    if (m.mNumFaces > 0 && !m.mFaces) throw Error(fmt::format("{}: a mesh's faces could not be read", path));
    IndexedMesh out;
    out.positions.resize(m.mNumVertices);
    for (unsigned i = 0; i < m.mNumVertices; ++i) {
        out.positions[i] = glm::vec3(m.mVertices[i].x, m.mVertices[i].y, m.mVertices[i].z);
        if (!std::isfinite(out.positions[i].x + out.positions[i].y + out.positions[i].z))
            throw Error(fmt::format("{}: mesh '{}' vertex {} is ({}, {}, {}): not finite", path, m.mName.C_Str(), i,
                                    out.positions[i].x, out.positions[i].y, out.positions[i].z));
    }
    if (m.mNormals) {
        out.normals.resize(m.mNumVertices);
        for (unsigned i = 0; i < m.mNumVertices; ++i)
            out.normals[i] = glm::vec3(m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z);
    }
    if (m.mTextureCoords[0]) {  // v up the image (OpenGL's): flipped, as OBJ's
        out.texcoords.resize(m.mNumVertices);
        for (unsigned i = 0; i < m.mNumVertices; ++i)
            out.texcoords[i] = glm::vec2(m.mTextureCoords[0][i].x, 1.0f - m.mTextureCoords[0][i].y);
    }
    out.indices.reserve(std::size_t(m.mNumFaces) * 3);
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        if (face.mNumIndices < 3 || !face.mIndices) {
            ++skipped;
            continue;
        }
        for (unsigned c = 0; c < face.mNumIndices; ++c)
            if (face.mIndices[c] >= m.mNumVertices)
                throw Error(fmt::format("{}: mesh '{}' face {} names vertex {}, but there are {} vertices", path,
                                        m.mName.C_Str(), f, face.mIndices[c], m.mNumVertices));
        for (unsigned c = 1; c + 1 < face.mNumIndices; ++c) {
            out.indices.push_back(face.mIndices[0]);
            out.indices.push_back(face.mIndices[c]);
            out.indices.push_back(face.mIndices[c + 1]);
        }
    }
    return out;
}

// What the file holds that facet does not read, one line per kind.
void note_ignored(const aiScene& ai, std::set<std::string>& ignored) {
    if (ai.mNumAnimations > 0)
        ignored.insert(fmt::format("{} animations (the rest pose is rendered)", ai.mNumAnimations));
    if (ai.mNumLights > 0) ignored.insert(fmt::format("{} lights (a default light is added)", ai.mNumLights));
    if (ai.mNumCameras > 0) ignored.insert(fmt::format("{} cameras (the model is framed)", ai.mNumCameras));
    for (unsigned i = 0; i < ai.mNumMeshes; ++i) {
        const aiMesh& m = *ai.mMeshes[i];
        if (m.mNumBones > 0) ignored.insert("skins (bones)");
        if (m.mNumAnimMeshes > 0) ignored.insert("morph targets");
        if (m.mColors[0]) ignored.insert("vertex colours");
        if (m.mTextureCoords[1]) ignored.insert("texture coordinate sets after the first");
    }
}

const aiScene* read(const std::string& path, Assimp::Importer& importer) {
    check_input_file(path, "model file", kMaxAssimpFileBytes);
    auto* files = new AssimpFiles(text::directory_of(path));
    importer.SetIOHandler(files);  // the importer owns it
    const aiScene* ai = nullptr;
    try {
        ai = importer.ReadFile(path, aiProcess_ValidateDataStructure);
        if (ai && ai->mRootNode)
            ai = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                              aiProcess_SortByPType);
    } catch (const std::exception& e) {  // Assimp catches its own; this is for allocation failures
        throw Error(fmt::format("{}: Assimp cannot read the file: {}", path, e.what()));
    }
    if (!ai || !ai->mRootNode) {
        std::string why = importer.GetErrorString();
        if (!files->refusal().empty()) why += fmt::format(" ({})", files->refusal());
        throw Error(fmt::format("{}: Assimp cannot read the file: {}", path, why.empty() ? "unknown error" : why));
    }
    if (ai->mNumMeshes == 0 || !ai->mMeshes) throw Error(fmt::format("{}: the file holds no mesh", path));
    for (unsigned i = 0; i < ai->mNumMeshes; ++i)
        if (!ai->mMeshes[i]) throw Error(fmt::format("{}: mesh {} could not be read", path, i));
    return ai;
}

}  // namespace

const std::vector<AssimpFormat>& assimp_formats() {
    static const std::vector<AssimpFormat> formats = {
        {".stl", "STL"},   {".fbx", "FBX"},       {".dae", "Collada"},     {".3ds", "3DS"}, {".off", "OFF"},
        {".x", "DirectX"}, {".lwo", "LightWave"}, {".ase", "3ds Max ASE"}, {".ac", "AC3D"}, {".ms3d", "Milkshape 3D"},
    };
    return formats;
}

bool is_assimp_format(std::string_view ext) {
    const auto& f = assimp_formats();
    return std::any_of(f.begin(), f.end(), [&](const AssimpFormat& a) { return a.extension == ext; });
}

void load_assimp(const std::string& path, Scene& scene, const MeshOptions& options) {
    Assimp::Importer importer;
    const aiScene* ai = read(path, importer);
    std::set<std::string> ignored;
    note_ignored(*ai, ignored);
    std::map<unsigned, int> materials;  // Assimp's index -> scene.materials
    auto material_of = [&](unsigned index) {
        if (options.material_override >= 0) return options.material_override;
        if (index >= ai->mNumMaterials || !ai->mMaterials || !ai->mMaterials[index]) {
            if (!materials.count(~0u)) materials[~0u] = add_material(scene, default_material(), "default");
            return materials[~0u];
        }
        if (!materials.count(index)) {
            const Material m = assimp_material(*ai, index, path, scene, ignored);
            aiString name;
            ai->mMaterials[index]->Get(AI_MATKEY_NAME, name);
            materials[index] = add_material(scene, m, name.length > 0 ? name.C_Str() : fmt::format("#{}", index));
        }
        return materials[index];
    };
    std::vector<IndexedMesh> meshes(ai->mNumMeshes);
    std::vector<bool> converted(ai->mNumMeshes, false);
    MeshTally tally;
    std::size_t skipped = 0, placed = 0;
    // The hierarchy, depth first without recursion (a deep file cannot exhaust the stack).
    std::vector<std::pair<const aiNode*, glm::mat4>> stack{{ai->mRootNode, options.transform}};
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const glm::mat4 transform = parent * to_glm(node->mTransformation);
        for (unsigned i = 0; i < node->mNumMeshes && node->mMeshes; ++i) {
            const unsigned index = node->mMeshes[i];
            if (index >= ai->mNumMeshes)
                throw Error(fmt::format("{}: node '{}' names mesh {}, but there are {} meshes", path,
                                        node->mName.C_Str(), index, ai->mNumMeshes));
            if (++placed > kMaxPlacedMeshes)
                throw Error(fmt::format("{}: the node hierarchy places more than {} meshes", path, kMaxPlacedMeshes));
            if (!converted[index]) meshes[index] = convert(path, *ai->mMeshes[index], skipped), converted[index] = true;
            const int material = material_of(ai->mMeshes[index]->mMaterialIndex);
            add_indexed_mesh(meshes[index], transform, material, options.normals, false, scene, tally);
        }
        for (unsigned c = 0; c < node->mNumChildren && node->mChildren; ++c)
            if (node->mChildren[c]) stack.emplace_back(node->mChildren[c], transform);
    }
    if (skipped > 0)
        scene.warnings.push_back(
            fmt::format("{}: {} points and lines were skipped (facet renders surfaces)", path, skipped));
    for (const std::string& what : ignored)
        scene.warnings.push_back(fmt::format("{}: facet does not read {}; ignored", path, what));
    finish_mesh_file(path, tally, options.normals, "area-weighted vertex normals", "face normals: the file has none",
                     scene);
}

}  // namespace facet
