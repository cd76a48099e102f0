#!/usr/bin/env python3
"""Builds facet's demo scenes in Blender Cycles through PyPI's `bpy` module (bench/README.md,
"Blender Cycles baseline").

build(name, ...), imported by equal_time.py, builds in memory, in bpy's current scene, the
facet scene both renderers draw: the Mitsuba bench's (bench/mitsuba/<scene>.json, the
demo scene with its materials reduced to the models the renderers share, or
scenes/<scene>.json where nothing needed replacing), with Cycles' unbiased settings.
facet's JSON, OBJ and MTL are read by bench/mitsuba/translate.py's readers
(facet_scene_path, scene_shapes, scene_materials, the conductor table), loaded here.

Conventions:
  * coordinates are facet's (y up) unchanged; only the environment lookup cares about the
    up axis, and the world shader turns facet's direction d into Cycles' (d.z, d.x, d.y):
    Cycles' equirectangular map puts u = 0.5 - atan2(y, x) / 2pi and the top row at +z,
    facet's (kernels/shared/environment_layout.h) u = phi / 2pi, v = theta / pi with
    d = (sin theta sin phi, cos theta, -sin theta cos phi): the same texel for both;
  * environment map: `facet sky`'s EXR itself, Cycles' `Closest` interpolation (facet's
    default nearest lookup), the scene's scale as the background strength;
  * camera: vertical fov (sensor fit vertical), look-at as facet's;
  * depth: facet max_depth counts path vertices after the camera (1 = direct light),
    Cycles' max_bounces counts bounces (0 = direct light): Cycles = facet - 1, for every
    kind of bounce (diffuse, glossy, transmission, transparent);
  * pixel filter: box of width 1 pixel; no clamping, no glossy filter (blur_glossy 0),
    caustics on, no adaptive sampling, no denoiser (unless asked), no light threshold;
  * facet's analytic spheres: Cycles point clouds (a one-vertex mesh made into a point of
    that radius by a geometry-nodes modifier), which Cycles intersects as true spheres;
    a dielectric sphere is an icosphere of 81920 triangles shaded smooth instead (a ray
    refracted into a point-cloud sphere cannot leave it: Cycles skips the exit as a hit
    on the same primitive);
  * one-sided emission (facet's area lights emit on the winding's front side): emission
    strength 1 - Backfacing, and emission sampling of the front side only;
  * roughness: facet's is the microfacet alpha, Cycles' roughness is sqrt(alpha);
  * Lambert -> Diffuse BSDF (roughness 0); conductor (eta, k) -> Metallic BSDF with the
    physical-conductor Fresnel, GGX (single scattering, as facet); diffuse + microfacet lobe
    with dielectric Fresnel -> Add Shader of a Diffuse BSDF (rho, or rho (1 - F0) for
    lambert_1mf0) and a Metallic BSDF with ior = the index, extinction 0 (the conductor
    Fresnel with k = 0 is the dielectric Fresnel); dielectric -> Glass BSDF (GGX or
    Beckmann, roughness sqrt(alpha); sharp at alpha 0).

Not matched (and so what the agreement check of equal_time.py --check may show):
  * Cycles' Glass BSDF colour tints the reflected part as well; facet's transmittance
    tints refraction only (glass_metal_sky's water_tinted);
  * the Smith G term: facet's side keeps the separable G of the Mitsuba bench's files;
    measured, Cycles' rough lobes agree with it (material_grid, 150 x 175, every sphere
    within noise), and come out 1-10 % darker than facet's height-correlated G at
    alpha >= 0.5;
  * Russian roulette differs (Cycles' own rule): variance only;
  * Cycles' light tree and its background importance map: variance only.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True   # no __pycache__ in the source tree


def _load_facet_readers():
    """bench/mitsuba/translate.py, the readers of facet's scenes, under its own name (this
    file is also called translate.py)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(
        "mitsuba_translate", os.path.join(ROOT, "bench", "mitsuba", "translate.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


facet_scene = _load_facet_readers()

SCENES = facet_scene.SCENES
ALPHA_MIRROR = facet_scene.ALPHA_MIRROR
GLASS_SUBDIVISIONS = 6   # icosphere of 81920 triangles, shaded smooth, for a dielectric sphere


facet_scene_path = facet_scene.facet_scene_path


# --------------------------------------------------------------------------------------
# Materials

def _nodes(mat):
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"
    return nt, out


def _metallic(nt, distribution, alpha, eta, k):
    n = nt.nodes.new("ShaderNodeBsdfMetallic")
    n.distribution = distribution
    n.fresnel_type = "PHYSICAL_CONDUCTOR"
    eta = eta if isinstance(eta, list) else [eta] * 3
    k = k if isinstance(k, list) else [k] * 3
    n.inputs["IOR"].default_value = eta
    n.inputs["Extinction"].default_value = k
    n.inputs["Roughness"].default_value = math.sqrt(alpha) if alpha >= ALPHA_MIRROR else 0.0
    return n


def _diffuse(nt, rho):
    n = nt.nodes.new("ShaderNodeBsdfDiffuse")
    n.inputs["Color"].default_value = list(rho) + [1.0]
    n.inputs["Roughness"].default_value = 0.0
    return n


def _ndf(name):
    return {"ggx": "GGX", "beckmann": "BECKMANN"}[name]


def surface(nt, m, name):
    """The BSDF node of facet material m (one of the models the bench scenes use)."""
    model = m.get("model", "lambert")
    if model == "lambert":
        return _diffuse(nt, m.get("diffuse", [0.5, 0.5, 0.5]))
    if model == "conductor":
        eta, k = facet_scene.CONDUCTORS[m["conductor"]]
        return _metallic(nt, "GGX", m.get("roughness", 0.3), eta, k)
    if model == "microfacet":
        if m.get("fresnel") != "dielectric" or m.get("specular_model") != "microfacet":
            raise SystemExit(f"{name}: only the dielectric-Fresnel microfacet lobe is translated")
        ior = m["ior"]
        rho = m.get("diffuse", [0.5, 0.5, 0.5])
        if m.get("diffuse_model") == "lambert_1mf0":
            f0 = facet_scene.fresnel_dielectric(1.0, ior)
            rho = [c * (1.0 - f0) for c in rho]
        spec = _metallic(nt, _ndf(m.get("ndf", "ggx")), m.get("roughness", 0.3), ior, 0.0)
        if max(rho) <= 0.0:
            return spec
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(_diffuse(nt, rho).outputs[0], add.inputs[0])
        nt.links.new(spec.outputs[0], add.inputs[1])
        return add
    if model == "dielectric":
        n = nt.nodes.new("ShaderNodeBsdfGlass")
        alpha = m.get("roughness", 0.0)
        n.distribution = _ndf(m.get("ndf", "ggx"))
        n.inputs["Roughness"].default_value = math.sqrt(alpha) if alpha >= ALPHA_MIRROR else 0.0
        n.inputs["IOR"].default_value = m.get("ior", 1.5)
        n.inputs["Color"].default_value = list(m.get("transmittance", [1.0, 1.0, 1.0])) + [1.0]
        return n
    raise SystemExit(f"{name}: model '{model}' is not translated to Cycles")


def material(bpy, name, m):
    mat = bpy.data.materials.new(name)
    nt, out = _nodes(mat)
    shader = surface(nt, m, name)
    emission = m.get("emission")
    if emission and max(emission) > 0.0:
        # One-sided: strength 1 - Backfacing (facet emits on the front side only).
        em = nt.nodes.new("ShaderNodeEmission")
        em.inputs["Color"].default_value = list(emission) + [1.0]
        geo = nt.nodes.new("ShaderNodeNewGeometry")
        inv = nt.nodes.new("ShaderNodeMath")
        inv.operation = "SUBTRACT"
        inv.inputs[0].default_value = 1.0
        nt.links.new(geo.outputs["Backfacing"], inv.inputs[1])
        nt.links.new(inv.outputs[0], em.inputs["Strength"])
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(shader.outputs[0], add.inputs[0])
        nt.links.new(em.outputs[0], add.inputs[1])
        shader = add
        mat.cycles.emission_sampling = "FRONT"
    else:
        mat.cycles.emission_sampling = "NONE"
    nt.links.new(shader.outputs[0], out.inputs["Surface"])
    return mat


# --------------------------------------------------------------------------------------
# Geometry

def mesh_object(bpy, name, v, f, mat):
    me = bpy.data.meshes.new(name)
    me.vertices.add(len(v))
    me.vertices.foreach_set("co", v.reshape(-1).astype("float32"))
    me.loops.add(3 * len(f))
    me.loops.foreach_set("vertex_index", f.reshape(-1).astype("int32"))
    me.polygons.add(len(f))
    me.polygons.foreach_set("loop_start", [3 * i for i in range(len(f))])
    me.update()
    me.materials.append(mat)
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def _points_group(bpy):
    """Geometry nodes: each vertex of the mesh -> a point of radius `Radius` with the
    material `Material` (Cycles renders points as spheres, intersected analytically)."""
    g = bpy.data.node_groups.get("facet_sphere")
    if g:
        return g
    g = bpy.data.node_groups.new("facet_sphere", "GeometryNodeTree")
    g.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    g.interface.new_socket("Radius", in_out="INPUT", socket_type="NodeSocketFloat")
    g.interface.new_socket("Material", in_out="INPUT", socket_type="NodeSocketMaterial")
    g.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    gi, go = g.nodes.new("NodeGroupInput"), g.nodes.new("NodeGroupOutput")
    pts = g.nodes.new("GeometryNodeMeshToPoints")
    setm = g.nodes.new("GeometryNodeSetMaterial")
    g.links.new(gi.outputs["Geometry"], pts.inputs["Mesh"])
    g.links.new(gi.outputs["Radius"], pts.inputs["Radius"])
    g.links.new(pts.outputs[0], setm.inputs["Geometry"])
    g.links.new(gi.outputs["Material"], setm.inputs["Material"])
    g.links.new(setm.outputs[0], go.inputs[0])
    return g


def sphere_object(bpy, name, center, radius, mat):
    me = bpy.data.meshes.new(name)
    me.vertices.add(1)
    me.vertices.foreach_set("co", [float(c) for c in center])
    me.update()
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    mod = ob.modifiers.new("sphere", "NODES")
    mod.node_group = _points_group(bpy)
    items = mod.node_group.interface.items_tree
    mod[items["Radius"].identifier] = float(radius)
    mod[items["Material"].identifier] = mat
    return ob


# --------------------------------------------------------------------------------------
# Camera, world, settings

def camera(bpy, cam, width, height):
    from mathutils import Matrix, Vector
    eye, target = Vector(cam["eye"]), Vector(cam["target"])
    up = Vector(cam.get("up", [0, 1, 0]))
    fwd = (target - eye).normalized()
    right = fwd.cross(up).normalized()
    upu = right.cross(fwd)
    # Blender's camera looks along its local -z with +y up.
    rot = Matrix((right, upu, -fwd)).transposed()
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(cam["fov"])
    data.clip_start = 1e-3
    data.clip_end = 1e6
    ob = bpy.data.objects.new("camera", data)
    ob.matrix_world = Matrix.Translation(eye) @ rot.to_4x4()
    bpy.context.scene.collection.objects.link(ob)
    bpy.context.scene.camera = ob


def world(bpy, env, sky_exr):
    w = bpy.data.worlds.new("world")
    bpy.context.scene.world = w
    w.use_nodes = True
    nt = w.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputWorld")
    bg = nt.nodes.new("ShaderNodeBackground")
    nt.links.new(bg.outputs[0], out.inputs[0])
    if not env:
        bg.inputs["Strength"].default_value = 0.0
        return
    if "sky" not in env or "rotate" in env or isinstance(env.get("scale", 1.0), list):
        raise SystemExit("only an unrotated sky with a scalar scale is translated")
    if facet_scene.env_filter(env) != "nearest":
        raise SystemExit("only facet's nearest environment lookup is translated (Cycles' Closest): "
                         "give the scene's environment \"filter\": \"nearest\"")
    bg.inputs["Strength"].default_value = float(env.get("scale", 1.0))
    tex = nt.nodes.new("ShaderNodeTexEnvironment")
    tex.interpolation = "Closest"
    tex.projection = "EQUIRECTANGULAR"
    tex.image = bpy.data.images.load(sky_exr)
    tex.image.use_half_precision = False   # the sun's texels exceed half floats' 65504
    coord = nt.nodes.new("ShaderNodeTexCoord")
    sep = nt.nodes.new("ShaderNodeSeparateXYZ")
    comb = nt.nodes.new("ShaderNodeCombineXYZ")
    nt.links.new(coord.outputs["Generated"], sep.inputs[0])
    # facet (x, y, z) -> Cycles (z, x, y): module docstring.
    nt.links.new(sep.outputs["Z"], comb.inputs["X"])
    nt.links.new(sep.outputs["X"], comb.inputs["Y"])
    nt.links.new(sep.outputs["Y"], comb.inputs["Z"])
    nt.links.new(comb.outputs[0], tex.inputs["Vector"])
    nt.links.new(tex.outputs["Color"], bg.inputs["Color"])


def settings(bpy, render, width, height, threads):
    """Cycles on the CPU, unbiased: no clamping, no glossy filter, no adaptive sampling,
    no denoiser, box filter of 1 pixel, facet's bounce limit."""
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.render.resolution_x, sc.render.resolution_y = width, height
    sc.render.resolution_percentage = 100
    sc.render.pixel_aspect_x = sc.render.pixel_aspect_y = 1.0
    sc.render.threads_mode = "FIXED"
    sc.render.threads = threads
    sc.render.use_persistent_data = True   # later renders reuse the synced scene and kernels
    sc.render.film_transparent = False
    sc.render.use_compositing = False
    sc.render.use_sequencer = False
    sc.view_settings.view_transform = "Standard"
    sc.view_settings.look = "None"
    sc.view_settings.exposure = 0.0
    sc.view_settings.gamma = 1.0
    c = sc.cycles
    c.device = "CPU"
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    bounces = max(0, int(render["max_depth"]) - 1)
    c.max_bounces = bounces
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
    c.transparent_max_bounces = c.volume_bounces = bounces
    c.use_animated_seed = False
    img = sc.render.image_settings
    img.file_format = "OPEN_EXR"
    img.color_depth = "32"
    img.exr_codec = "NONE"
    img.color_mode = "RGB"


def build(name, width, height, threads, sky_exr=None):
    """Empties bpy's scene and builds facet's scene `name` (its bench variant) in it."""
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    desc = facet_scene.load_json(os.path.join(ROOT, facet_scene_path(name)))
    mats_desc = facet_scene.scene_materials(name, desc)
    mats = {}
    for i, (ply, geometry, faces, mname) in enumerate(facet_scene.scene_shapes(name, desc)):
        if mname not in mats:
            mats[mname] = material(bpy, mname, mats_desc[mname])
        if ply is None:
            center, radius, inward = geometry
            if inward:
                raise SystemExit(f"{name}: inward spheres are not translated")
            if mats_desc[mname].get("model") == "dielectric":
                # A refracted ray leaves a point-cloud sphere through the same primitive,
                # which Cycles skips as a self-intersection: glass is a smooth mesh.
                v, f = facet_scene.icosphere(center, radius, GLASS_SUBDIVISIONS, False)
                ob = mesh_object(bpy, f"{i:03d}_{mname}", v, f, mats[mname])
                ob.data.shade_smooth()
            else:
                sphere_object(bpy, f"{i:03d}_{mname}", center, radius, mats[mname])
        else:
            mesh_object(bpy, f"{i:03d}_{mname}", geometry, faces, mats[mname])
    settings(bpy, desc["render"], width, height, threads)
    camera(bpy, desc["camera"], width, height)
    world(bpy, desc.get("environment"), sky_exr)
    return desc


if __name__ == "__main__":
    print(__doc__)
    sys.exit(2)
