#!/usr/bin/env python3
"""Translates facet's four demo scenes into Mitsuba 3 (bench/mitsuba/README section of
bench/README.md, "Mitsuba 3 baseline").

Two jobs:

  translate.py scenes      writes, once, the committed files of bench/mitsuba/:
                           <scene>.xml (the Mitsuba scene) and, for the scenes whose
                           materials Mitsuba lacks, <scene>.json (the facet scene both
                           renderers then draw: the demo scene with those materials
                           replaced by the nearest model both renderers share).
  translate.py assets DIR  writes the geometry the XML files load (one PLY per mesh
                           shape, facet's own triangles; analytic spheres are Mitsuba
                           `sphere` shapes in the XML) and the
                           environment map, under DIR; run by equal_time.py before
                           rendering (deterministic, a second or two).

Conventions (checked by equal_time.py --check, which compares the two renderers'
long renders region by region):
  * camera: facet's vertical fov -> Mitsuba perspective with fov_axis y, look-at;
  * depth: facet max_depth counts path vertices after the camera (1 = direct light),
    Mitsuba's counts segments (2 = direct light): Mitsuba max_depth = facet + 1;
    Russian roulette: facet applies it after the bounce at vertex d when d + 1 >=
    rr_depth, Mitsuba when its depth (incremented after that same bounce) >= rr_depth:
    the same number; facet survives with max(throughput) (<= 0.95), Mitsuba with
    max(throughput) * eta^2 (<= 0.95), which changes variance only;
  * pixel filter: a 1-pixel box (Mitsuba `box`, radius 0.5);
  * facet shades both sides of every surface: opaque BSDFs are wrapped in `twosided`;
  * facet's smooth lobes inside a blend (a mirror beside a diffuse lobe) become rough
    ones of alpha 1e-3 (Mitsuba 3.9.1's blendbsdf is biased with a delta component);
    a smooth dielectric alone stays Mitsuba's delta `dielectric` (no blend, no bias);
  * Mitsuba's microfacet models use the separable Smith G: the facet side uses
    `"geometry": "smith_separable"` (facet's presets use the height-correlated one);
  * Mitsuba has no Schlick Fresnel: F0 = 0.04-like lobes become the exact dielectric
    Fresnel of the index with that F0 (1.5 for 0.04), on both sides (Mitsuba:
    roughconductor with eta = that index and k = 0, which is the same function);
  * facet's diffuse + specular sum is Mitsuba's blendbsdf with weight w = facet's
    specular-lobe probability at normal incidence, each component divided by its weight (w at most 1 - max(rho): a
    diffuse reflectance above 1 is refused by Mitsuba).
"""
import json
import math
import os
import struct
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENES = ["cornell_box", "spheres_sky", "material_grid", "glass_metal_sky"]
ALPHA_MIRROR = 1e-4          # facet's FC_ALPHA_MIRROR
ALPHA_SMOOTH_IN_BLEND = 1e-3  # the rough stand-in for a delta lobe inside a blendbsdf
ENV_UPSAMPLE = 2             # for facet's nearest lookup (the default), Mitsuba, which
                             # interpolates bilinearly, gets each texel repeated 2 x 2:
                             # its blur is a quarter texel wide (write_sky); for the
                             # bilinear lookup, a map it interpolates exactly as facet

# facet's tables (host/scene/material.cpp), copied: the XML must hold numbers.
CONDUCTORS = {
    "gold": ([0.188, 0.543, 1.33], [3.40, 2.23, 1.87]),
    "silver": ([0.056, 0.054, 0.047], [4.28, 3.43, 2.81]),
    "copper": ([0.271, 1.10, 1.24], [3.41, 2.59, 2.40]),
    "aluminium": ([1.37, 0.958, 0.665], [7.62, 6.69, 5.66]),
    "aluminum": ([1.37, 0.958, 0.665], [7.62, 6.69, 5.66]),
    "iron": ([2.88, 2.80, 2.55], [3.05, 2.95, 2.80]),
}
F0_PRESETS = {"water": 0.02, "plastic": 0.03, "plastic_low": 0.03, "glass": 0.03,
              "glass_low": 0.03, "plastic_high": 0.05, "glass_high": 0.08, "ruby": 0.08,
              "diamond": 0.17}


def luminance(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def ior_from_f0(f0):
    r = math.sqrt(f0)
    return (1.0 + r) / (1.0 - r)


def fresnel_dielectric(cos_i, eta):
    """Unpolarised Fresnel reflectance, light arriving from the outside (index 1)."""
    sin2_t = (1.0 - cos_i * cos_i) / (eta * eta)
    if sin2_t >= 1.0:
        return 1.0
    cos_t = math.sqrt(1.0 - sin2_t)
    rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
    rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    return 0.5 * (rs * rs + rp * rp)


def fmt3(v):
    return ", ".join(f"{x:.9g}" for x in v)


# --------------------------------------------------------------------------------------
# Materials

class Translated:
    """One facet material: what facet renders (a JSON material) and its Mitsuba BSDF."""

    def __init__(self, facet, bsdf_xml, note=None):
        self.facet = facet
        self.bsdf_xml = bsdf_xml
        self.note = note


def rgb(name, v):
    return f'<rgb name="{name}" value="{fmt3(v)}"/>'


def twosided(inner):
    return f'<bsdf type="twosided">\n    {inner}\n</bsdf>'


def diffuse_xml(rho):
    return f'<bsdf type="diffuse">{rgb("reflectance", rho)}</bsdf>'


def roughconductor_xml(distribution, alpha, eta, k, scale=1.0):
    eta = eta if isinstance(eta, list) else [eta] * 3
    k = k if isinstance(k, list) else [k] * 3
    # A float (Mitsuba's `uniform` spectrum): an <rgb> reflectance must lie in [0, 1].
    extra = "" if scale == 1.0 else f'<float name="specular_reflectance" value="{scale:.9g}"/>'
    return (f'<bsdf type="roughconductor"><string name="distribution" value="{distribution}"/>'
            f'<float name="alpha" value="{alpha:.9g}"/>{rgb("eta", eta)}{rgb("k", k)}{extra}</bsdf>')


def glossy(name, diffuse, diffuse_model, ndf, alpha, ior, note):
    """Diffuse (lambert or lambert x (1 - F0)) + microfacet lobe with the exact dielectric
    Fresnel of index `ior`, separable Smith G: the model both renderers share."""
    facet = {"model": "microfacet", "diffuse": diffuse, "diffuse_model": diffuse_model,
             "specular_model": "microfacet", "ndf": ndf, "geometry": "smith_separable",
             "fresnel": "dielectric", "ior": round(ior, 6), "roughness": alpha}
    f0 = fresnel_dielectric(1.0, ior)
    rho = [c * (1.0 - f0) for c in diffuse] if diffuse_model == "lambert_1mf0" else list(diffuse)
    # facet's specular_probability at normal incidence (kernels/bsdf/bsdf.cl).
    s, d = f0, max(luminance(rho), 0.0)
    w = min(max(s / (s + d), 0.05), 0.95) if s + d > 0 else 0.5
    w = min(w, 1.0 - max(rho))   # the diffuse component rho / (1 - w) must stay <= 1
    mi_alpha = alpha if alpha >= ALPHA_MIRROR else ALPHA_SMOOTH_IN_BLEND
    if max(rho) <= 0.0:
        xml = twosided(roughconductor_xml(ndf, mi_alpha, ior, 0.0))
    else:
        inner = (f'<bsdf type="blendbsdf"><float name="weight" value="{w:.9g}"/>\n'
                 f'        {diffuse_xml([c / (1.0 - w) for c in rho])}\n'
                 f'        {roughconductor_xml(ndf, mi_alpha, ior, 0.0, 1.0 / w)}\n    </bsdf>')
        xml = twosided(inner)
    if alpha < ALPHA_MIRROR:
        note = (note + "; " if note else "") + "mirror: Mitsuba alpha 1e-3 (blendbsdf)"
    return Translated(facet, xml, note)


def conductor(name, eta, k, alpha, note=None):
    facet = {"model": "conductor", "eta": eta, "k": k, "roughness": alpha,
             "geometry": "smith_separable"}
    if alpha < ALPHA_MIRROR:
        xml = twosided(f'<bsdf type="conductor">{rgb("eta", eta)}{rgb("k", k)}</bsdf>')
    else:
        xml = twosided(roughconductor_xml("ggx", alpha, eta, k))
    return Translated(facet, xml, note)


def translate_material(name, m):
    model = m.get("model", "lambert")
    diffuse = m.get("diffuse", [0.5, 0.5, 0.5])
    rough = m.get("roughness", 0.3)
    emission = m.get("emission")
    if m.get("two_sided_emission"):
        raise SystemExit(f"{name}: two-sided emission is not translated")

    if model in ("lambert", "oren_nayar"):
        t = Translated({"model": "lambert", "diffuse": diffuse}, twosided(diffuse_xml(diffuse)),
                       None if model == "lambert" else "Oren-Nayar -> Lambert (Mitsuba 3 has no Oren-Nayar)")
    elif model == "dielectric":
        ior = m.get("ior", 1.5)
        trans = m.get("transmittance", [1.0, 1.0, 1.0])
        alpha = m.get("roughness", 0.0)
        ndf = m.get("ndf", "ggx")
        facet = dict(m)
        common = (f'<float name="int_ior" value="{ior:.9g}"/><float name="ext_ior" value="1"/>'
                  + ("" if trans == [1.0, 1.0, 1.0] else rgb("specular_transmittance", trans)))
        if alpha < ALPHA_MIRROR:
            xml = f'<bsdf type="dielectric">{common}</bsdf>'
            note = None
        else:
            facet["geometry"] = "smith_separable"
            xml = (f'<bsdf type="roughdielectric"><string name="distribution" value="{ndf}"/>'
                   f'<float name="alpha" value="{alpha:.9g}"/>{common}</bsdf>')
            note = "separable Smith G"
        t = Translated(facet, xml, note)
    elif model == "conductor":
        metal = m.get("conductor", "aluminium")
        eta, k = CONDUCTORS[metal]
        note = "separable Smith G"
        if m.get("fresnel") == "schlick":
            note = "Schlick F0 -> the metal's exact conductor Fresnel (Mitsuba has no Schlick)"
        t = conductor(name, eta, k, rough, note)
        t.facet = {"model": "conductor", "conductor": metal, "roughness": rough,
                   "geometry": "smith_separable"}
    elif model == "ggx":
        f0 = m.get("f0", m.get("specular", [0.04, 0.04, 0.04]))
        if isinstance(f0, str) and f0 in CONDUCTORS and max(diffuse) == 0.0:
            eta, k = CONDUCTORS[f0]
            t = conductor(name, eta, k, rough, f"Schlick F0 '{f0}' -> {f0}'s conductor Fresnel")
            t.facet = {"model": "conductor", "conductor": f0, "roughness": rough,
                       "geometry": "smith_separable"}
        else:
            f0v = F0_PRESETS[f0] if isinstance(f0, str) else luminance(f0)
            t = glossy(name, diffuse, "lambert_1mf0", "ggx", rough, ior_from_f0(f0v),
                       "Schlick F0 -> exact dielectric Fresnel; separable Smith G")
    elif model in ("cook_torrance", "blinn_phong", "blinn_phong_normalized", "ashikhmin_shirley"):
        f0 = m.get("f0", m.get("specular", [0.04, 0.04, 0.04]))
        f0v = F0_PRESETS[f0] if isinstance(f0, str) else luminance(f0)
        diffuse_model = "lambert_1mf0" if model == "ashikhmin_shirley" else "lambert"
        note = {"cook_torrance": "Cook-Torrance G and Schlick F -> separable Smith G, exact dielectric F",
                "blinn_phong": "Blinn-Phong lobe (Ks, no Fresnel) -> Beckmann of the same m, dielectric F with F0 = Ks",
                "blinn_phong_normalized": "normalized Blinn-Phong -> Beckmann of the same m, dielectric F with F0 = Ks",
                "ashikhmin_shirley": "Ashikhmin-Shirley -> Lambert x (1 - F0) + Beckmann of the same m, dielectric F"}[model]
        t = glossy(name, diffuse, diffuse_model, "beckmann", rough, ior_from_f0(f0v), note)
    else:
        raise SystemExit(f"{name}: model '{model}' is not translated")

    if emission:
        t.facet["emission"] = emission
    t.emission = emission
    return t


# --------------------------------------------------------------------------------------
# Geometry: facet's own triangles (host/scene/shapes.cpp, tinyobjloader's triangulation)

def icosphere(center, radius, subdivisions, inward):
    f32 = np.float32
    t = f32(0.5) * (f32(1.0) + np.sqrt(f32(5.0)))
    verts = [np.array(v, dtype=f32) for v in
             [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
              (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    verts = [v / np.sqrt(np.dot(v, v)) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        mid = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                v = verts[a] + verts[b]
                verts.append((v / np.sqrt(np.dot(v, v))).astype(f32))
                mid[key] = len(verts) - 1
            return mid[key]
        out = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = out
    v = np.array(verts, dtype=f32) * f32(radius) + np.array(center, dtype=f32)
    f = np.array(faces, dtype=np.int32)
    if inward:
        f = f[:, [0, 2, 1]]
    return v, f


def quad(corner, e1, e2):
    c, e1, e2 = (np.array(x, dtype=np.float32) for x in (corner, e1, e2))
    v = np.array([c, c + e1, c + e1 + e2, c + e2], dtype=np.float32)
    return v, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32)


def read_obj_by_material(path):
    """Triangles of an OBJ grouped by `usemtl`, quads split along the shorter diagonal."""
    verts, groups, current = [], {}, None
    with open(path) as f:
        for line in f:
            tok = line.split()
            if not tok:
                continue
            if tok[0] == "v":
                verts.append([float(x) for x in tok[1:4]])
            elif tok[0] == "usemtl":
                current = tok[1]
            elif tok[0] == "f":
                idx = [int(x.split("/")[0]) for x in tok[1:]]
                idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
                tris = groups.setdefault(current, [])
                if len(idx) == 4:
                    p = [np.array(verts[i]) for i in idx]
                    if np.sum((p[2] - p[0]) ** 2) < np.sum((p[3] - p[1]) ** 2):
                        tris += [(idx[0], idx[1], idx[2]), (idx[0], idx[2], idx[3])]
                    else:
                        tris += [(idx[0], idx[1], idx[3]), (idx[1], idx[2], idx[3])]
                else:
                    tris += [(idx[0], idx[i], idx[i + 1]) for i in range(1, len(idx) - 1)]
    v = np.array(verts, dtype=np.float32)
    return {name: (v, np.array(t, dtype=np.int32)) for name, t in groups.items()}


def read_mtl(path):
    mats, cur = {}, None
    with open(path) as f:
        for line in f:
            tok = line.split()
            if not tok or tok[0].startswith("#"):
                continue
            if tok[0] == "newmtl":
                cur = mats.setdefault(tok[1], {})
            elif tok[0] in ("Kd", "Ke"):
                cur[tok[0]] = [float(x) for x in tok[1:4]]
            elif tok[0] in ("Ks", "illum", "Pr", "Pm", "Tf"):
                raise SystemExit(f"{path}: {tok[0]} is not translated")
    return mats


def write_ply(path, v, f):
    with open(path, "wb") as out:
        out.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\n"
                   "property float x\nproperty float y\nproperty float z\n"
                   f"element face {len(f)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        out.write(np.ascontiguousarray(v, dtype="<f4").tobytes())
        rows = np.zeros(len(f), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rows["n"] = 3
        rows["i"] = f
        out.write(rows.tobytes())


# --------------------------------------------------------------------------------------
# Scenes

def load_json(path):
    with open(path) as f:
        return json.load(f)


def scene_shapes(name, scene):
    """[(ply_name, vertices, faces, facet material)] of a facet JSON scene; an analytic
    sphere is (None, (center, radius, inward), None, material)."""
    out = []
    if name == "cornell_box":
        groups = read_obj_by_material(os.path.join(ROOT, "scenes", "cornell_box.obj"))
        for mat, (v, f) in groups.items():
            out.append((f"{mat}.ply", v, f, mat))
        return out
    for i, s in enumerate(scene["shapes"]):
        if s["type"] == "sphere" and not s.get("tessellate", False):
            # facet's spheres are analytic (docs/spheres.md): Mitsuba's `sphere` shape.
            out.append((None, (s["center"], s["radius"], s.get("inward", False)), None, s["material"]))
            continue
        if s["type"] == "sphere":
            v, f = icosphere(s["center"], s["radius"], s.get("subdivisions", 3), s.get("inward", False))
        else:
            v, f = quad(s["corner"], s["edge1"], s["edge2"])
        out.append((f"{i:02d}_{s['material']}.ply", v, f, s["material"]))
    return out


def scene_materials(name, scene):
    if name == "cornell_box":
        mtl = read_mtl(os.path.join(ROOT, "scenes", "cornell_box.mtl"))
        return {k: {"model": "lambert", "diffuse": v["Kd"], **({"emission": v["Ke"]} if "Ke" in v else {})}
                for k, v in mtl.items()}
    return scene["materials"]


def mitsuba_xml(name, scene, materials, shapes):
    cam, r = scene["camera"], scene["render"]
    if cam.get("projection", "perspective") != "perspective":
        raise SystemExit(f"{name}: only perspective cameras are translated")
    lines = ['<?xml version="1.0" encoding="utf-8"?>',
             f'<!-- facet scenes/{name}.json translated by bench/mitsuba/translate.py: do not edit. -->',
             '<scene version="3.0.0">',
             '    <default name="assets" value="../../out/bench/mitsuba/assets"/>',
             '    <default name="sampler" value="independent"/>',
             '    <default name="spp" value="16"/>',
             '    <default name="seed" value="0"/>',
             f'    <default name="width" value="{r["width"]}"/>',
             f'    <default name="height" value="{r["height"]}"/>',
             f'    <!-- facet max_depth {r["max_depth"]} (vertices after the camera) = Mitsuba {r["max_depth"] + 1} (segments) -->',
             '    <integrator type="path">',
             f'        <integer name="max_depth" value="{r["max_depth"] + 1}"/>',
             f'        <integer name="rr_depth" value="{r["rr_depth"]}"/>',
             '    </integrator>',
             '    <sensor type="perspective">',
             '        <string name="fov_axis" value="y"/>',
             f'        <float name="fov" value="{cam["fov"]:.9g}"/>',
             '        <transform name="to_world">',
             f'            <lookat origin="{fmt3(cam["eye"])}" target="{fmt3(cam["target"])}" up="{fmt3(cam.get("up", [0, 1, 0]))}"/>',
             '        </transform>',
             '        <sampler type="$sampler">',
             '            <integer name="sample_count" value="$spp"/>',
             '            <integer name="seed" value="$seed"/>',
             '        </sampler>',
             '        <film type="hdrfilm">',
             '            <integer name="width" value="$width"/>',
             '            <integer name="height" value="$height"/>',
             '            <string name="pixel_format" value="rgb"/>',
             '            <rfilter type="box"/>',
             '        </film>',
             '    </sensor>']
    for mname, t in materials.items():
        if t.note:
            lines.append(f'    <!-- {mname}: {t.note} -->')
        bsdf = t.bsdf_xml.replace("<bsdf type=", f'<bsdf id="{mname}" type=', 1)
        lines += ["    " + l for l in bsdf.split("\n")]
    for ply, geometry, _, mname in shapes:
        if ply is None:
            center, radius, inward = geometry
            lines.append('    <shape type="sphere">')
            lines.append('        <point name="center" x="{:.9g}" y="{:.9g}" z="{:.9g}"/>'.format(*center))
            lines.append(f'        <float name="radius" value="{radius:.9g}"/>')
            if inward:
                lines.append('        <boolean name="flip_normals" value="true"/>')
        else:
            lines.append('    <shape type="ply">')
            lines.append(f'        <string name="filename" value="$assets/{name}/{ply}"/>')
            lines.append('        <boolean name="face_normals" value="true"/>')
        lines.append(f'        <ref id="{mname}"/>')
        if materials[mname].emission:
            lines.append(f'        <emitter type="area">{rgb("radiance", materials[mname].emission)}</emitter>')
        lines.append('    </shape>')
    env = scene.get("environment")
    if env:
        if "sky" not in env or "rotate" in env or isinstance(env.get("scale", 1.0), list):
            raise SystemExit(f"{name}: only an unrotated sky with a scalar scale is translated")
        lines += ['    <emitter type="envmap">',
                  f'        <string name="filename" value="$assets/{sky_file(env)}"/>',
                  f'        <float name="scale" value="{env.get("scale", 1.0):.9g}"/>',
                  '    </emitter>']
    lines.append('</scene>')
    return "\n".join(lines) + "\n"


def sky_args(sky):
    return ["--width", str(sky.get("width", 1024)), "--elevation", str(sky.get("elevation", 25)),
            "--azimuth", str(sky.get("azimuth", 40)), "--turbidity", str(sky.get("turbidity", 3))]


def env_filter(env):
    return env.get("filter", "nearest")


def sky_file(env):
    kind = "bilinear" if env_filter(env) == "bilinear" else f"x{ENV_UPSAMPLE}"
    return "sky_" + "_".join(sky_args(env["sky"])[1::2]) + f"_{kind}.exr"


def facet_scene_path(name):
    """The facet scene both renderers draw (relative to the repository root)."""
    variant = os.path.join("bench", "mitsuba", f"{name}.json")
    return variant if os.path.exists(os.path.join(ROOT, variant)) else os.path.join("scenes", f"{name}.json")


def translate_scenes():
    for name in SCENES:
        scene = load_json(os.path.join(ROOT, "scenes", f"{name}.json"))
        mats = {k: translate_material(k, v) for k, v in scene_materials(name, scene).items()}
        shapes = scene_shapes(name, scene)
        used = {s[3] for s in shapes}
        mats = {k: v for k, v in mats.items() if k in used}
        with open(os.path.join(HERE, f"{name}.xml"), "w") as f:
            f.write(mitsuba_xml(name, scene, mats, shapes))
        if name != "cornell_box":
            variant = dict(scene)
            variant["materials"] = {k: v.facet for k, v in mats.items()}
            with open(os.path.join(HERE, f"{name}.json"), "w") as f:
                json.dump(variant, f, indent=1)
                f.write("\n")
        changed = {k: v.note for k, v in mats.items() if v.note}
        print(f"{name}: {len(shapes)} shapes, {len(mats)} materials" +
              "".join(f"\n  {k}: {n}" for k, n in changed.items()))


def write_sky(facet, env, out_dir):
    """The environment for Mitsuba: facet's map (`facet sky`, W x H), made into the map
    Mitsuba's bilinear interpolation reads as facet reads its own. Mitsuba puts column i
    at phi = 2 pi (i + 0.5) / W (wrapping around), as facet does, and row k of H' rows at
    theta = pi k / (H' - 1).
      * facet's nearest lookup (the default): each texel repeated 2 x 2, the rows so
        that each of Mitsuba's takes the facet texel its direction falls in; Mitsuba's
        interpolation still blurs the map by a quarter texel (an exact copy would need
        a far larger map, which slows Mitsuba down: bench/README.md).
      * facet's bilinear lookup ("filter": "bilinear"): W x (2H + 1), exact. facet row
        y's centre is at theta = pi (y + 0.5) / H and facet holds the first and last rows
        constant toward the poles: row 2 y + 1 is facet's row y, row 2 y between them is
        their mean (facet's value half-way between the centres, where its interpolation
        is linear), rows 0 and 2 H are facet's first and last rows; between two of these
        rows both interpolate linearly along the same segment."""
    import mitsuba as mi
    if mi.variant() is None:
        mi.set_variant("scalar_rgb")
    path = os.path.join(out_dir, sky_file(env))
    if os.path.exists(path):
        return path
    raw = os.path.join(out_dir, "sky_facet.exr")
    subprocess.run([facet, "sky", raw] + sky_args(env["sky"]), check=True, stdout=subprocess.DEVNULL)
    src = np.array(mi.Bitmap(raw).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, False),
                   dtype=np.float64)
    h, w = src.shape[:2]
    if env_filter(env) == "bilinear":
        big = np.empty((2 * h + 1, w, 3))
        big[1::2] = src
        big[2:-1:2] = 0.5 * (src[:-1] + src[1:])
        big[0], big[-1] = src[0], src[-1]
    else:
        k = ENV_UPSAMPLE
        rows = np.minimum((np.arange(k * h) / (k * h - 1) * h).astype(np.int64), h - 1)
        cols = np.minimum(((np.arange(k * w) + 0.5) / (k * w) * w).astype(np.int64), w - 1)
        big = src[rows][:, cols]
    big = np.ascontiguousarray(big.astype(np.float32))
    mi.Bitmap(big, mi.Bitmap.PixelFormat.RGB).write(path)
    os.remove(raw)
    return path


def write_assets(out_dir, facet):
    os.makedirs(out_dir, exist_ok=True)
    for name in SCENES:
        scene = load_json(os.path.join(ROOT, "scenes", f"{name}.json"))
        d = os.path.join(out_dir, name)
        os.makedirs(d, exist_ok=True)
        for ply, v, f, _ in scene_shapes(name, scene):
            if ply is None:
                continue  # an analytic sphere: in the XML itself
            p = os.path.join(d, ply)
            if not os.path.exists(p):
                write_ply(p, v, f)
        env = scene.get("environment")
        if env and "sky" in env:
            write_sky(facet, env, out_dir)


def main(argv):
    if len(argv) >= 2 and argv[1] == "scenes":
        translate_scenes()
    elif len(argv) >= 3 and argv[1] == "assets":
        facet = argv[3] if len(argv) > 3 else os.path.join(ROOT, "build", "facet")
        write_assets(argv[2], facet)
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
