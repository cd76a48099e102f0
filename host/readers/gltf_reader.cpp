// glTF 2.0 through tinygltf: the file is parsed (images kept undecoded: gltf_material.cpp
// decodes those a material uses), the extensions it requires are checked, then the default
// scene's node tree is walked with its transforms; each primitive's accessors are read with bounds
// checks (gltf_accessor.cpp) and added as an indexed mesh (triangle_mesh.cpp): copied into
// world space for a mesh one node uses, stored once in object space with one instance per
// node for a mesh several nodes use (Scene::meshes, Scene::instances).
#include "host/readers/gltf_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include <sys/stat.h>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <tiny_gltf.h>

#include "host/error.hpp"
#include "host/readers/gltf_accessor.hpp"
#include "host/readers/gltf_draco.hpp"
#include "host/readers/gltf_material.hpp"
#include "host/readers/text_parse.hpp"
#include "host/util/input_file.hpp"
#include "host/util/strings.hpp"
#include "kernels/shared/render_layout.h"

namespace facet {
namespace {

using gltf::Ignored;

// Images are kept undecoded, their bytes in Image::image: gltf_material.cpp decodes
// those a material uses (gltf::texture_index).
// `model` (the user data) is the model being loaded: tinygltf 2.5 hands an image of a
// .glb bufferView over without checking that the view lies inside its buffer (found by
// tests/fuzz/fuzz_gltf), so the bytes are copied only when they lie inside one buffer.
bool keep_image_undecoded(tinygltf::Image* image, const int, std::string* err, std::string*, int, int,
                          const unsigned char* bytes, int size, void* model) {
    if (bytes && size > 0) {
        const auto at = reinterpret_cast<std::uintptr_t>(bytes);
        bool inside = false;
        for (const tinygltf::Buffer& b : static_cast<const tinygltf::Model*>(model)->buffers) {
            const auto lo = reinterpret_cast<std::uintptr_t>(b.data.data());
            if (!b.data.empty() && at >= lo && at - lo <= b.data.size() &&
                std::size_t(size) <= b.data.size() - (at - lo))
                inside = true;
        }
        // a file or data URI image comes in tinygltf's own bytes; a bufferView's must lie in a buffer
        if (!inside && image->bufferView >= 0) {
            if (err) *err += "an image's bufferView lies outside its buffer\n";
            return false;
        }
        image->image.assign(bytes, bytes + size);
    }
    image->width = image->height = -1;
    return true;
}

// Finite and within +-1e18, the coordinate range of the scene (load_scene.cpp).
bool within_scene(glm::vec3 p) {
    for (int c = 0; c < 3; ++c)
        if (!(std::fabs(p[c]) <= 1e18f)) return false;
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    return s;
}

// The largest external buffer or image file a glTF may name.
constexpr std::uint64_t kMaxGltfResourceBytes = std::uint64_t(2) << 30;

// tinygltf opens the files a glTF names (external buffers and images, by URIs that may
// lead anywhere through "../") through these callbacks, so they pass facet's input
// checks (util/input_file.hpp): regular files only (a FIFO would block the open for ever,
// a folder made tinygltf allocate its "size"), of bounded size, never a shell expansion
// of the name (tinygltf's own ExpandFilePath runs wordexp on it).
bool resource_exists(const std::string& path, void*) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

// A URI written on Windows (".\\textures\\wood.png") has its backslashes read as
// separators when no file has the name as written (text::join_asset_path, as for MTL).
std::string resource_path(const std::string& path, void*) {
    struct stat st {};
    if (path.find('\\') == std::string::npos || ::stat(path.c_str(), &st) == 0) return path;
    std::string slashed = path;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    return std::filesystem::path(slashed).lexically_normal().string();
}

bool read_resource(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    try {
        const std::string bytes = read_input_file(path, "file", kMaxGltfResourceBytes);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const std::exception& e) {  // facet::Error, or no memory for the bytes
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
}

bool refuse_write(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
    if (err) *err += "facet does not write '" + path + "'\n";
    return false;
}

void parse(const std::string& path, tinygltf::Model& model, Scene& scene) {
    check_input_file(path, "glTF file");
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(tinygltf::FsCallbacks{resource_exists, resource_path, read_resource, refuse_write, nullptr});
    loader.SetImageLoader(keep_image_undecoded, &model);
    std::string err, warn;
    const bool binary = lower(std::filesystem::path(path).extension().string()) == ".glb";
    bool ok = false;
    try {
        // Draco primitives: their indices removed first (gltf_draco.hpp), the rest as the file says.
        const std::string bytes = read_input_file(path, "glTF file", 0xffffffffu);  // tinygltf takes 32-bit sizes
        const std::string base = std::filesystem::path(path).parent_path().string();
        const std::optional<std::string> stripped = gltf::without_draco_indices(bytes, binary);
        const std::string& text = stripped ? *stripped : bytes;
        const auto* data = reinterpret_cast<const unsigned char*>(text.data());
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, unsigned(text.size()), base)
                    : loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), base);
    } catch (const std::exception& e) {  // tinygltf reports its own errors; this is for allocation failures
        err = e.what();
    }
    for (std::string_view line : text::split_lines(warn))
        if (!trim(line).empty()) scene.warnings.push_back(fmt::format("{}: {}", path, trim(line)));
    if (!ok || !err.empty())
        throw Error(fmt::format("{}: not a valid glTF 2.0 file: {}", path, err.empty() ? "unknown error" : trim(err)));
    if (!model.asset.version.empty() && model.asset.version.rfind("2.", 0) != 0)
        throw Error(fmt::format("{}: asset.version is '{}': facet reads glTF 2.0", path, model.asset.version));
    for (const std::string& required : model.extensionsRequired)
        if (!gltf::supported_extension(required))
            throw Error(fmt::format(
                "{}: the file requires the extension {}, which facet does not support "
                "(supported: KHR_lights_punctual, KHR_materials_ior, KHR_materials_transmission, "
                "KHR_materials_emissive_strength, KHR_materials_volume, KHR_materials_specular, "
                "KHR_materials_clearcoat, KHR_materials_sheen, KHR_materials_anisotropy, KHR_texture_transform, "
                "KHR_draco_mesh_compression)",
                path, required));
}

glm::mat4 local_transform(const tinygltf::Node& n, const std::string& path, const std::string& place) {
    if (!n.matrix.empty()) {
        if (n.matrix.size() != 16) throw Error(fmt::format("{}: {}: matrix must have 16 numbers", path, place));
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[std::size_t(i)]);
        return m;
    }
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (!n.translation.empty()) {
        if (n.translation.size() != 3) throw Error(fmt::format("{}: {}: translation must have 3 numbers", path, place));
        t[3] = glm::vec4(float(n.translation[0]), float(n.translation[1]), float(n.translation[2]), 1.0f);
    }
    if (!n.rotation.empty()) {
        if (n.rotation.size() != 4) throw Error(fmt::format("{}: {}: rotation must have 4 numbers", path, place));
        const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
        const float len = glm::length(q);
        if (!(len > 0.0f) || !std::isfinite(len))
            throw Error(fmt::format("{}: {}: rotation is not a unit quaternion", path, place));
        r = glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
        if (n.scale.size() != 3) throw Error(fmt::format("{}: {}: scale must have 3 numbers", path, place));
        s = glm::scale(glm::mat4(1.0f), glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    }
    return t * r * s;
}

class Reader {
public:
    Reader(const std::string& path, const tinygltf::Model& model, Scene& scene, const GltfLoadOptions& options)
        : path_(path), model_(model), scene_(scene), options_(options), materials_(model.materials.size(), -1) {}

    bool run() {
        note_model_features();
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (std::size_t(s) >= model_.scenes.size())
                throw Error(fmt::format("{}: scene {} does not exist ({} scenes)", path_, s, model_.scenes.size()));
            roots = model_.scenes[std::size_t(s)].nodes;
        } else {
            // No scene: every node that is no other node's child (the specification leaves
            // this to the application).
            std::vector<bool> child(model_.nodes.size(), false);
            for (const tinygltf::Node& n : model_.nodes)
                for (int c : n.children)
                    if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
            for (std::size_t i = 0; i < child.size(); ++i)
                if (!child[i]) roots.push_back(int(i));
            scene_.warnings.push_back(
                fmt::format("{}: the file has no scenes; every root node ({}) is rendered", path_, roots.size()));
        }
        std::vector<bool> on_path(model_.nodes.size(), false);
        for (int root : roots) visit(root, options_.mesh.transform, on_path, 0);
        place_meshes();
        if (!options_.camera_name.empty() && !camera_taken_) {
            std::string names;
            for (const tinygltf::Camera& c : model_.cameras) names += (names.empty() ? "'" : ", '") + c.name + "'";
            throw Error(
                fmt::format("{}: --camera {}: no camera of the rendered scene has that name (the file's "
                            "cameras: {})",
                            path_, options_.camera_name, names.empty() ? "none" : names));
        }
        ignored_.warn(path_, scene_.warnings);
        finish_mesh_file(path_, tally_, options_.mesh.normals, "\"normals\": \"smooth\"",
                         "no NORMAL attribute: glTF's rule is flat shading", scene_);
        return camera_taken_;
    }

private:
    void note_model_features() {
        for (const std::string& used : model_.extensionsUsed)
            if (!gltf::supported_extension(used)) ignored_.add("extension " + used, "extensionsUsed");
        if (!model_.animations.empty())
            ignored_.add("animation", fmt::format("{} animations", model_.animations.size()));
        if (!model_.skins.empty())
            ignored_.add("skinning", fmt::format("{} skins (meshes in bind pose)", model_.skins.size()));
    }

    void visit(int index, const glm::mat4& parent, std::vector<bool>& on_path, int depth) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size())
            throw Error(fmt::format("{}: node {} does not exist ({} nodes)", path_, index, model_.nodes.size()));
        const std::string place = fmt::format("nodes[{}]", index);
        if (++visits_ > kMaxNodeVisits)
            throw Error(
                fmt::format("{}: the node hierarchy instances more than {} nodes (nodes shared down many "
                            "levels multiply)",
                            path_, kMaxNodeVisits));
        if (on_path[std::size_t(index)])
            throw Error(
                fmt::format("{}: {}: the node hierarchy has a cycle (the node is its own ancestor)", path_, place));
        if (depth > kMaxNodeDepth)
            throw Error(fmt::format("{}: {}: the node hierarchy is more than {} levels deep, more than facet walks",
                                    path_, place, kMaxNodeDepth));
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::mat4 world = parent * local_transform(node, path_, place);
        if (node.mesh >= 0) uses_.push_back(MeshUse{node.mesh, world, place});
        if (node.camera >= 0) camera(node.camera, world, place);
        if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end())
            light(it->second, world, place);
        if (!node.weights.empty()) ignored_.add("morph target weights", place);
        on_path[std::size_t(index)] = true;
        for (int child : node.children) visit(child, world, on_path, depth + 1);
        on_path[std::size_t(index)] = false;
    }

    int material(int index, const std::string& place) {
        if (options_.mesh.material_override >= 0) return options_.mesh.material_override;
        if (index < 0) {
            if (default_material_ < 0)
                default_material_ = add_material(scene_, gltf::default_gltf_material(), "gltf_default");
            return default_material_;
        }
        if (std::size_t(index) >= model_.materials.size())
            throw Error(fmt::format("{}: {}: material {} does not exist ({} materials)", path_, place, index,
                                    model_.materials.size()));
        int& slot = materials_[std::size_t(index)];
        if (slot < 0) {
            const tinygltf::Material& g = model_.materials[std::size_t(index)];
            const std::string mplace = fmt::format("materials[{}]", index);
            slot = add_material(scene_, gltf::convert_material(g, path_, mplace, ignored_, model_, scene_),
                                g.name.empty() ? mplace : g.name);
        }
        return slot;
    }

    struct MeshUse {
        int mesh;
        glm::mat4 world;
        std::string place;
    };
    struct Primitive {
        IndexedMesh mesh;
        int material;
    };
    static constexpr int kUnread = -1, kCopied = -2, kEmpty = -3;

    // Every node's mesh, in node order: a mesh that two or more nodes use is stored once and
    // instanced (unless options_.instancing is off, it emits light: the light list samples
    // world-space triangles, or a node's transform is not invertible), else it is copied
    // into the world for each node.
    void place_meshes() {
        std::vector<int> uses(model_.meshes.size(), 0), shared(model_.meshes.size(), kUnread);
        for (const MeshUse& u : uses_)
            if (u.mesh >= 0 && std::size_t(u.mesh) < uses.size()) ++uses[std::size_t(u.mesh)];
        for (const MeshUse& u : uses_) {
            if (options_.instancing && u.mesh >= 0 && std::size_t(u.mesh) < uses.size() &&
                uses[std::size_t(u.mesh)] >= 2 && instance_transform_ok(u.world)) {
                int& slot = shared[std::size_t(u.mesh)];
                if (slot == kUnread) slot = share_mesh(u.mesh, u.place);
                if (slot == kEmpty) continue;
                if (slot >= 0) {
                    add_instance(scene_, slot, u.world);
                    continue;
                }
            }
            add_mesh(u.mesh, u.world, u.place);
        }
    }

    // Mesh `index` in object space as a shared mesh: its index in scene_.meshes, kCopied when
    // it emits light, kEmpty when no triangle is left.
    int share_mesh(int index, const std::string& node_place) {
        std::vector<Primitive> prims = primitives(index, node_place);
        for (const Primitive& p : prims) {
            const glm::vec3 e = scene_.materials[std::size_t(p.material)].emission;
            if (e.x > 0.0f || e.y > 0.0f || e.z > 0.0f) return kCopied;
        }
        Scene object;  // the triangles alone; materials index scene_'s
        for (const Primitive& p : prims)
            add_indexed_mesh(p.mesh, glm::mat4(1.0f), p.material, options_.mesh.normals, false, object, tally_);
        if (object.shading.empty()) return kEmpty;
        SharedMesh m;
        const std::string& name = model_.meshes[std::size_t(index)].name;
        m.name = name.empty() ? fmt::format("meshes[{}]", index) : name;
        m.vertices = std::move(object.vertices);
        m.shading = std::move(object.shading);
        m.texcoords = std::move(object.texcoords);
        return add_shared_mesh(scene_, std::move(m));
    }

    void add_mesh(int index, const glm::mat4& world, const std::string& node_place) {
        for (const Primitive& p : primitives(index, node_place))
            add_indexed_mesh(p.mesh, world, p.material, options_.mesh.normals, false, scene_, tally_);
    }

    // The triangle primitives of mesh `index` and their scene materials.
    std::vector<Primitive> primitives(int index, const std::string& node_place) {
        if (std::size_t(index) >= model_.meshes.size())
            throw Error(fmt::format("{}: {}: mesh {} does not exist ({} meshes)", path_, node_place, index,
                                    model_.meshes.size()));
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(index)];
        std::vector<Primitive> out;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const std::string place = fmt::format("meshes[{}].primitives[{}]", index, p);
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                ignored_.add("points and lines (primitive modes 0-3)", place);
                continue;
            }
            for (const auto& [name, accessor] : prim.attributes)
                if (name != "POSITION" && name != "NORMAL" && name != "TEXCOORD_0" && name != "TANGENT")
                    ignored_.add("attribute " + name, place);
            if (!prim.targets.empty()) ignored_.add("morph targets", place);
            for (const auto& [name, value] : prim.extensions)
                if (name != gltf::kDracoExtension) ignored_.add("primitive extension " + name, place);
            if (gltf::is_draco(prim)) {  // decoded by Draco; the accessors only describe the result
                if (mode != TINYGLTF_MODE_TRIANGLES)
                    throw Error(fmt::format("{}: {}: a Draco-compressed primitive must be of triangles (mode 4)", path_,
                                            place));
                IndexedMesh m = gltf::decode_draco(model_, prim, path_, place);
                out.push_back(Primitive{std::move(m), material(prim.material, place)});
                continue;
            }
            const auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end())
                throw Error(fmt::format("{}: {}: no POSITION attribute", path_, place));
            IndexedMesh m;
            m.positions = gltf::read_vec3(model_, position->second, path_, place + ".attributes.POSITION");
            if (auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end()) {
                m.normals = gltf::read_vec3(model_, n->second, path_, place + ".attributes.NORMAL");
                if (m.normals.size() != m.positions.size())
                    throw Error(fmt::format("{}: {}: NORMAL has {} elements, POSITION {}", path_, place,
                                            m.normals.size(), m.positions.size()));
            }
            if (auto uv = prim.attributes.find("TEXCOORD_0"); uv != prim.attributes.end()) {
                const std::vector<glm::vec2> uvs =
                    gltf::read_vec2(model_, uv->second, path_, place + ".attributes.TEXCOORD_0");
                if (uvs.size() != m.positions.size())
                    throw Error(fmt::format("{}: {}: TEXCOORD_0 and POSITION have different counts", path_, place));
                m.texcoords = uvs;
            }
            if (auto t = prim.attributes.find("TANGENT"); t != prim.attributes.end()) {
                m.tangents = gltf::read_tangents(model_, t->second, path_, place + ".attributes.TANGENT");
                if (m.tangents.size() != m.positions.size())
                    throw Error(fmt::format("{}: {}: TANGENT has {} elements, POSITION {}", path_, place,
                                            m.tangents.size(), m.positions.size()));
            }
            std::vector<std::uint32_t> order;
            if (prim.indices >= 0) {
                order = gltf::read_indices(model_, prim.indices, m.positions.size(), path_, place + ".indices");
            } else {
                order.resize(m.positions.size());
                for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
            }
            m.indices = triangles(order, mode);
            out.push_back(Primitive{std::move(m), material(prim.material, place)});
        }
        return out;
    }

    static std::vector<std::uint32_t> triangles(const std::vector<std::uint32_t>& v, int mode) {
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            std::vector<std::uint32_t> t(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 3 * 3));
            return t;
        }
        std::vector<std::uint32_t> t;
        for (std::size_t i = 2; i < v.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_FAN) t.insert(t.end(), {v[0], v[i - 1], v[i]});
            else if (i % 2 == 0) t.insert(t.end(), {v[i - 2], v[i - 1], v[i]});
            else t.insert(t.end(), {v[i - 1], v[i - 2], v[i]});  // odd: keep the winding
        }
        return t;
    }

    void camera(int index, const glm::mat4& world, const std::string& place) {
        if (std::size_t(index) >= model_.cameras.size())
            throw Error(fmt::format("{}: {}: camera {} does not exist ({} cameras)", path_, place, index,
                                    model_.cameras.size()));
        const tinygltf::Camera& c = model_.cameras[std::size_t(index)];
        if (!options_.take_camera) {
            ignored_.add("cameras inside a JSON scene (its own camera is used)", place);
            return;
        }
        if (!options_.camera_name.empty()) {
            if (c.name != options_.camera_name) return;  // not the one asked for
            if (camera_taken_)
                throw Error(fmt::format("{}: --camera {}: several nodes use a camera of that name", path_, c.name));
        } else if (camera_taken_) {
            ignored_.add("every camera but the first", fmt::format("{} '{}'", place, c.name));
            return;
        }
        CameraDesc d;
        d.eye = glm::vec3(world * glm::vec4(0, 0, 0, 1));
        const glm::vec3 forward = glm::vec3(world * glm::vec4(0, 0, -1, 0));
        d.up = glm::vec3(world * glm::vec4(0, 1, 0, 0));
        const std::string cplace = fmt::format("cameras[{}]", index);
        if (!(glm::length(forward) > 0.0f) || !(glm::length(glm::cross(forward, d.up)) > 0.0f) ||
            !std::isfinite(glm::length(forward) + glm::length(d.up)))
            throw Error(fmt::format("{}: {}: the node's transform gives the camera no view direction", path_, place));
        if (!within_scene(d.eye))
            throw Error(fmt::format("{}: {}: the camera's position must be finite and within +-1e18", path_, place));
        d.target = d.eye + glm::normalize(forward) * std::max(1.0f, glm::length(d.eye) * 1e-3f);
        if (c.type == "perspective") {
            const double fov = c.perspective.yfov * 180.0 / M_PI;
            if (!(fov > 0.0 && fov < 180.0))
                throw Error(fmt::format("{}: {}.perspective.yfov must be in (0, pi), got {:g}", path_, cplace,
                                        c.perspective.yfov));
            d.fov_y_degrees = float(fov);
            d.projection = FC_PROJECTION_PERSPECTIVE;
            if (c.perspective.aspectRatio > 0.0) aspect(c.perspective.aspectRatio, cplace);
        } else if (c.type == "orthographic") {
            if (!(c.orthographic.ymag > 0.0 && c.orthographic.xmag > 0.0 && std::isfinite(c.orthographic.ymag)))
                throw Error(fmt::format("{}: {}.orthographic: xmag and ymag must be > 0", path_, cplace));
            d.projection = FC_PROJECTION_ORTHOGRAPHIC;
            d.ortho_height = float(2.0 * c.orthographic.ymag);
            aspect(c.orthographic.xmag / c.orthographic.ymag, cplace);
        } else {
            throw Error(fmt::format("{}: {}: unknown camera type '{}'", path_, cplace, c.type));
        }
        scene_.camera = d;
        camera_taken_ = true;
    }

    // The image keeps its width; its height follows the camera's aspect ratio.
    void aspect(double ratio, const std::string& place) {
        const double h = std::round(scene_.settings.width / ratio);
        if (!(h >= 1.0 && h <= 16384.0))
            throw Error(fmt::format("{}: {}: aspect ratio {:g} gives an image height of {:g}", path_, place, ratio, h));
        scene_.settings.height = int(h);
    }

    void light(const tinygltf::Value& ext, const glm::mat4& world, const std::string& place) {
        if (!ext.IsObject() || !ext.Has("light") || !ext.Get("light").IsNumber())
            throw Error(
                fmt::format("{}: {}.extensions.KHR_lights_punctual: expected {{\"light\": index}}", path_, place));
        const int index = gltf::index_value(ext.Get("light"));
        if (index < 0 || std::size_t(index) >= model_.lights.size())
            throw Error(fmt::format("{}: {}: light {:g} does not exist ({} lights)", path_, place,
                                    ext.Get("light").GetNumberAsDouble(), model_.lights.size()));
        if (!options_.take_lights) return;
        const tinygltf::Light& g = model_.lights[std::size_t(index)];
        const std::string lplace = fmt::format("KHR_lights_punctual.lights[{}]", index);
        PunctualLight l;
        glm::vec3 color(1.0f);
        if (!g.color.empty() && g.color.size() != 3)
            throw Error(fmt::format("{}: {}: color must have 3 numbers", path_, lplace));
        for (std::size_t c = 0; c < g.color.size(); ++c) color[int(c)] = float(g.color[c]);
        // glTF gives candela (point, spot) or lux (directional); facet's colour is
        // Hoffman's c_light, with I = pi c_light and E = pi c_light (docs/lights.md).
        l.color = color * float(g.intensity / M_PI);
        for (int c = 0; c < 3; ++c)
            if (!(l.color[c] >= 0.0f && l.color[c] <= FC_MAX_RADIANCE))
                throw Error(fmt::format("{}: {}: color x intensity / pi must be in [0, {:g}] (got {:g})", path_, lplace,
                                        FC_MAX_RADIANCE, l.color[c]));
        l.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
        if (!within_scene(l.position))
            throw Error(fmt::format("{}: {}: the light's position must be finite and within +-1e18", path_, place));
        l.direction = glm::vec3(world * glm::vec4(0, 0, -1, 0));
        if (!(glm::length(l.direction) > 0.0f) || !std::isfinite(glm::length(l.direction)))
            throw Error(fmt::format("{}: {}: the node's transform gives the light no direction", path_, place));
        l.direction = glm::normalize(l.direction);
        if (g.type == "point") l.type = FC_LIGHT_POINT;
        else if (g.type == "directional") l.type = FC_LIGHT_DIRECTIONAL;
        else if (g.type == "spot") {
            l.type = FC_LIGHT_SPOT;
            const double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
            if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2))
                throw Error(
                    fmt::format("{}: {}: spot cone angles must satisfy 0 <= inner < outer <= pi/2 (got {:g}, {:g})",
                                path_, lplace, inner, outer));
            l.inner_degrees = float(inner * 180.0 / M_PI);
            l.outer_degrees = float(outer * 180.0 / M_PI);
        } else {
            throw Error(fmt::format("{}: {}: unknown light type '{}'", path_, lplace, g.type));
        }
        if (g.range > 0.0) ignored_.add("light range (facet's lights have no cut-off)", lplace);
        scene_.punctual_lights.push_back(l);
    }

    const std::string& path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    const GltfLoadOptions& options_;
    std::vector<int> materials_;  // glTF material -> scene material, -1 until used
    int default_material_ = -1;
    bool camera_taken_ = false;
    MeshTally tally_;
    Ignored ignored_;
    std::vector<MeshUse> uses_;  // every node's mesh, in node order
    static constexpr std::size_t kMaxNodeVisits = 1000000;
    static constexpr int kMaxNodeDepth = 4096;  // the walk recurses once per level
    std::size_t visits_ = 0;
};

}  // namespace

bool load_gltf(const std::string& path, Scene& scene, const GltfLoadOptions& options) {
    tinygltf::Model model;
    parse(path, model, scene);
    return Reader(path, model, scene, options).run();
}

}  // namespace facet
