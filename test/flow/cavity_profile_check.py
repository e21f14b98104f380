#!/usr/bin/python3
"""F2 (docs/verification.md): centreline velocity profiles of the quasi-2-D lid-driven cavity against the
published tables in test/flow/data/: u on the vertical centreline and v on the horizontal centreline,
at the 17 stations of Ghia, Ghia & Shin 1982. Re 100 is checked against Ghia et al.; Re 1000 against
Botella & Peyret 1998 (Ghia's Re 1000 columns with --reference ghia, for comparison only).

Input: a vofdem profile CSV with the header `line,s,x,y,z,u,v,w`. `line` names the axis the line is
parallel to (x, y or z); each line runs through the box centre, wall to wall, its end points on the
walls. Used here: line y (u against y at the centre x) and line x (v against x at the centre y). The
position along a line is read from its x or y column, not from s, so it does not matter where s
starts. Lines z and any other columns are ignored, except w, whose largest magnitude is printed to
show the flow stayed two-dimensional.

Conventions: lid at the upper y wall moving in +x with --lid-speed; the box (--box) is mapped onto the
unit square; velocities are divided by the lid speed, so the tolerance is a fraction of the lid speed.

Interpolation to the stations (--interp): `cubic` (default) is the Lagrange cubic through the four
nearest profile points, exact for cubics and fourth-order accurate on any spacing (cell centres plus
the wall points are not uniform); `linear` joins neighbours and is second-order: it adds up to
h^2/8 max|f''| of its own, which counts on a coarse grid near the lid. Both reproduce the profile's
own points exactly.

Output: one line per station, then per profile
  F2 Re 100 u(y) at x=0.5: max |u - u_Ghia| = 3.1e-03 (tolerance 1.0e-02) ok
and `result: quantity | value | reference | ok|FAIL` lines for scripts/validate. Exit status 0 when
both profiles are within tolerance, 1 on FAIL, 2 on bad input (one line naming the file and problem).

Then the extrema u_min (line y), v_max and v_min (line x) of the interpolated profiles next to the
grid-converged values of data/cavity-extrema.csv; checked too with --extrema-tolerance. They show
what the 17 stations cannot: whether the vortex converges to the right strength (Ghia's own Re 100
extrema are 0.3-0.85 % of the lid speed weaker than the converged ones).

  cavity_profile_check.py PROFILE.csv --re 100 [--tolerance 0.01] [--lid-speed 1]
                          [--box XLO,YLO,XHI,YHI] [--interp cubic|linear] [--reference ghia|botella]
                          [--extrema-tolerance TOL]
"""
import argparse
import csv
import os
import sys

import numpy as np

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
# (Re, reference) -> file stem and the name printed; the defaults are the F2 references.
REFERENCES = {
    (100, "ghia"): ("ghia1982-re100", "Ghia", "Ghia, Ghia & Shin 1982, Tables I and II"),
    (1000, "ghia"): ("ghia1982-re1000", "Ghia", "Ghia, Ghia & Shin 1982, Tables I and II"),
    (1000, "botella"): ("botella1998-re1000", "Botella", "Botella & Peyret 1998, Tables 9 and 10"),
}
DEFAULT_REFERENCE = {100: "ghia", 1000: "botella"}


class InputError(Exception):
    pass


def read_reference(stem, component):
    """Stations and values of one reference table: '#' comments, then a header and two columns."""
    path = os.path.join(DATA, "%s-%s.csv" % (stem, component))
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    table = np.array([[float(a), float(b)] for a, b in rows[1:]])
    return table[:, 0], table[:, 1]


def interpolate(s, f, targets, kind):
    """Values at targets of the profile f(s), s strictly increasing, targets inside [s0, s_end]."""
    s = np.asarray(s, dtype=float)
    f = np.asarray(f, dtype=float)
    if kind == "linear":
        return np.interp(targets, s, f)
    if len(s) < 4:
        raise InputError("cubic interpolation needs at least 4 points on a line, got %d" % len(s))
    out = []
    for t in np.atleast_1d(targets):
        i = int(np.clip(np.searchsorted(s, t) - 1, 0, len(s) - 2))  # s[i] <= t <= s[i+1]
        lo = min(max(i - 1, 0), len(s) - 4)
        idx = range(lo, lo + 4)
        value = 0.0
        for j in idx:
            basis = 1.0
            for k in idx:
                if k != j:
                    basis *= (t - s[k]) / (s[j] - s[k])
            value += basis * f[j]
        out.append(value)
    return np.array(out)


def read_profile(path):
    """Rows of the profile CSV grouped by line: {'x': array of rows, ...} with named columns."""
    try:
        f = open(path, newline="")
    except OSError as e:
        raise InputError("%s: cannot open: %s" % (path, e.strerror))
    with f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header is None:
            raise InputError("%s: empty file" % path)
        header = [h.strip() for h in header]
        for need in ("line", "x", "y", "u", "v"):
            if need not in header:
                raise InputError("%s:1: no column '%s' (header %s; expected line,s,x,y,z,u,v,w)"
                                 % (path, need, ",".join(header)))
        cols = {name: i for i, name in enumerate(header)}
        lines = {}
        for n, row in enumerate(reader, start=2):
            if not row or row[0].startswith("#"):
                continue
            if len(row) != len(header):
                raise InputError("%s:%d: %d fields, the header has %d" % (path, n, len(row), len(header)))
            label = row[cols["line"]].strip()
            if label not in ("x", "y", "z"):
                raise InputError("%s:%d: line '%s' is not x, y or z" % (path, n, label))
            rec = {}
            for name, i in cols.items():
                if name != "line":
                    try:
                        rec[name] = float(row[i])
                    except ValueError:
                        raise InputError("%s:%d: %s '%s' is not a number" % (path, n, name, row[i]))
                    if not np.isfinite(rec[name]):
                        raise InputError("%s:%d: %s is %s" % (path, n, name, row[i].strip()))
            lines.setdefault(label, []).append(rec)
    return lines


def centreline(path, lines, label, along, across, comp, lo, hi, lid):
    """Normalised position along the line and normalised velocity component, sorted, checked."""
    if label not in lines:
        raise InputError("%s: no line %s (needed for %s against %s)" % (path, label, comp, along))
    rows = lines[label]
    pos = np.array([(r[along] - lo[along]) / (hi[along] - lo[along]) for r in rows])
    off = max(abs((r[across] - 0.5 * (lo[across] + hi[across])) / (hi[across] - lo[across])) for r in rows)
    if off > 1e-6:
        raise InputError("%s: line %s is off the box centre in %s by %.3g of the box (check --box)"
                         % (path, label, across, off))
    order = np.argsort(pos, kind="stable")
    pos = pos[order]
    val = np.array([rows[i][comp] for i in order]) / lid
    if np.any(np.diff(pos) <= 0):
        raise InputError("%s: line %s has two points at the same %s" % (path, label, along))
    slack = 1e-9
    if pos[0] > slack or pos[-1] < 1 - slack:
        raise InputError("%s: line %s covers %s/L in [%.6g, %.6g]; it must run wall to wall, [0, 1] (check --box)"
                         % (path, label, along, pos[0], pos[-1]))
    return np.clip(pos, 0.0, 1.0), val


def check(label_re, comp, along, fixed, stations, ref, pos, val, kind, tol, name):
    """Print the station lines and the summary; return (max error, ok)."""
    got = interpolate(pos, val, stations, kind)
    err = np.abs(got - ref)
    for st, g, r, e in zip(stations, got, ref, err):
        print("  %s %.4f  %s %10.6f  %s_%s %10.7f  |diff| %.1e %s"
              % (along, st, comp, g, comp, name, r, e, "ok" if e < tol else "FAIL"))
    worst = float(err.max())
    ok = worst < tol
    print("F2 Re %d %s(%s) at %s=0.5: max |%s - %s_%s| = %.1e (tolerance %.1e) %s"
          % (label_re, comp, along, fixed, comp, comp, name, worst, tol, "ok" if ok else "FAIL"))
    print("result: F2 Re %d %s(%s) at %s=0.5, max abs(%s - %s_%s) | %.2e | %s, < %.1e | %s"
          % (label_re, comp, along, fixed, comp, comp, name, worst, name, tol, "ok" if ok else "FAIL"))
    return worst, ok


def read_extrema(re_number):
    """{quantity: (value, position)} of the grid-converged extrema at this Re (data/cavity-extrema.csv)."""
    with open(os.path.join(DATA, "cavity-extrema.csv")) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    return {q: (float(v), float(x)) for r, q, v, x in rows[1:] if int(r) == re_number}


def extremum(pos, val, kind, want_max):
    """Value and position of the largest (or smallest) value of the interpolated profile: the
    interpolant of the stations, sampled at 1/200 of the profile spacing around the extreme point."""
    i = int(np.argmax(val) if want_max else np.argmin(val))
    lo, hi = pos[max(i - 1, 0)], pos[min(i + 1, len(pos) - 1)]
    fine = np.linspace(lo, hi, 401)
    f = interpolate(pos, val, fine, kind)
    j = int(np.argmax(f) if want_max else np.argmin(f))
    return float(f[j]), float(fine[j])


def check_extrema(re_number, yu, uu, xv, vv, kind, tol):
    """Print the extrema next to the grid-converged values; with tol, also the verdict."""
    ref = read_extrema(re_number)
    found = {"u_min": extremum(yu, uu, kind, False) + ("y",),
             "v_max": extremum(xv, vv, kind, True) + ("x",),
             "v_min": extremum(xv, vv, kind, False) + ("x",)}
    ok = True
    for q in ("u_min", "v_max", "v_min"):
        value, where, axis = found[q]
        rv, rx = ref[q]
        err = abs(value - rv)
        verdict = "" if tol is None else (" (tolerance %.1e) %s" % (tol, "ok" if err < tol else "FAIL"))
        print("F2 Re %d %s = %.5f at %s = %.4f; grid-converged %.5f at %.4f: |diff| %.1e%s"
              % (re_number, q, value, axis, where, rv, rx, err, verdict))
        if tol is not None:
            print("result: F2 Re %d %s, abs(diff) from the grid-converged value | %.2e | < %.1e | %s"
                  % (re_number, q, err, tol, "ok" if err < tol else "FAIL"))
            ok = ok and err < tol
    return ok


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("profile", help="vofdem profile CSV (line,s,x,y,z,u,v,w)")
    p.add_argument("--re", type=int, choices=(100, 1000), required=True, help="Reynolds number U L / nu")
    p.add_argument("--tolerance", type=float, default=0.01,
                   help="largest allowed |deviation| as a fraction of the lid speed (default 0.01)")
    p.add_argument("--lid-speed", type=float, default=1.0, help="lid speed U in m/s (default 1)")
    p.add_argument("--box", default="0,0,1,1",
                   help="XLO,YLO,XHI,YHI: the cavity in x and y in m (default the unit square)")
    p.add_argument("--interp", choices=("cubic", "linear"), default="cubic",
                   help="interpolation to the stations (default cubic: 4-point Lagrange)")
    p.add_argument("--extrema-tolerance", type=float,
                   help="also require the profile extrema (u_min, v_max, v_min) within this fraction of the lid "
                        "speed of the grid-converged values in data/cavity-extrema.csv (default: print them only)")
    p.add_argument("--reference", choices=("ghia", "botella"),
                   help="reference table (default: ghia at Re 100, botella at Re 1000)")
    return p.parse_args(argv)


def main(argv):
    a = parse_args(argv)
    try:
        reference = a.reference or DEFAULT_REFERENCE[a.re]
        if (a.re, reference) not in REFERENCES:
            raise InputError("option --reference: no %s table at Re %d" % (reference, a.re))
        if not (np.isfinite(a.tolerance) and a.tolerance > 0):
            raise InputError("option --tolerance: %g must be positive" % a.tolerance)
        if a.extrema_tolerance is not None and not (np.isfinite(a.extrema_tolerance) and a.extrema_tolerance > 0):
            raise InputError("option --extrema-tolerance: %g must be positive" % a.extrema_tolerance)
        if not (np.isfinite(a.lid_speed) and a.lid_speed > 0):
            raise InputError("option --lid-speed: %g must be positive (the lid moves in +x)" % a.lid_speed)
        try:
            xlo, ylo, xhi, yhi = (float(t) for t in a.box.split(","))
        except ValueError:
            raise InputError("option --box: '%s' is not 4 comma-separated numbers XLO,YLO,XHI,YHI" % a.box)
        if not (xhi > xlo and yhi > ylo):
            raise InputError("option --box: the upper corner must exceed the lower corner in x and y")
        if abs((xhi - xlo) - (yhi - ylo)) > 1e-9 * (xhi - xlo):
            raise InputError("option --box: %g x %g is not square; the references are for a square cavity"
                             % (xhi - xlo, yhi - ylo))
        lo, hi = {"x": xlo, "y": ylo}, {"x": xhi, "y": yhi}
        stem, name, citation = REFERENCES[(a.re, reference)]
        lines = read_profile(a.profile)
        yu, uu = centreline(a.profile, lines, "y", "y", "x", "u", lo, hi, a.lid_speed)
        xv, vv = centreline(a.profile, lines, "x", "x", "y", "v", lo, hi, a.lid_speed)
    except InputError as e:
        print("cavity_profile_check: %s" % e)
        return 2
    wmax = max(abs(r.get("w", 0.0)) for rows in lines.values() for r in rows) / a.lid_speed
    print("F2 lid-driven cavity, Re %d, against %s; %s interpolation; %d points on line y, %d on line x; "
          "max |w|/U on the lines %.1e" % (a.re, citation, a.interp, len(yu), len(xv), wmax))
    ys, us = read_reference(stem, "u")
    xs, vs = read_reference(stem, "v")
    _, ok_u = check(a.re, "u", "y", "x", ys, us, yu, uu, a.interp, a.tolerance, name)
    _, ok_v = check(a.re, "v", "x", "y", xs, vs, xv, vv, a.interp, a.tolerance, name)
    ok_e = check_extrema(a.re, yu, uu, xv, vv, a.interp, a.extrema_tolerance)
    return 0 if ok_u and ok_v and ok_e else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
