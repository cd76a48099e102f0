#!/usr/bin/env python3
"""Parallel efficiency of facet's device group and MPI ranks (issue 17), on one machine.

Renders one scene with the same total threads three ways, alternated round by round
(these machines are noisy), and reports medians of the render seconds of each:

  one     one process, one context, POCL_MAX_PTHREAD_COUNT=THREADS
  group   one process, --device 0,0 (two contexts on PoCL's one device; PoCL keeps one
          thread pool per device, so the two contexts share THREADS threads)
  ranks   mpirun -n 2, POCL_MAX_PTHREAD_COUNT=THREADS/2 in each rank

Efficiency = one's seconds / the other's (1 = no cost for splitting the work). For the
ranks it also reports the film reduction's cost per pass (the `reduce` line rank 0 prints:
the one-word gather and MPI_Ireduce of the half buffers, including waiting for the slower
rank). Skips the ranks (exit 0) when mpirun is absent or facet was built without MPI.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def render(facet, cmd_prefix, env_extra, scene, args, tag, folder):
    out = os.path.join(folder, f"{tag}.exr")
    cmd = cmd_prefix + [facet, "render", scene, "--width", str(args.width), "--height", str(args.height),
                        "--spp", str(args.spp), "--seed", "3", "--out", out,
                        "--report", os.path.join(folder, f"{tag}.csv")]
    if tag.startswith("group"):
        cmd += ["--device", "0,0"]
    env = dict(os.environ, **env_extra)
    run = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"parallel_efficiency: {' '.join(cmd)} failed ({run.returncode}):\n{run.stderr[-2000:]}")
    report = json.load(open(os.path.join(folder, f"{tag}.json")))
    reduce_s = None
    m = re.search(r"^reduce\s+([0-9.]+) s", run.stdout, re.M)
    if m:
        reduce_s = float(m.group(1))
    elif tag.startswith("ranks"):
        raise NoMpi("facet was built without MPI (no rank lines in its summary)")
    return report["render_s"], report["passes"], reduce_s


class NoMpi(Exception):
    pass


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--facet", default=os.path.join(ROOT, "build", "facet"))
    ap.add_argument("--scene", default=os.path.join(ROOT, "scenes", "cornell_box.json"))
    ap.add_argument("--width", type=int, default=320)
    ap.add_argument("--height", type=int, default=320)
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--threads", type=int, default=2, help="threads in all (default 2)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "bench"), help="output folder")
    args = ap.parse_args()
    if args.threads < 2 or args.threads % 2:
        sys.exit("parallel_efficiency: --threads must be even and at least 2")
    mpi_ok = shutil.which("mpirun") is not None
    env_mpi = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
               "POCL_MAX_PTHREAD_COUNT": str(args.threads // 2)}
    programs = [("one", [], {"POCL_MAX_PTHREAD_COUNT": str(args.threads)}),
                ("group", [], {"POCL_MAX_PTHREAD_COUNT": str(args.threads)})]
    if mpi_ok:
        programs.append(("ranks", ["mpirun", "-n", "2", "--oversubscribe", "-x", "POCL_MAX_PTHREAD_COUNT"], env_mpi))
    else:
        print("parallel_efficiency: skipping MPI ranks: no mpirun (apt-get install openmpi-bin)")
    results = {name: [] for name, _, _ in programs}
    with tempfile.TemporaryDirectory(prefix="facet_parallel_") as folder:
        for r in range(args.rounds):
            for name, prefix, env in list(programs):
                try:
                    seconds, passes, reduce_s = render(args.facet, prefix, env, args.scene, args, f"{name}_{r}",
                                                       folder)
                except NoMpi as e:
                    print(f"parallel_efficiency: skipping MPI ranks: {e}")
                    programs = [p for p in programs if p[0] != name]
                    del results[name]
                    continue
                results[name].append({"render_s": seconds, "passes": passes, "reduce_s": reduce_s})
                extra = f", reduce {reduce_s:.3f} s" if reduce_s is not None else ""
                print(f"  round {r + 1} {name:6s} {seconds:7.2f} s, {passes} passes{extra}", flush=True)
    one = statistics.median(x["render_s"] for x in results["one"])
    rows = []
    for name, _, _ in programs:
        med = statistics.median(x["render_s"] for x in results[name])
        passes = statistics.median(x["passes"] for x in results[name])
        reduces = [x["reduce_s"] for x in results[name] if x["reduce_s"] is not None]
        per_pass = statistics.median(reduces) / passes * 1e3 if reduces else None
        rows.append({"program": name, "median_render_s": med, "efficiency": one / med, "passes": passes,
                     "reduce_ms_per_pass": per_pass, "runs": results[name]})
    scene = os.path.basename(args.scene)
    lines = [f"# Parallel efficiency: {scene} {args.width}x{args.height}, {args.spp} spp, {args.threads} threads in all",
             "", f"Medians of {args.rounds} alternated rounds; load average {os.getloadavg()[0]:.1f} at the end.", "",
             "| program | render s (median) | efficiency | passes | film reduction per pass |", "|---|---|---|---|---|"]
    for row in rows:
        red = f"{row['reduce_ms_per_pass']:.1f} ms" if row["reduce_ms_per_pass"] is not None else "—"
        lines.append(f"| {row['program']} | {row['median_render_s']:.2f} | {row['efficiency']:.2f} | "
                     f"{row['passes']:.0f} | {red} |")
    text = "\n".join(lines) + "\n"
    print(text)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "parallel_efficiency.md"), "w") as f:
        f.write(text)
    with open(os.path.join(args.out, "parallel_efficiency.json"), "w") as f:
        json.dump({"scene": scene, "width": args.width, "height": args.height, "spp": args.spp,
                   "threads": args.threads, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
