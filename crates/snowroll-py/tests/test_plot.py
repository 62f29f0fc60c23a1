"""``result.plot()`` and the multi-model call (issue 22): the figure's
lines are the results' own columns, one line per model in each panel; a
list of models runs each on the same keywords. Needs matplotlib (pinned in
scripts/test-python.sh); skipped where it is not installed, except the test
of the message that names it."""

import builtins
import math

import numpy as np
import pytest

import snowroll

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")


def _lines(ax):
    """The data lines of a panel (not its legend), as (label, x, y)."""
    return [(l.get_label(), np.asarray(l.get_xdata()), np.ma.getdata(l.get_ydata())) for l in ax.lines]


def test_a_run_plots_its_own_columns():
    r = snowroll.simulate("eq4", dt=0.25, t_end=6)
    fig = r.plot()
    axes = fig.get_axes()
    # a/(g sin alpha), v, x, N, |F|/N: no ledger without losses or `ledger`.
    assert len(axes) == 5
    g_along = 9.81 * math.sin(math.radians(30))
    for ax, want in zip(axes, [r.a_m_s2 / g_along, r.v_m_s, r.x_m, r.normal_n]):
        [(label, x, y)] = _lines(ax)
        assert label == "torque-cm"
        assert np.array_equal(x, r.t_s) and np.array_equal(y, want)
        # Each legend sits right of its axes, outside the data.
        assert ax.get_legend().get_bbox_to_anchor().x0 >= ax.get_window_extent().x1
    # Eq. (4) from rest: a(0) = (2/3) g sin alpha.
    assert _lines(axes[0])[0][2][0] == pytest.approx(2 / 3, rel=1e-12)


def test_several_models_share_one_figure_a_line_each():
    models = ["eq4", "eq6", "eq14"]
    rs = snowroll.simulate(model=models, dt=0.5, t_end=5, ledger=True)
    assert isinstance(rs, snowroll.Results) and [r.model for r in rs] == ["torque-cm", "torque-contact", "energy"]
    # Each the run of its model alone, to the bit.
    alone = snowroll.simulate("eq6", dt=0.5, t_end=5, ledger=True)
    assert np.array_equal(rs[1].v_m_s, alone.v_m_s)
    fig = rs.plot()
    axes = fig.get_axes()
    # Five panels, then one ledger panel per model.
    assert len(axes) == 5 + 3
    for ax in axes[:5]:
        assert [l[0] for l in _lines(ax)] == [r.model for r in rs]
    speed = {label: y for label, _, y in _lines(axes[1])}
    for r in rs:
        assert np.array_equal(speed[r.model], r.v_m_s)
    # The ledger's shares add up to 1 (the sum's markers), to its residual.
    label, _, total = _lines(axes[5])[-1]
    assert label == "sum of the shares"
    assert np.allclose(total, 1.0, atol=1e-8)  # the ledger's residual over the released energy


def test_turns_plot_the_per_turn_means_and_extremes():
    rs = snowroll.turns(["turns", "turns-exact"], turns=20)
    fig = rs.plot()
    means, speeds, normals = fig.get_axes()
    g_along = 9.81 * math.sin(math.radians(30))
    lines = {label: (x, y) for label, x, y in _lines(means)}
    assert len(lines) == 8
    for r in rs:
        x, y = lines[f"{r.model}: greatest in the turn"]
        assert np.array_equal(x, r.turn) and np.array_equal(y, r.max_a_m_s2 / g_along)
    assert [l[0] for l in _lines(speeds)] == ["turns", "turns-exact"]
    assert np.array_equal(_lines(normals)[0][2], rs[0].min_normal_over_mg)
    # One turn result plots alone too.
    assert len(rs[0].plot().get_axes()[0].lines) == 4


def test_an_empty_model_list_is_refused():
    with pytest.raises(ValueError, match="empty list"):
        snowroll.simulate(model=[])


def test_without_matplotlib_the_message_says_how_to_install_it(monkeypatch):
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name.startswith("matplotlib"):
            raise ImportError(f"No module named {name!r}")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    with pytest.raises(ImportError, match="pip install matplotlib"):
        snowroll.simulate(t_end=1).plot()


def test_several_models_stack_in_one_frame_with_a_model_column():
    pd = pytest.importorskip("pandas")
    rs = snowroll.simulate(model=["eq4", "eq14"], times=[0.0, 1.0, 2.0])
    frame = rs.to_pandas()
    assert list(frame.columns[:2]) == ["model", "t_s"]
    assert frame["model"].tolist() == ["torque-cm"] * 3 + ["energy"] * 3
    energy = frame[frame["model"] == "energy"]
    assert np.array_equal(energy["v_m_s"].to_numpy(), rs[1].v_m_s)
    assert isinstance(frame, pd.DataFrame)
