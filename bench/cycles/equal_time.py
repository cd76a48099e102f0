#!/usr/bin/env python3
"""Equal-time error of facet against Blender Cycles (PyPI's `bpy`) on facet's demo scenes
(bench/README.md, "Blender Cycles baseline").

The protocol is the Mitsuba bench's (bench/mitsuba/equal_time.py, whose reference and
error functions are imported, not copied):

  1. a long reference with each renderer, as two halves of independent seeds, so the
     reference's own noise is known and taken out of every RMSE; cached under
     out/bench/cycles/refs/ while the scene file, size, time and renderer match;
  2. --check: the two references compared region by region (means and z from the
     halves): a translation error shows here, and invalidates the timing;
  3. for each budget, --repeats rounds, each running facet then Cycles (seed 100 + round):
     RMSE against (a) the program's own renderer's reference, (b) the other's, and the
     three-cornered figure that needs neither reference's noise estimate; medians;
  4. --denoise: facet at 4, 16 and 64 spp with `--denoise facet`, and Cycles with OIDN
     at the time facet took (its render_s): the denoised images' RMSE against both
     references, beside each renderer's noisy one.

Time counted: facet's `render_s` (its kernels' time over the progressive passes); Cycles'
own render time (the `cycles.<layer>.render_time` it writes into the EXR's header: path
tracing, and the denoiser when on; its scene synchronisation is not counted, and a 1-sample
warm-up render per scene has loaded its kernels first). Cycles renders the budget with its
own time limit (scene.cycles.time_limit), progressively, as facet does with --time.

Cycles: CPU, 2 threads, unbiased settings (bench/cycles/translate.py): no clamping, no
glossy filter, no adaptive sampling, no denoiser outside --denoise, a 1-pixel box filter,
facet's bounce limit. Without bpy the script says how to install it and exits 0.
"""
import argparse
import hashlib
import importlib.util
import json
import math
import os
import re
import statistics
import struct
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True   # no __pycache__ in the source tree

INSTALL_HINT = ("Blender Cycles not installed: pip install bpy==5.0.0 numpy (Python 3.11; a 380 MB "
                "wheel): skipping the Blender Cycles baseline")
bpy = None


def _load(name, path):
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, path))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# The Mitsuba bench's reference machinery (reference(), Ref, rmse, the three-cornered
# RMSE, regions, write_outputs, its Facet program); it needs no Mitsuba until it reads
# an EXR, which here goes through bpy instead (read_exr below).
met = _load("mitsuba_equal_time", "bench/mitsuba/equal_time.py")
cyt = _load("cycles_translate", "bench/cycles/translate.py")


def read_exr(path):
    """RGB of an EXR, top row first, through bpy's image loader."""
    img = bpy.data.images.load(path, check_existing=False)
    w, h = img.size
    a = np.empty(w * h * 4, dtype=np.float32)
    img.pixels.foreach_get(a)
    bpy.data.images.remove(img)
    return a.reshape(h, w, 4)[::-1, :, :3].astype(np.float64)


met.read_exr = read_exr


def exr_string_attributes(path):
    """The string attributes of an EXR's header (name -> value)."""
    out = {}
    with open(path, "rb") as f:
        data = f.read(1 << 16)
    pos = 8   # magic number and version
    while True:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode("latin-1")
        if not name:
            return out
        tend = data.index(b"\0", end + 1)
        kind = data[end + 1:tend].decode("latin-1")
        (size,) = struct.unpack_from("<i", data, tend + 1)
        value = data[tend + 5:tend + 5 + size]
        if kind == "string":
            out[name] = value.decode("utf-8", "replace")
        pos = tend + 5 + size


def seconds_of(text):
    """Blender's "MM:SS.hh" or "HH:MM:SS.hh" -> seconds."""
    s = 0.0
    for part in text.split(":"):
        s = 60.0 * s + float(part)
    return s


class Scene:
    def __init__(self, name, scale):
        self.name = name
        self.facet_json = cyt.facet_scene_path(name)
        with open(os.path.join(ROOT, self.facet_json)) as f:
            self.desc = json.load(f)
        r = self.desc["render"]
        self.width = max(8, int(round(r["width"] * scale)))
        self.height = max(8, int(round(r["height"] * scale)))
        self.pixels = self.width * self.height
        # Both renderers draw the same facet file; Cycles' scene is built from it by the
        # translator, whose digest is part of Cycles' key.
        keys = {}
        for renderer, files in (("facet", [self.facet_json]),
                                ("cycles", [self.facet_json, "bench/cycles/translate.py"])):
            h = hashlib.sha256()
            for p in files:
                with open(os.path.join(ROOT, p), "rb") as f:
                    h.update(f.read())
            keys[renderer] = f"{name}_{self.width}x{self.height}_{h.hexdigest()[:10]}"
        self.keys = keys


class Facet(met.Facet):
    def render_denoised(self, scene, seed, spp):
        """`facet render --spp N --denoise facet`: (noisy, denoised, spp, render_s, denoise_s)."""
        out = os.path.join(self.work, f"facet_{scene.name}_dn.exr")
        text = met.run([self.exe, "render", scene.facet_json, "--out", out, "--seed", str(seed),
                        "--width", str(scene.width), "--height", str(scene.height), "--spp", str(spp),
                        "--denoise", "facet"])
        m = re.search(r"denoised .*\(([^,]+), ([0-9.]+) s;", text)
        with open(out[:-4] + ".json") as f:
            rep = json.load(f)
        return (read_exr(out), read_exr(out[:-4] + ".denoised.exr"), int(rep["spp"]), float(rep["render_s"]),
                float(m.group(2)) if m else float("nan"))


class Cycles:
    renderer = "cycles"

    def __init__(self, threads, work, assets, facet_exe, denoise=False):
        self.threads, self.work, self.assets, self.facet_exe = threads, work, assets, facet_exe
        self.denoise = denoise
        self.label = "Cycles + OIDN" if denoise else "Cycles"
        self.current = None
        self.rate = None   # samples per pixel per second (prepare)

    def version(self):
        return "cycles-" + bpy.app.version_string.replace(" ", "")

    def sky(self, desc):
        env = desc.get("environment")
        if not env or "sky" not in env:
            return None
        path = os.path.join(self.assets, "sky_" + "_".join(met.translate.sky_args(env["sky"])[1::2]) + ".exr")
        if not os.path.exists(path):
            met.run([self.facet_exe, "sky", path] + met.translate.sky_args(env["sky"]))
        return path

    def prepare(self, scene):
        """Builds the scene in bpy (once while it stays the current one), renders one
        untimed sample (kernels loaded, shaders compiled), then measures Cycles' samples
        per second with a render of a fixed sample count of about 5 s."""
        if self.current == (scene.name, scene.width, scene.height):
            return
        cyt.build(scene.name, scene.width, scene.height, self.threads, self.sky(scene.desc))
        # Persistent data would skip the re-synchronisation, but bpy 5.0 then ignores a
        # changed sample count; sync time is not counted anyway (render_time excludes it).
        bpy.context.scene.render.use_persistent_data = False
        self.current = (scene.name, scene.width, scene.height)
        _, _, t1 = self._render(1, 0.0, 1, denoise=False)
        n = max(2, int(5.0 / max(t1, 1e-3)))
        _, n, t = self._render(n, 0.0, 2, denoise=False)
        self.rate = n / t   # samples per pixel per second
        print(f"  Cycles {scene.name} {scene.width}x{scene.height}: {n} spp in {t:.2f} s, "
              f"{self.rate * scene.pixels * 1e-6:.3f} Msamples/s", flush=True)

    def _render(self, samples, limit, seed, denoise):
        """(image, samples per pixel, Cycles' render time)."""
        c = bpy.context.scene.cycles
        c.samples = samples
        c.time_limit = limit
        c.seed = seed
        c.use_denoising = denoise
        if denoise:
            c.denoiser = "OPENIMAGEDENOISE"
            c.denoising_input_passes = "RGB_ALBEDO_NORMAL"
            c.denoising_prefilter = "ACCURATE"
            c.denoising_use_gpu = False
        bpy.ops.render.render()
        out = os.path.join(self.work, "cycles.exr")
        bpy.data.images["Render Result"].save_render(out)
        attrs = exr_string_attributes(out)
        t = next((seconds_of(v) for k, v in attrs.items() if k.startswith("cycles.") and k.endswith(".render_time")),
                 float("nan"))
        if limit > 0:
            # bpy does not say how many samples a time-limited render reached (its
            # header holds the requested count, its progress messages come every 128
            # or so): the samples per second of the fixed-count render of prepare().
            samples = self.rate * t
        return read_exr(out), samples, t

    def render(self, scene, seed, seconds=None, spp=None):
        self.prepare(scene)
        if seconds is not None:
            img, n, t = self._render(1 << 24, float(seconds), seed, self.denoise)
        else:
            img, n, t = self._render(int(spp), 0.0, seed, self.denoise)
        return img, n * scene.pixels, t


# --------------------------------------------------------------------------------------

def check(scenes, progs, seconds, refs_dir, out_dir):
    """The two renderers' references compared region by region (the Mitsuba bench's check)."""
    met.check(scenes, progs, seconds, refs_dir, out_dir, other="cycles", name="Cycles", title="Blender Cycles")


def refs_of(sc, makers, seconds, refs_dir):
    refs = {r: met.Ref(*met.reference(makers[r], sc, seconds, refs_dir)) for r in ("facet", "cycles")}
    cross = float(np.mean((refs["facet"].image - refs["cycles"].image) ** 2))
    return refs, cross


def errors(img, refs, renderer, cross):
    own, other = refs[renderer], refs["cycles" if renderer == "facet" else "facet"]
    return {"rmse_own": met.rmse(img, own), "rmse_other": met.rmse(img, other),
            "rmse_3c": met.rmse_three_cornered(img, own, other, cross)}


def measure(scenes, progs, budgets, repeats, ref_seconds, refs_dir, out_dir, info):
    rows = []
    for sc in scenes:
        refs, cross = refs_of(sc, progs, ref_seconds, refs_dir)
        progs["cycles"].prepare(sc)
        for budget in budgets:
            runs = {k: [] for k in progs}
            for rep in range(repeats):
                for key, p in progs.items():   # alternate: every program once per round
                    img, n, t = p.render(sc, 100 + rep, seconds=budget)
                    r = {"spp": n / sc.pixels, "seconds": t, "msamples_s": n / t * 1e-6,
                         **errors(img, refs, p.renderer, cross)}
                    runs[key].append(r)
                    print(f"  {sc.name} {budget:g} s #{rep + 1} {p.label:8s} {r['spp']:8.1f} spp {t:7.2f} s "
                          f"{r['msamples_s']:6.3f} Msamples/s  rmse own {met.fmt_rmse(r['rmse_own'])} other "
                          f"{met.fmt_rmse(r['rmse_other'])} 3c {met.fmt_rmse(r['rmse_3c'])}", flush=True)
            for key, rs in runs.items():
                med = {k: statistics.median(r[k] for r in rs) for k in rs[0]}
                med["rmse_pooled"] = math.sqrt(statistics.fmean(r["rmse_own"] ** 2 for r in rs))
                rows.append({"scene": sc.name, "size": f"{sc.width}x{sc.height}", "s": budget,
                             "program": progs[key].label, "renderer": progs[key].renderer, "runs": rs,
                             "median": med, "ref_spp": {r: refs[r].spp for r in refs},
                             "ref_noise_rmse": {r: math.sqrt(refs[r].noise_mse) for r in refs}})
    info["load_after"] = " ".join(f"{x:.1f}" for x in os.getloadavg())
    lines = ["# facet vs Blender Cycles, equal time", "",
             f"Medians of {repeats} runs, programs alternated; load average {info['load_before']} before, "
             f"{info['load_after']} after. RMSE against each renderer's reference with the reference's own noise "
             "taken out; 'own': the program's renderer, 'other': the other renderer's; three-cornered: neither "
             "reference's noise estimate.", "",
             "| scene | budget (s) | program | spp | Msamples/s | RMSE own | RMSE other | RMSE 3c | 3c / facet's |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        base = next(x for x in rows if x["scene"] == r["scene"] and x["s"] == r["s"] and x["renderer"] == "facet")
        m, b3 = r["median"], base["median"]["rmse_3c"]
        lines.append(f"| {r['scene']} {r['size']} | {r['s']:g} | {r['program']} | {m['spp']:.1f} | "
                     f"{m['msamples_s']:.3f} | {met.fmt_rmse(m['rmse_own'])} | {met.fmt_rmse(m['rmse_other'])} | "
                     f"{met.fmt_rmse(m['rmse_3c'])} | "
                     f"{m['rmse_3c'] / b3 if b3 > 0 else float('nan'):.2f} |")
    refs_line = sorted({(r["scene"], r["size"], round(r["ref_spp"]["facet"]), round(r["ref_spp"]["cycles"]))
                        for r in rows})
    lines += ["", "References (spp): " + "; ".join(f"{s} {sz}: facet {a}, Cycles {b}" for s, sz, a, b in refs_line)]
    lines += met.under_noise_lines(rows)
    info["rows"] = rows
    met.write_outputs(out_dir, "cycles_equal_time", lines, info)


def denoised(scenes, progs, spps, repeats, ref_seconds, refs_dir, out_dir, info):
    """facet `--denoise facet` at N spp against Cycles + OIDN given facet's render time."""
    facet, cyc = progs["facet"], progs["cycles"]
    cyc_dn = Cycles(cyc.threads, cyc.work, cyc.assets, cyc.facet_exe, denoise=True)
    rows = []
    for sc in scenes:
        refs, cross = refs_of(sc, {"facet": facet, "cycles": cyc}, ref_seconds, refs_dir)
        for spp in spps:
            runs = []
            for rep in range(repeats):
                seed = 300 + rep
                noisy, den, n, t, t_dn = facet.render_denoised(sc, seed, spp)
                c_img, c_n, c_t = cyc.render(sc, seed, seconds=t)
                cyc_dn.current, cyc_dn.rate = cyc.current, cyc.rate   # the same bpy scene
                d_img, d_n, d_t = cyc_dn.render(sc, seed, seconds=t)
                r = {"facet_spp": n, "facet_render_s": t, "facet_denoise_s": t_dn,
                     "facet_noisy": errors(noisy, refs, "facet", cross),
                     "facet_denoised": errors(den, refs, "facet", cross),
                     "cycles_spp": c_n / sc.pixels, "cycles_s": c_t,
                     "cycles_noisy": errors(c_img, refs, "cycles", cross),
                     "cycles_oidn_spp": d_n / sc.pixels, "cycles_oidn_s": d_t,
                     "cycles_oidn": errors(d_img, refs, "cycles", cross)}
                runs.append(r)
                print(f"  {sc.name} {spp} spp #{rep + 1}: facet {t:.2f} s + {t_dn:.2f} s noisy "
                      f"{r['facet_noisy']['rmse_own']:.4g} denoised {r['facet_denoised']['rmse_own']:.4g}; Cycles "
                      f"{r['cycles_spp']:.0f} spp noisy {r['cycles_noisy']['rmse_own']:.4g}, OIDN {d_t:.2f} s "
                      f"{r['cycles_oidn']['rmse_own']:.4g} (against facet's ref {r['cycles_oidn']['rmse_other']:.4g})",
                      flush=True)
            med = lambda f: statistics.median(f(r) for r in runs)  # noqa: E731
            rows.append({"scene": sc.name, "size": f"{sc.width}x{sc.height}", "spp": spp, "runs": runs,
                         "median": {"facet_render_s": med(lambda r: r["facet_render_s"]),
                                    "facet_denoise_s": med(lambda r: r["facet_denoise_s"]),
                                    "cycles_spp": med(lambda r: r["cycles_spp"]),
                                    "cycles_oidn_s": med(lambda r: r["cycles_oidn_s"]),
                                    **{f"{k}_{e}": med(lambda r, k=k, e=e: r[k][e])
                                       for k in ("facet_noisy", "facet_denoised", "cycles_noisy", "cycles_oidn")
                                       for e in ("rmse_own", "rmse_other", "rmse_3c")}}})
    info["load_after"] = " ".join(f"{x:.1f}" for x in os.getloadavg())
    lines = ["# facet's denoiser against Blender Cycles + OIDN at equal time", "",
             f"Medians of {repeats} runs; load average {info['load_before']} before, {info['load_after']} after. "
             "Cycles renders for facet's render time (its time limit), noisy and with OIDN (albedo and normal, "
             "accurate prefilter); RMSE against facet's reference (noise taken out), in brackets against Cycles' "
             "own.", "",
             "| scene | facet spp | facet render s | facet noisy | facet denoised | facet denoise s | Cycles spp "
             "| Cycles noisy | Cycles + OIDN | Cycles + OIDN s |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        m = r["median"]
        cell = lambda k: f"{m[k + '_rmse_other' if k.startswith('cycles') else k + '_rmse_own']:.4g} " \
                         f"({m[k + '_rmse_own' if k.startswith('cycles') else k + '_rmse_other']:.4g})"  # noqa: E731
        lines.append(f"| {r['scene']} {r['size']} | {r['spp']} | {m['facet_render_s']:.2f} | {cell('facet_noisy')} | "
                     f"{cell('facet_denoised')} | {m['facet_denoise_s']:.2f} | {m['cycles_spp']:.1f} | "
                     f"{cell('cycles_noisy')} | {cell('cycles_oidn')} | {m['cycles_oidn_s']:.2f} |")
    info["rows"] = rows
    met.write_outputs(out_dir, "cycles_denoised", lines, info)


def main():
    global bpy
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--budgets", default="10,60", help="time budgets in seconds (default 10,60)")
    ap.add_argument("--repeats", type=int, default=3, help="runs of each program per budget (default 3)")
    ap.add_argument("--quick", action="store_true", help="budgets 2,5, 1 repeat, 30 s references, quarter size")
    ap.add_argument("--scenes", default="cornell_box", help="comma-separated scene names (default cornell_box)")
    ap.add_argument("--scale", type=float, default=1.0, help="image size relative to the scene's (default 1)")
    ap.add_argument("--reference-seconds", type=float, default=300,
                    help="time of each renderer's reference (two halves; default 300)")
    ap.add_argument("--check", action="store_true", help="agreement in mean only: the two references compared")
    ap.add_argument("--denoise", action="store_true",
                    help="facet --denoise facet at --denoise-spp against Cycles + OIDN at facet's render time")
    ap.add_argument("--denoise-spp", default="4,16,64", help="facet's sample counts for --denoise (default 4,16,64)")
    ap.add_argument("--threads", type=int, default=2, help="Cycles threads (default 2, as facet's PoCL here)")
    ap.add_argument("--facet", default=os.path.join(ROOT, "build", "facet"), help="the facet binary")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench"), help="output folder")
    a = ap.parse_args()
    try:
        import bpy as bpy_module
    except ImportError:
        print(INSTALL_HINT)
        return 0
    bpy = bpy_module
    if not os.path.exists(a.facet):
        raise SystemExit(f"equal_time.py: {a.facet} not found (make build first)")
    work, assets, refs_dir = met.prepare_work(a, "cycles")
    scenes = [Scene(n, a.scale) for n in a.scenes.split(",")]
    progs = {"facet": Facet(a.facet, None, work), "cycles": Cycles(a.threads, work, assets, a.facet)}
    info = {"blender": bpy.app.version_string, "threads": a.threads,
            "load_before": " ".join(f"{x:.1f}" for x in os.getloadavg())}
    t0 = time.time()
    check(scenes, progs, a.reference_seconds, refs_dir, a.out)   # the references, compared
    if a.check:
        return 0
    if a.denoise:
        denoised(scenes, progs, [int(x) for x in a.denoise_spp.split(",")], a.repeats, a.reference_seconds,
                 refs_dir, a.out, info)
    else:
        measure(scenes, progs, [float(x) for x in a.budgets.split(",")], a.repeats, a.reference_seconds, refs_dir,
                a.out, info)
    print(f"equal_time.py: {time.time() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
