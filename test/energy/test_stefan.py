#!/usr/bin/python3
"""E1, reduced: one-dimensional Stefan melting with -physics energy (docs/physics.md F3, F7; docs/verification.md E1).
Metal in z in [0, 0.01] m, 100 cells across the final melted length (200 and 500 in all) (rho 1000 kg/m^3, cp 1000 J/(kg K), k 1 W/(m K): alpha 1e-6 m^2/s,
L 1e5 J/kg, melting at T_m = 1000 K with a mushy range of 1 % of T_w - T_m), the wall z = 0 at T_w:
  - one phase (solid at T_m) at St 0.1 and 1; two phases (St_l 1, St_s 0.5, the far face held at the solid's T_i);
  - the front s = sum f_l h (the melted length) follows Neumann's s = 2 lambda sqrt(alpha t), lambda from
    lambda e^(lambda^2) erf(lambda) = St/sqrt(pi) (one phase) or the two-phase relation, solved here by
    bisection: lambda 0.220016 / 0.620063 / 0.469851; within 0.5 % at the end, when 100 cells have melted
    (the largest error from t_end/4 on is printed too);
  - the heat through the walls equals the sensible plus latent heat gained: |(E - E_0) - (W - E_0)| below
    1e-10 of E - E_0, W the walls' input integrated by the scheme's own quadrature (energy_accounted_J);
  - 1 and 2 ranks give the same front to 1e-10;
  - seed 000's erf melt law (-energy_melt_law erf, F3) over the same range at St 1 meets the same bounds, and its
    front (the melted length gained: the erf law holds f_l = 0.0023 at T_m from the start) differs from the linear
    ramp's (the option acts) while agreeing with it to 0.5 %.
  test_stefan.py VOFDEM"""
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts", "lib"))
from testcheck import check, finish, run_vofdem  # noqa: E402

TM, L, CP, ALPHA, LZ, AREA = 1000.0, 1e5, 1000.0, 1e-6, 0.01, 1e-6


def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (f(mid) > 0) == (f(hi) > 0):
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def one_phase_lambda(st):
    return bisect(lambda x: x * math.exp(x * x) * math.erf(x) - st / math.sqrt(math.pi), 1e-6, 3)


def two_phase_lambda(stl, sts, nu=1.0):
    return bisect(lambda x: stl / (math.exp(x * x) * math.erf(x)) - sts * nu / (math.exp(nu * nu * x * x) * math.erfc(nu * x)) - x * math.sqrt(math.pi), 1e-6, 3)


CASES = {  # name: (St_l, St_s, lambda, expected lambda as the design quotes it)
    "one phase St 0.1": (0.1, 0.0, one_phase_lambda(0.1), 0.220016),
    "one phase St 1": (1.0, 0.0, one_phase_lambda(1.0), 0.620063),
    "two phases St_l 1, St_s 0.5": (1.0, 0.5, two_phase_lambda(1.0, 0.5), 0.469851),
}
ERF_CASE = ("one phase St 1, erf law", (1.0, 0.0, one_phase_lambda(1.0), 0.620063, ("-energy_melt_law", "erf")))


def arguments(out, ranks, stl, sts, lam, melted=100):
    """vofdem's arguments for one case with `melted` cells across the final melted length, monitor.csv in `out`:
    (t_end, arguments). scripts/work-precision E1 runs them with -energy_time_scheme as its variant."""
    tw, ti = TM + stl * L / CP, TM - sts * L / CP
    dT = tw - TM
    s_end = (0.5 if sts == 0 else 0.2) * LZ  # two phases: the solid's thermal layer (about 2 s/lambda) stays inside the box
    cells = melted * (2 if sts == 0 else 5)
    t_end = (s_end / (2 * lam)) ** 2 / ALPHA
    args = ["-physics", "energy", "-grid_cells", "1,1,%d" % cells, "-grid_upper", "0.001,0.001,%g" % LZ, "-grid_ranks", "1,1,%d" % ranks,
            "-energy_metal_density", "1000", "-energy_metal_specific_heat", "%g" % CP, "-energy_metal_conductivity", "1",
            "-energy_metal_latent_heat", "%g" % L, "-energy_metal_solidus", "%.12g" % TM, "-energy_metal_liquidus", "%.12g" % (TM + 0.01 * dT),
            "-energy_interface_radiation", "0", "-energy_initial_temperature", "%.12g" % (ti if sts > 0 else TM),
            "-energy_bc_zlo", "temperature", "-energy_bc_zlo_value", "%.12g" % tw,
            "-dt", "%.12g" % (t_end / 800), "-final_time", "%.12g" % t_end, "-max_steps", "100000", "-monitor_every", "20", "-monitor_timing", "0",
            "-output_dir", out]
    if sts > 0:
        args += ["-energy_bc_zhi", "temperature", "-energy_bc_zhi_value", "%.12g" % ti]
    return t_end, args


def monitor(out):
    """The rows of out/monitor.csv as {column: value}."""
    with open(os.path.join(out, "monitor.csv")) as f:
        head, *rows = [line.strip().split(",") for line in f if line.strip()]
    col = {n: i for i, n in enumerate(head)}
    return [{n: float(r[i]) for n, i in col.items()} for r in rows]


def run(exe, tmp, name, ranks, stl, sts, lam, melted=100, extra=()):
    """Monitor rows of one case with `melted` cells across the final melted length (t_end, rows)."""
    out = os.path.join(tmp, name.replace(" ", "_").replace(",", "") + "-%d-%d" % (ranks, melted))
    t_end, args = arguments(out, ranks, stl, sts, lam, melted)
    run_vofdem(exe, ranks, args + list(extra))
    return t_end, monitor(out)


def front_error(rows, lam):
    """The front's relative error against Neumann's at the last row."""
    last = rows[-1]
    return last["melt_volume_m3"] / AREA / (2 * lam * math.sqrt(ALPHA * last["time_s"])) - 1


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="vofdem-stefan-")
    try:
        linear = {}
        for name, (stl, sts, lam, quoted, extra) in [(n, c + ((),)) for n, c in CASES.items()] + [ERF_CASE]:
            check(abs(lam - quoted) < 1e-6, "%s: lambda %.6f (quoted %.6f)" % (name, lam, quoted))
            fronts = {}
            for ranks in (1, 2):
                t_end, rows = run(exe, tmp, name, ranks, stl, sts, lam, extra=extra)
                worst, at = 0.0, 0.0
                # The erf law is never 0: the solid at T_m holds f_l = 0.0023 everywhere from the start, so its front is
                # the melted length gained since then (the linear ramp's start is exactly 0).
                base = rows[0]["melt_volume_m3"] if extra else 0.0
                for r in rows:
                    if r["time_s"] < t_end / 4:
                        continue
                    s = (r["melt_volume_m3"] - base) / AREA
                    exact = 2 * lam * math.sqrt(ALPHA * r["time_s"])
                    if abs(s / exact - 1) > abs(worst):
                        worst, at = s / exact - 1, r["time_s"]
                last, first = rows[-1], rows[0]
                final = (last["melt_volume_m3"] - base) / AREA / (2 * lam * math.sqrt(ALPHA * last["time_s"])) - 1
                gained = last["energy_total_J"] - first["energy_total_J"]
                walls = last["energy_accounted_J"] - first["energy_total_J"]
                fronts[ranks] = [r["melt_volume_m3"] - base for r in rows]
                check(abs(final) < 5e-3 and rows[-1]["time_s"] >= t_end * (1 - 1e-9),
                      "%s, %d rank(s): front at t = %.4g s (100 cells melted) %.3f %% from Neumann's (tolerance 0.5 %%); largest from t_end/4 on %.3f %% at t = %.3g s"
                      % (name, ranks, last["time_s"], 100 * final, 100 * worst, at))
                check(gained > 0 and abs(gained - walls) <= 1e-10 * gained,
                      "%s, %d rank(s): heat through the wall %.12e J, sensible + latent gained %.12e J: difference %.2e of it (tolerance 1e-10)"
                      % (name, ranks, walls, gained, abs(gained - walls) / gained))
            diff = max(abs(a - b) / max(abs(a), 1e-300) for a, b in zip(fronts[1], fronts[2]) if a > 0)
            check(len(fronts[1]) == len(fronts[2]) and diff <= 1e-10, "%s: 1 and 2 ranks give the same front to %.1e (tolerance 1e-10)" % (name, diff))
            linear[name] = fronts[1]
            if extra:  # the erf law against the linear ramp at the same Stefan number
                ref = linear["one phase St 1"]
                dev = max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(fronts[1][len(ref) // 4:], ref[len(ref) // 4:]) if b > 0)
                check(len(ref) == len(fronts[1]) and 1e-6 < dev < 5e-3,
                      "%s: the front differs from the linear ramp's by at most %.2e from t_end/4 on (the law acts: above 1e-6; the same physics: below 0.5 %%)" % (name, dev))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finish()


if __name__ == "__main__":
    main()
