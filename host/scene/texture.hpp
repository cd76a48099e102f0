// Image textures on the host (docs/textures.md): images decoded through host/film's
// read_image (OpenImageIO; PFM only in the lean build) into linear RGBA float texels,
// a box-filtered mip pyramid each, and the scene's textures, material bindings and
// per-triangle uvs compiled into the kernels' arrays (kernels/shared/texture_layout.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "host/scene/texture_binding.hpp"
#include "kernels/shared/texture_layout.h"

namespace facet {

struct Scene;

// How an image's values are read: colours (base colour, specular, emission) decoded
// from sRGB when the file holds integers (8 or 16 bits), data (roughness, metalness,
// normals) as stored. Float images (EXR, HDR, PFM) are linear either way.
enum class TextureSpace { Color, Data };

// A decoded texture with its mip pyramid: `texels` holds 4 floats (RGBA; A = 1 unless the
// file has an alpha channel, `has_alpha`) a texel,
// level 0 (width x height, top row first) then each smaller level down to 1 x 1.
// `format` is how the device stores level 0 (FC_TEXEL_*, kernels/shared/texture_layout.h):
// as precise as the file, no more (8-bit files in 4 bytes a texel, sRGB colours decoded
// on the device; 16-bit ones as half floats; float files as floats). `mip_format` is that
// of the smaller levels, whose averages are kept to half precision at least (an average
// of 8-bit texels re-quantised to 8 bits would be off by up to half a step).
struct TextureImage {
    std::string path;
    TextureSpace space = TextureSpace::Color;
    int width = 0;
    int height = 0;
    int levels = 0;
    int wrap_u = FC_WRAP_REPEAT;
    int wrap_v = FC_WRAP_REPEAT;
    int format = FC_TEXEL_RGBA32F;
    int mip_format = FC_TEXEL_RGBA32F;
    bool has_alpha = false;
    std::vector<float> texels;
};

// A texture from level-0 RGBA texels: the pyramid is built by 2x2 box filtering (the
// last row or column of an odd size folded into its neighbour, so every level averages
// the whole image).
TextureImage make_texture(int width, int height, std::vector<float> rgba, int wrap_u = FC_WRAP_REPEAT,
                          int wrap_v = FC_WRAP_REPEAT);

// Reads an image file as a texture. Throws facet::Error naming the file and `owner`
// (e.g. "material 'wood' (map_Kd)") when it is missing, unreadable or corrupt.
TextureImage load_texture(const std::string& path, TextureSpace space, const std::string& owner);

// An image file held in memory (embedded in a model: glTF's data URIs and buffer views,
// FBX's aiTexture), decoded through a temporary file named with `ext` (".png", ".jpg"):
// host/image's reader reads files. Errors as load_texture's; the path is left empty.
TextureImage load_texture_bytes(const void* data, std::size_t size, const std::string& ext, TextureSpace space,
                                const std::string& owner);

// What stands in for a texture that cannot be read: a magenta and black checker, 4 x 4
// checks over the uv square (as other tools show a missing texture).
TextureImage missing_texture();

// The index in scene.textures of the image at `path` read as `space` with these wrap
// modes, loading it on first use. An image that cannot be read (missing, unreadable,
// corrupt) is a warning naming it and its owner, and stands in as missing_texture() for a
// colour, or is left out (-1) as data; with scene.strict_assets it is load_texture's error.
int add_texture(Scene& scene, const std::string& path, TextureSpace space, const std::string& owner,
                int wrap_u = FC_WRAP_REPEAT, int wrap_v = FC_WRAP_REPEAT);

// Gives scene triangle `tri` these vertex uvs (v = 0 at the image's top row). Triangles
// never given uvs have (0, 0) at every vertex.
void set_triangle_texcoords(Scene& scene, std::size_t tri, glm::vec2 uv0, glm::vec2 uv1, glm::vec2 uv2);

// Whether any material that some triangle uses binds a texture.
bool scene_uses_textures(const Scene& scene);
// Whether the triangles' uvs and tangents go to the device: the scene uses textures, or some
// material that a triangle uses is anisotropic (its frame follows the tangents).
bool scene_uses_texcoords(const Scene& scene);

// The device's texture arrays: one-element placeholders when the scene has no
// textures (and texcoords none unless scene_uses_texcoords), so the kernels' arguments are always bound; one (empty)
// binding per material always, since the generic program reads them.
struct DeviceTextures {
    std::vector<FcTexture> table;
    std::vector<std::uint32_t> texels;  // the pool: the sRGB table, then each texture in its format
    std::vector<FcMaterialTextures> materials;
    std::vector<FcTriTexcoords> texcoords;

    std::uint64_t bytes() const {
        return table.size() * sizeof(FcTexture) + texels.size() * sizeof(std::uint32_t) +
               materials.size() * sizeof(FcMaterialTextures) + texcoords.size() * sizeof(FcTriTexcoords);
    }
};

// The kernels' struct of a material's bindings.
FcMaterialTextures device_material_textures(const MaterialTextures& t);

// The scene's textures as the kernels read them; build_lights() must have run (an
// area light's uvs follow its edge order).
DeviceTextures compile_textures(const Scene& scene);

}  // namespace facet
