"""snowroll: a log rolling down a snowy slope, picking up snow as it goes.

Every model of K. T. McDonald's note, computed by the Rust library ``snowroll``
(the same code as the ``snowroll`` command line, so a run here equals the CLI's
run with the same parameters to the last bit). Keyword names are the
project's one parameter table, :data:`PARAMS` (the CLI's long flags in
snake_case: ``alpha_deg``, ``snow_depth``, ``r0``, ...), with each one's unit,
range and default. Units are SI, angles in degrees.

>>> import snowroll
>>> r = snowroll.simulate("torque-cm", alpha_deg=30, snow_depth=0.01, t_end=10)
>>> r.stop["reason"], r.v_m_s[-1] > 0
('end-time', True)

Functions: :func:`simulate`, :func:`turns`, :func:`models`, :func:`sweep`,
:func:`fit` (the models fitted to a measured x(t)).
Bad parameters raise ``ValueError`` with the library's message (a
parameter it names is written as its keyword, ``snow_depth=``, where the CLI
writes ``--snow-depth``), a parameter of the wrong type ``TypeError`` naming its keyword, a
failed integration ``RuntimeError``. Float keywords take any real number
(int, float, numpy scalar), count keywords (``turns``, ``max_rows``,
``max_steps``) an integer. The computation runs with the GIL released, so threads
calling these functions run in parallel.
"""

from __future__ import annotations

import functools as _functools
import inspect as _inspect
import numbers as _numbers
import sys as _sys
import warnings as _warnings
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as _np

from . import _plot, _snowroll

__version__: str = _snowroll.__version__

#: The default of ``max_memory``, bytes (2 GiB): the most a call's result
#: may hold before it raises ``MemoryError``.
MAX_MEMORY: int = _snowroll.MAX_MEMORY

#: The axes a sweep's grid takes, in grid order: the parameter table's
#: numeric sweep parameters (each also a column of :class:`SweepResult`).
SWEEP_AXES: Tuple[str, ...] = tuple(_snowroll.SWEEP_AXES)

__all__ = ["simulate", "turns", "models", "sweep", "fit", "FitResult", "Result", "TurnResult", "Results", "SweepResult", "sweep_chunks", "dask", "MAX_MEMORY", "__version__"]


def _jaro(a: str, b: str) -> float:
    """The Jaro similarity of two strings (0 to 1), as the ``strsim`` crate
    computes it for the command line's suggestions."""
    if a == b:
        return 1.0
    if not a or not b:
        return 0.0
    reach = max(len(a), len(b)) // 2 - 1
    reach = max(reach, 0)
    used_b = [False] * len(b)
    matched_a = []
    for i, c in enumerate(a):
        for j in range(max(0, i - reach), min(len(b), i + reach + 1)):
            if not used_b[j] and b[j] == c:
                used_b[j] = True
                matched_a.append(c)
                break
    m = len(matched_a)
    if m == 0:
        return 0.0
    matched_b = [c for c, used in zip(b, used_b) if used]
    half_swaps = sum(x != y for x, y in zip(matched_a, matched_b)) / 2
    return (m / len(a) + m / len(b) + (m - half_swaps) / m) / 3


def _nearest(name: str, names: Sequence[str]) -> Optional[str]:
    """The name of ``names`` most like ``name``, when one is alike enough:
    the command line's rule (clap's), a Jaro similarity above 0.7."""
    scored = [(_jaro(name, n), n) for n in names]
    best = max(scored, default=(0.0, ""))
    return best[1] if best[0] > 0.7 else None


def _unexpected(function: str, key: str, names: Sequence[str]) -> str:
    """The message of an unknown keyword, with the nearest known one as the
    command line suggests a flag (``tip: a similar argument exists``)."""
    message = f"{function}() got an unexpected keyword argument {key!r}"
    near = _nearest(key, names)
    return message + (f"; a similar keyword exists: {near!r}" if near else "")


def _suggesting(f: Any) -> Any:
    """``f`` (a function with fixed keywords) with an unknown keyword
    refused as :func:`_unexpected` words it, naming the nearest keyword."""
    sig = _inspect.signature(f)
    names = [n for n, p in sig.parameters.items() if p.kind != p.POSITIONAL_ONLY]

    @_functools.wraps(f)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        for k in kwargs:
            if k not in sig.parameters:
                raise TypeError(_unexpected(f.__name__, k, names))
        return f(*args, **kwargs)

    return wrapper


class _Columns:
    """Columns as numpy arrays, by attribute (``r.v_m_s``) or key (``r["v_m_s"]``)."""

    # The columns by name. A column with a mask (|F|/N) comes from the
    # native module as its data, with the mask in `_masks`; the pair becomes
    # a `numpy.ma.MaskedArray` when the columns are first read (numpy.ma's
    # constructor is Python code, a few microseconds that a call which reads
    # no column should not pay).
    _cols: Dict[str, Any]
    _masks: Optional[Dict[str, Any]] = None

    @property
    def _columns(self) -> Dict[str, Any]:
        cols = self.__dict__.get("_cols", {})
        masks = self.__dict__.get("_masks")
        if masks:
            for name, mask in masks.items():
                cols[name] = _np.ma.masked_array(cols[name], mask=mask)
            self._masks = None
        return cols

    @_columns.setter
    def _columns(self, columns: Dict[str, Any]) -> None:
        self._cols = columns
        self._masks = None

    def _set_raw_columns(self, raw: Dict[str, Any]) -> None:
        # The native module's columns and their masks, as it returned them.
        self._cols = raw["columns"]
        self._masks = raw["masks"]

    @property
    def columns(self) -> List[str]:
        """The column names, in the order of the CLI's CSV header."""
        return list(self._columns)

    def __getitem__(self, name: str) -> Any:
        return self._columns[name]

    def __getattr__(self, name: str) -> Any:
        # Only called when normal lookup fails: columns by attribute.
        columns = self._columns if "_cols" in self.__dict__ else {}
        if name in columns:
            return columns[name]
        raise AttributeError(
            f"{type(self).__name__} has no attribute or column {name!r}; "
            f"columns: {', '.join(columns)}"
        )

    def __contains__(self, name: object) -> bool:
        return name in self._columns

    def __iter__(self) -> Iterator[str]:
        return iter(self._columns)

    def __len__(self) -> int:
        first = next(iter(self._columns.values()), None)
        return 0 if first is None else len(first)

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self._columns))

    def to_dict(self) -> Dict[str, Any]:
        """The columns as a dict of numpy arrays (the arrays themselves, not copies)."""
        return dict(self._columns)

    def _undefined_as_missing(self, missing: Any, text: Any) -> Dict[str, Any]:
        # Masked entries (|F|/N where N <= 0) as the frame library's own
        # missing value, never NaN; text columns (object arrays of str or
        # None) as the library's string type, None as its missing value,
        # even in a column where every cell is missing.
        out: Dict[str, Any] = {}
        for name, col in self._columns.items():
            if isinstance(col, _np.ma.MaskedArray):
                out[name] = missing(col)
            elif col.dtype == object:
                out[name] = text(col)
            else:
                out[name] = col
        return out

    def to_pandas(self) -> Any:
        """The columns as a ``pandas.DataFrame`` (needs pandas, not a dependency)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        frame = pd.DataFrame(
            self._undefined_as_missing(
                lambda c: pd.arrays.FloatingArray(
                    _np.ma.getdata(c).copy(), _np.ma.getmaskarray(c).copy()
                ),
                lambda c: pd.array(c, dtype="string"),
            )
        )
        frame.attrs.update(self._frame_attrs())
        return frame

    def _frame_attrs(self) -> Dict[str, Any]:
        # What a pandas frame keeps besides the columns (`DataFrame.attrs`).
        return {
            "params": dict(self.params),
            "stop": dict(self.stop),
            "model": self.model,
            "version": self.version,
        }

    def to_polars(self) -> Any:
        """The columns as a ``polars.DataFrame`` (needs polars, not a dependency)."""
        try:
            import polars as pl
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_polars() needs polars: pip install polars") from e
        return pl.DataFrame(
            self._undefined_as_missing(
                lambda c: pl.Series(c.tolist(), dtype=pl.Float64),
                lambda c: pl.Series(c.tolist(), dtype=pl.String),
            )
        )


class _Run(_Columns):
    """What :class:`Result` and :class:`TurnResult` share: the run's
    parameters, made a dict when first read (the native module returns the
    library's record; its dict is a fifth of what a call would otherwise
    add to the library's own time)."""

    _params: Any

    @property
    def params(self) -> Dict[str, Any]:
        """The run's parameters (the keys of the CLI's output metadata)."""
        p = self._params
        if type(p) is not dict:
            p = self._params = p.to_dict()
        return p

    @params.setter
    def params(self, value: Dict[str, Any]) -> None:
        self._params = value


class Result(_Run):
    """One trajectory: what :func:`simulate` returns.

    Attributes: the columns (``t_s``, ``x_m``, ``v_m_s``, ``a_m_s2``, ``r_m``,
    ``mass_kg``, ``normal_n``, ``friction_n``, ``friction_ratio`` and, for the
    turn models, ``turn``, ``theta_rad``, ``omega_rad_s``) as numpy arrays;
    ``friction_ratio`` (|F|/N) is a ``numpy.ma.MaskedArray``, masked where
    N <= 0 (undefined there: the log has left the ground; the CSV cell is
    empty, the JSON value null; no NaN or infinity anywhere);
    ``stop`` (dict: ``reason``, ``description``, ``t_s``, ``x_m``, ``v_m_s`` and
    for the turn models ``turn``, ``theta_rad``, ``omega_rad_s``); ``params``
    (dict, the keys of the CLI's output metadata); ``model``, ``equation``,
    ``version``, ``warnings``.
    """

    def __init__(self, raw: Dict[str, Any]) -> None:
        self._set_raw_columns(raw)
        self.stop: Dict[str, Any] = raw["stop"]
        self._params = raw["params"]
        self.model: str = raw["model"]
        self.equation: str = raw["equation"]
        self.version: str = raw["version"]
        self.warnings: List[str] = raw["warnings"]

    def __repr__(self) -> str:
        return (
            f"<snowroll.Result {self.model} ({self.equation}): {len(self)} samples, "
            f"stop {self.stop['reason']} at t_s = {self.stop['t_s']}>"
        )

    def plot(self) -> Any:
        """The run drawn as the CLI's ``simulate --plot`` draws it (needs
        matplotlib, not a dependency): a/(g sin alpha), v, x, N and |F|/N
        against t, and the energy ledger as shares when the run recorded it.
        Returns the ``matplotlib.figure.Figure`` (``.savefig(path)``)."""
        return _plot.plot_runs([self])


class TurnResult(_Run):
    """One row per turn: what :func:`turns` returns.

    Columns as numpy arrays (``turn``, ``t_start_s``, ``x_start_m``,
    ``v_start_m_s``, ``t_end_s``, ``v_end_m_s``, ``v_after_m_s``,
    ``collision_loss_j``, ``mean_a_turn_m_s2``, ``min_a_m_s2``, ``max_a_m_s2``,
    ``mean_a_with_collision_m_s2``, ``min_normal_n``, ``min_normal_over_mg``,
    ``max_friction_ratio``, a ``numpy.ma.MaskedArray`` masked in the turns
    where N <= 0 somewhere); ``summary`` (dict: ``g_along_m_s2``, ``turns``,
    ``checkpoints``, the long-run means of a/(g sin alpha) that the note's
    eqs. (77)-(79) estimate); ``stop``, ``params``, ``model``, ``equation``,
    ``version``, ``warnings`` as in :class:`Result`.
    """

    def __init__(self, raw: Dict[str, Any]) -> None:
        self._set_raw_columns(raw)
        self._summary = raw["summary"]
        self.stop: Dict[str, Any] = raw["stop"]
        self._params = raw["params"]
        self.model: str = raw["model"]
        self.equation: str = raw["equation"]
        self.version: str = raw["version"]
        self.warnings: List[str] = raw["warnings"]

    @property
    def summary(self) -> Dict[str, Any]:
        """The long-run means of a/(g sin alpha), as a dict (made when first
        read from the library's record)."""
        s = self._summary
        if type(s) is not dict:
            s = self._summary = s.to_dict()
        return s

    @summary.setter
    def summary(self, value: Dict[str, Any]) -> None:
        self._summary = value

    def __repr__(self) -> str:
        return (
            f"<snowroll.TurnResult {self.model} ({self.equation}): {len(self)} turns, "
            f"stop {self.stop['reason']}>"
        )

    def plot(self) -> Any:
        """The turns drawn as the CLI's ``turns --plot`` draws them (needs
        matplotlib, not a dependency): per turn the means and extremes of
        a/(g sin alpha), the start speed and the least N/(M g). Returns the
        ``matplotlib.figure.Figure``."""
        return _plot.plot_turns([self])


class Results(list):  # type: ignore[type-arg]
    """Several models' results of one scenario, in the order asked for: what
    :func:`simulate` and :func:`turns` return for a list of models. A list of
    :class:`Result` or :class:`TurnResult`; :meth:`plot` draws them in one
    figure, one curve per model; :meth:`to_pandas` stacks their rows with a
    ``model`` column first."""

    def plot(self) -> Any:
        """One figure, one curve per model in each panel (needs matplotlib)."""
        if self and isinstance(self[0], TurnResult):
            return _plot.plot_turns(self)
        return _plot.plot_runs(self)

    def to_pandas(self) -> Any:
        """The rows of every result, in order, with a ``model`` column first
        (needs pandas). Columns a model lacks (a turn model's ``turn``) are
        missing values in the others' rows."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        frames = []
        for r in self:
            frame = r.to_pandas()
            frame.insert(0, "model", pd.array([r.model] * len(frame), dtype="string"))
            frames.append(frame)
        return pd.concat(frames, ignore_index=True)


class SweepResult(_Columns):
    """The rows of a sweep: what :func:`sweep` returns.

    Columns (those of the CLI's ``snowroll sweep`` CSV, in its order), every
    one a numpy array: ``index`` (uint64, the grid index), ``model``, one
    column per axis of :data:`SWEEP_AXES` (the parameter table's numeric
    sweep parameters, in its order, under their keys), ``on_hop``,
    ``collision``, ``stop``, ``t_s``, ``x_m``, ``v_m_s``,
    ``a_over_g_sin_alpha``, ``turns``, ``error``, ``warnings`` (the codes of
    the warnings :func:`simulate` gives for the row's point, ``;``-separated,
    such as ``b-over-r0;loose-tolerance``). The numbers are float64
    arrays with NaN where the CSV cell is empty (an optional parameter such
    as ``x_end`` or ``mu`` unset, a failed run). The text columns ``model``, ``on_hop``,
    ``collision``, ``stop``, ``error`` and ``warnings`` are numpy object arrays of ``str``,
    ``None`` where the cell is empty (a fixed-width numpy ``str`` array could
    not hold the missing cells); :meth:`to_pandas` makes them ``string``
    columns with ``pd.NA`` there, :meth:`to_polars` ``String`` columns with
    nulls, even where every cell is empty (``error`` when no run failed). ``len`` is the size of the whole grid, ``shard`` the
    ``(i, n)`` these rows are.
    """

    #: The columns holding text, as object arrays.
    TEXT_COLUMNS = ("model", "on_hop", "collision", "stop", "error", "warnings")

    def __init__(self, raw: Dict[str, Any]) -> None:
        # The native module returns the text columns as object arrays whose
        # cells share one string per distinct value (a row costs 8 bytes a
        # text column, not a string object of its own).
        self._columns = raw["columns"]
        self.grid_len: int = raw["len"]
        self.shard: Tuple[int, int] = tuple(raw["shard"])
        #: The grid indices ``(start, end)`` of the rows (end excluded).
        self.rows: Tuple[int, int] = tuple(raw["rows"])
        #: Every setting of the sweep as text, by name, as the CLI's header
        #: records it: the models, each parameter (its values, or its
        #: default), ``collision``, ``on_hop`` and ``method``.
        self.settings: Dict[str, str] = dict(raw["settings"])
        self.version: str = raw["version"]
        # No `params`, `stop` or `model` attributes: `r.model` and `r.stop`
        # are the columns of those names.

    def __repr__(self) -> str:
        i, n = self.shard
        return f"<snowroll.SweepResult {len(self)} rows of {self.grid_len} (shard {i}/{n})>"

    @staticmethod
    def concat(parts: Sequence["SweepResult"]) -> "SweepResult":
        """The shards of one sweep joined in grid order: the whole sweep,
        bit for bit. Checked as the CLI's ``snowroll merge`` checks shard
        files, and refused with ``ValueError`` naming what is wrong: parts of
        different sweeps (each differing setting named with both values:
        ``alpha_deg: 10,20 in part 0, 70,80 in part 1``), of different shard
        counts, a shard given twice, a missing shard (named with its rows:
        ``missing shards: 1/3 (rows 16..32) of the 48 points``), and a part
        whose rows are not all of its shard's (rows dropped or reordered
        since). There is no way to join an incomplete set: run the missing
        shards. The parts may come in any order."""
        parts = list(parts)
        if not parts:
            raise ValueError("concat() needs at least one SweepResult")
        for k, p in enumerate(parts):
            if not isinstance(p, SweepResult):
                raise TypeError(f"concat(): part {k} is a {type(p).__name__}, not a SweepResult")
        first = parts[0]
        n = first.shard[1]
        for k, p in enumerate(parts[1:], 1):
            differs = [
                f"{key}: {mine} in part 0, {p.settings.get(key, 'none')} in part {k}"
                for key, mine in first.settings.items()
                if p.settings.get(key) != mine
            ]
            if p.version != first.version:
                differs.insert(0, f"version: {first.version} in part 0, {p.version} in part {k}")
            if p.shard[1] != n:
                differs.append(f"shards: {n} in part 0, {p.shard[1]} in part {k}")
            if differs:
                raise ValueError(
                    f"concat(): parts 0 and {k} are not shards of the same sweep: " + "; ".join(differs)
                )
        by_shard: Dict[int, int] = {}
        for k, p in enumerate(parts):
            i = p.shard[0]
            if i in by_shard:
                raise ValueError(f"concat(): shard {i}/{n} is given twice: parts {by_shard[i]} and {k}")
            by_shard[i] = k
        points = first.grid_len

        def cut(i: int) -> int:
            # The first row of shard i of n, as the library splits a grid.
            return points * i // n

        if len(by_shard) < n:
            # The first few missing shards by name (n may be far larger than
            # the parts given), then how many in all.
            missing: List[str] = []
            i = 0
            while len(missing) < 5 and i < n:
                if i not in by_shard:
                    missing.append(f"{i}/{n} (rows {cut(i)}..{cut(i + 1)})")
                i += 1
            more = n - len(by_shard) - len(missing)
            tail = f" and {more} more" if more else ""
            raise ValueError(
                f"concat(): missing shards: {', '.join(missing)}{tail} of the {points} points"
            )
        ordered = [parts[by_shard[i]] for i in range(n)]
        for i, p in enumerate(ordered):
            want = _np.arange(cut(i), cut(i + 1), dtype=_np.uint64)
            if p.rows != (cut(i), cut(i + 1)) or not _np.array_equal(p["index"], want):
                raise ValueError(
                    f"concat(): part {by_shard[i]} (shard {i}/{n}) does not hold the rows "
                    f"{cut(i)}..{cut(i + 1)} of its shard in order (it has {len(p)} rows)"
                )
            if p.columns != first.columns:
                raise ValueError(f"concat(): part {by_shard[i]} has other columns than part 0")
        out = SweepResult.__new__(SweepResult)
        out._columns = {
            name: _np.concatenate([p[name] for p in ordered]) for name in first.columns
        }
        out.grid_len = points
        out.shard = (0, 1)
        out.rows = (0, points)
        out.settings = dict(first.settings)
        out.version = first.version
        return out

    def _frame_attrs(self) -> Dict[str, Any]:
        return {"grid_len": self.grid_len, "shard": self.shard, "version": self.version}


@_suggesting
def sweep(
    grid: Mapping[str, Any],
    *,
    shard: Optional[Tuple[int, int]] = None,
    method: str = "auto",
    max_memory: int = MAX_MEMORY,
) -> SweepResult:
    """Run every model over a grid of parameters, one summary row per run
    (the CLI's ``snowroll sweep``), rows computed in parallel with the GIL
    released.

    ``grid``: ``{"model": "torque-cm,energy" or a list of ids, AXIS: values}``
    with AXIS one of :data:`SWEEP_AXES` (the parameter table's numeric sweep
    parameters) and values a number, a sequence of numbers, or a string as the CLI reads it:
    ``"10,20,30"`` or ``"start:end:count"`` (both ends included); and the
    settings ``collision`` (``"note"``, ``"charged"``, ``"pivot"``) and
    ``on_hop`` (``"stop"``, ``"continue"``), a list of ids or ``"a,b"``.
    Parameters not in the grid take their defaults (t_end 100 s, no mu,
    collision note, on_hop stop).

    ``shard=(i, n)``: only shard i (0-based) of n, as ``--shard i/n``; the
    shards' rows, joined with :meth:`SweepResult.concat`, are the whole
    sweep's. ``method``: ``"auto"`` (the circular models' closed form where it
    applies, the ODE elsewhere) or ``"ode"``.

    ``a_over_g_sin_alpha`` is the acceleration at the end of each run over
    g sin alpha, to compare with the late-time fractions of :func:`models`
    and the note's eq. (79) (4/9).

    ``max_memory``: the most bytes the result may hold (default
    :data:`MAX_MEMORY`, 2 GiB); a grid whose rows would not fit raises
    ``MemoryError`` before it starts: give a shard, or raise the limit.
    Ctrl-C stops the sweep within about a second (``KeyboardInterrupt``).

    Raises ``ValueError`` for a bad grid (the library's message) or a shard
    outside ``0 <= i < n``, ``TypeError`` for a value of the wrong type.
    """
    if shard is not None:
        try:
            i, n = shard
        except (TypeError, ValueError):
            raise TypeError(
                f"shard: expected a pair (i, n) of integers, got {type(shard).__name__}"
            ) from None
        i, n = _count("shard", i, 0), _count("shard", n, 1)
        if i >= n:
            raise ValueError(f"shard = ({i}, {n}) is out of range: expected 0 <= i < n")
        shard = (i, n)
    return SweepResult(
        _snowroll.sweep(
            _grid(grid),
            shard=shard,
            method=_text("method", method),
            max_memory=_count("max_memory", max_memory),
        )
    )


@_suggesting
def sweep_chunks(
    grid: Mapping[str, Any],
    *,
    rows: int = 100_000,
    method: str = "auto",
) -> Iterator[SweepResult]:
    """The rows of :func:`sweep` a chunk at a time, for grids too large to
    hold at once: yields one :class:`SweepResult` per shard of about ``rows``
    rows, in grid order (``SweepResult.concat`` of them all is the whole
    sweep, bit for bit). Memory stays that of one chunk; stop iterating to
    stop the sweep. Write each chunk out (``.to_pandas().to_parquet(...)``)
    as it comes.
    """
    per = _count("rows", rows, 1)
    total = _snowroll.grid_len(_grid(grid))
    shards = max(1, -(-total // per))
    for i in range(shards):
        yield sweep(grid, shard=(i, shards), method=method)


# The largest count the library takes (a u64).
_COUNT_MAX = 2**64 - 1


def _axis(key: str, value: Any) -> Any:
    """A sweep axis's values, checked as :func:`simulate` checks a number:
    a string (``"a,b,c"``, ``"start:end:count"``), a real number, or a
    sequence or array of them. ``TypeError`` naming the axis for anything
    else: a bool, a complex number, an array of bools or complex numbers
    (numpy would make them 1.0 and 0.0, or drop the imaginary part)."""
    if isinstance(value, str):
        return value
    if isinstance(value, _np.ndarray):
        if value.dtype.kind not in "iuf":
            raise TypeError(f"{key}: expected numbers, got an array of {value.dtype}")
        if value.ndim == 0:
            return _number(key, value[()])
        if value.ndim != 1:
            raise TypeError(f"{key}: expected a 1-D array, got {value.ndim} dimensions")
        # As float64, each value rounded as float() rounds it: the native
        # module reads the array's buffer at once (no Python float a value).
        return _np.asarray(value, dtype=_np.float64)
    if isinstance(value, (bool, _np.bool_)) or not hasattr(value, "__iter__"):
        return _number(key, value)
    return [_number(key, v) for v in value]


def _grid(grid: Mapping[str, Any]) -> Dict[str, Any]:
    """A sweep's grid with every axis checked by :func:`_axis`; an unknown
    key is a ``ValueError`` naming the nearest known one."""
    if not isinstance(grid, Mapping):
        raise TypeError(f"grid: expected a dict, got {type(grid).__name__}")
    keys = ["model", "collision", "on_hop", *_snowroll.SWEEP_AXES]
    out = {}
    for key, value in grid.items():
        if not isinstance(key, str):
            raise TypeError(f"grid: a key is a str, got {type(key).__name__}")
        if key not in keys:
            near = _nearest(key, keys)
            hint = f"; a similar key exists: {near!r}" if near else ""
            raise ValueError(
                f"unknown axis {key!r}: expected model, collision, on_hop or one of "
                f"{', '.join(_snowroll.SWEEP_AXES)}{hint}"
            )
        out[key] = value if key in ("model", "collision", "on_hop") else _axis(key, value)
    return out


def _number(name: str, value: Any) -> Optional[float]:
    """``None``, or ``value`` (any real number: int, float, numpy scalar) as a
    float, rounded as the native module would round it; ``TypeError`` naming
    the keyword for anything else (a ``str`` is not read as a number)."""
    kind = type(value)
    if kind is float:
        return value
    if value is None:
        return None
    if kind is not int and (isinstance(value, bool) or not isinstance(value, _numbers.Real)):
        raise TypeError(f"{name}: expected a number, got {type(value).__name__}")
    try:
        return float(value)
    except OverflowError:
        raise ValueError(f"{name} = {value} is out of range: expected a finite number") from None


def _numbers_list(name: str, value: Any) -> Optional[List[float]]:
    """``None``, or a sequence of real numbers as a list of floats."""
    if value is None:
        return None
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise TypeError(f"{name}: expected a sequence of numbers, got {type(value).__name__}")
    return [_number(name, v) for v in value]


def _count(name: str, value: Any, lowest: int = 1) -> Optional[int]:
    """``None``, or an integer from ``lowest`` to 2^64 - 1 (the native
    module's u64): ``TypeError`` for a non-integer, ``ValueError`` naming
    the keyword and its range for an integer outside it."""
    if value is None:
        return None
    if type(value) is int:
        n = value
    elif isinstance(value, bool) or not isinstance(value, _numbers.Integral):
        raise TypeError(f"{name}: expected an integer, got {type(value).__name__}")
    else:
        n = int(value)
    if not lowest <= n <= _COUNT_MAX:
        raise ValueError(
            f"{name} = {n} is out of range: expected an integer {lowest} <= {name} <= 2^64 - 1"
        )
    return n


def _text(name: str, value: Any) -> Optional[str]:
    """``None``, or a ``str``; ``TypeError`` naming the keyword otherwise."""
    if value is None or isinstance(value, str):
        return value
    raise TypeError(f"{name}: expected a str, got {type(value).__name__}")


def _number_or_text(name: str, value: Any) -> Any:
    """``None``, a ``str`` (the word the parameter takes besides a number,
    ``chord`` for ``swath_width``; the native module refuses any other) or a
    finite number, as :func:`_number` checks it."""
    if isinstance(value, str):
        return value
    return _number(name, value)


def _flag(name: str, value: Any) -> bool:
    """A bool (Python's or numpy's); ``TypeError`` naming the keyword otherwise."""
    if isinstance(value, (bool, _np.bool_)):
        return bool(value)
    raise TypeError(f"{name}: expected True or False, got {type(value).__name__}")


# The parameter table of the library (`snowroll::params`), one dict per
# parameter: the keywords of simulate() and turns(), their checks, their
# signatures and the parameter sections of their docstrings all come from it.
PARAMS: List[Dict[str, Any]] = _snowroll.PARAMS
_PARAM = {p["key"]: p for p in PARAMS}

# How a keyword of each kind is checked before the native module sees it.
_CHECK_OF_KIND = {
    "real": _number,
    "optional_real": _number,
    "optional_real_or": _number_or_text,
    "count": _count,
    "optional_count": _count,
    "flag": _flag,
    "choice": _text,
    "reals": _numbers_list,
    "text": _text,
}

# The Python type of a keyword of each kind, for signatures and the stub.
_TYPE_OF_KIND = {
    "real": "Optional[float]",
    "optional_real": "Optional[float]",
    "optional_real_or": "Optional[Union[float, str]]",
    "count": "Optional[int]",
    "optional_count": "Optional[int]",
    "flag": "bool",
    "choice": "Optional[str]",
    "reals": "Optional[Sequence[float]]",
    "text": "Optional[str]",
}

# The table's scopes each function takes.
_SCOPES = {"simulate": ("shared", "sampling", "turns"), "turns": ("turns", "shared"), "fit": ("shared",)}


def _keywords(function: str) -> List[Dict[str, Any]]:
    """The table's parameters that ``function`` takes, in its keyword order:
    for turns() the turn count first, as its main setting; for models() the
    scenario and the losses (the flags of ``snowroll models``)."""
    if function == "models":
        return [p for p in PARAMS if p["scope"] == "shared" and p["group"] in ("scenario", "losses")]
    scopes = _SCOPES[function]
    return sorted(
        (p for p in PARAMS if p["scope"] in scopes),
        key=lambda p: scopes.index(p["scope"]) if function == "turns" else 0,
    )


def _allowed(function: str) -> List[str]:
    """The keywords ``function`` takes, in its keyword order."""
    allowed = [p["key"] for p in _keywords(function)]
    if function not in ("models", "fit"):
        allowed.append("max_memory")
    return allowed


# Each function's keywords and the check of each (`max_memory` is a
# keyword of its own, so it has no check here), built once: a call looks
# its keywords up instead of sorting the table again.
# The functions that take the table's keywords (``fit`` in ``_fit.py``).
_FUNCTIONS = ("simulate", "turns", "models", "fit")
_ALLOWED = {f: _allowed(f) for f in _FUNCTIONS}
_CHECKS = {f: {p["key"]: _CHECK_OF_KIND[p["kind"]] for p in _keywords(f)} for f in _FUNCTIONS}


# Each function's keywords of a real kind, and of the list kind: a float
# or an int given to one of them, or a list of floats and ints, is converted
# here as `_number` would convert it, without a call (a call per keyword was
# most of what this wrapper added to a call).
_REALS = {
    f: {k for k, check in checks.items() if check in (_number, _number_or_text)}
    for f, checks in _CHECKS.items()
}
_LISTS = {f: {k for k, check in checks.items() if check is _numbers_list} for f, checks in _CHECKS.items()}


def _plain_reals(values: List[Any]) -> Optional[List[float]]:
    """A list of floats and ints as floats; ``None`` when an item is of
    another type or an int too large for a float (`_number` words those)."""
    out = []
    for v in values:
        t = type(v)
        if t is float:
            out.append(v)
        elif t is int and -_FLOAT_INT_MAX <= v <= _FLOAT_INT_MAX:
            out.append(float(v))
        else:
            return None
    return out


# The largest int float() takes (beyond it, OverflowError).
_FLOAT_INT_MAX = int(_sys.float_info.max)


def _checked(function: str, params: Dict[str, Any]) -> Dict[str, Any]:
    """The keywords of ``function``, each checked and converted by its kind,
    in place (``params`` is the call's own ``**params``): an unknown keyword
    or a wrong type raises ``TypeError`` and an out-of-range count
    ``ValueError``, each naming the keyword (the native module would raise
    ``TypeError`` or ``OverflowError`` without it)."""
    checks = _CHECKS[function]
    reals = _REALS[function]
    lists = _LISTS[function]
    for k, v in params.items():
        t = type(v)
        if t is float and k in reals:
            continue
        if t is int and k in reals and -_FLOAT_INT_MAX <= v <= _FLOAT_INT_MAX:
            params[k] = float(v)
            continue
        if t is list and k in lists:
            plain = _plain_reals(v)
            if plain is not None:
                params[k] = plain
                continue
        check = checks.get(k)
        if check is None:
            raise TypeError(_unexpected(function, k, _ALLOWED[function]))
        params[k] = check(k, v)
    return params


def _param_doc(function: str) -> str:
    """The docstring section listing the keywords of ``function`` from the
    table: name, unit, help line with its range, default."""
    lines = ["", "    Keywords (from the parameter table ``snowroll.PARAMS``; ``None`` = the default):", ""]
    for p in _keywords(function):
        unit = f" [{p['unit']}]" if p["unit"] else ""
        applies = "" if p["applies"] == "all" else f"; {p['applies']} only"
        lines.append(f"    ``{p['key']}``{unit}: {p['help']} (default {p['default_text']}{applies}).")
    return "\n".join(lines) + "\n"


def _signature(function: str, model_default: str) -> _inspect.Signature:
    """The signature of ``function``: the model, then its keywords from the table."""
    P = _inspect.Parameter
    params = [
        P("model", P.POSITIONAL_OR_KEYWORD, default=model_default, annotation="Union[str, Sequence[str]]")
    ]
    for p in _keywords(function):
        default = False if p["kind"] == "flag" else None
        params.append(P(p["key"], P.KEYWORD_ONLY, default=default, annotation=_TYPE_OF_KIND[p["kind"]]))
    params.append(P("max_memory", P.KEYWORD_ONLY, default=MAX_MEMORY, annotation=int))
    return _inspect.Signature(params)


def _warn(messages: Sequence[str]) -> None:
    for m in messages:
        _warnings.warn(m, RuntimeWarning, stacklevel=3)


def _is_model_list(model: Any) -> bool:
    """Whether ``model`` asks for several models: a list or tuple of ids
    (each checked as one model is), not empty."""
    if isinstance(model, (list, tuple)):
        if not model:
            raise ValueError("model: an empty list; give one model id or a list of them")
        return True
    return False


def simulate(
    model: Union[str, Sequence[str]] = "torque-cm", *, max_memory: int = MAX_MEMORY, **params: Any
) -> Union[Result, "Results"]:
    """Integrate one model for one scenario (the CLI's ``snowroll simulate``).

    ``model``: an id or equation alias from :func:`models` (case-insensitive):
    ``"snowless"`` (eq95), ``"torque-cm"`` (eq4, torque about the centre of
    mass), ``"torque-contact"`` (eq6), ``"energy"`` (eq14), ``"energy-thin"``
    (eq15), ``"lagrangian-printed"`` (eq21), ``"quasi-circular"`` (eq32),
    ``"quasi-circular-lift"`` (eq32+36), ``"loney"`` (fn4, closed form),
    ``"turns"`` (eq73: eqs. (73), (76), (89)), ``"turns-exact"`` (eq88).

    The radius grows as r(x) = sqrt(r0^2 + b x / pi), eq. (8). The turn
    models take no losses (``ValueError``; their per-turn extremes rest on
    the energy integral of a turn, §2.1) but take ``ledger``, which adds the
    energy-ledger columns; a run with losses always has them. Rows: every
    accepted step by default, else ``times`` or a ``dt`` grid. A run whose
    row count is known beforehand and above ``max_rows`` raises
    ``ValueError`` before it starts; one that reaches ``max_rows`` or
    ``max_steps`` stops there (``row-limit``, ``step-limit``), its rows kept.
    With drag on the snowless log, ``r.stop["v_terminal_m_s"]`` is the
    closed-form v_t^2 = 2 M g sin alpha/(rho_a C_d A).

    Returns a :class:`Result`: columns as numpy arrays (``r.v_m_s`` or
    ``r["v_m_s"]``), ``r.stop``, ``r.params``, ``r.version``, ``r.to_pandas()``,
    ``r.plot()``. A list of models (``model=["eq4", "eq6"]``) runs each on
    the same keywords and returns :class:`Results`, one :class:`Result` per
    model in that order (``.plot()``: one figure, a curve per model).
    Validity warnings of the model (b/r0 beyond its range) are issued as
    ``RuntimeWarning`` and kept in ``r.warnings``.

    ``max_memory``: the most bytes the result may hold (default
    :data:`MAX_MEMORY`, 2 GiB): a run whose rows would not fit raises
    ``MemoryError``, before it starts where its row count is known (``dt``,
    ``times``). Ctrl-C stops it within about a second (``KeyboardInterrupt``).

    Raises ``ValueError`` for bad parameters (the library's message) and
    ``RuntimeError`` when the integration fails.
    """
    if type(model) is not str:
        if _is_model_list(model):
            return Results(simulate(m, max_memory=max_memory, **params) for m in model)
        model = _text("model", model)
    if max_memory is not MAX_MEMORY:
        max_memory = _count("max_memory", max_memory)
    raw = _snowroll.simulate(model, max_memory=max_memory, **_checked("simulate", params))
    result = Result(raw)
    if result.warnings:
        _warn(result.warnings)
    return result


def turns(
    model: Union[str, Sequence[str]] = "turns", *, max_memory: int = MAX_MEMORY, **params: Any
) -> Union[TurnResult, "Results"]:
    """Run a turn model of the note's §3 for ``turns`` full turns (default 100);
    one row per turn (the CLI's ``snowroll turns``).

    ``model``: ``"turns"`` (the note's eqs. (73), (76), alias ``eq73``) or
    ``"turns-exact"`` (exact geometry, eq. (88), alias ``eq88``). Each turn
    integrates eq. (64); at its end the log climbs the new layer by the
    collision ``collision`` (``"note"``: eq. (89)). ``t_end`` defaults to 1e9 s,
    so the turn count ends the run. Other keywords as in :func:`simulate`;
    ``max_rows`` below the turn count raises ``ValueError``. The turn models
    take the log only: ``shape="sphere"`` raises ``ValueError`` (a ball that
    picks up a swath in one turn gains a band round its equator, not a shell;
    docs/snowball-and-losses.md §1.2).

    Losses and ledger: the keywords of :func:`simulate`, same names. The turn
    models take no losses: a loss above 0 raises ``ValueError`` (a turn's
    slip, smallest normal force and range of a come from its energy
    integral, which losses break; docs/snowball-and-losses.md §3.2).
    ``ledger=True`` adds per turn the energy ledger at the end of the turn,
    just before its collision (``collision_j`` the kinetic energy the
    earlier collisions removed, ``created_j`` what the note's eq. (89)
    created by lifting the log by b for free).

    A list of models (``model=["turns", "turns-exact"]``) returns
    :class:`Results`, one :class:`TurnResult` each.

    Returns a :class:`TurnResult`: one numpy array per column and ``summary``,
    the long-run means of a/(g sin alpha) whose value the note's
    eqs. (77)-(79) estimate as 4/9.

    ``max_memory``: the most bytes the result may hold (default
    :data:`MAX_MEMORY`, 2 GiB; a turn holds about 300 bytes): more turns
    than fit raise ``MemoryError`` before the run starts. Ctrl-C stops it
    within about a second (``KeyboardInterrupt``).

    Raises ``ValueError`` for bad parameters or a model that is not a turn
    model, ``RuntimeError`` when the integration fails.
    """
    if type(model) is not str:
        if _is_model_list(model):
            return Results(turns(m, max_memory=max_memory, **params) for m in model)
        model = _text("model", model)
    if max_memory is not MAX_MEMORY:
        max_memory = _count("max_memory", max_memory)
    raw = _snowroll.turns(model, max_memory=max_memory, **_checked("turns", params))
    result = TurnResult(raw)
    if result.warnings:
        _warn(result.warnings)
    return result


for _f, _model in ((simulate, "torque-cm"), (turns, "turns")):
    _f.__doc__ = (_f.__doc__ or "") + _param_doc(_f.__name__)
    _f.__signature__ = _signature(_f.__name__, _model)  # type: ignore[attr-defined]


def models(**params: Any) -> List[Dict[str, Any]]:
    """Every model (the CLI's ``snowroll models``), one dict each.

    Keys: ``id``, ``alias`` (e.g. ``eq4``), ``equation`` (the note's equation
    number), ``description``, ``terminal_fraction`` (late-time acceleration
    over g sin alpha, e.g. 2/3 for eq. (4) with no snow, or ``None``),
    ``stall_slope_deg`` (the slope below which the model started from rest
    does not roll on, fn. 7, for the body, snow and losses of the keywords,
    by default the log of the default scenario without losses; ``None`` when
    it always rolls, or does not take that body or those losses: the turn
    models take the log only, and no losses), ``stall_kind``
    (``"does-not-start"`` or ``"stalls-in-first-turn"``), ``validity``
    (order in b/r kept, largest b/r0 without a warning, statement).
    """
    return _snowroll.models(**_checked("models", params))


models.__doc__ = (models.__doc__ or "") + _param_doc("models")
models.__signature__ = _inspect.Signature(  # type: ignore[attr-defined]
    [
        _inspect.Parameter(
            p["key"],
            _inspect.Parameter.KEYWORD_ONLY,
            default=False if p["kind"] == "flag" else None,
            annotation=_TYPE_OF_KIND[p["kind"]],
        )
        for p in _keywords("models")
    ]
)


# `snowroll.dask.sweep`: a sweep as a dask.dataframe (imports dask only when
# called). Last, since it uses the functions above.
from . import dask  # noqa: E402


from ._fit import FitResult, fit  # noqa: E402  (uses the helpers above)
