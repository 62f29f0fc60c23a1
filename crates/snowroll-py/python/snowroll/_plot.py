"""``result.plot()``: the panels of the CLI's ``--plot`` (issue 22), drawn
with matplotlib, which is imported only here and only when a plot is asked
for (it is not a dependency of the package).

A trajectory (:class:`snowroll.Result`, or several of one scenario from
``simulate(model=[...])``): a/(g sin alpha), v and x against t; N and |F|/N;
for each run that recorded the energy ledger, its terms as shares of the
potential energy released. A turn table (:class:`snowroll.TurnResult`):
per turn the mean acceleration in the turn and with its collision and the
least and greatest acceleration, over g sin alpha (one colour per model,
one dash per quantity); the speed at each turn's start; the least
N/(M g) of each turn. One curve per model in each panel; the legend to the
right of each panel, outside the data, as in the report.
"""

from __future__ import annotations

import math
from typing import Any, Callable, List, Sequence, Tuple

import numpy as _np

# The ledger terms the report draws (its `loss_figures.rs`), in its order:
# column, legend entry, sign in the balance.
_LEDGER_TERMS: List[Tuple[str, str, float]] = [
    ("kinetic_j", "kinetic energy", 1.0),
    ("drag_j", "air drag", 1.0),
    ("rolling_j", "rolling resistance", 1.0),
    ("compaction_j", "compaction", 1.0),
    ("model_j", "snow pick-up (W_model)", 1.0),
]
# The turn models' terms, drawn when not zero.
_COLLISION_TERMS: List[Tuple[str, str, float]] = [
    ("collision_j", "collisions", 1.0),
    ("created_j", "created by the collisions (-)", -1.0),
]

# Per-turn accelerations: column, legend entry, line style.
_TURN_ACCELERATIONS = [
    ("mean_a_turn_m_s2", "mean in the turn", "-"),
    ("mean_a_with_collision_m_s2", "mean with its collision", "--"),
    ("min_a_m_s2", "least in the turn", ":"),
    ("max_a_m_s2", "greatest in the turn", "-."),
]

# Height of one panel, inches (the CLI's panels are 960 x 600 px).
_PANEL_HEIGHT = 3.6
_FIGURE_WIDTH = 9.6


def _pyplot() -> Any:
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError(
            "plot() needs matplotlib, which snowroll does not install: pip install matplotlib"
        ) from e
    return plt


def _g_along(r: Any) -> float:
    """g sin alpha of the run's scenario, m/s^2."""
    return r.params["g"] * math.sin(math.radians(r.params["alpha_deg"]))


def _legend_outside(ax: Any) -> None:
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize="small")


def _panels(n: int) -> Tuple[Any, List[Any]]:
    plt = _pyplot()
    fig, axes = plt.subplots(n, 1, figsize=(_FIGURE_WIDTH, _PANEL_HEIGHT * n), squeeze=False)
    return fig, [a for a in axes[:, 0]]


def plot_runs(runs: Sequence[Any]) -> Any:
    """The figure of the trajectories ``runs`` (one scenario): see the
    module's documentation. Returns the ``matplotlib.figure.Figure``."""
    panels: List[Tuple[str, str, Callable[[Any], Any]]] = [
        ("Acceleration over g sin α", "a/(g sin α)", lambda r: r.a_m_s2 / _g_along(r)),
        ("Speed down the slope", "speed v [m/s]", lambda r: r.v_m_s),
        ("Distance rolled", "distance x [m]", lambda r: r.x_m),
        ("Normal force of the slope", "normal force N [N]", lambda r: r.normal_n),
        ("Friction that rolling without slipping needs", "|F|/N", lambda r: r.friction_ratio),
    ]
    ledgers = [r for r in runs if "released_j" in r]
    fig, axes = _panels(len(panels) + len(ledgers))
    for ax, (title, label, y) in zip(axes, panels):
        for r in runs:
            ax.plot(r.t_s, y(r), label=r.model)
        ax.set_title(title)
        ax.set_xlabel("time t [s]")
        ax.set_ylabel(label)
        _legend_outside(ax)
    for ax, r in zip(axes[len(panels):], ledgers):
        _ledger_panel(ax, r)
    fig.tight_layout()
    return fig


def _ledger_panel(ax: Any, r: Any) -> None:
    """The ledger of run ``r`` as shares of the released energy against
    time, where some energy was released, and their sum (markers)."""
    keep = r.released_j > 0.0
    t, released = r.t_s[keep], r.released_j[keep]
    terms = list(_LEDGER_TERMS)
    terms += [c for c in _COLLISION_TERMS if _np.any(r[c[0]] != 0.0)]
    total = _np.zeros_like(released)
    for column, name, sign in terms:
        share = sign * r[column][keep] / released
        total = total + share
        ax.plot(t, share, label=name)
    ax.plot(t, total, "o", markersize=3, label="sum of the shares")
    ax.set_title(f"Where the released energy goes: {r.model}")
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("share of the potential energy released")
    _legend_outside(ax)


def plot_turns(runs: Sequence[Any]) -> Any:
    """The figure of the turn tables ``runs`` (one scenario): see the
    module's documentation. Returns the ``matplotlib.figure.Figure``."""
    fig, (means, speeds, normals) = _panels(3)
    for i, r in enumerate(runs):
        colour = f"C{i}"
        for column, what, style in _TURN_ACCELERATIONS:
            means.plot(r.turn, r[column] / _g_along(r), style, color=colour, label=f"{r.model}: {what}")
        speeds.plot(r.turn, r.v_start_m_s, color=colour, label=r.model)
        normals.plot(r.turn, r.min_normal_over_mg, color=colour, label=r.model)
    for ax, title, label in (
        (means, "Acceleration per turn, over g sin α", "a/(g sin α)"),
        (speeds, "Speed at the start of each turn", "speed v at the turn's start [m/s]"),
        (normals, "Least normal force of each turn", "least N/(M g) in the turn"),
    ):
        ax.set_title(title)
        ax.set_xlabel("turn k")
        ax.set_ylabel(label)
        _legend_outside(ax)
    fig.tight_layout()
    return fig
