"""Runs the DEM benchmark of the DEM engine issue in vofdem and LIGGGHTS (see dem-vs-liggghts).

The bed: equal spheres d = 100 um, E = 1e8 Pa, nu = 0.28, e = 0.5, mu = 0.27, rolling friction
0.0315 (LIGGGHTS' epsd2, vofdem -dem_rolling epsd2), density 8000, no cohesion, in a 3 x 3 mm box
with walls. It is made once by vofdem (a jittered lattice dropped and settled), cached under
build/bench/, and given to both codes as the same particle list with zero velocities. Each timed
run first takes --warmup steps, then --steps timed steps, with the same dt in both codes.
--mix makes the bed a 2:1 mix (d = 100 and 50 um, equal mass fractions), --ratio R an R:1 mix (d = 100
and 100/R um), with a smaller dt for the smaller spheres' Rayleigh time.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(ROOT, "build")
WORK = os.path.join(BUILD, "bench", "dem-vs-liggghts")
VOFDEM = os.path.join(BUILD, "vofdem")
D, L, RHO, SKIN = 1e-4, 3e-3, 8000.0, 2e-5
DT = 5e-7
MIX = []  # extra fill options for a size mix
MODEL = ("-physics dem -dem_radius 5e-5 -dem_density 8000 -dem_youngs_modulus 1e8 -dem_poisson_ratio 0.28 -dem_restitution 0.5 "
         "-dem_friction 0.27 -dem_rolling epsd2 -dem_rolling_friction 0.0315 -dem_skin 2e-5").split()
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")


def run(cmd, **kw):
    p = subprocess.run(cmd, env=ENV, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        sys.exit("dem-vs-liggghts: command failed: %s\n%s%s" % (" ".join(cmd), p.stdout[-3000:], p.stderr[-3000:]))
    return p.stdout


def mpi(n):
    return ["mpiexec", "-n", str(n), "--bind-to", "core", "--map-by", "core"]


def box_height(layers):
    return (layers * 1.15 + 4) * D


def settled_bed(layers):
    """Drops a jittered lattice of `layers` layers (26 x 26 spheres each) and lets it settle."""
    path = os.path.join(WORK, "settled-%s%d.csv" % ("mix%s-" % MIX[1].split(",")[1] if MIX else "", layers))
    if os.path.exists(path):
        return path
    h = box_height(layers)
    print("preparing the settled bed (%d layers), once; cached in %s" % (layers, path), flush=True)
    run(mpi(2) + [VOFDEM] + MODEL + ["-grid_upper", "%g,%g,%g" % (L, L, h), "-grid_cells", "12,12,%d" % max(2, round(h / 2.5e-4)),
                                     "-grid_ranks", "2,1,1", "-dem_fill_count", "-1", "-dem_fill_spacing", "%g" % (1.15 * D),
                                     "-dem_fill_jitter", "0.5", "-seed", "2027", "-dt", "%g" % DT, "-final_time", "0.03",
                                     "-max_steps", "1000000", "-monitor_every", "10000", "-dem_save_particles", path] + MIX)
    return path


def read_bed(path):
    """(x, y, z, radius) rows of a particle CSV, by its header."""
    lines = open(path).read().splitlines()
    cols = lines[0].split(",")
    ix, iy, iz = cols.index("x"), cols.index("y"), cols.index("z")
    ir = cols.index("radius") if "radius" in cols else None
    rows = []
    for l in lines[1:]:
        if l.strip():
            v = l.split(",")
            rows.append((v[ix], v[iy], v[iz], v[ir] if ir is not None else "%g" % (D / 2)))
    return rows


def still(src, dst, copies=1, height=0.0):
    """The bed with zero velocities, optionally stacked `copies` times `height` apart."""
    rows = read_bed(src)
    with open(dst, "w") as f:
        f.write("x,y,z,radius\n")
        for c in range(copies):
            for x, y, z, r in rows:
                f.write("%s,%s,%.17g,%s\n" % (x, y, float(z) + c * height, r))
    return len(rows) * copies


def liggghts_input(csv, h, steps, warmup, tag):
    rows = read_bed(csv)
    data = os.path.join(WORK, "bed-%s.data" % tag)
    with open(data, "w") as f:
        f.write("LIGGGHTS data file\n\n%d atoms\n1 atom types\n\n0 %g xlo xhi\n0 %g ylo yhi\n0 %g zlo zhi\n\nAtoms\n\n" % (len(rows), L, L, h))
        for i, (x, y, z, r) in enumerate(rows):
            f.write("%d 1 %.17g %g %s %s %s\n" % (i + 1, 2 * float(r), RHO, x, y, z))
    walls = "".join("fix w%d all wall/gran model hertz tangential history rolling_friction epsd2 primitive type 1 %s %g\n" % (i, p, v)
                    for i, (p, v) in enumerate([("xplane", 0), ("xplane", L), ("yplane", 0), ("yplane", L), ("zplane", 0), ("zplane", h)]))
    text = f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
processors * * 1
read_data {data}
neighbor {SKIN} bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 1e8
fix m2 all property/global poissonsRatio peratomtype 0.28
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.27
fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.0315
pair_style gran model hertz tangential history rolling_friction epsd2
pair_coeff * *
timestep {DT}
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
{walls}fix integr all nve/sphere
thermo {max(steps, 1)}
thermo_style custom step atoms ke
run {warmup}
run {steps}
"""
    path = os.path.join(WORK, "in-%s.liggghts" % tag)
    open(path, "w").write(text)
    return path


def time_liggghts(ranks, inp, steps):
    out = run(mpi(ranks) + ["stdbuf", "-o0", "-e0", "liggghts", "-in", inp, "-echo", "none"], cwd=WORK)
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out)
    if len(loops) < 2 or int(loops[-1][1]) != steps:
        sys.exit("dem-vs-liggghts: no loop time in LIGGGHTS' output:\n" + out[-2000:])
    whitelisted = "not located in any whitelist" not in out
    return float(loops[-1][0]), int(loops[-1][2]), whitelisted


def time_vofdem(ranks, csv, h, steps, warmup):
    outdir = os.path.join(WORK, "vofdem-out-%d" % ranks)
    run(mpi(ranks) + [VOFDEM] + MODEL + ["-grid_upper", "%g,%g,%g" % (L, L, h), "-grid_cells", "12,12,%d" % max(2, round(h / 2.5e-4)),
                                          "-grid_ranks", "%d,1,1" % ranks, "-dem_particles_file", csv, "-dt", "%g" % DT,
                                          "-max_steps", str(warmup + steps), "-monitor_every", str(warmup), "-output_dir", outdir])
    lines = open(os.path.join(outdir, "monitor.csv")).read().splitlines()
    col = lines[0].split(",").index("wall_time_s")
    rows = [l.split(",") for l in lines[1:]]
    wall = {int(r[0]): float(r[col]) for r in rows}
    n = int(rows[-1][3])
    return wall[warmup + steps] - wall[warmup], n


def max_rss_kb(cmd, cwd=None):
    out = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M"] + cmd, env=ENV, capture_output=True, text=True, cwd=cwd)
    m = re.search(r"MAXRSS (\d+)", out.stderr)
    if out.returncode != 0 or not m:
        sys.exit("dem-vs-liggghts: memory run failed: %s\n%s" % (" ".join(cmd), out.stderr[-2000:]))
    return int(m.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--steps", type=int, default=3000)
    ap.add_argument("--warmup", type=int, default=500)
    ap.add_argument("--layers", type=int, default=31, help="lattice layers of 26 x 26 spheres before settling (31: 20,956 spheres)")
    ap.add_argument("--mix", action="store_true", help="a 2:1 size mix (d = 100 and 50 um, equal mass fractions)")
    ap.add_argument("--ratio", type=float, default=0, help="an R:1 size mix (d = 100 and 100/R um, equal mass fractions)")
    ap.add_argument("--no-memory", action="store_true", help="skip the memory measurement")
    ap.add_argument("--memory-only", action="store_true", help="only the memory measurement (no timed runs)")
    a = ap.parse_args()
    global DT
    if a.mix:
        a.ratio = 2
    if a.ratio:
        MIX.extend(["-dem_fill_radii", "5e-5,%g" % (5e-5 / a.ratio), "-dem_fill_mass_fractions", "0.5,0.5"])
        # 0.8 of 0.3 of the small spheres' Rayleigh time (P9), to 2 digits (2:1: 3e-7 s)
        G = 1e8 / (2 * 1.28)
        tr = math.pi * (5e-5 / a.ratio) * math.sqrt(RHO / G) / (0.1631 * 0.28 + 0.8766)
        DT = float("%.1g" % (0.8 * 0.3 * tr))
    os.makedirs(WORK, exist_ok=True)
    h = box_height(a.layers)
    bed = settled_bed(a.layers)
    csv = os.path.join(WORK, "bed.csv")
    n = still(bed, csv)
    top = max(float(l.split(",")[2]) for l in open(csv).read().splitlines()[1:])
    lig = liggghts_input(csv, h, a.steps, a.warmup, "N")
    small = sum(1 for r in read_bed(csv) if float(r[3]) < 0.75 * D / 2)
    print("bed: %d spheres, %s, settled height %.3f mm in a %g x %g x %.2f mm box; dt %g s; %d timed steps after %d" %
          (n, "d = 100 um" if not a.ratio else "%g:1 mix, %d of d = %g um and %d of d = 100 um" % (a.ratio, small, 100 / a.ratio, n - small), 1e3 * (top + D / 2), 1e3 * L, 1e3 * L,
           1e3 * h, DT, a.steps, a.warmup), flush=True)
    if a.memory_only:
        mem = memory(csv, h, n, top)
        print("memory per particle (resident-size slope, %d -> %d spheres, 1 rank): vofdem %.0f B, LIGGGHTS %.0f B" % (n, 2 * n, mem["vofdem"], mem["liggghts"]))
        print("target: memory < 1 KB per particle: %s" % ("met" if mem["vofdem"] < 1024 else "NOT met"))
        return
    ns = {("liggghts", 1): [], ("liggghts", 2): [], ("vofdem", 1): [], ("vofdem", 2): []}
    whitelisted = True
    for rep in range(a.repeats):
        for ranks in (1, 2):
            t, nl, wl = time_liggghts(ranks, lig, a.steps)
            whitelisted = whitelisted and wl
            if nl != n:
                sys.exit("dem-vs-liggghts: LIGGGHTS ended with %d atoms, not %d (lost particles)" % (nl, n))
            ns[("liggghts", ranks)].append(t / (a.steps * n) * 1e9)
            t, nv = time_vofdem(ranks, csv, h, a.steps, a.warmup)
            if nv != n:
                sys.exit("dem-vs-liggghts: vofdem ended with %d particles, not %d" % (nv, n))
            ns[("vofdem", ranks)].append(t / (a.steps * n) * 1e9)
            print("  repeat %d, %d rank%s: LIGGGHTS %.1f ns, vofdem %.1f ns per particle-step" %
                  (rep + 1, ranks, "s" if ranks > 1 else "", ns[("liggghts", ranks)][-1], ns[("vofdem", ranks)][-1]), flush=True)
    med = {k: statistics.median(v) for k, v in ns.items()}
    mem = None
    if not a.no_memory:
        mem = memory(csv, h, n, top)
    print()
    print("| code | ranks | ns per particle-step (median of %d) | speed-up over LIGGGHTS |" % a.repeats)
    print("| --- | --- | --- | --- |")
    for ranks in (1, 2):
        print("| LIGGGHTS 3.8 | %d | %.1f | 1 |" % (ranks, med[("liggghts", ranks)]))
        print("| vofdem | %d | %.1f | %.2f |" % (ranks, med[("vofdem", ranks)], med[("liggghts", ranks)] / med[("vofdem", ranks)]))
    eff = med[("vofdem", 1)] / (2 * med[("vofdem", 2)])
    eff_l = med[("liggghts", 1)] / (2 * med[("liggghts", 2)])
    print()
    print("vofdem 2-rank parallel efficiency: %.0f %% (LIGGGHTS: %.0f %%)" % (100 * eff, 100 * eff_l))
    if mem:
        print("memory per particle (resident-size slope, %d -> %d spheres, 1 rank): vofdem %.0f B, LIGGGHTS %.0f B" % (n, 2 * n, mem["vofdem"], mem["liggghts"]))
    print("targets: 1-rank speed-up >= 1.5: %s; 2-rank efficiency >= 85 %%: %s; memory < 1 KB per particle: %s" %
          ("met" if med[("liggghts", 1)] / med[("vofdem", 1)] >= 1.5 else "NOT met", "met" if eff >= 0.85 else "NOT met",
           ("met" if mem["vofdem"] < 1024 else "NOT met") if mem else "not measured"))
    if not whitelisted:
        print("note: LIGGGHTS warned that hertz + history + epsd2 is not in its whitelist (\"unoptimized version, up to 20 % slower\")")


def memory(csv, h, n, top):
    """Memory per particle: slope of the peak resident size between N and 2N spheres (1 rank, 10 steps)."""
    bed = csv
    csv2 = os.path.join(WORK, "bed2.csv")
    n2 = still(bed, csv2, copies=2, height=top + 2 * D)
    h2 = 2 * h + 2 * D
    lig2 = liggghts_input(csv2, h2, 10, 0, "2N")
    lig1 = liggghts_input(csv, h, 10, 0, "N10")
    mem = {}
    for code in ("vofdem", "liggghts"):
        rss = []
        for c, hh, li in ((csv, h, lig1), (csv2, h2, lig2)):
            if code == "vofdem":
                cmd = [VOFDEM] + MODEL + ["-grid_upper", "%g,%g,%g" % (L, L, hh), "-grid_cells", "12,12,%d" % max(2, round(hh / 2.5e-4)),
                                          "-dem_particles_file", c, "-dt", "%g" % DT, "-max_steps", "10", "-monitor_every", "10"]
            else:
                cmd = ["liggghts", "-in", li, "-echo", "none", "-log", "none"]
            rss.append(max_rss_kb(cmd, cwd=WORK))
        mem[code] = (rss[1] - rss[0]) * 1024.0 / (n2 - n)
    return mem


if __name__ == "__main__":
    main()
