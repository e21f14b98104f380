"""Centre-line profiles of the 3-D lid-driven cavity at Re 100 for flow-vs-openfoam: steady runs of
both codes, the reference, and the comparison.

Reference: no published table of the cubic cavity at Re 100 could be found and checked here (Ku,
Hirsh & Taylor 1987 give it as plots), so the reference is a grid-converged run: OpenFOAM (icoFoam,
the benchmark's settings) from rest to steady state on three grids (default 32^3, 48^3, 64^3),
Richardson-extrapolated with order 2 from the coarsest and finest; the middle grid gives the observed
order and a second extrapolation whose difference from the first is printed as the uncertainty.
Every profile is compared at s = i/32 (i = 0..32): these points are cell faces of the grids that are
multiples of 32, so each grid's value there is an average of neighbouring cell centres with the same
relative position and the extrapolation cancels that interpolation error too.
"""
import math
import os
import time

import numpy as np

import foam_cavity as fc

END_TIME = 16.0          # lid passages: the profiles then change by ~2e-5 per passage (decay ~x0.58 per passage; printed by every steady run)
S_REF = np.arange(33) / 32.0
LINES = (("y", 0, "u"), ("x", 1, "v"))  # (line, velocity component, name): u(y) at x=z=0.5, v(x) at y=z=0.5
REF_GRIDS = (32, 48, 64)  # --reference-grids; (32, 64, 96) is better but takes hours on a quiet 2-core machine
REF_FILE_NAME = "scripts/bench/data/cavity3d-re100-reference.csv"
REF_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", os.path.basename(REF_FILE_NAME))


def centre_line(U, line):
    """(s, values [len(s), 3]) along the line through the box centre parallel to `line`, from the
    cell-centred field U[i, j, k, c]: bilinear in the two other directions, wall values added at s = 0, 1."""
    n = U.shape[0]
    f = 0.5 * n - 0.5                   # index position of 0.5 among the cell centres (i + 0.5)/n
    i0 = int(math.floor(f))
    w = f - i0
    wts = [(i0, 1 - w), (i0 + 1, w)] if w > 0 else [(i0, 1.0)]
    axis = "xyz".index(line)
    vals = np.zeros((n, 3))
    for a, wa in wts:
        for b, wb in wts:
            if axis == 0:
                vals += wa * wb * U[:, a, b, :]
            elif axis == 1:
                vals += wa * wb * U[a, :, b, :]
            else:
                vals += wa * wb * U[a, b, :, :]
    lo = np.zeros(3)
    hi = np.array([1.0, 0, 0]) if line == "y" else np.zeros(3)   # the lid is the y = 1 face
    s = np.concatenate(([0.0], (np.arange(n) + 0.5) / n, [1.0]))
    return s, np.vstack((lo, vals, hi))


def at_ref(s, vals, comp):
    return np.interp(S_REF, s, vals[:, comp])


def steady_foam(n, ranks, work, env, mpi, end_time):
    """icoFoam from rest to end_time; returns the cell field at the end, the largest change of any
    cell velocity over the last lid passage (steady-state check), and the case directory if a
    finished run with the same dictionaries was reused (else None)."""
    case = os.path.join(work, "foam-steady-%d" % n)
    sign = fc.signature(n, ranks, end_time=end_time, write_every=1.0)
    done = os.path.join(case, "steady.done")
    reused = None
    if os.path.exists(done) and open(done).read() == sign:
        reused = os.path.relpath(case, os.path.dirname(os.path.dirname(os.path.dirname(work))))
    else:
        # untimed: let waiting ranks yield the core, so that a busy machine does not stall the halo exchanges
        env = dict(env, OMPI_MCA_mpi_yield_when_idle="1")
        fc.make_case(case, n, ranks, env, end_time=end_time, write_every=1.0)
        fc.run(fc.solver_cmd(ranks, mpi), case, env, os.path.join(case, "log.icoFoam"))
        if ranks > 1:
            fc.run(["reconstructPar"], case, env, os.path.join(case, "log.reconstructPar"))
    times = [t for t in fc.time_dirs(case) if t[0] > 0]
    if not times or abs(times[-1][0] - end_time) > 1e-6:
        raise RuntimeError("%s: no field written at t = %g" % (case, end_time))
    U = fc.cell_field(case, n, times[-1][1])
    change = float(np.abs(U - fc.cell_field(case, n, times[-2][1])).max()) if len(times) > 1 else float("nan")
    if not reused:
        with open(done, "w") as f:
            f.write(sign)
    return U, change, reused


def observed_order(fs, grids, mask):
    """Order p with (f1 - f2)/(f2 - f3) = (h1^p - h2^p)/(h2^p - h3^p) in the max norm over the points
    `mask` (those that are cell faces of all three grids)."""
    h = [1.0 / g for g in grids]
    q = np.abs(fs[0] - fs[1])[mask].max() / max(np.abs(fs[1] - fs[2])[mask].max(), 1e-300)
    g = lambda p: (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - q
    lo, hi = 0.2, 6.0
    if g(lo) * g(hi) > 0:
        return float("nan")
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def richardson(coarse, fine, r):
    return (r * r * fine - coarse) / (r * r - 1)


def faces(g):
    """The points of S_REF that are cell faces of an N = g grid."""
    return np.abs(S_REF * g - np.round(S_REF * g)) < 1e-9


def make_reference(work, env, mpi, say, end_time, grids=REF_GRIDS):
    """Reference = Richardson extrapolation (order 2) of the coarsest and finest grids; the middle grid
    gives the observed order and a second extrapolation (middle, finest) as the uncertainty."""
    g0, g1, g2 = grids
    say("reference: OpenFOAM at %s to t = %g (1 rank up to 32^3, 2 above)" % (", ".join("%d^3" % g for g in grids), end_time))
    prof = {}
    for g in grids:
        t0 = time.monotonic()
        U, change, reused = steady_foam(g, 1 if g <= 32 else 2, work, env, mpi, end_time)
        say("  %d^3: largest cell velocity change over the last lid passage %.2e (%s)" %
            (g, change, "reused the finished run in %s" % reused if reused else "%.0f s" % (time.monotonic() - t0)))
        for line, comp, name in LINES:
            prof[(line, g)] = at_ref(*centre_line(U, line), comp)
    if not faces(g0).all() or not faces(g2).all():
        raise RuntimeError("the coarsest and finest reference grids must be multiples of 32")
    common = faces(g0) & faces(g1) & faces(g2)
    os.makedirs(os.path.dirname(REF_FILE), exist_ok=True)
    with open(REF_FILE, "w") as f:
        f.write("# 3-D lid-driven cubic cavity, Re 100 (lid (1,0,0) on y = 1, nu 0.01), steady state (t = %g).\n" % end_time)
        f.write("# Grid-converged reference made by scripts/bench/flow-vs-openfoam --reference: OpenFOAM v1912 icoFoam\n")
        f.write("# (Gauss linear, Euler, PISO 2 correctors, GAMG, CFL 0.5 at the lid speed) at %s.\n" % ", ".join("%d^3" % g for g in grids))
        f.write("# reference = Richardson extrapolation of order 2 from %d^3 and %d^3: (r^2 f%d - f%d)/(r^2 - 1), r = %g;\n" %
                (g0, g2, g2, g0, g2 / g0))
        f.write("# check = the same from %d^3 and %d^3, at the points that are cell faces of %d^3 (else empty).\n" % (g1, g2, g1))
        f.write("# line y: u at x = z = 0.5; line x: v at y = z = 0.5; s along the line; openfoamN: the N^3 run.\n")
        f.write("line,component,s,reference,check," + ",".join("openfoam%d" % g for g in grids) + "\n")
        for line, comp, name in LINES:
            fs = [prof[(line, g)] for g in grids]
            ref = richardson(fs[0], fs[2], g2 / g0)
            check = richardson(fs[1], fs[2], g2 / g1)
            m1 = faces(g1)
            say("  line %s (%s): observed order %.2f (max norm at the %d points that are faces of every grid); "
                "Richardson correction to %d^3 at most %.1e; the two extrapolations differ by at most %.1e"
                % (line, name, observed_order(fs, grids, common), int(common.sum()), g2, np.abs(ref - fs[2]).max(),
                   np.abs(ref - check)[m1].max()))
            for i, s in enumerate(S_REF):
                f.write("%s,%s,%.6f,%.8f,%s,%s\n" % (line, name, s, ref[i], "%.8f" % check[i] if m1[i] else "",
                                                    ",".join("%.8f" % x[i] for x in fs)))
    say("  written %s" % REF_FILE_NAME)


def reference_provenance():
    """The reference file's 'reference = ...' comment line."""
    for l in open(REF_FILE):
        if l.startswith("# reference = "):
            return l[2:].strip().rstrip(";") + ", " + REF_FILE_NAME
    return REF_FILE_NAME


def read_reference(column="reference"):
    """{line: values at S_REF} of one column of the reference file (reference, openfoam32, ...)."""
    ref = {}
    cols = None
    for l in open(REF_FILE):
        if l.startswith("#") or not l.strip():
            continue
        v = l.strip().split(",")
        if v[0] == "line":
            cols = v
            continue
        ref.setdefault(v[0], []).append(float(v[cols.index(column)]))
    return {k: np.array(v) for k, v in ref.items()}


def reference_grids():
    for l in open(REF_FILE):
        if l.startswith("line,"):
            return [int(c[len("openfoam"):]) for c in l.strip().split(",") if c.startswith("openfoam")]
    return []


def read_vofdem_profile(path):
    """{line: (s, values[:, 3])} from the contract's profile.csv (header line,s,x,y,z,u,v,w)."""
    lines = [l for l in open(path).read().splitlines() if l.strip()]
    cols = lines[0].split(",")
    need = ["line", "s", "u", "v", "w"]
    if any(c not in cols for c in need):
        raise ValueError("%s: header %s lacks one of %s" % (path, lines[0], need))
    out = {}
    for l in lines[1:]:
        v = dict(zip(cols, l.split(",")))
        out.setdefault(v["line"].strip(), []).append((float(v["s"]), float(v["u"]), float(v["v"]), float(v["w"])))
    res = {}
    for k, rows in out.items():
        rows.sort()
        a = np.array(rows)
        res[k] = (a[:, 0], a[:, 1:])
    return res


def vofdem_steadiness(path):
    """The end time and the relative change of the flow kinetic energy over the last lid passage."""
    try:
        lines = [l.split(",") for l in open(path).read().splitlines() if l.strip()]
        cols = lines[0]
        it, ik = cols.index("time_s"), cols.index("flow_kinetic_energy_J")
        rows = [(float(r[it]), float(r[ik])) for r in lines[1:]]
    except (OSError, ValueError, IndexError) as e:
        return "no steady-state check (%s)" % e
    t_end, k_end = rows[-1]
    t_prev, k_prev = min(rows, key=lambda r: abs(r[0] - (t_end - 1)))
    return "ran to t = %.4g; flow kinetic energy %.6e, relative change over t = %.4g..%.4g %.2e" % (
        t_end, k_end, t_prev, t_end, abs(k_end - k_prev) / max(abs(k_end), 1e-300))


def compare(n, work, env, mpi, say, end_time, run_vofdem, VofdemFailed):
    if not os.path.exists(REF_FILE):
        say("profiles: no reference file %s (make it with --reference)" % REF_FILE_NAME)
        return
    ref = read_reference()
    say("profiles: both codes from rest to t = %g at %d^3 on 2 ranks; reference: grid-converged OpenFOAM run "
        "(%s)" % (end_time, n, reference_provenance()))
    U, change, reused = steady_foam(n, 2, work, env, mpi, end_time)
    say("  OpenFOAM: largest cell velocity change over the last lid passage %.2e%s" %
        (change, " (reused the finished run in %s, same dictionaries)" % reused if reused else ""))
    prof = {"OpenFOAM": {line: at_ref(*centre_line(U, line), comp) for line, comp, _ in LINES}}
    vofdem_error = None
    outdir = os.path.join(work, "vofdem-steady-%d" % n)
    try:
        run_vofdem(2, n, outdir, ["-final_time", "%g" % end_time, "-max_steps", str(int(40 * end_time * n)),
                                  "-monitor_every", str(max(1, n)), "-flow_profile_output", os.path.join(outdir, "profile.csv")])
        say("  vofdem: %s" % vofdem_steadiness(os.path.join(outdir, "monitor.csv")))
        vp = read_vofdem_profile(os.path.join(outdir, "profile.csv"))
        prof["vofdem"] = {line: np.interp(S_REF, vp[line][0], vp[line][1][:, comp]) for line, comp, _ in LINES}
    except (VofdemFailed, ValueError, KeyError, OSError) as e:
        vofdem_error = str(e)
    say()
    say("| code | max abs(u - u_ref) on u(y), x = z = 0.5 | max abs(v - v_ref) on v(x), y = z = 0.5 |")
    say("| --- | --- | --- |")
    err = {}
    for code in ("OpenFOAM", "vofdem"):
        if code not in prof:
            say("| %s | failed | failed |" % code)
            continue
        cells = []
        for line, comp, name in LINES:
            d = np.abs(prof[code][line] - ref[line])
            k = int(d.argmax())
            err[(code, line)] = d[k]
            cells.append("%.4f (at s = %.3f)" % (d[k], S_REF[k]))
        say("| %s %d^3 | %s |" % (code, n, " | ".join(cells)))
    for g in reference_grids():
        of = read_reference("openfoam%d" % g)
        say("| (OpenFOAM %d^3, reference run) | %s |" % (g, " | ".join("%.4f" % np.abs(of[l] - ref[l]).max() for l, _, _ in LINES)))
    say()
    say("profiles at s = i/8 (reference, OpenFOAM, vofdem):")
    say("| s | u_ref(y) | OpenFOAM | vofdem | v_ref(x) | OpenFOAM | vofdem |")
    say("| --- | --- | --- | --- | --- | --- | --- |")
    for i in range(0, 33, 4):
        row = ["%.3f" % S_REF[i]]
        for line, _, _ in LINES:
            row += ["%.4f" % ref[line][i], "%.4f" % prof["OpenFOAM"][line][i],
                    "%.4f" % prof["vofdem"][line][i] if "vofdem" in prof else "-"]
        say("| " + " | ".join(row) + " |")
    if vofdem_error:
        say("vofdem half FAILED: %s" % vofdem_error)
        say("target (vofdem error <= OpenFOAM's at equal resolution): not measured")
    else:
        ok = all(err[("vofdem", l)] <= err[("OpenFOAM", l)] for l, _, _ in LINES)
        say("target (vofdem error <= OpenFOAM's at equal resolution): %s" % ("met" if ok else "NOT met"))
