/* The closed list of kernel features: code paths that a scene may not need and that
 * the host leaves out of its program (host/render/features.cpp decides, per scene).
 * Each FC_HAS_* is 1 unless the program's prelude defines it as 0, so a program built
 * with no prelude is the generic one (every feature, chosen at run time), the
 * reference `--generic` renders with. Add a feature here, in FC_FEATURE_LIST, and in
 * features.cpp's scene analysis; tests/features_test.cpp exercises every one. */
#ifndef FACET_SHARED_FEATURE_FLAGS_H
#define FACET_SHARED_FEATURE_FLAGS_H

/* X(name, bit) for every feature. */
#define FC_FEATURE_LIST(X)    \
    X(AREA_LIGHTS, 0)         \
    X(PUNCTUAL_LIGHTS, 1)     \
    X(ENVIRONMENT, 2)         \
    X(OREN_NAYAR, 3)          \
    X(ASHIKHMIN_SHIRLEY, 4)   \
    X(BLINN_PHONG, 5)         \
    X(MICROFACET, 6)          \
    X(BECKMANN, 7)            \
    X(DIELECTRIC, 8)          \
    X(TEXTURES, 9)            \
    X(SPHERES, 10)            \
    X(INSTANCES, 11)          \
    X(METALLIC, 12)           \
    X(ALPHA, 13)              \
    X(VOLUME, 14)             \
    X(CLEARCOAT, 15)          \
    X(SHEEN, 16)              \
    X(ANISOTROPY, 17)         \
    X(CLEARCOAT_TEXTURES, 18) \
    X(SHEEN_TEXTURES, 19)     \
    X(SPECULAR_TEXTURES, 20)  \
    X(CLEARCOAT_NORMAL, 21)

#ifndef FC_HAS_AREA_LIGHTS
#define FC_HAS_AREA_LIGHTS 1
#endif
#ifndef FC_HAS_PUNCTUAL_LIGHTS
#define FC_HAS_PUNCTUAL_LIGHTS 1
#endif
#ifndef FC_HAS_ENVIRONMENT
#define FC_HAS_ENVIRONMENT 1
#endif
#ifndef FC_HAS_OREN_NAYAR
#define FC_HAS_OREN_NAYAR 1
#endif
#ifndef FC_HAS_ASHIKHMIN_SHIRLEY
#define FC_HAS_ASHIKHMIN_SHIRLEY 1
#endif
#ifndef FC_HAS_BLINN_PHONG
#define FC_HAS_BLINN_PHONG 1
#endif
#ifndef FC_HAS_MICROFACET
#define FC_HAS_MICROFACET 1
#endif
#ifndef FC_HAS_BECKMANN
#define FC_HAS_BECKMANN 1
#endif
#ifndef FC_HAS_DIELECTRIC
#define FC_HAS_DIELECTRIC 1
#endif
#ifndef FC_HAS_TEXTURES
#define FC_HAS_TEXTURES 1
#endif
#ifndef FC_HAS_SPHERES
#define FC_HAS_SPHERES 1
#endif
#ifndef FC_HAS_INSTANCES
#define FC_HAS_INSTANCES 1
#endif
#ifndef FC_HAS_METALLIC
#define FC_HAS_METALLIC 1
#endif
/* Alpha cut-outs and stochastic transparency: the any-hit test in traversal
 * (kernels/trace/alpha_test.cl). */
#ifndef FC_HAS_ALPHA
#define FC_HAS_ALPHA 1
#endif
/* Beer-Lambert absorption inside transmissive materials (FcMaterial.attenuation,
 * kernels/integrator/path.cl). */
#ifndef FC_HAS_VOLUME
#define FC_HAS_VOLUME 1
#endif
#ifndef FC_HAS_CLEARCOAT
#define FC_HAS_CLEARCOAT 1
#endif
#ifndef FC_HAS_SHEEN
#define FC_HAS_SHEEN 1
#endif
/* Shading frames that follow the surface's tangent for FC_MAT_ANISOTROPIC materials
 * (kernels/bsdf/anisotropy.cl, kernels/integrator/surface.cl). */
#ifndef FC_HAS_ANISOTROPY
#define FC_HAS_ANISOTROPY 1
#endif
/* The glTF extensions' textures (kernels/texture/extension_textures.cl): the clearcoat's
 * weight and roughness, the sheen's colour and roughness, KHR_materials_specular per hit. */
#ifndef FC_HAS_CLEARCOAT_TEXTURES
#define FC_HAS_CLEARCOAT_TEXTURES 1
#endif
#ifndef FC_HAS_SHEEN_TEXTURES
#define FC_HAS_SHEEN_TEXTURES 1
#endif
#ifndef FC_HAS_SPECULAR_TEXTURES
#define FC_HAS_SPECULAR_TEXTURES 1
#endif
/* The clearcoat's own normal (FC_MAT_CLEARCOAT_NORMAL): its normal map, or the surface's normal
 * under a base normal map, and the coat lobe evaluated in that frame (kernels/bsdf/clearcoat.cl). */
#ifndef FC_HAS_CLEARCOAT_NORMAL
#define FC_HAS_CLEARCOAT_NORMAL 1
#endif

#endif
