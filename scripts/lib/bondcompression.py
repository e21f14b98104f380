"""Verification G3 (docs/physics.md P13): a bonded cylinder of spheres in uniaxial compression between two platens.
What scripts/bond-compression and test/dem/test_bond_compression.py share: the specimen, the run, and the reading of the
stress-strain curve.

The specimen. Spheres of one radius r = 1 mm on a face-centred cubic lattice (nearest centres 2 r + g apart, g = 0.5 r,
the cube's z axis along the cylinder's), kept inside a cylinder of diameter D and height about 2 D, every centre moved
by a random jitter of at most j = 0.12 r per component (from a seed: the same file on any rank count; none in z on the
bottom and top layers, which stay flat). At t = 0 every pair closer than -dem_bond_gap 1.0 r is bonded: the 12 nearest
neighbours (gap 0.5 r -/+ 0.42 r), none of the next (gap 1.54 r -/+ 0.42 r). Parallel bonds, lambda = 1.

The loading. Two planes (-dem_walls) touch the bottom and top layers; from t = 0 each moves toward the other at v / 2
(-dem_wall_*_velocity), so the platens close at v. The platens meet the spheres by the linear contact law (P4, a
stiffness of 2 k_n A, -dem_dt_factor 1: the bonds set the step); the spheres do not touch each other before the peak
(the smallest gap closes at a strain of ~0.03). Stress = the mean of the two platens' forces / the lattice's section
A = (spheres per layer) dnn^2 (each layer a square lattice of side dnn = 2 r + g; the circle of diameter D cuts it
unevenly, so pi D^2 / 4 would not be the section the spheres fill); strain = the platens' approach / the initial
height H (the platens' gap). No gravity; no damping but the contact law's at the
platens (bonds have none, P13).

Quasi-static. The specimen's P-wave speed is c = sqrt(E / rho_b), E the measured modulus and rho_b the bulk density;
the loading rate is stated as v / c. The platens' start sends a stress wave of rho_b c v, a strain v / c, that rings
undamped: the curve is within (v / c) / eps of the quasi-static one at strain eps, so a rate is quasi-static when
v / c is far below the strain at the peak.
"""
import csv
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from testcheck import run_vofdem  # noqa: E402

R_P = 1e-3           # sphere radius, m
RHO = 2500.0         # sphere density, kg/m^3
GAP = 0.5 * R_P      # lattice gap between nearest neighbours, m
JITTER = 0.12 * R_P  # per-component jitter, m
KN = 4e11            # bond normal stiffness per area, Pa/m
KS = 2e11            # bond shear stiffness per area, Pa/m
SIGMA_C = 2e6        # bond tensile strength, Pa
TAU_C = 2e6          # bond shear strength, Pa
BOND_A = math.pi * R_P**2
K_WALL = 2 * KN * BOND_A  # platen contact stiffness, N/m


def specimen(diameter_in_radii, seed=4):
    """The cylinder's spheres, a list of (x, y, z, r) in a frame with the axis at x = y = 0 and the bottom layer's
    centres at z = 0; the height H between the platens that touch the bottom and top layers; the diameter D; and
    the lattice's section A = (spheres per layer) dnn^2."""
    dnn = 2 * R_P + GAP
    a = math.sqrt(2) * dnn          # the cube's side
    D = diameter_in_radii * R_P
    rc = D / 2 - R_P                # centres inside this radius: the spheres inside the cylinder
    layers = int(math.floor((2 * D - 2 * R_P) / (a / 2) + 1e-9)) + 1
    rng = random.Random(seed)
    n = int(math.ceil(D / a)) + 1
    pts = []
    for k in range(layers):
        z = k * a / 2
        for i in range(-n, n + 1):
            for j in range(-n, n + 1):
                if (i + j + k) % 2:  # fcc: a square lattice of side a / sqrt 2 per layer, shifted by half each layer
                    continue
                x, y = i * a / 2, j * a / 2
                if x * x + y * y > rc * rc:
                    continue
                dx, dy, dz = (JITTER * (2 * rng.random() - 1) for _ in range(3))
                rad = R_P
                if k in (0, layers - 1):  # the end layers flat, touching the platens
                    dz = 0.0
                pts.append((x + dx, y + dy, z + dz, rad))
    H = (layers - 1) * a / 2 + 2 * R_P
    return pts, H, D, len(pts) / layers * dnn * dnn


def options(pts, H, D, speed, strain_end, out, ranks):
    """The run's options and the particle file: the box is the cylinder's bounding box with room to bulge."""
    margin = 0.5 * D
    lo = (-D / 2 - margin, -D / 2 - margin, -R_P - 0.02 * H)
    hi = (D / 2 + margin, D / 2 + margin, H - R_P + 0.02 * H)
    path = os.path.join(out, "specimen.csv")
    with open(path, "w") as fh:
        fh.write("x,y,z,radius\n")
        for p in pts:
            fh.write("%.17g,%.17g,%.17g,%.17g\n" % p)
    cells = max(2, int(round((hi[0] - lo[0]) / (4 * R_P))))
    zcells = max(2, int(round((hi[2] - lo[2]) / (4 * R_P))))
    t_end = strain_end * H / speed
    args = ["-physics", "dem", "-grid_lower", "%.17g,%.17g,%.17g" % lo, "-grid_upper", "%.17g,%.17g,%.17g" % hi,
            "-grid_cells", "%d,%d,%d" % (cells, cells, zcells), "-gravity", "0,0,0", "-dem_radius", "%.17g" % R_P,
            "-dem_density", "%.17g" % RHO, "-dem_contact", "linear", "-dem_linear_stiffness", "%.17g" % K_WALL, "-dem_dt_factor", "1",
            "-dem_cohesion", "bond", "-dem_bond_radius_ratio", "1", "-dem_bond_normal_stiffness", "%.17g" % KN,
            "-dem_bond_shear_stiffness", "%.17g" % KS, "-dem_bond_tensile_strength", "%.17g" % SIGMA_C,
            "-dem_bond_shear_strength", "%.17g" % TAU_C, "-dem_bond_gap", "%.17g" % (1.0 * R_P),
            "-dem_walls", "bottom,top", "-dem_wall_bottom_type", "plane", "-dem_wall_bottom_point", "0,0,%.17g" % -R_P,
            "-dem_wall_bottom_normal", "0,0,1", "-dem_wall_bottom_velocity", "0,0,%.17g" % (speed / 2),
            "-dem_wall_top_type", "plane", "-dem_wall_top_point", "0,0,%.17g" % (H - R_P), "-dem_wall_top_normal", "0,0,-1",
            "-dem_wall_top_velocity", "0,0,%.17g" % (-speed / 2), "-dem_particles_file", path, "-final_time", "%.17g" % t_end,
            "-max_steps", "100000000", "-monitor_every", "MONITOR", "-monitor_timing", "0", "-output_dir", out]
    if ranks == 2:
        args += ["-grid_ranks", "1,1,2"]
    return args


def run(exe, ranks, diameter_in_radii, speed, strain_end, out, rows=400, timeout=3600, reuse=False):
    """Runs one compression to strain_end with about `rows` monitor rows; returns the curve (see curve()). reuse: read
    the monitor an earlier run left in out instead (to read the curves again)."""
    os.makedirs(out, exist_ok=True)
    pts, H, D, area = specimen(diameter_in_radii)
    args = options(pts, H, D, speed, strain_end, out, ranks)
    # the step is set by the bonds (P13): the lightest sphere in 12 bonds of the largest section, omega^2 = 24 (k_n + 3.5 k_s) A / m,
    # omega dt = 1 (the rows are then about `rows`, the count does not matter)
    m = RHO * 4.0 / 3.0 * math.pi * (min(p[3] for p in pts)) ** 3
    dt = 1 / math.sqrt(24 * (KN + 3.5 * KS) * BOND_A / m)
    steps = strain_end * H / speed / dt
    args[args.index("MONITOR")] = str(max(1, int(steps / rows)))
    if not reuse and run_vofdem(exe, ranks, args, timeout=timeout).returncode:
        return None
    c = curve(os.path.join(out, "monitor.csv"), len(pts), H, area, speed)
    c["mass"] = sum(RHO * 4.0 / 3.0 * math.pi * p[3] ** 3 for p in pts)
    return c


def curve(monitor, particles, H, area, speed):
    """The monitor's rows as the stress-strain curve: dict of lists t, strain, stress (Pa, the mean of the platens'),
    stress_bottom, stress_top, broken, intact; and the specimen's particles, H, section area, speed."""
    c = dict(t=[], strain=[], stress=[], stress_bottom=[], stress_top=[], broken=[], intact=[], particles=particles, H=H, area=area, speed=speed)
    with open(monitor) as fh:
        for row in csv.DictReader(fh):
            t = float(row["time_s"])
            fb, ft = float(row["wall_bottom_fz_N"]), float(row["wall_top_fz_N"])  # the particles' force on each platen
            c["t"].append(t)
            c["strain"].append(speed * t / H)
            c["stress_bottom"].append(-fb / area)  # pushed down
            c["stress_top"].append(ft / area)  # pushed up
            c["stress"].append((ft - fb) / 2 / area)
            c["broken"].append(int(row["bonds_broken"]))
            c["intact"].append(int(row["bonds_intact"]))
    return c


def analyse(c, fit=(0.1, 0.5)):
    """The curve's numbers: Young's modulus E (Pa, the least-squares slope through the origin-free line of the points
    before the peak with stress between fit[0] and fit[1] of the peak), the peak stress and its strain, the bonds broken
    at the peak and at the end, the bulk density, the P-wave speed c = sqrt(E / rho_b) and the rate v / c. None if the
    curve has no peak before its end (the stress still rising on the last row)."""
    s, e = c["stress"], c["strain"]
    k = max(range(len(s)), key=lambda i: s[i])
    out = dict(particles=c["particles"], speed=c["speed"], peak=s[k], strain_peak=e[k], broken_peak=c["broken"][k], broken_end=c["broken"][-1],
               made=c["broken"][-1] + c["intact"][-1], has_peak=k < len(s) - 1 and s[-1] < s[k])
    pts = [(e[i], s[i]) for i in range(k + 1) if fit[0] * s[k] <= s[i] <= fit[1] * s[k]]
    n = len(pts)
    mx, my = sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    out["E"] = sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx
    out["fit_points"] = n
    # the worst departure of the fitted points from the line, per the peak: how linear the rise is
    out["fit_residual"] = max(abs(p[1] - my - out["E"] * (p[0] - mx)) for p in pts) / s[k]
    out["rho_b"] = c["mass"] / (c["area"] * c["H"])
    out["c_p"] = math.sqrt(out["E"] / out["rho_b"])
    out["rate"] = c["speed"] / out["c_p"]
    return out
