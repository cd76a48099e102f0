#!/usr/bin/env python3
"""Equal-time error of facet against Mitsuba 3 on facet's demo scenes (bench/README.md,
"Mitsuba 3 baseline").

For each scene (bench/mitsuba/<scene>.xml for Mitsuba; the facet scene both draw is
bench/mitsuba/<scene>.json where materials had to be replaced, else scenes/<scene>.json):

  1. a long reference with each renderer, as two halves of independent seeds (so that
     the reference's own noise is known and taken out of every RMSE below); cached
     under out/bench/mitsuba/refs/ and reused while the scene files, settings and the
     renderer (facet's binary, Mitsuba's version) match;
  2. for each time budget, `--repeats` rounds, each running every program once in turn
     (facet, facet --sampler independent, Mitsuba's independent sampler, Mitsuba's best
     sampler, then again): the image reached in the budget, its samples per second and
     its RMSE against (a) the same renderer's reference and (b) the other renderer's;
     (a) is noise, (b) - (a) shows bias between the two;
  3. medians over the repeats, into out/bench/mitsuba_equal_time.{md,json}.

Time counted: facet's `render_s` (kernel time of its progressive passes, without program
build, scene load or file output); Mitsuba's time inside mi.render() + dr.eval() of its
passes, after untimed warm-up passes that JIT-compile the kernels of every pass size it
then uses (the scene load and those compiles are not counted). facet stops at the first
pass ending at or after the budget, each pass sized to the time left; Mitsuba renders
passes of two fixed sizes (about 24 % and 3 % of the budget: some samplers bake the
sample count into the kernel) and ends within half a small pass of the budget.

Mitsuba: variant llvm_ad_rgb on 2 threads, which needs a system libLLVM (Debian's
libllvm19: DRJIT_LIBLLVM_PATH is set to it when found). Without Mitsuba the script says
how to install it and exits 0.

Other modes: --check (agreement in mean: the two references, region by region with a
z-test from their halves), --equal-spp N (RMSE at N samples per pixel: error per sample,
insensitive to machine load), --per-sample K (error per sample without a reference: the
variance across K images of independent seeds).
"""
import argparse
import glob
import hashlib
import json
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True   # no __pycache__ in the source tree
import translate  # noqa: E402

INSTALL_HINT = ("Mitsuba 3 not installed: pip install mitsuba==3.9.1, and libllvm19 from Debian "
                "(apt-get install libllvm19; DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so)")
MAX_LANES = 1 << 26   # Mitsuba pass size cap, width * height * spp (its megakernel keeps
                      # no per-sample arrays: 16 M samples of the Cornell box in 155 MB)

mi = dr = None


# --------------------------------------------------------------------------------------
# Set-up

def find_libllvm():
    if os.environ.get("DRJIT_LIBLLVM_PATH"):
        return os.environ["DRJIT_LIBLLVM_PATH"]
    for pattern in ("/usr/lib/*-linux-gnu/libLLVM-2[0-9].so", "/usr/lib/*-linux-gnu/libLLVM-19.so",
                    "/usr/lib/*-linux-gnu/libLLVM.so.19*", "/usr/lib/llvm-19/lib/libLLVM*.so*"):
        found = sorted(glob.glob(pattern))
        if found:
            return found[-1]
    return None


def import_mitsuba(threads):
    """Imports Mitsuba on `threads` threads, or returns a reason it cannot run."""
    global mi, dr
    llvm = find_libllvm()
    if llvm:
        os.environ["DRJIT_LIBLLVM_PATH"] = llvm
    try:
        import drjit
        import mitsuba
    except ImportError:
        return INSTALL_HINT
    try:
        mitsuba.set_variant("llvm_ad_rgb")
    except Exception as e:  # the LLVM backend could not start
        return f"{INSTALL_HINT}\n  (Mitsuba is installed but its LLVM backend failed: {e})"
    drjit.set_thread_count(threads)
    mitsuba.set_log_level(mitsuba.LogLevel.Warn)
    mi, dr = mitsuba, drjit
    return None


def run(cmd):
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise SystemExit(f"equal_time.py: {' '.join(cmd)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return r.stdout


def read_exr(path):
    b = mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, False)
    return np.array(b, dtype=np.float64)


class Scene:
    def __init__(self, name, scale):
        self.name = name
        self.facet_json = translate.facet_scene_path(name)
        self.xml = os.path.join("bench", "mitsuba", f"{name}.xml")
        with open(os.path.join(ROOT, self.facet_json)) as f:
            desc = json.load(f)
        self.desc = desc
        r = desc["render"]
        self.width = max(8, int(round(r["width"] * scale)))
        self.height = max(8, int(round(r["height"] * scale)))
        self.pixels = self.width * self.height
        # A reference depends on the scene file its own renderer reads, not on the other's.
        self.keys = {}
        for renderer, p in (("facet", self.facet_json), ("mitsuba", self.xml)):
            with open(os.path.join(ROOT, p), "rb") as f:
                digest = hashlib.sha256(f.read()).hexdigest()[:10]
            self.keys[renderer] = f"{name}_{self.width}x{self.height}_{digest}"


# --------------------------------------------------------------------------------------
# Renderers: each returns (image, spp, counted seconds)

class Facet:
    renderer = "facet"

    def __init__(self, exe, sampler, work, options=()):
        """options: more of facet's options, as its label shows them (facet_unguided's
        --caustic-guide 0: the sampling strategies Mitsuba has, BSDF and light with MIS)."""
        self.exe, self.sampler, self.work, self.options = exe, sampler, work, list(options)
        self.label = " ".join(["facet"] + ([f"--sampler {sampler}"] if sampler else []) + self.options)

    def version(self):
        """facet's references are kept per build: a change to the kernels or to how the
        host builds the scene changes the image a scene file gives."""
        with open(self.exe, "rb") as f:
            return "facet-" + hashlib.sha256(f.read()).hexdigest()[:10]

    def render(self, scene, seed, seconds=None, spp=None):
        out = os.path.join(self.work, f"facet_{scene.name}.exr")
        cmd = [self.exe, "render", scene.facet_json, "--out", out, "--seed", str(seed), "--quiet",
               "--width", str(scene.width), "--height", str(scene.height)]
        cmd += ["--time", f"{seconds:g}", "--spp", str(1 << 24)] if seconds else ["--spp", str(spp)]
        if self.sampler:
            cmd += ["--sampler", self.sampler]
        run(cmd + self.options)
        with open(out[:-4] + ".json") as f:
            rep = json.load(f)
        return read_exr(out), int(rep["spp"]) * scene.pixels, float(rep["render_s"])


# Mitsuba 3's samplers, all tried for its best (--mitsuba-best auto), each with both pass
# sizes of PASS_LANES: None = large passes of about 24 % of the budget, else passes of that
# many lanes (width x height x spp; about 4 M ran Mitsuba fastest in issue 29's runs).
SAMPLERS = ("independent", "stratified", "multijitter", "orthogonal", "ldsampler")
PASS_LANES = (None, 1 << 22)


class Mitsuba:
    renderer = "mitsuba"

    def __init__(self, sampler, assets, pass_lanes=None):
        self.sampler, self.assets, self.pass_lanes = sampler, assets, pass_lanes
        self.label = f"Mitsuba {sampler}" + (f", {pass_lanes / (1 << 20):g} M-lane passes" if pass_lanes else "")
        self.loaded = {}

    def version(self):
        return "mitsuba-" + mi.__version__

    def scene(self, scene):
        if scene.name not in self.loaded:
            s = mi.load_file(os.path.join(ROOT, scene.xml), assets=self.assets, sampler=self.sampler,
                             width=str(scene.width), height=str(scene.height))
            self.loaded[scene.name] = [s, None]   # [scene, seconds per spp]
        return self.loaded[scene.name]

    def _pass(self, s, spp, seed):
        t = time.perf_counter()
        img = mi.render(s, spp=spp, seed=seed)
        dr.eval(img)
        dr.sync_thread()
        return img, time.perf_counter() - t

    def warm_up(self, scene, sizes=()):
        """Untimed passes that JIT-compile the kernels: Dr.Jit bakes the sample count
        of some samplers (multijitter, ldsampler, ...) into the kernel, so every pass
        size used later is rendered once here first."""
        entry = self.scene(scene)
        if entry[1] is None:
            self._pass(entry[0], self.round_spp(1), 999983)
            _, t = self._pass(entry[0], self.round_spp(2), 999979)
            entry[1] = t / entry[0].sensors()[0].sampler().sample_count()
            entry.append(set())
        for n in sizes:
            if n not in entry[2]:
                _, t = self._pass(entry[0], n, 999961)
                entry[1] = t / entry[0].sensors()[0].sampler().sample_count()
                entry[2].add(n)
        return entry

    def round_spp(self, n):
        """The largest pass size <= n (at least the smallest) that the sampler takes as
        it is: ldsampler wants powers of 4, stratified squares, orthogonal squares of
        primes, multijitter products r * ceil(n / r) with r = isqrt(n) (others it rounds
        up: 186 to 195); independent any count."""
        if self.sampler in ("ldsampler", "stratified"):
            r = max(1, int(math.isqrt(n)))
            if self.sampler == "ldsampler":
                r = 1 << (r.bit_length() - 1)
            return max(r * r, 4 if self.sampler == "ldsampler" else 1)
        if self.sampler == "orthogonal":
            p = max(2, int(math.isqrt(n)))
            while p > 2 and any(p % d == 0 for d in range(2, int(math.isqrt(p)) + 1)):
                p -= 1
            return p * p
        if self.sampler == "multijitter":
            m = max(1, n)
            while math.isqrt(m) * -(-m // math.isqrt(m)) != m:
                m -= 1
            return m
        return max(1, n)

    def render(self, scene, seed, seconds=None, spp=None):
        """Passes of two fixed sizes, compiled beforehand: a large one (about a quarter
        of the budget, so that a stratified sampler keeps large stratified sets) while
        it fits in the time left, then a small one (3 % of the budget) while at least
        half of it fits. With spp: passes of that many samples in all (several where one
        would be over MAX_LANES)."""
        cap = max(1, MAX_LANES // scene.pixels)
        s, per_spp = self.warm_up(scene)[:2]
        if seconds is not None:
            big = self.round_spp(min(cap, max(1, int(0.24 * seconds / per_spp) if self.pass_lanes is None
                                              else self.pass_lanes // scene.pixels)))
            small = self.round_spp(min(cap, max(1, int(0.03 * seconds / per_spp))))
            sizes = [big, small]
        else:
            # passes of at most `cap` samples, the last of what is left (as the sampler takes
            # it), so that every program renders the spp asked, not a whole pass beyond it
            sizes, planned = [], 0
            while planned < spp:
                sizes.append(self.round_spp(min(cap, spp - planned)))
                planned += sizes[-1]
        s, per_spp = self.warm_up(scene, sorted(set(sizes)))[:2]
        sampler = s.sensors()[0].sampler()
        acc, done, elapsed, npass = None, 0, 0.0, 0
        while True:
            if seconds is not None:
                left = seconds - elapsed
                if left >= sizes[0] * per_spp:
                    n = sizes[0]
                elif left >= 0.5 * sizes[1] * per_spp:
                    n = sizes[1]
                else:
                    break
            else:
                if npass >= len(sizes):
                    break
                n = sizes[npass]
            img, t = self._pass(s, n, (seed * 4099 + npass) % (1 << 32))
            n = sampler.sample_count()   # what it really took
            img = np.array(img, dtype=np.float64)
            acc = img * n if acc is None else acc + img * n
            done += n
            elapsed += t
            npass += 1
            per_spp = elapsed / done
        return acc / done, done * scene.pixels, elapsed


# --------------------------------------------------------------------------------------
# References and errors

def reference(prog, scene, seconds, refs_dir):
    """(half A, half B, samples per pixel of both): two halves of independent seeds."""
    path = os.path.join(refs_dir, f"{scene.keys[prog.renderer]}_{prog.version()}_{seconds:g}s.npz")
    if os.path.exists(path):
        z = np.load(path)
        return z["a"], z["b"], float(z["spp"])
    print(f"  reference {prog.label} {scene.name} {scene.width}x{scene.height}: 2 x {seconds / 2:g} s", flush=True)
    a, n_a, _ = prog.render(scene, 7001, seconds=seconds / 2)
    b, n_b, _ = prog.render(scene, 7002, seconds=seconds / 2)
    spp = (n_a + n_b) / scene.pixels
    np.savez_compressed(path, a=a.astype(np.float32), b=b.astype(np.float32), spp=spp)
    return a, b, spp


class Ref:
    def __init__(self, a, b, spp):
        self.image = 0.5 * (a + b)
        # E[((a - b) / 2)^2] is the variance of (a + b) / 2: the reference's own noise.
        self.noise_mse = float(np.mean((0.5 * (a - b)) ** 2))
        self.spp = spp


def rmse_three_cornered(img, own, other, cross):
    """The image's RMSE from its squared differences to both references and theirs to
    each other (the "three-cornered hat"): with v the variances and b the bias between
    the renderers, |img - own|^2 = v_img + v_own, |img - other|^2 = v_img + v_other + b^2
    and |own - other|^2 = v_own + v_other + b^2, so v_img comes out without either
    reference's noise estimate and whatever the bias."""
    d_own = float(np.mean((img - own.image) ** 2))
    d_other = float(np.mean((img - other.image) ** 2))
    return math.sqrt(max(0.5 * (d_own + d_other - cross), 0.0))


def rmse(img, ref):
    """RMSE against a reference, its noise taken out (clamped at 0)."""
    mse = float(np.mean((img - ref.image) ** 2)) - ref.noise_mse
    return math.sqrt(max(mse, 0.0))


# Where a noise-corrected RMSE clamps at 0, the tables say so instead of printing 0.
UNDER_NOISE = "< ref. noise"
UNDER_NOISE_NOTE = (f"'{UNDER_NOISE}': the image's squared difference to that reference is below the "
                    "reference's own noise, which is taken out (the difference clamps at 0): the error "
                    "is too small for that reference to measure; longer references (--reference-seconds) "
                    "resolve it.")


def fmt_rmse(x):
    """An RMSE for the tables and the progress lines: 4 significant digits, or UNDER_NOISE
    where it clamped at 0."""
    return f"{x:.4g}" if x > 0.0 else UNDER_NOISE


def under_noise_lines(rows):
    """The note for under a table of rows (each with its "median" figures) where any RMSE
    clamped at 0, as lines to append; none otherwise."""
    clamped = any(r["median"][k] <= 0.0 for r in rows for k in ("rmse_own", "rmse_other", "rmse_3c"))
    return ["", UNDER_NOISE_NOTE] if clamped else []


# --------------------------------------------------------------------------------------
# Agreement in mean (--check)

def camera_project(desc, width, height):
    cam = desc["camera"]
    eye, target = np.array(cam["eye"], float), np.array(cam["target"], float)
    up = np.array(cam.get("up", [0, 1, 0]), float)
    fwd = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(fwd, up)
    right /= np.linalg.norm(right)
    upu = np.cross(right, fwd)
    th = math.tan(math.radians(cam.get("fov", 40)) / 2)
    aspect = width / height

    def project(p, r):
        d = np.asarray(p, float) - eye
        z = d @ fwd
        sx, sy = (d @ right) / (z * th * aspect), (d @ upu) / (z * th)
        x, y = (sx + 1) / 2 * width, (1 - sy) / 2 * height
        return x, y, r / (z * th) * height / 2
    return project


def regions(scene):
    """Named pixel boxes: the whole image, each sphere's inner part (by material), then
    a 4 x 4 grid of blocks."""
    out = [("whole image", (0, 0, scene.width, scene.height))]
    W, H = scene.width, scene.height
    project = camera_project(scene.desc, W, H)
    for s in scene.desc.get("shapes", []):
        if s["type"] != "sphere" or s.get("inward"):
            continue
        x, y, r = project(s["center"], s["radius"])
        h = max(1, int(0.6 * r))
        box = (int(x) - h, int(y) - h, int(x) + h + 1, int(y) + h + 1)
        if box[0] >= 0 and box[1] >= 0 and box[2] <= W and box[3] <= H:
            out.append((s["material"], box))
    for j in range(4):
        for i in range(4):
            out.append((f"block {i},{j}", (i * W // 4, j * H // 4, (i + 1) * W // 4, (j + 1) * H // 4)))
    return out


def check(scenes, progs, seconds, refs_dir, out_dir, other="mitsuba", name="Mitsuba", title="Mitsuba 3"):
    """Long renders of facet and progs[other] (its `name` in tables), compared region by
    region; written to out_dir/<other>_check.{md,json} (the Cycles bench calls it too)."""
    lines = [f"# facet vs {title}: agreement in mean (references of {seconds:g} s each, as two halves)", "",
             "z: the difference over its standard error, estimated from each reference's two halves; "
             "** marks |z| > 4 where the difference is above 0.2 % (the sky's pixels, the same texels in "
             "both, have almost no noise, so differences of 1e-4 read as large z).", ""]
    results = {}
    for sc in scenes:
        f_a, f_b, f_spp = reference(progs["facet"], sc, seconds, refs_dir)
        m_a, m_b, m_spp = reference(progs[other], sc, seconds, refs_dir)
        lines += [f"## {sc.name} ({sc.width}x{sc.height}; facet {f_spp:.0f} spp, {name} {m_spp:.0f} spp)", "",
                  f"| region | facet (R, G, B) | {name} (R, G, B) | {name} / facet - 1 | max abs z |",
                  "|---|---|---|---|---|"]
        rows = []
        for region, (x0, y0, x1, y1) in regions(sc):
            def stats(a, b):
                A, B = a[y0:y1, x0:x1].reshape(-1, 3), b[y0:y1, x0:x1].reshape(-1, 3)
                n = len(A)
                return 0.5 * (A + B).mean(0), np.sqrt(np.sum((0.5 * (A - B)) ** 2, 0)) / n
            fm, fs = stats(f_a, f_b)
            mm, ms = stats(m_a, m_b)
            z = (mm - fm) / np.maximum(np.sqrt(fs ** 2 + ms ** 2), 1e-12)
            rel = mm / np.maximum(fm, 1e-12) - 1
            zmax = float(np.max(np.abs(z)))
            rows.append({"region": region, "facet": fm.tolist(), other: mm.tolist(),
                         "rel": rel.tolist(), "z": z.tolist()})
            flag = " **" if np.any((np.abs(z) > 4) & (np.abs(rel) > 0.002)) else ""
            lines.append(f"| {region} | {fmt_rgb(fm)} | {fmt_rgb(mm)} | {fmt_rgb(rel, '+.3f')} | {zmax:.1f}{flag} |")
        lines.append("")
        results[sc.name] = rows
    write_outputs(out_dir, f"{other}_check", lines, results)


def fmt_rgb(v, f=".4g"):
    return ", ".join(format(x, f) for x in v)


# --------------------------------------------------------------------------------------
# Equal time / equal spp

def select_best(sc, refs, cross, assets, budget, info):
    """Mitsuba's best program on this scene: each of the five samplers with each pass size
    of PASS_LANES renders `budget` seconds once (seed 900); the lowest three-cornered RMSE
    wins. The candidates' figures go to info["selection"]."""
    tried = []
    for sampler in SAMPLERS:
        for lanes in PASS_LANES:
            p = Mitsuba(sampler, assets, lanes)
            p.warm_up(sc)
            img, n, t = p.render(sc, 900, seconds=budget)
            e = rmse_three_cornered(img, refs["mitsuba"], refs["facet"], cross)
            tried.append((e, p, n / t * 1e-6))
            print(f"  {sc.name} selection {budget:g} s {p.label:40s} {n / sc.pixels:7.1f} spp {n / t * 1e-6:6.2f} "
                  f"Msamples/s  rmse 3c {e:.4g}", flush=True)
            p.loaded.clear()
    best = min(tried, key=lambda x: x[0])[1]
    info.setdefault("selection", {})[sc.name] = {
        "budget_s": budget, "best": best.label,
        "tried": [{"program": p.label, "rmse_3c": e, "msamples_s": r} for e, p, r in tried]}
    print(f"  {sc.name}: Mitsuba's best at {budget:g} s: {best.label}", flush=True)
    best.label += " (best)"
    return best


def measure(scenes, progs, makers, budgets, repeats, spp, ref_seconds, refs_dir, out_dir, info, best_auto=False):
    """makers: the program that renders each renderer's reference. best_auto: Mitsuba's best
    program chosen per scene by select_best, at the longest budget."""
    rows = []
    for sc in scenes:
        refs = {}
        for r in ("facet", "mitsuba"):
            refs[r] = Ref(*reference(makers[r], sc, ref_seconds, refs_dir))
        cross = float(np.mean((refs["facet"].image - refs["mitsuba"].image) ** 2))
        if best_auto and "mitsuba_best" in progs and not spp:
            progs["mitsuba_best"] = select_best(sc, refs, cross, progs["mitsuba"].assets, max(budgets), info)
        for p in progs.values():
            if isinstance(p, Mitsuba):
                p.warm_up(sc)
        points = [("spp", spp)] if spp else [("s", b) for b in budgets]
        for kind, amount in points:
            runs = {k: [] for k in progs}
            for rep in range(repeats):
                for key, p in progs.items():   # alternate: every program once per round
                    seed = 100 + rep
                    if kind == "s":
                        img, n, t = p.render(sc, seed, seconds=amount)
                    else:
                        img, n, t = p.render(sc, seed, spp=amount)
                    own, other = refs[p.renderer], refs["mitsuba" if p.renderer == "facet" else "facet"]
                    runs[key].append({"spp": n / sc.pixels, "seconds": t, "msamples_s": n / t * 1e-6,
                                      "rmse_own": rmse(img, own), "rmse_other": rmse(img, other),
                                      "rmse_3c": rmse_three_cornered(img, own, other, cross)})
                    print(f"  {sc.name} {amount:g} {kind} #{rep + 1} {p.label:28s} {n / sc.pixels:8.1f} spp "
                          f"{t:7.2f} s {n / t * 1e-6:6.2f} Msamples/s  rmse own {fmt_rmse(runs[key][-1]['rmse_own'])} "
                          f"other {fmt_rmse(runs[key][-1]['rmse_other'])} 3c {fmt_rmse(runs[key][-1]['rmse_3c'])}",
                          flush=True)
            for key, rs in runs.items():
                med = {k: statistics.median(r[k] for r in rs) for k in rs[0]}
                # The RMSE of the mean squared error over the runs: what the expected error
                # is, where a median of a few runs of a firefly-dominated image is not.
                med["rmse_pooled"] = math.sqrt(statistics.fmean(r["rmse_own"] ** 2 for r in rs))
                rows.append({"scene": sc.name, "size": f"{sc.width}x{sc.height}", kind: amount,
                             "program": progs[key].label, "renderer": progs[key].renderer,
                             "runs": rs, "median": med,
                             "ref_spp": {r: refs[r].spp for r in refs},
                             "ref_noise_rmse": {r: math.sqrt(refs[r].noise_mse) for r in refs}})
    info["load_after"] = " ".join(f"{x:.1f}" for x in os.getloadavg())
    title = f"equal spp ({spp} samples per pixel)" if spp else "equal time"
    lines = [f"# facet vs Mitsuba 3, {title}", "",
             f"Medians of {repeats} runs, programs alternated; load average {info['load_before']} before, "
             f"{info['load_after']} after. RMSE against each renderer's reference with the reference's own "
             "noise taken out; 'own': the program's renderer, 'other': the other renderer's.", ""]
    col = "spp" if spp else "budget (s)"
    lines += [f"| scene | {col} | program | spp | Msamples/s | RMSE own | RMSE other | RMSE / facet's (own) "
              "| RMSE pooled (√ mean MSE) | pooled / facet's | RMSE three-cornered | 3c / facet's |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        amount = r.get("spp", r.get("s"))
        base = next(x for x in rows if x["scene"] == r["scene"] and x.get("spp", x.get("s")) == amount
                    and x["program"] == "facet")
        m = r["median"]
        ratio = m["rmse_own"] / base["median"]["rmse_own"] if base["median"]["rmse_own"] > 0 else float("nan")
        pooled = m["rmse_pooled"] / base["median"]["rmse_pooled"] if base["median"]["rmse_pooled"] > 0 else float("nan")
        b3 = base["median"]["rmse_3c"]
        ratio3 = m["rmse_3c"] / b3 if b3 > 0 else float("nan")
        lines.append(f"| {r['scene']} | {amount:g} | {r['program']} | {m['spp']:.1f} | {m['msamples_s']:.2f} | "
                     f"{fmt_rmse(m['rmse_own'])} | {fmt_rmse(m['rmse_other'])} | {ratio:.2f} | "
                     f"{fmt_rmse(m['rmse_pooled'])} | {pooled:.2f} | {fmt_rmse(m['rmse_3c'])} | {ratio3:.2f} |")
    refs_line = sorted({(r["scene"], r["size"], round(r["ref_spp"]["facet"]), round(r["ref_spp"]["mitsuba"]))
                        for r in rows})
    lines += ["", "References (spp): " + "; ".join(f"{s} {sz}: facet {a}, Mitsuba {b}" for s, sz, a, b in refs_line)]
    lines += under_noise_lines(rows)
    cautions = reference_cautions(rows, ref_seconds)
    if cautions:
        lines += [""] + cautions  # printed with the table by write_outputs
    info["rows"] = rows
    write_outputs(out_dir, "mitsuba_equal_spp" if spp else "mitsuba_equal_time", lines, info)


def reference_cautions(rows, ref_seconds):
    """A line for each scene and budget whose references' own noise (RMSE) is over half the
    lowest image error: the figures then rest on taking that noise out, which holds on average
    but not for a few runs of a firefly-dominated image (glass_metal_sky with 90 s references:
    docs/performance.md, "A second CPU"). The suggested length brings the noise to half."""
    out = []
    for key in sorted({(r["scene"], r.get("spp", r.get("s"))) for r in rows}):
        group = [r for r in rows if (r["scene"], r.get("spp", r.get("s"))) == key]
        lowest = min(r["median"]["rmse_own"] for r in group)
        noise = max(group[0]["ref_noise_rmse"].values())
        if lowest > 0 and noise > 0.5 * lowest:
            need = ref_seconds * (noise / (0.5 * lowest)) ** 2
            unit = "spp" if "spp" in group[0] else "s"
            out.append(f"Caution: {key[0]} at {key[1]:g} {unit}: a reference's own noise (RMSE {noise:.4g}) is "
                       f"{noise / lowest:.2f} of the lowest image error ({lowest:.4g}); the ratios rest on taking it "
                       f"out. References of about {math.ceil(need / 60) * 60:g} s (--reference-seconds) would bring "
                       "it to half.")
    return out


def per_sample(scenes, progs, spp, images, out_dir, info):
    """Error per sample without a reference: `images` images of independent seeds per
    program at `spp` samples per pixel; the per-pixel variance across them, averaged over
    the image, is the MSE of one image (its square root below). No reference's noise to
    take out, insensitive to the machine's load; on a firefly-dominated image (the sun
    through glass) a handful of samples decide it."""
    rows = []
    for sc in scenes:
        for key, p in progs.items():
            imgs, n = [], 0
            for k in range(images):
                img, samples, _ = p.render(sc, 500 + k, spp=spp)
                imgs.append(img)
                n += samples
            stack = np.stack(imgs)
            rmse1 = math.sqrt(float(np.mean(np.var(stack, axis=0, ddof=1))))
            rows.append({"scene": sc.name, "size": f"{sc.width}x{sc.height}", "program": p.label,
                         "spp": n / images / sc.pixels, "images": images, "rmse_one_image": rmse1,
                         "mean": stack.mean(axis=(0, 1, 2)).tolist()})
            print(f"  {sc.name} {p.label:28s} {rows[-1]['spp']:.1f} spp x {images}: RMSE of one image {rmse1:.4g}",
                  flush=True)
    info["load_after"] = " ".join(f"{x:.1f}" for x in os.getloadavg())
    lines = [f"# facet vs Mitsuba 3, error per sample ({images} images of independent seeds, {spp} spp)", "",
             f"Load average {info['load_before']} before, {info['load_after']} after. RMSE of one image: the "
             "square root of the per-pixel variance across the images, averaged over the image.", "",
             "| scene | program | spp | RMSE of one image | / facet's |", "|---|---|---|---|---|"]
    for r in rows:
        base = next(x for x in rows if x["scene"] == r["scene"] and x["program"] == "facet")
        lines.append(f"| {r['scene']} {r['size']} | {r['program']} | {r['spp']:.1f} | {r['rmse_one_image']:.4g} | "
                     f"{r['rmse_one_image'] / base['rmse_one_image']:.2f} |")
    info["rows"] = rows
    write_outputs(out_dir, "mitsuba_per_sample", lines, info)


def write_outputs(out_dir, stem, lines, data):
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(out_dir, stem + ".md"), "w") as f:
        f.write(text)
    with open(os.path.join(out_dir, stem + ".json"), "w") as f:
        json.dump(data, f, indent=1)
    print(f"wrote {os.path.join(out_dir, stem)}.md and .json")


# --------------------------------------------------------------------------------------

def prepare_work(a, name):
    """--quick's short settings applied to the parsed options `a`, and the baseline's work,
    asset and reference folders under a.out/name made (shared with bench/cycles)."""
    if a.quick:
        a.budgets, a.repeats, a.reference_seconds, a.scale = "2,5", 1, 30, 0.25
    work = os.path.join(a.out, name)
    assets, refs_dir = os.path.join(work, "assets"), os.path.join(work, "refs")
    for d in (work, assets, refs_dir):
        os.makedirs(d, exist_ok=True)
    return work, assets, refs_dir


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--budgets", default="10,60", help="time budgets in seconds (default 10,60)")
    ap.add_argument("--repeats", type=int, default=3, help="runs of each program per budget (default 3)")
    ap.add_argument("--quick", action="store_true", help="budgets 2,5, 1 repeat, 30 s references, quarter size")
    ap.add_argument("--scenes", default=",".join(translate.SCENES), help="comma-separated scene names")
    ap.add_argument("--scale", type=float, default=1.0, help="image size relative to the scene's (default 1)")
    ap.add_argument("--reference-seconds", type=float, default=300,
                    help="time of each renderer's reference (two halves; default 300)")
    ap.add_argument("--mitsuba-best", default="auto",
                    help="Mitsuba's best sampler, run beside its default 'independent': a sampler's name, or "
                         "auto (default): per scene, the best of the five samplers x two pass sizes in one run "
                         "of the longest budget; with --equal-spp or --per-sample, all five samplers run; "
                         "SAMPLER@4M: that sampler in passes of 4 M lanes (what auto's selection may pick)")
    ap.add_argument("--equal-spp", type=int, default=0, help="instead of time budgets: N samples per pixel")
    ap.add_argument("--per-sample", type=int, default=0, metavar="K",
                    help="error per sample without a reference: K images of independent seeds per program at "
                         "--equal-spp samples per pixel (default 16)")
    ap.add_argument("--check", action="store_true",
                    help="agreement in mean: the two references compared region by region")
    ap.add_argument("--programs", default="facet,facet_independent,mitsuba,mitsuba_best",
                    help="which programs to run, of facet, facet_independent, facet_unguided (--caustic-guide 0: "
                         "no sampling toward glass, Mitsuba's strategies), facet_roulette1 (--roulette-gain 1: "
                         "Mitsuba's Russian roulette, so paths as long as its, for samples per second at equal "
                         "work), mitsuba (its default sampler) and "
                         "mitsuba_best (default: facet, facet_independent, mitsuba, mitsuba_best)")
    ap.add_argument("--threads", type=int, default=2, help="Mitsuba threads (default 2, as facet's PoCL here)")
    ap.add_argument("--facet", default=os.path.join(ROOT, "build", "facet"), help="the facet binary")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench"), help="output folder")
    a = ap.parse_args()

    why = import_mitsuba(a.threads)
    if why:
        print(why)
        return 0
    if not os.path.exists(a.facet):
        raise SystemExit(f"equal_time.py: {a.facet} not found (make build first)")
    work, assets, refs_dir = prepare_work(a, "mitsuba")
    translate.write_assets(assets, a.facet)
    scenes = [Scene(n, a.scale) for n in a.scenes.split(",")]
    progs = {"facet": Facet(a.facet, None, work), "facet_independent": Facet(a.facet, "independent", work),
             "facet_unguided": Facet(a.facet, None, work, ("--caustic-guide", "0")),
             "facet_roulette1": Facet(a.facet, None, work, ("--roulette-gain", "1")),
             "mitsuba": Mitsuba("independent", assets)}
    best_auto = a.mitsuba_best == "auto"
    if best_auto and (a.equal_spp or a.per_sample):
        for s in SAMPLERS[1:]:
            progs[f"mitsuba_{s}"] = Mitsuba(s, assets)
    elif best_auto:
        progs["mitsuba_best"] = Mitsuba("multijitter", assets)   # replaced per scene by select_best
    elif a.mitsuba_best and a.mitsuba_best != "independent":
        sampler, _, lanes = a.mitsuba_best.partition("@")
        if sampler not in SAMPLERS or (lanes and lanes != "4M"):
            raise SystemExit(f"equal_time.py: --mitsuba-best {a.mitsuba_best}: one of {', '.join(SAMPLERS)} "
                             "(with @4M: passes of 4 M lanes), or auto")
        progs["mitsuba_best"] = Mitsuba(sampler, assets, PASS_LANES[1] if lanes else None)
    wanted = a.programs.split(",")
    if best_auto and (a.equal_spp or a.per_sample):
        wanted += [f"mitsuba_{s}" for s in SAMPLERS[1:]]
    unknown = [k for k in wanted if k not in set(progs) | {"mitsuba_best"}]
    if unknown or "facet" not in wanted:
        raise SystemExit(f"equal_time.py: --programs {a.programs}: needs facet, and only facet, "
                         "facet_independent, facet_unguided, facet_roulette1, mitsuba, mitsuba_best")
    refs_progs = dict(progs)   # both renderers' references are made whatever runs
    progs = {k: p for k, p in progs.items() if k in wanted}
    info = {"mitsuba": mi.__version__, "variant": mi.variant(), "threads": a.threads,
            "load_before": " ".join(f"{x:.1f}" for x in os.getloadavg())}
    if a.check:
        check(scenes, refs_progs, a.reference_seconds, refs_dir, a.out)
        return 0
    if a.per_sample:
        if a.per_sample < 2:
            raise SystemExit("equal_time.py: --per-sample needs at least 2 images")
        per_sample(scenes, progs, a.equal_spp or 16, a.per_sample, a.out, info)
        return 0
    budgets = [float(x) for x in a.budgets.split(",")]
    t0 = time.time()
    check(scenes, refs_progs, a.reference_seconds, refs_dir, a.out)   # the references, compared
    measure(scenes, progs, refs_progs, budgets, a.repeats, a.equal_spp, a.reference_seconds, refs_dir, a.out, info,
            best_auto)
    print(f"equal_time.py: {time.time() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
