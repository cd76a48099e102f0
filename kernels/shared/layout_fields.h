/* Every shared struct and field, as an X-macro list, so the host (static_assert and
 * tests/layout_test.cpp) and a test kernel (layout_kernels.cl) compute
 * sizeof/offsetof over exactly the same list. Add new structs and fields here. */
#ifndef FACET_SHARED_LAYOUT_FIELDS_H
#define FACET_SHARED_LAYOUT_FIELDS_H

#define FC_LAYOUT_STRUCTS(S) \
    S(FcBvhNode)             \
    S(FcBvhNode8)            \
    S(FcBvhNodeQ)            \
    S(FcTriBlock)            \
    S(FcTriangle)            \
    S(FcTriShading)          \
    S(FcMaterial)            \
    S(FcLight)               \
    S(FcCamera)              \
    S(FcRenderParams)        \
    S(FcEnvironment)         \
    S(FcTexture)             \
    S(FcMaterialTextures)    \
    S(FcTriTexcoords)        \
    S(FcSphere)              \
    S(FcInstance)            \
    S(FcDenoiseParams)

// clang-format off
#define FC_LAYOUT_FIELDS(F)                                                                                                 \
    F(FcBvhNode, lo_x) F(FcBvhNode, lo_y) F(FcBvhNode, lo_z) F(FcBvhNode, hi_x)                                             \
    F(FcBvhNode, hi_y) F(FcBvhNode, hi_z) F(FcBvhNode, index) F(FcBvhNode, count)                                           \
    F(FcBvhNode8, lo_x) F(FcBvhNode8, lo_y) F(FcBvhNode8, lo_z) F(FcBvhNode8, hi_x) F(FcBvhNode8, hi_y)                     \
    F(FcBvhNode8, hi_z) F(FcBvhNode8, index) F(FcBvhNode8, count)                                                           \
    F(FcBvhNodeQ, origin) F(FcBvhNodeQ, exps) F(FcBvhNodeQ, child_base) F(FcBvhNodeQ, leaf_base) F(FcBvhNodeQ, meta)        \
    F(FcBvhNodeQ, q_lo_x) F(FcBvhNodeQ, q_lo_y) F(FcBvhNodeQ, q_lo_z) F(FcBvhNodeQ, q_hi_x)                                 \
    F(FcBvhNodeQ, q_hi_y) F(FcBvhNodeQ, q_hi_z)                                                                             \
    F(FcTriBlock, x0) F(FcTriBlock, y0) F(FcTriBlock, z0) F(FcTriBlock, x1) F(FcTriBlock, y1)                              \
    F(FcTriBlock, z1) F(FcTriBlock, x2) F(FcTriBlock, y2) F(FcTriBlock, z2) F(FcTriBlock, tri)                              \
    F(FcTriangle, v0) F(FcTriangle, prim) F(FcTriangle, v1) F(FcTriangle, v2)                                               \
    F(FcTriShading, n0) F(FcTriShading, material) F(FcTriShading, n1) F(FcTriShading, light)                                \
    F(FcTriShading, n2)                                                                                                     \
    F(FcMaterial, diffuse) F(FcMaterial, diffuse_model) F(FcMaterial, specular) F(FcMaterial, specular_model)               \
    F(FcMaterial, emission) F(FcMaterial, ndf) F(FcMaterial, eta) F(FcMaterial, geometry)                                   \
    F(FcMaterial, k) F(FcMaterial, fresnel) F(FcMaterial, alpha_x) F(FcMaterial, alpha_y)                                   \
    F(FcMaterial, exponent_x) F(FcMaterial, exponent_y) F(FcMaterial, ior) F(FcMaterial, sigma)                             \
    F(FcMaterial, flags) F(FcMaterial, sampling) F(FcMaterial, metallic) F(FcMaterial, alpha) F(FcMaterial, alpha_cutoff)   \
    F(FcMaterial, alpha_texture) F(FcMaterial, attenuation) F(FcMaterial, clearcoat) F(FcMaterial, sheen)                   \
    F(FcMaterial, clearcoat_alpha) F(FcMaterial, sheen_roughness) F(FcMaterial, anisotropy) F(FcMaterial, anisotropy_direction) \
    F(FcMaterial, specular_f90) F(FcMaterial, clearcoat_normal) \
    F(FcLight, p0) F(FcLight, type) F(FcLight, e1) F(FcLight, prim)                                                         \
    F(FcLight, e2) F(FcLight, area) F(FcLight, color) F(FcLight, pick_pdf)                                                  \
    F(FcLight, cos_inner) F(FcLight, cos_outer) F(FcLight, flags) F(FcLight, n)                                             \
    F(FcCamera, eye) F(FcCamera, projection) F(FcCamera, forward) F(FcCamera, right)                                        \
    F(FcCamera, up) F(FcCamera, lens_radius) F(FcCamera, focus_distance)                                                    \
    F(FcRenderParams, camera) F(FcRenderParams, width) F(FcRenderParams, height) F(FcRenderParams, sample_begin)            \
    F(FcRenderParams, sample_count) F(FcRenderParams, seed) F(FcRenderParams, max_depth) F(FcRenderParams, rr_depth)        \
    F(FcRenderParams, light_count) F(FcRenderParams, row_begin) F(FcRenderParams, row_count) F(FcRenderParams, environment) \
    F(FcRenderParams, environment_light) F(FcRenderParams, strategy) F(FcRenderParams, sampler)                             \
    F(FcRenderParams, filter) F(FcRenderParams, filter_radius) F(FcRenderParams, clamp) F(FcRenderParams, roulette_gain)                                     \
    F(FcEnvironment, width) F(FcEnvironment, height) F(FcEnvironment, enabled) F(FcEnvironment, scale)                      \
    F(FcEnvironment, total) F(FcEnvironment, to_map)                                                                        \
    F(FcTexture, offset) F(FcTexture, width) F(FcTexture, height) F(FcTexture, levels) F(FcTexture, wrap_u)                 \
    F(FcTexture, wrap_v) F(FcTexture, format) F(FcTexture, mip_format) F(FcMaterialTextures, base_color) F(FcMaterialTextures, normal)               \
    F(FcMaterialTextures, base_factor) F(FcMaterialTextures, flags) F(FcMaterialTextures, uv_transform) F(FcMaterialTextures, clearcoat) F(FcMaterialTextures, clearcoat_normal_scale) F(FcMaterialTextures, specular_color_f0) F(FcMaterialTextures, specular_weight)                     \
    F(FcTriTexcoords, uv) F(FcTriTexcoords, tangent_flags) F(FcTriTexcoords, tangent)                                       \
    F(FcSphere, center) F(FcSphere, radius) F(FcSphere, material) F(FcSphere, light) F(FcSphere, flags)                     \
    F(FcSphere, prim)                                                                                                       \
    F(FcInstance, world_to_object) F(FcInstance, object_to_world) F(FcInstance, lo) F(FcInstance, root)                     \
    F(FcInstance, hi) F(FcInstance, tri_offset)                                                                             \
    F(FcDenoiseParams, width) F(FcDenoiseParams, height) F(FcDenoiseParams, radius) F(FcDenoiseParams, patch_radius)        \
    F(FcDenoiseParams, guides) F(FcDenoiseParams, variance_radius) F(FcDenoiseParams, variance_scale_a)                     \
    F(FcDenoiseParams, k_color) F(FcDenoiseParams, sigma_albedo) F(FcDenoiseParams, sigma_normal)                           \
    F(FcDenoiseParams, sigma_depth) F(FcDenoiseParams, variance_scale_b) F(FcDenoiseParams, width8) F(FcDenoiseParams, pad) \
    F(FcDenoiseParams, pitch) F(FcDenoiseParams, plane)
// clang-format on

#endif
