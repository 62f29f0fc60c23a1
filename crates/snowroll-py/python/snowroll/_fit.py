"""``snowroll.fit``: the models fitted to a measured x(t), as the CLI's
``snowroll fit`` fits them (the same library code, the same records).

>>> import numpy as np, snowroll
>>> t = np.linspace(0.1, 3.0, 60)
>>> x = snowroll.simulate("energy", alpha_deg=30, snow_depth=0.01, times=t, t_end=3.0).x_m
>>> f = snowroll.fit(t, x, models=["energy", "torque-cm"], free=["snow_depth"], t0=0, x0=0,
...                  alpha_deg=30)
>>> f.best["model"], round(f.best["params"]["snow_depth"]["value"], 6)
('energy', 0.01)
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence

import numpy as _np


class FitResult:
    """What :func:`snowroll.fit` returns: ``fits``, a list of dicts sorted by
    rank (1 = best: converged fits first, then by AIC), each with ``model``,
    ``equation``, ``params`` (``{KEY: {"value", "stderr", "unit",
    "start"}}``, ``stderr`` ``None`` for a parameter the data do not fix),
    ``correlations``, ``unseparated`` (combinations the data cannot
    separate, named), ``rms_m``, ``aic``, ``bic``, ``rank``, ``converged``,
    ``reason``, ``iterations``, ``residuals_m`` (numpy), ``curve_t_s`` and
    ``curve_x_m`` (the fitted x(t) on a fine grid, numpy); ``t_s`` and
    ``x_m``, the data; ``free``; ``skipped`` (models that cannot run the
    scenario, with the reason); ``version``."""

    def __init__(self, raw: Dict[str, Any]) -> None:
        self.fits: List[Dict[str, Any]] = raw["fits"]
        for f in self.fits:
            for key in ("residuals_m", "curve_t_s", "curve_x_m"):
                f[key] = _np.asarray(f[key], dtype=float)
        self.t_s = _np.asarray(raw["t_s"], dtype=float)
        self.x_m = _np.asarray(raw["x_m"], dtype=float)
        self.free: List[str] = raw["free"]
        self.skipped: List[Any] = raw["skipped"]
        self.version: str = raw["version"]

    @property
    def best(self) -> Dict[str, Any]:
        """The fit ranked first."""
        return self.fits[0]

    def __repr__(self) -> str:
        ranking = ", ".join(f"{f['rank']}. {f['model']} ({f['rms_m']:.3g} m)" for f in self.fits)
        return f"<snowroll.FitResult {len(self.t_s)} points, free {self.free}: {ranking}>"

    def to_pandas(self) -> Any:
        """One row per model, in rank order: ``model``, ``rank``, ``rms_m``,
        ``aic``, ``bic``, ``converged``, then ``KEY`` and ``KEY_stderr`` for
        each free parameter (``NaN`` where the data do not fix it). Needs
        pandas, not a dependency."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        rows = []
        for f in self.fits:
            row: Dict[str, Any] = {k: f[k] for k in ("model", "rank", "rms_m", "aic", "bic", "converged")}
            for key, p in f["params"].items():
                row[key] = p["value"]
                row[f"{key}_stderr"] = float("nan") if p["stderr"] is None else p["stderr"]
            rows.append(row)
        frame = pd.DataFrame(rows)
        frame.attrs.update({"free": list(self.free), "version": self.version})
        return frame

    def plot(self) -> Any:
        """The data with each fitted model's x(t), and the residuals below,
        as ``snowroll fit --plot`` draws them (needs matplotlib, not a
        dependency). Returns the ``matplotlib.figure.Figure``."""
        from ._plot import _legend_outside, _panels

        fig, (top, bottom) = _panels(2)
        top.plot(self.t_s, self.x_m, "o", markersize=3, label="data")
        bottom.axhline(0.0, linestyle=":", linewidth=1)
        for f in self.fits:
            name = f"{f['rank']}. {f['model']}"
            (line,) = top.plot(f["curve_t_s"], f["curve_x_m"], label=name)
            bottom.plot(self.t_s, f["residuals_m"], ".-", color=line.get_color(), label=name)
        top.set_title("distance x: data and each fitted model")
        top.set_ylabel("distance x [m]")
        bottom.set_title("residuals: model − data")
        bottom.set_ylabel("residual [m]")
        for ax in (top, bottom):
            ax.set_xlabel("time t [s]")
            _legend_outside(ax)
        fig.tight_layout()
        return fig


def fit(
    t: Sequence[float],
    x: Sequence[float],
    *,
    models: Optional[Sequence[str]] = None,
    free: Optional[Sequence[str]] = None,
    t0: Optional[float] = None,
    x0: Optional[float] = None,
    max_iterations: Optional[int] = None,
    **params: Any,
) -> FitResult:
    """Fit the models to a measured trajectory (the CLI's ``snowroll fit``).

    ``t`` (s, increasing) and ``x`` (m, along the slope): the data, at least
    5 points, every value finite. ``models``: model ids (default: every
    model that can run the scenario). ``free``: the parameters
    fitted, any real parameter of the scenario or the losses (keys of
    :data:`snowroll.PARAMS`: ``alpha_deg``, ``snow_depth``, ``r0``, ...) and
    ``t0`` (s, the time the body is let go on the data's clock) and ``x0``
    (m, its position then); default ``["snow_depth", "t0", "x0"]``. ``t0``/``x0``:
    their start (when free) or value (default: the first data point; a free
    t0 starts at the release time of a constant acceleration). Every other
    keyword is a parameter of the scenario, as for :func:`snowroll.simulate`:
    the fixed values, and the free parameters' starts.

    Levenberg–Marquardt with finite-difference Jacobians from the models'
    own runs, each parameter kept in its range; standard errors from s²
    (JᵀJ)⁻¹; combinations the data cannot separate (eq. (4) sees r0 and b
    only through π r0²/b) are named in ``unseparated`` and their parameters
    get no standard error. Returns a :class:`FitResult`. Raises
    ``ValueError`` for bad data or parameters, ``TypeError`` for an unknown
    keyword.
    """
    from . import _checked, _snowroll

    raw = _snowroll.fit(
        [float(v) for v in t],
        [float(v) for v in x],
        models=None if models is None else [str(m) for m in models],
        free=None if free is None else [str(k) for k in free],
        t0=t0,
        x0=x0,
        max_iterations=max_iterations,
        **_checked("fit", params),
    )
    return FitResult(raw)
