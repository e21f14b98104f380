#!/usr/bin/python3
"""The metal files of config/materials (every file with a solidus: in718, in625, 304l, ...) as the energy module
reads them (-physics energy -energy_metal FILE), against the file's own numbers read here with PyYAML:
  - the banner's density, solidus, liquidus and latent heat, and the laser's absorptivity (its default is the metal's);
  - the specific heat table and the latent heat through the initial energy: a box of metal at T0 holds
    V rho (int_300^T0 cp dT + L f_l(T0)) (piecewise linear between the rows, constant beyond them; f_l linear),
    at T0 past the liquidus and in the middle of the mushy range, to 1e-12;
  - the conductivity table through the banner's explicit diffusion limit, rho min(cp) / (2 max(k) sum 1/h^2)
    (the gas made a poor conductor so that the metal sets it), to the banner's 5 digits;
on 1 rank (a 4^3 box, no step taken).
  test_material_files.py VOFDEM"""
import os
import re
import shutil
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

MATERIALS = os.path.join(ROOT, "config", "materials")
T_REF = 300.0
N, L_BOX = 4, 1e-3


def table(v):
    """A number or [[T, value], ...] as (Ts, values)."""
    if isinstance(v, (int, float)):
        return [], [float(v)]
    return [float(r[0]) for r in v], [float(r[1]) for r in v]


def at(tab, t):
    T, v = tab
    if len(v) == 1 or t <= T[0]:
        return v[0]
    if t >= T[-1]:
        return v[-1]
    i = next(i for i in range(1, len(T)) if t < T[i])
    return v[i - 1] + (t - T[i - 1]) / (T[i] - T[i - 1]) * (v[i] - v[i - 1])


def integral(tab, a, b):
    """int_a^b of the table (exact: trapezoids between the nodes, constant beyond the ends)."""
    T, _ = tab
    xs = [a] + [t for t in T if a < t < b] + [b]
    return sum(0.5 * (at(tab, x0) + at(tab, x1)) * (x1 - x0) for x0, x1 in zip(xs, xs[1:]))


def run(exe, tmp, path, t0):
    out = os.path.join(tmp, "%s-%g" % (os.path.basename(path), t0))
    args = ["-physics", "energy", "-energy_metal", path, "-grid_cells", "%d,%d,%d" % (N, N, N), "-grid_upper", "%g,%g,%g" % (L_BOX, L_BOX, L_BOX),
            "-energy_initial_temperature", "%.12g" % t0, "-energy_gas_conductivity", "1e-12", "-dt", "1e-6", "-max_steps", "0",
            "-laser_power", "1e-3", "-laser_radius", "2e-4", "-laser_path", "5e-4,5e-4", "-monitor_timing", "0", "-output_dir", out]
    p = run_vofdem(exe, 1, args)
    with open(os.path.join(out, "monitor.csv")) as f:
        head, first = [line.strip().split(",") for line in f if line.strip()][:2]
    return p.stdout, dict(zip(head, map(float, first)))


def main():
    exe = sys.argv[1]
    files = sorted(f for f in os.listdir(MATERIALS) if f.endswith(".yaml"))
    metals = [f for f in files if "solidus" in (yaml.safe_load(open(os.path.join(MATERIALS, f))) or {})]
    check({"in718.yaml", "in625.yaml", "304l.yaml"} <= set(metals), "metal files: %s" % ", ".join(metals))
    tmp = tempfile.mkdtemp(prefix="vofdem-material-files-")
    try:
        check_files(exe, tmp, metals)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


def check_files(exe, tmp, metals):
    for name in metals:
        path = os.path.join(MATERIALS, name)
        m = yaml.safe_load(open(path))
        rho, ts, tl, lat, eta = (float(m[k]) for k in ("density", "solidus", "liquidus", "latent_heat", "absorptivity"))
        cp, k = table(m["specific_heat"]), table(m["conductivity"])
        for t0, f in ((tl + 200.0, 1.0), (0.5 * (ts + tl), 0.5)):
            screen, row = run(exe, tmp, path, t0)
            banner = re.search(r"^energy: metal \S+ \(rho ([0-9.e+-]+) kg/m\^3, T_s ([0-9.e+-]+) K, T_l ([0-9.e+-]+) K, L ([0-9.e+-]+) J/kg", screen, re.M)
            laser = re.search(r"^laser: .*absorptivity ([0-9.e+-]+),", screen, re.M)
            limit = re.search(r"explicit diffusion limit ([0-9.e+-]+) s", screen)
            if not (banner and laser and limit):
                check(False, "%s: the banner names the metal's values, the laser's absorptivity and the diffusion limit" % name)
                continue
            got = [float(x) for x in banner.groups()]
            check(got == [rho, ts, tl, lat] and float(laser.group(1)) == eta,
                  "%s: banner rho %g, T_s %g, T_l %g, L %g, absorptivity %g (file: %g, %g, %g, %g, %g)" % ((name,) + tuple(got) + (float(laser.group(1)), rho, ts, tl, lat, eta)))
            want = L_BOX ** 3 * rho * (integral(cp, T_REF, t0) + lat * f)
            err = row["energy_total_J"] / want - 1
            check(abs(err) <= 1e-12, "%s: energy of the box at %.1f K %.12e J, file's cp table and L give %.12e J (%.1e)" % (name, t0, row["energy_total_J"], want, err))
            h = L_BOX / N
            expected = rho * min(cp[1]) / (2 * max(k[1]) * 3 / (h * h))
            err = float(limit.group(1)) / expected - 1
            check(abs(err) <= 1e-4, "%s: explicit diffusion limit %s s, file's min cp and max k give %.5g s (%.1e)" % (name, limit.group(1), expected, err))


if __name__ == "__main__":
    main()
