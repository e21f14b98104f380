"""Runs the VOF benchmark of issue 8 in vofdem and OpenFOAM v1912 interIsoFoam (see vof-vs-openfoam).

The case: the Martin & Moyce (1952) dam break of config/scenes/dam-break.yaml (V5), density ratio 1000,
a/h = --resolution cells across the water column (grid 5N x 2.5N x 1: vofdem between slip walls, OpenFOAM
with empty faces), to T = t sqrt(2 g / a) = 3. vofdem runs examples/ex30_dam_break (the program's
own coupled step; it prints the front at Martin & Moyce's times); OpenFOAM runs interIsoFoam at its
tutorial settings (foam_dambreak.py), once for timing (no output) and once writing alpha every 0.05 in T
for the front. Front: the wetted length sum(alpha h) of the floor row, in both codes.
Speed: cell-steps per second (cells x steps / wall time of the solver process) and the wall time to
T = 3, on 1 and 2 ranks, back to back, --repeats times, medians. Accuracy: front error against Martin &
Moyce at their times up to T = 3, both codes side by side.
"""
import argparse
import datetime
import math
import os
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foam_cavity as fc  # noqa: E402  (run())
import foam_dambreak as fd  # noqa: E402
import record  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("VOFDEM_BUILD", os.path.join(ROOT, "build"))
WORK = os.path.join(BUILD, "bench", "vof-vs-openfoam")
RESULTS = os.path.join(ROOT, "results", "bench-vof-vs-openfoam.md")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
T_END = 3.0
# Martin & Moyce (1952), n^2 = 2: front Z = x/a when it passed each gauge, at T = t sqrt(2 g / a)
# (the table examples/ex30_dam_break.cpp compares with).
MM_T = [0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98]
MM_Z = [1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67]
OUT = []


def say(s=""):
    print(s, flush=True)
    OUT.append(s)


def mpi(n):
    # pml ob1 for both codes: Debian's Open MPI otherwise opens its network layers first (libpsm2 sleeps in its
    # constructor), ~0.2 s per start on one machine. vofdem chooses it by itself (MpiStartupDefaults.hpp);
    # OpenFOAM would not, and its parallel start-up should not be charged for it.
    return ["mpiexec", "--mca", "pml", "ob1", "-n", str(n), "--bind-to", "core", "--map-by", "core"]


def interpolate(ts, zs, t):
    for k in range(1, len(ts)):
        if ts[k] >= t:
            w = (t - ts[k - 1]) / (ts[k] - ts[k - 1])
            return zs[k - 1] + w * (zs[k] - zs[k - 1])
    return float("nan")


def run_vofdem(ranks, n):
    """ex30 at a/h = n: (cells, steps, wall s, {T: Z}) or raises RuntimeError with the reason."""
    exe = os.path.join(BUILD, "examples", "ex30_dam_break")
    if not os.access(exe, os.X_OK):
        raise RuntimeError("no %s (build the examples)" % os.path.relpath(exe, ROOT))
    # One rank runs without mpiexec, as OpenFOAM's serial run does (mpiexec's start-up is ~0.5 s).
    cmd = (mpi(ranks) if ranks > 1 else []) + [exe, "-resolution", str(n), "-front_check", "0"]
    t0 = time.monotonic()
    p = subprocess.run(cmd, env=ENV, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        raise RuntimeError("ex30 failed: " + (p.stderr + p.stdout).strip().splitlines()[-1:][0] if (p.stderr + p.stdout).strip() else "ex30 failed")
    m = re.search(r"V5 dam break, (\d+) x (\d+) x (\d+) cells .*?, (\d+) steps to T", p.stdout)
    if not m:
        raise RuntimeError("ex30 printed no summary line")
    cells = int(m.group(1)) * int(m.group(2)) * int(m.group(3))
    fronts = {float(t): float(z) for t, z in re.findall(r"T (\d+\.\d+): Z (\d+\.\d+), measured", p.stdout)}
    return cells, int(m.group(4)), wall, fronts


def run_openfoam(ranks, n, with_front):
    """interIsoFoam at a/h = n: (cells, steps, solver wall s, {T: Z})."""
    nx, ny = 5 * n, (5 * n) // 2
    case = os.path.join(WORK, "foam-%d-%d%s" % (n, ranks, "-front" if with_front else ""))
    scale = math.sqrt(2 * fd.G / fd.A)
    every = (0.05 if with_front else 10 * T_END) / scale
    fd.make_case(case, nx, ny, ranks, ENV, fc.run, T_END / scale, every)
    cmd = (mpi(ranks) + ["interIsoFoam", "-parallel"]) if ranks > 1 else ["interIsoFoam"]
    t0 = time.monotonic()
    fc.run(cmd, case, ENV, os.path.join(case, "log.interIsoFoam"))
    wall = time.monotonic() - t0
    steps, _ = fd.parse_log(os.path.join(case, "log.interIsoFoam"))
    fronts = {}
    if with_front:
        hist = fd.front_positions(case, nx, ny, ranks, ENV, fc.run)
        ts = [0.0] + [fd.scaled_time(t) for t, _ in hist]
        zs = [1.0] + [x / fd.A for _, x in hist]
        fronts = {t: interpolate(ts, zs, t) for t in MM_T}
    return nx * ny, steps, wall, fronts


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    # 32 (12,800 cells, ~2-10 s per run): at 16 (3,200 cells) 2 ranks measure mostly mpiexec's start-up and the first solves
    ap.add_argument("--resolution", type=int, default=32, help="cells across the water column a (default 32: 160 x 80)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--no-record", action="store_true", help="do not write the block into results/")
    a = ap.parse_args()
    os.makedirs(WORK, exist_ok=True)
    n, ranks = a.resolution, [int(r) for r in a.ranks.split(",")]
    say("## %s, commit %s" % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
                              subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()))
    say("dam break (Martin & Moyce n^2 = 2), a/h = %d, to T = %g; medians of %d repeats; load %.1f at the start" % (n, T_END, a.repeats, os.getloadavg()[0]))
    say("")
    say("| ranks | code | cells | steps | wall (s) | cell-steps/s | vofdem / OpenFOAM (rate) | vofdem / OpenFOAM (time to T=3) |")
    say("| --- | --- | --- | --- | --- | --- | --- | --- |")
    fronts = {}
    for r in ranks:
        rows = {"vofdem": [], "OpenFOAM": []}
        for _ in range(a.repeats):  # back to back, alternating
            try:
                c, s, w, f = run_vofdem(r, n)
                rows["vofdem"].append((c, s, w))
                fronts.setdefault("vofdem", f)
            except RuntimeError as e:
                say("vofdem on %d rank(s): %s" % (r, e))
            c, s, w, _ = run_openfoam(r, n, False)
            rows["OpenFOAM"].append((c, s, w))
        med = {}
        for code, rr in rows.items():
            if not rr:
                continue
            c, s = rr[0][0], rr[0][1]
            w = statistics.median(x[2] for x in rr)
            med[code] = (c * s / w, w)
            say("| %d | %s | %d | %d | %.2f | %.3g | | |" % (r, code, c, s, w, c * s / w))
        if len(med) == 2:
            say("| %d | ratio | | | | | %.2f | %.2f |" % (r, med["vofdem"][0] / med["OpenFOAM"][0], med["OpenFOAM"][1] / med["vofdem"][1]))
    _, _, _, fronts["OpenFOAM"] = run_openfoam(1, n, True)
    say("")
    say("Front Z = x/a against Martin & Moyce (error in %):")
    say("")
    say("| T | measured | vofdem | error | OpenFOAM | error |")
    say("| --- | --- | --- | --- | --- | --- |")
    worst = {}
    for t, z in zip(MM_T, MM_Z):
        cells = []
        for code in ("vofdem", "OpenFOAM"):
            v = fronts.get(code, {}).get(t, float("nan"))
            e = 100 * (v - z) / z
            if not math.isnan(e):
                worst[code] = max(worst.get(code, 0.0), abs(e))
            cells += ["%.3f" % v, "%+.1f" % e]
        say("| %.2f | %.2f | %s |" % (t, z, " | ".join(cells)))
    say("")
    say("largest front error: " + ", ".join("%s %s" % (code, "%.1f %%" % worst[code] if code in worst else "n/a (did not run)") for code in ("vofdem", "OpenFOAM")))
    if not a.no_record:
        record.prepend_block(RESULTS, "# vof-vs-openfoam (scripts/bench/vof-vs-openfoam), newest first", OUT, ROOT)


if __name__ == "__main__":
    main()
