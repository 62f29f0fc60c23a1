"""Shared helpers of the derivation scripts: one PASS/FAIL line per formula.

Every script calls `check(name, ok)` (or `same(name, lhs, rhs)` for a symbolic
identity) and ends with `finish()`, which exits non-zero if any check failed.
Needs only python3 and sympy.
"""

import sys

import sympy as sp

_failures = []
_count = [0]


def check(name, ok, detail=""):
    """Records one verdict and prints it."""
    _count[0] += 1
    ok = bool(ok)
    print(("PASS " if ok else "FAIL ") + name + (f"  [{detail}]" if detail and not ok else ""))
    if not ok:
        _failures.append(name)
    return ok


def is_zero(expr, assumptions=None):
    """True when `expr` simplifies to 0 (tries several simplifiers)."""
    e = sp.sympify(expr)
    for f in (sp.expand, sp.cancel, sp.simplify, lambda z: sp.simplify(sp.expand_trig(z))):
        try:
            if f(e) == 0:
                return True
        except Exception:  # noqa: BLE001 - a simplifier may give up; try the next one
            pass
    return False


def same(name, lhs, rhs):
    """Checks the identity lhs == rhs symbolically."""
    diff = sp.sympify(lhs) - sp.sympify(rhs)
    return check(name, is_zero(diff), detail=str(sp.simplify(diff))[:200])


def close(name, got, want, rel=1e-9, abs_=0.0):
    """Checks |got − want| <= rel |want| + abs_ for numbers."""
    got, want = float(got), float(want)
    ok = abs(got - want) <= rel * abs(want) + abs_
    return check(name, ok, detail=f"got {got!r}, want {want!r}")


def series_zero(name, expr, var, order):
    """Checks that `expr` is O(var**order) as var -> 0."""
    s = sp.series(sp.sympify(expr), var, 0, order).removeO()
    return check(name, is_zero(s), detail=str(sp.simplify(s))[:200])


def finish():
    """Prints the tally and exits non-zero on any failure."""
    n = _count[0]
    print(f"{n - len(_failures)} passed, {len(_failures)} failed")
    sys.exit(1 if _failures else 0)
