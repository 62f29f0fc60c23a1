"""Type stubs of the native module ``snowroll._snowroll`` (Rust, PyO3).

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

def simulate(
    model: str = "torque-cm",
    *,
    alpha_deg: Optional[float] = None,
    snow_depth: Optional[float] = None,
    r0: Optional[float] = None,
    g: Optional[float] = None,
    density: Optional[float] = None,
    length: Optional[float] = None,
    v0: Optional[float] = None,
    shape: Optional[str] = None,
    swath_width: Optional[Union[float, str]] = None,
    core_radius: Optional[float] = None,
    core_mass: Optional[float] = None,
    t_end: Optional[float] = None,
    x_end: Optional[float] = None,
    turns: Optional[int] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    max_rows: Optional[int] = None,
    max_steps: Optional[int] = None,
    dt: Optional[float] = None,
    times: Optional[Sequence[float]] = None,
    mu: Optional[float] = None,
    collision: Optional[str] = None,
    on_hop: Optional[str] = None,
    drag_coefficient: Optional[float] = None,
    air_density: Optional[float] = None,
    rolling_resistance: Optional[float] = None,
    compaction_energy: Optional[float] = None,
    ledger: bool = False,
    terminal_tol: Optional[float] = None,
    max_memory: int = ...,
) -> Dict[str, Any]:
    """Integrate one model (e.g. eq. (4) ``torque-cm``, eq. (14) ``energy``,
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

def turns(
    model: str = "turns",
    *,
    turns: Optional[int] = None,
    alpha_deg: Optional[float] = None,
    snow_depth: Optional[float] = None,
    r0: Optional[float] = None,
    g: Optional[float] = None,
    density: Optional[float] = None,
    length: Optional[float] = None,
    v0: Optional[float] = None,
    shape: Optional[str] = None,
    swath_width: Optional[Union[float, str]] = None,
    core_radius: Optional[float] = None,
    core_mass: Optional[float] = None,
    t_end: Optional[float] = None,
    x_end: Optional[float] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    max_rows: Optional[int] = None,
    max_steps: Optional[int] = None,
    mu: Optional[float] = None,
    collision: Optional[str] = None,
    on_hop: Optional[str] = None,
    drag_coefficient: Optional[float] = None,
    air_density: Optional[float] = None,
    rolling_resistance: Optional[float] = None,
    compaction_energy: Optional[float] = None,
    ledger: bool = False,
    terminal_tol: Optional[float] = None,
    max_memory: int = ...,
) -> Dict[str, Any]:
    """Run a turn model (eqs. (64), (73), (76) ``turns``; eq. (88)
    ``turns-exact``; collisions by eq. (89) or the ``charged``/``pivot``
    variants) for ``turns`` turns (default 100, ``t_end`` default 1e9 s).

    Returns the keys of :func:`simulate` (``columns`` one row per turn) plus
    ``summary``, a SummaryRecord whose ``to_dict()`` holds the long-run means
    of a/(g sin alpha) that eqs. (77)-(79) estimate as 4/9. The log only; no losses (ValueError), a ledger at each
    turn end, before its collision.
    """

def models(
    *,
    alpha_deg: Optional[float] = None,
    snow_depth: Optional[float] = None,
    r0: Optional[float] = None,
    g: Optional[float] = None,
    density: Optional[float] = None,
    length: Optional[float] = None,
    v0: Optional[float] = None,
    shape: Optional[str] = None,
    swath_width: Optional[Union[float, str]] = None,
    core_radius: Optional[float] = None,
    core_mass: Optional[float] = None,
    drag_coefficient: Optional[float] = None,
    air_density: Optional[float] = None,
    rolling_resistance: Optional[float] = None,
    compaction_energy: Optional[float] = None,
    ledger: bool = False,
    terminal_tol: Optional[float] = None,
) -> List[Dict[str, Any]]:
    """Every model: ``id``, ``alias``, ``equation``, ``description``,
    ``terminal_fraction`` (late-time a/(g sin alpha)), ``stall_slope_deg``
    and ``stall_kind`` (fn. 7) for the body, snow and losses of the
    keywords, ``validity``."""

def fit(
    t: Sequence[float],
    x: Sequence[float],
    *,
    models: Optional[Sequence[str]] = None,
    free: Optional[Sequence[str]] = None,
    t0: Optional[float] = None,
    x0: Optional[float] = None,
    max_iterations: Optional[int] = None,
    alpha_deg: Optional[float] = None,
    snow_depth: Optional[float] = None,
    r0: Optional[float] = None,
    g: Optional[float] = None,
    density: Optional[float] = None,
    length: Optional[float] = None,
    v0: Optional[float] = None,
    shape: Optional[str] = None,
    swath_width: Optional[Union[float, str]] = None,
    core_radius: Optional[float] = None,
    core_mass: Optional[float] = None,
    t_end: Optional[float] = None,
    x_end: Optional[float] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    max_rows: Optional[int] = None,
    max_steps: Optional[int] = None,
    mu: Optional[float] = None,
    collision: Optional[str] = None,
    on_hop: Optional[str] = None,
    drag_coefficient: Optional[float] = None,
    air_density: Optional[float] = None,
    rolling_resistance: Optional[float] = None,
    compaction_energy: Optional[float] = None,
    ledger: bool = False,
    terminal_tol: Optional[float] = None,
) -> Dict[str, Any]:
    """Fit each model's x(t) to the points ``t`` (s) and ``x`` (m) by
    Levenberg-Marquardt (finite-difference Jacobians from the models' own
    runs), the ``free`` parameters (table keys, ``t0``, ``x0``) from their
    starts, the rest fixed by the keywords.

    Returns ``{"fits": [dict], "free": [str], "t_s": [float], "x_m":
    [float], "skipped": [(model, reason)], "version": str}``, ``fits``
    sorted by rank, each the record of ``snowroll fit --format json`` plus
    ``residuals_m``, ``curve_t_s``, ``curve_x_m``.
    """

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
