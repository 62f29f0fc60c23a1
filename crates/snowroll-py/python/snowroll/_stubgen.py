"""The type stub of the native module, ``_snowroll.pyi``, written from the
parameter table: the keywords of ``simulate`` and ``turns`` are the table's,
so the stub cannot be edited by hand without going stale.
``tests/test_stub.py`` fails when the committed stub differs from what this
writes. To write it again after a change of the table:

    python -m snowroll._stubgen > crates/snowroll-py/python/snowroll/_snowroll.pyi
"""

from __future__ import annotations

from typing import List

from . import _TYPE_OF_KIND, _keywords

_HEAD = '''"""Type stubs of the native module ``snowroll._snowroll`` (Rust, PyO3).

Written by ``python -m snowroll._stubgen`` from the parameter table; do not
edit. Use the functions of the package ``snowroll`` instead: they wrap the
dicts returned here in ``snowroll.Result`` and ``snowroll.TurnResult``.
Every keyword left ``None`` takes the library's default, the same as the
CLI's.
"""

from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

__version__: str

#: The parameter table: one dict per parameter (``key``, ``kind``,
#: ``choices``, ``unit``, ``range``, ``help``, ``default``, ``default_text``,
#: ``scope``, ``applies``, ``aliases``).
PARAMS: List[Dict[str, Any]]
'''

_SIMULATE_DOC = '''    """Integrate one model (e.g. eq. (4) ``torque-cm``, eq. (14) ``energy``,
    eq. (32) ``quasi-circular``, eqs. (73), (76) ``turns``) for one scenario,
    the radius growing as r(x) = sqrt(r0^2 + b x / pi), eq. (8).

    Returns ``{"columns": {name: ndarray}, "masks": {name: ndarray},
    "stop": dict, "params": ParamsRecord, "version": str, "model": str,
    "equation": str, "warnings": [str]}``; ``params.to_dict()`` is the dict
    of the CLI's JSON ``params``; columns ``t_s x_m v_m_s a_m_s2 r_m
    mass_kg normal_n friction_n friction_ratio`` (float64; ``friction_ratio``
    undefined where N <= 0: 0.0 there, True in its mask ``masks["friction_ratio"]``;
    ``snowroll.Result`` makes it a ``numpy.ma.MaskedArray``), for the turn models ``turn``
    (uint64), ``theta_rad``, ``omega_rad_s``, and with losses or a ledger the
    ledger columns ``kinetic_j released_j drag_j rolling_j compaction_j
    model_j collision_j created_j residual_j`` (J).

    Raises ValueError (bad parameters) or RuntimeError (failed integration).
    """
'''

_TURNS_DOC = '''    """Run a turn model (eqs. (64), (73), (76) ``turns``; eq. (88)
    ``turns-exact``; collisions by eq. (89) or the ``charged``/``pivot``
    variants) for ``turns`` turns (default 100, ``t_end`` default 1e9 s).

    Returns the keys of :func:`simulate` (``columns`` one row per turn) plus
    ``summary``, a SummaryRecord whose ``to_dict()`` holds the long-run means
    of a/(g sin alpha) that eqs. (77)-(79) estimate as 4/9. The log only; no losses (ValueError), a ledger at each
    turn end, before its collision.
    """
'''

_TAIL = '''
MAX_MEMORY: int

#: The numeric axes a sweep's grid takes, in grid order.
SWEEP_AXES: List[str]

#: Bytes a sweep row holds until ``sweep`` returns (measured; the bound
#: ``max_memory`` is checked against).
SWEEP_ROW_BYTES: int

def grid_len(grid: Dict[str, Any]) -> int:
    """The number of points of ``grid`` (models × axes × settings)."""

def sweep(
    grid: Dict[str, Any],
    *,
    shard: Optional[Tuple[int, int]] = None,
    method: str = "auto",
    max_memory: int = ...,
) -> Dict[str, Any]:
    """Every model of ``grid["model"]`` at every point of the other axes
    (each key of ``SWEEP_AXES``; a number, a sequence, or ``"a,b,c"`` /
    ``"start:end:count"``) and of the settings ``collision`` (``note``,
    ``charged``, ``pivot``) and ``on_hop`` (``stop``, ``continue``), each a
    list of ids or ``"a,b"``, one summary row each, in grid order; shard
    ``(i, n)`` only. The circular models take the closed form of their speed
    (``method="auto"``) or the ODE (``"ode"``).

    Returns ``{"columns": {name: ndarray}, "len": int, "shard": (i, n),
    "rows": (start, end), "settings": [(name, text)], "version": str}``: the
    numbers as numpy arrays, the text columns (``model``, ``on_hop``,
    ``collision``, ``stop``, ``error``, ``warnings``) as numpy object arrays
    of ``str`` or ``None``; ``settings`` every setting as the CLI's header
    records it. A result that cannot fit in ``max_memory`` or in the memory
    the machine has raises ``MemoryError``. Library messages name keywords
    where the CLI's name flags (``--snow-depth`` becomes ``snow_depth=``).
    """
'''


def _function(name: str, model_default: str, doc: str) -> List[str]:
    lines = [f"def {name}(", f'    model: str = "{model_default}",', "    *,"]
    for p in _keywords(name):
        default = "False" if p["kind"] == "flag" else "None"
        lines.append(f"    {p['key']}: {_TYPE_OF_KIND[p['kind']]} = {default},")
    lines.append("    max_memory: int = ...,")
    lines.append(") -> Dict[str, Any]:")
    return lines + [doc.rstrip("\n"), ""]


_MODELS_DOC = '''    """Every model: ``id``, ``alias``, ``equation``, ``description``,
    ``terminal_fraction`` (late-time a/(g sin alpha)), ``stall_slope_deg``
    and ``stall_kind`` (fn. 7) for the body, snow and losses of the
    keywords, ``validity``."""
'''


def _models() -> List[str]:
    lines = ["def models(", "    *,"]
    for p in _keywords("models"):
        default = "False" if p["kind"] == "flag" else "None"
        lines.append(f"    {p['key']}: {_TYPE_OF_KIND[p['kind']]} = {default},")
    lines.append(") -> List[Dict[str, Any]]:")
    return lines + [_MODELS_DOC.rstrip("\n"), ""]


_FIT_DOC = '''    """Fit each model's x(t) to the points ``t`` (s) and ``x`` (m) by
    Levenberg-Marquardt (finite-difference Jacobians from the models' own
    runs), the ``free`` parameters (table keys, ``t0``, ``x0``) from their
    starts, the rest fixed by the keywords.

    Returns ``{"fits": [dict], "free": [str], "t_s": [float], "x_m":
    [float], "skipped": [(model, reason)], "version": str}``, ``fits``
    sorted by rank, each the record of ``snowroll fit --format json`` plus
    ``residuals_m``, ``curve_t_s``, ``curve_x_m``.
    """
'''


def _fit() -> List[str]:
    lines = [
        "def fit(",
        "    t: Sequence[float],",
        "    x: Sequence[float],",
        "    *,",
        "    models: Optional[Sequence[str]] = None,",
        "    free: Optional[Sequence[str]] = None,",
        "    t0: Optional[float] = None,",
        "    x0: Optional[float] = None,",
        "    max_iterations: Optional[int] = None,",
    ]
    for p in _keywords("fit"):
        default = "False" if p["kind"] == "flag" else "None"
        lines.append(f"    {p['key']}: {_TYPE_OF_KIND[p['kind']]} = {default},")
    lines.append(") -> Dict[str, Any]:")
    return lines + [_FIT_DOC.rstrip("\n"), ""]


def stub() -> str:
    """The text of ``_snowroll.pyi``."""
    lines = [_HEAD]
    lines += _function("simulate", "torque-cm", _SIMULATE_DOC)
    lines += _function("turns", "turns", _TURNS_DOC)
    lines += _models()
    lines += _fit()
    return "\n".join(lines) + _TAIL


if __name__ == "__main__":
    print(stub(), end="")
