"""The Result object, the package surface, and two closed forms that pin the
columns to their physical meaning."""

import math

import numpy as np
import pytest

import snowroll


def test_columns_by_attribute_and_key():
    r = snowroll.simulate("torque-cm", t_end=5)
    assert r.columns[:4] == ["t_s", "x_m", "v_m_s", "a_m_s2"]
    for name in r.columns:
        assert r[name] is getattr(r, name)
        assert isinstance(r[name], np.ndarray) and r[name].dtype == np.float64
        assert len(r[name]) == len(r)
    assert "v_m_s" in r and "turn" not in r
    assert r.stop["reason"] == "end-time" and r.stop["t_s"] == 5
    assert r.params["alpha_deg"] == 30 and r.params["x_end"] is None
    assert r.version == snowroll.__version__
    with pytest.raises(AttributeError, match="no attribute or column"):
        r.no_such_column
    with pytest.raises(KeyError):
        r["no_such_column"]


def test_turn_models_have_turn_columns():
    r = snowroll.simulate("turns", turns=3)
    assert r.columns[-3:] == ["turn", "theta_rad", "omega_rad_s"]
    assert r.turn.dtype == np.uint64
    assert r.stop["reason"] == "turns" and r.stop["turn"] == 2


def test_snowless_acceleration_is_two_thirds_g_sin_alpha():
    """A solid cylinder rolling without slipping: a = (2/3) g sin alpha (App. A).
    Tolerance 1e-12 relative: a few roundings of g sin alpha times 2/3."""
    alpha, g = 35.0, 9.81
    r = snowroll.simulate("snowless", alpha_deg=alpha, snow_depth=0, g=g, dt=0.5, t_end=3)
    expected = 2.0 / 3.0 * g * math.sin(math.radians(alpha))
    assert np.allclose(r.a_m_s2, expected, rtol=1e-12, atol=0)
    assert np.allclose(r.v_m_s, expected * r.t_s, rtol=1e-12, atol=1e-15)


def test_radius_follows_eq_8():
    """r(x) = sqrt(r0^2 + b x / pi), eq. (8), along a snowy trajectory; the
    same formula evaluated here in numpy, so agreement to 1e-12 relative
    (rounding of a square root and a few products)."""
    b, r0 = 0.01, 0.12
    r = snowroll.simulate("energy", snow_depth=b, r0=r0, t_end=10)
    assert np.allclose(r.r_m, np.sqrt(r0**2 + b * r.x_m / math.pi), rtol=1e-12, atol=0)


def test_requested_times():
    ts = [0.0, 0.5, 2.0, 4.0]
    r = snowroll.simulate(times=np.array(ts), t_end=10)
    assert r.t_s.tolist() == ts
    assert r.params["times"] == ts


def test_models_listing():
    listed = snowroll.models()
    ids = [m["id"] for m in listed]
    assert "torque-cm" in ids and "turns-exact" in ids
    torque = next(m for m in listed if m["id"] == "torque-cm")
    assert torque["alias"] == "eq4" and torque["equation"] == "eq. (4)"
    with pytest.raises(ValueError):
        snowroll.models(r0=-1)


# The ball's stall slope of eq. (14) from its closed form to the float's
# last bits: both are one arctangent of the same sum.
BALL_STALL_TOL = 1e-12


@pytest.mark.parametrize("b, r0", [(0.01, 0.1), (0.03, 0.2), (0.002, 0.05)])
def test_models_stall_slope_of_the_ball_is_the_closed_form(b, r0):
    """Issue 22: models() takes the body keywords. The energy model's ball
    (swath 2r) does not start below tan a* = 2b/(pi r0) + 3b^2/(4 pi r0^2);
    the log of the same b, r0 has another threshold."""
    want = math.degrees(math.atan(2 * b / (math.pi * r0) + 3 * b * b / (4 * math.pi * r0 * r0)))
    ball = {m["id"]: m for m in snowroll.models(shape="sphere", snow_depth=b, r0=r0)}
    log = {m["id"]: m for m in snowroll.models(snow_depth=b, r0=r0)}
    assert ball["energy"]["stall_slope_deg"] == pytest.approx(want, rel=BALL_STALL_TOL)
    assert log["energy"]["stall_slope_deg"] != pytest.approx(want, rel=1e-3)
    # The turn models take the log only: no stall slope for a ball.
    assert ball["turns"]["stall_slope_deg"] is None
    assert log["turns"]["stall_slope_deg"] is not None


def test_models_takes_the_losses_and_refuses_other_keywords():
    """Rolling resistance raises every circular model's stall slope; the
    turn models take no losses, so they list none; a run keyword (t_end) or
    an unknown one is a TypeError naming it."""
    plain = {m["id"]: m for m in snowroll.models()}
    lossy = {m["id"]: m for m in snowroll.models(rolling_resistance=0.05)}
    assert lossy["energy"]["stall_slope_deg"] > plain["energy"]["stall_slope_deg"]
    assert lossy["turns"]["stall_slope_deg"] is None
    for bad in ({"t_end": 5.0}, {"slope": 3.0}):
        with pytest.raises(TypeError, match=next(iter(bad))):
            snowroll.models(**bad)
    with pytest.raises(TypeError, match="shape"):
        snowroll.models(shape=3)


def test_turns_summary():
    t = snowroll.turns(turns=20)
    assert len(t) == 20 and t.turn.tolist() == list(range(20))
    assert t.summary["turns"] == 20
    # Turn k+1 starts where turn k ends: contact position advances by 2 pi r_k.
    assert np.all(np.diff(t.x_start_m) > 0)
    assert np.array_equal(t.t_start_s[1:], t.t_end_s[:-1])


def test_help_cites_the_note():
    doc = snowroll.simulate.__doc__
    assert "eq. (8)" in doc and "alpha_deg" in doc and "ValueError" in doc
    assert "eqs. (77)-(79)" in snowroll.turns.__doc__


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    r = snowroll.simulate(t_end=2)
    frame = r.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == r.columns
    assert np.array_equal(frame["v_m_s"].to_numpy(), r.v_m_s)


def test_validity_warning_is_issued():
    with pytest.warns(RuntimeWarning, match="snowless ignores the snow"):
        r = snowroll.simulate("snowless", t_end=1)
    assert r.warnings


def test_on_hop_and_undefined_friction_ratio():
    """fn. 10: at 80 degrees the turn model loses contact in its second turn
    (docs/contact-forces.md section 4.4). By default the run stops there with
    `hop`; with on_hop="continue" it goes on, and |F|/N is masked exactly
    where N <= 0 (undefined), never NaN or infinite; elsewhere it is |F|/N of
    the same row, to the bit (the same division)."""
    stopped = snowroll.simulate("turns", alpha_deg=80, turns=4, dt=0.01)
    assert stopped.stop["reason"] == "hop" and stopped.stop["turn"] == 1
    r = snowroll.simulate("turns", alpha_deg=80, turns=4, dt=0.01, on_hop="continue")
    assert r.stop["reason"] == "turns" and r.params["on_hop"] == "continue"
    ratio = r.friction_ratio
    assert isinstance(ratio, np.ma.MaskedArray)
    off = r.normal_n <= 0
    assert off.any() and not off.all()
    assert np.array_equal(np.ma.getmaskarray(ratio), off)
    assert np.all(np.isfinite(np.ma.getdata(ratio)))
    on = ~off
    assert np.array_equal(ratio[on].data, np.abs(r.friction_n[on]) / r.normal_n[on])
    t = snowroll.turns(alpha_deg=80, turns=4, on_hop="continue")
    assert np.array_equal(np.ma.getmaskarray(t.max_friction_ratio), t.min_normal_n <= 0)
    assert np.all(np.isfinite(np.ma.getdata(t.max_friction_ratio)))
    pd = pytest.importorskip("pandas")
    frame = r.to_pandas()
    assert frame["friction_ratio"].isna().sum() == off.sum()
    assert not np.isnan(frame["friction_ratio"].dropna().to_numpy(dtype=float)).any()
    assert isinstance(frame, pd.DataFrame)
def test_shape_sphere_keyword_rolls_a_ball():
    """issue 11: ``shape="sphere"`` makes a uniform ball, I = 2/5 M r^2, so the
    snowless ball accelerates at (5/7) g sin alpha; its mass is 4/3 pi rho r0^3.
    Tolerance 1e-12 relative: a few roundings of quantities of order one."""
    alpha, g = 30.0, 9.81
    r = snowroll.simulate("snowless", shape="sphere", snow_depth=0, alpha_deg=alpha, dt=0.5, t_end=2)
    want = 5.0 / 7.0 * g * math.sin(math.radians(alpha))
    assert np.allclose(r.a_m_s2, want, rtol=1e-12, atol=0)
    assert np.allclose(r.mass_kg, 4.0 / 3.0 * math.pi * 400 * 0.1**3, rtol=1e-12, atol=0)
    assert r.params["shape"] == "sphere" and "swath_width" not in r.params
    w = snowroll.simulate("torque-cm", shape="sphere", swath_width=0.05, t_end=1)
    assert w.params["swath_width"] == 0.05
    # issue 21: the contact chord, as the word; the run is the CLI's, and
    # mass_kg is (4/3) pi rho r^3 of its own radius column (1e-12: roundings).
    c = snowroll.simulate("torque-cm", shape="sphere", swath_width="chord", t_end=1, dt=0.5)
    assert c.params["swath_width"] == "chord"
    assert np.allclose(c.mass_kg, 4.0 / 3.0 * math.pi * 400 * c.r_m**3, rtol=1e-12, atol=0)
    with pytest.raises(ValueError, match="a number or chord"):
        snowroll.simulate("torque-cm", shape="sphere", swath_width="cord")


def test_shape_errors_name_the_problem():
    with pytest.raises(ValueError, match="swath width"):
        snowroll.simulate("torque-cm", swath_width=0.1)
    with pytest.raises(ValueError, match="unknown shape"):
        snowroll.simulate("torque-cm", shape="cube")
    with pytest.raises(ValueError, match="does not support shape = sphere"):
        snowroll.simulate("turns", shape="sphere", turns=2)


def test_losses_keywords_terminal_velocity_and_ledger():
    """Issue 11: the snowless log with drag stops at the closed-form terminal
    velocity v_t^2 = M g sin(alpha) / (0.5 rho_a C_d 2 r0 l) (defaults: 22.664 m/s);
    |1 - v/v_t| <= tol/2 at the stop, plus the integration error (~1e-10)."""
    with pytest.warns(RuntimeWarning):
        r = snowroll.simulate("snowless", drag_coefficient=1.0, air_density=1.2, terminal_tol=1e-10, t_end=1e4)
    assert r.stop["reason"] == "terminal"
    m = math.pi * 400 * 0.1**2
    vt = math.sqrt(m * 9.81 * math.sin(math.radians(30)) / (0.5 * 1.2 * 1.0 * 2 * 0.1))
    assert abs(r.stop["v_m_s"] / vt - 1) < 1e-9
    assert abs(r.stop["v_terminal_m_s"] / vt - 1) < 1e-14
    assert r.params["drag_coefficient"] == 1.0
    # The ledger sums to the initial energy (zero from rest) within 1e-8 of its largest term.
    r = snowroll.simulate("energy", rolling_resistance=0.02, compaction_energy=2.0, t_end=20)
    total = r.kinetic_j + r.drag_j + r.rolling_j + r.compaction_j + r.model_j - r.released_j
    assert np.all(np.abs(total) <= 1e-8 * np.maximum(r.released_j, 1.0))
    assert np.allclose(r.compaction_j, 2.0 * (r.mass_kg - r.mass_kg[0]), rtol=1e-9, atol=1e-9)
    with pytest.raises(ValueError, match="rolling_resistance"):
        snowroll.simulate(rolling_resistance=-1)
