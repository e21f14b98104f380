#!/usr/bin/python3
"""Observed order of convergence from errors on a ladder of grids (F1, F5, E1 ... in docs/verification.md).

Input (a file, or standard input when the file is '-' or left out), either
  - lines containing `grid N error E` anywhere (other text on the line and other lines are ignored),
    e.g. the output of an example; or
  - a CSV of N,error: '#' comments and blank lines skipped, an optional header row; with a header, the
    columns named N (or n, grid, cells) and error are used, otherwise the first two.
N counts cells along one direction (finer grid, larger N). The observed order between successive
grids is p = ln(E_coarse / E_fine) / ln(N_fine / N_coarse).

Prints the table "N  error  order", then
  <label>: observed order 1.98 (last pair, 64 -> 128; expected 2, tolerance >= 1.8) ok
and a `result: quantity | value | reference | ok|FAIL` line for scripts/validate. The order checked is
the last pair's (--check last, the default: the finest grids, nearest the asymptotic range) or the
smallest over all pairs (--check min). Exit status 0 if it lies in [--min-order, --max-order], 1 if
not, 2 on bad input (one line).

  convergence_table.py [FILE] [--expect 2] [--min-order 1.8] [--max-order P] [--check last|min]
                       [--label NAME]
"""
import argparse
import csv
import math
import re
import sys

GRID_ERROR = re.compile(r"\bgrid\s+(\S+)\s+error\s+(\S+)")
N_NAMES = ("n", "grid", "cells")


class InputError(Exception):
    pass


def number(text, what, where):
    try:
        return float(text)
    except ValueError:
        raise InputError("%s: %s '%s' is not a number" % (where, what, text))


def parse(text, name):
    """[(N, error)] from `grid N error E` lines or, failing those, from CSV rows."""
    pairs = [(number(m.group(1), "N", "%s:%d" % (name, i)), number(m.group(2), "error", "%s:%d" % (name, i)))
             for i, line in enumerate(text.splitlines(), start=1) for m in [GRID_ERROR.search(line)] if m]
    if pairs:
        return pairs
    rows = [(i, r) for i, r in enumerate(csv.reader(text.splitlines()), start=1)
            if r and "".join(r).strip() and not r[0].lstrip().startswith("#")]
    if not rows:
        raise InputError("%s: no data (expected lines 'grid N error E' or a CSV of N,error)" % name)
    cols = (0, 1)
    first = [c.strip() for c in rows[0][1]]
    try:
        float(first[0])
    except ValueError:  # a header row
        lower = [c.lower() for c in first]
        ncol = next((lower.index(n) for n in N_NAMES if n in lower), None)
        if ncol is None or "error" not in lower:
            if len(first) < 2:
                raise InputError("%s:%d: header '%s' names no N and error columns" % (name, rows[0][0], ",".join(first)))
        else:
            cols = (ncol, lower.index("error"))
        rows = rows[1:]
    pairs = []
    for i, r in rows:
        if len(r) <= max(cols):
            raise InputError("%s:%d: expected at least %d comma-separated fields" % (name, i, max(cols) + 1))
        pairs.append((number(r[cols[0]].strip(), "N", "%s:%d" % (name, i)),
                      number(r[cols[1]].strip(), "error", "%s:%d" % (name, i))))
    return pairs


def orders(pairs, name):
    """Sorted (N, error) and the observed order of each successive pair."""
    pairs = sorted(pairs)
    if len(pairs) < 2:
        raise InputError("%s: %d grid; an order needs at least 2" % (name, len(pairs)))
    for n, e in pairs:
        if not (math.isfinite(n) and n > 0):
            raise InputError("%s: grid N = %g must be positive" % (name, n))
        if not (math.isfinite(e) and e > 0):
            raise InputError("%s: error %g at N = %g: the order needs positive errors" % (name, e, n))
    for (n0, _), (n1, _) in zip(pairs, pairs[1:]):
        if n1 == n0:
            raise InputError("%s: grid N = %g appears twice" % (name, n0))
    return pairs, [math.log(e0 / e1) / math.log(n1 / n0) for (n0, e0), (n1, e1) in zip(pairs, pairs[1:])]


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("file", nargs="?", default="-", help="input file ('-' or none: standard input)")
    p.add_argument("--expect", type=float, default=2.0, help="formal order of the method (default 2)")
    p.add_argument("--min-order", type=float, help="smallest acceptable order (default 0.9 x --expect)")
    p.add_argument("--max-order", type=float, default=math.inf,
                   help="largest acceptable order (default none); an order far above the formal one "
                        "often means the error measured is not the one intended")
    p.add_argument("--check", choices=("last", "min"), default="last",
                   help="which order is checked: the last pair's (default) or the smallest")
    p.add_argument("--label", default="convergence", help="name printed on the summary line")
    a = p.parse_args(argv)
    min_order = 0.9 * a.expect if a.min_order is None else a.min_order
    name = "<stdin>" if a.file == "-" else a.file
    try:
        if a.file == "-":
            text = sys.stdin.read()
        else:
            try:
                with open(a.file) as f:
                    text = f.read()
            except OSError as e:
                raise InputError("%s: cannot open: %s" % (a.file, e.strerror))
        if not min_order <= a.max_order:
            raise InputError("option --max-order: %g is below the minimum order %g" % (a.max_order, min_order))
        pairs, ps = orders(parse(text, name), name)
    except InputError as e:
        print("convergence_table: %s" % e)
        return 2
    print("%8s  %12s  %6s" % ("N", "error", "order"))
    print("%8g  %12.4e  %6s" % (pairs[0][0], pairs[0][1], "-"))
    for (n, e), order in zip(pairs[1:], ps):
        print("%8g  %12.4e  %6.2f" % (n, e, order))
    k = len(ps) - 1 if a.check == "last" else min(range(len(ps)), key=lambda i: ps[i])
    got = ps[k]
    ok = min_order <= got <= a.max_order
    bound = ">= %g" % min_order if math.isinf(a.max_order) else "in [%g, %g]" % (min_order, a.max_order)
    which = "last pair" if a.check == "last" else "smallest, pair"
    print("%s: observed order %.2f (%s, %g -> %g; expected %g, tolerance %s) %s"
          % (a.label, got, which, pairs[k][0], pairs[k + 1][0], a.expect, bound, "ok" if ok else "FAIL"))
    print("result: %s observed order (%s, %g -> %g) | %.2f (error %.3e) | expected %g, %s | %s"
          % (a.label, a.check, pairs[k][0], pairs[k + 1][0], got, pairs[k + 1][1], a.expect, bound,
             "ok" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
