"""Tolerance-aware comparison of program output against a reference.

Text must match exactly (runs of blanks count as one). Numbers are compared as numbers: when both
are integers (no point, no exponent) they must be equal; otherwise they must agree within
|actual - expected| <= atol + rtol * |expected|. PETSc's petscdiff masks every decimal, so a
changed physical value would pass there; here it fails.
"""
import difflib
import math
import re

_NUMBER = re.compile(r"[-+]?(?:(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?|nan|inf)(?![\w.])", re.IGNORECASE)
_WORD_CHAR = re.compile(r"[A-Za-z_]")


def tokenize(line):
    """Splits a line into ('text', str) and ('num', str) tokens. A digit run glued to a word
    (ex01, x2) stays text."""
    tokens, pos = [], 0
    for m in _NUMBER.finditer(line):
        start = m.start()
        if start > 0 and _WORD_CHAR.match(line[start - 1]):
            continue
        if start > pos:
            tokens.append(("text", line[pos:start]))
        tokens.append(("num", m.group()))
        pos = m.end()
    if pos < len(line):
        tokens.append(("text", line[pos:]))
    return tokens


def _is_int(s):
    return re.fullmatch(r"[-+]?\d+", s) is not None


def _norm_text(s):
    return " ".join(s.split())


def compare_lines(expected, actual, rtol, atol):
    """Returns None when the lines agree, else a short reason."""
    te, ta = tokenize(expected), tokenize(actual)
    kinds_e = [k for k, _ in te]
    kinds_a = [k for k, _ in ta]
    if kinds_e != kinds_a:
        return "different layout"
    for (kind, e), (_, a) in zip(te, ta):
        if kind == "text":
            if _norm_text(e) != _norm_text(a):
                return "text %r != %r" % (e.strip(), a.strip())
            continue
        if _is_int(e) and _is_int(a):
            if int(e) != int(a):
                return "integer %s != %s" % (a, e)
            continue
        fe, fa = float(e), float(a)
        if math.isnan(fe) or math.isnan(fa):
            if not (math.isnan(fe) and math.isnan(fa)):
                return "%s != %s" % (a, e)
            continue
        if math.isinf(fe) or math.isinf(fa):
            if fe != fa:
                return "%s != %s" % (a, e)
            continue
        if abs(fa - fe) > atol + rtol * abs(fe):
            return "%s differs from %s by %.3g (allowed %.3g)" % (a, e, abs(fa - fe), atol + rtol * abs(fe))
    return None


def compare(expected_text, actual_text, rtol=1e-8, atol=1e-12):
    """Returns (ok, report). The report lists each disagreeing line and a unified diff."""
    exp = [l for l in expected_text.splitlines() if l.strip()]
    act = [l for l in actual_text.splitlines() if l.strip()]
    problems = []
    if len(exp) != len(act):
        problems.append("line count %d != expected %d" % (len(act), len(exp)))
    for i, (e, a) in enumerate(zip(exp, act)):
        why = compare_lines(e, a, rtol, atol)
        if why:
            problems.append("line %d: %s" % (i + 1, why))
    if not problems:
        return True, ""
    diff = difflib.unified_diff(exp, act, "expected", "actual", lineterm="")
    return False, "\n".join(problems[:20] + ["(rtol %g, atol %g)" % (rtol, atol)] + list(diff))
