"""Issue 13: a run from Python equals the CLI's run with the same parameters
to the last bit. Both call the same library; these tests check that the
binding passes every parameter and default through unchanged and copies
every value out exactly (no tolerance: the comparison is of bit patterns)."""

import json
import warnings

import pytest

import snowroll
from conftest import parse_csv, run_cli, same_bits

# Keyword -> CLI flag: the one vocabulary (snake_case <-> kebab-case).
def flags(kwargs):
    out = []
    for key, value in kwargs.items():
        flag = "--" + key.replace("_", "-")
        if isinstance(value, (list, tuple)):
            value = ",".join(repr(float(v)) for v in value)
        if value is True:
            out += [flag]
            continue
        out += [flag, value]
    return out


CASES = [
    ("torque-cm", {}),
    ("torque-cm", {"alpha_deg": 25, "snow_depth": 0.02, "r0": 0.15, "t_end": 12.5}),
    ("torque-contact", {"dt": 0.25, "t_end": 20}),
    ("energy", {"times": [0.0, 0.1, 1.0, 2.5, 7.0], "v0": 0.5}),
    ("energy-thin", {"x_end": 30, "rtol": 1e-8, "atol": 1e-10}),
    ("lagrangian-printed", {"t_end": 5}),
    ("quasi-circular", {"density": 300, "length": 2, "g": 9.8}),
    ("quasi-circular-lift", {"alpha_deg": 10}),
    ("loney", {"t_end": 3}),
    ("snowless", {"snow_depth": 0, "dt": 0.1, "t_end": 2}),
    ("turns", {"turns": 5}),
    ("turns-exact", {"turns": 3, "collision": "pivot"}),
    ("turns", {"turns": 4, "collision": "charged", "mu": 0.5}),
    ("eq4", {"mu": 0.1, "t_end": 50}),
    ("torque-cm", {"alpha_deg": 1, "snow_depth": 0.05}),
    ("turns", {"turns": 3, "alpha_deg": 80}),
    ("turns", {"turns": 3, "alpha_deg": 80, "on_hop": "continue"}),
    ("turns-exact", {"turns": 3, "alpha_deg": 80, "on_hop": "stop", "mu": 2.0}),
    ("torque-cm", {"shape": "sphere", "t_end": 20}),
    ("energy", {"shape": "sphere", "swath_width": 0.05, "t_end": 10}),
    ("loney", {"shape": "sphere", "t_end": 5}),
    # Issue 11: the losses and the ledger columns.
    ("energy", {"drag_coefficient": 0.8, "air_density": 1.1, "rolling_resistance": 0.02, "compaction_energy": 2.5}),
    ("snowless", {"drag_coefficient": 1, "terminal_tol": 1e-6, "t_end": 200}),
    ("torque-cm", {"ledger": True, "t_end": 10}),
    # The ball's losses: drag on pi r^2, with its N and dM/dx, on both growth laws.
    ("snowless", {"shape": "sphere", "drag_coefficient": 1, "terminal_tol": 1e-6, "t_end": 200}),
    ("torque-cm", {"shape": "sphere", "drag_coefficient": 0.5, "rolling_resistance": 0.03, "compaction_energy": 1.5, "t_end": 20}),
    ("energy", {"shape": "sphere", "swath_width": 0.05, "drag_coefficient": 1, "air_density": 1.0, "t_end": 10}),
    # The turn models' ledger (collision losses; the note's created lift).
    ("turns", {"turns": 4, "ledger": True}),
    ("turns-exact", {"turns": 3, "collision": "pivot", "on_hop": "continue", "ledger": True}),
    # Issue 35: the unwinding roll, on a tube of its own mass (log and ball, with the ledger).
    ("energy-thin", {"alpha_deg": 0, "snow_depth": -1e-4, "r0": 0.06, "core_radius": 0.02, "core_mass": 0.005, "density": 700, "length": 0.1, "t_end": 200}),
    ("torque-cm", {"alpha_deg": 10, "snow_depth": -1e-4, "r0": 0.06, "core_radius": 0.02, "core_mass": 0.005, "shape": "sphere", "ledger": True, "t_end": 20}),
    # Issue 7's limits: a row limit and a step limit cut the run short.
    ("torque-cm", {"t_end": 30, "max_rows": 40}),
    ("energy", {"t_end": 30, "max_steps": 25}),
    ("turns", {"turns": 50, "max_steps": 25, "max_rows": 1000}),
]


@pytest.mark.parametrize("model,kwargs", CASES, ids=[f"{m}-{i}" for i, (m, _) in enumerate(CASES)])
def test_simulate_equals_cli(cli, model, kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        r = snowroll.simulate(model, **kwargs)
    stdout, _ = run_cli(cli, "simulate", "--model", model, *flags(kwargs))
    meta, cols = parse_csv(stdout)
    assert r.columns == list(cols), "column names and order as in the CSV header"
    assert len(r) == len(cols["t_s"]) > 0
    for name in cols:
        assert same_bits(r[name], cols[name]), name
    # The stop line: `end-time at t_s = 1 x_m = ... v_m_s = ...[ turn = ...]: ...`.
    stop = meta["stop"]
    reason, _, rest = stop.partition(" at ")
    assert r.stop["reason"] == reason
    fields = rest.split(": ")[0].split()
    values = dict(zip(fields[0::3], fields[2::3]))
    for key in ("t_s", "x_m", "v_m_s", "theta_rad", "omega_rad_s"):
        if key in values:
            assert r.stop[key] == float(values[key]), key
    if "turn" in values:
        assert r.stop["turn"] == int(values["turn"])
    # Parameters as the CSV header records them, same keys.
    for key in ("alpha_deg", "snow_depth", "r0", "g", "density", "length", "v0", "t_end", "rtol", "atol"):
        assert r.params[key] == float(meta[key]), key
    assert r.params["collision"] == meta["collision"]
    assert r.params["on_hop"] == meta["on_hop"] == kwargs.get("on_hop", "stop")
    assert r.params["shape"] == meta["shape"]
    if "swath_width" in meta:
        assert r.params["swath_width"] == float(meta["swath_width"])
    assert r.params["sampling"] == meta["sampling"]
    for key in ("max_rows", "max_steps"):
        assert r.params[key] == int(meta[key]), key
    assert r.model == meta["model"].split(" ")[0]


def test_json_params_equal_cli(cli):
    """`r.params` is the `params` object of the CLI's JSON output, key for key."""
    kwargs = {"alpha_deg": 20, "times": [0.0, 0.5, 1.5], "mu": 0.3}
    r = snowroll.simulate("energy", **kwargs)
    stdout, _ = run_cli(cli, "simulate", "--model", "energy", "--format", "json", *flags(kwargs))
    doc = json.loads(stdout)
    assert r.params == doc["params"]
    assert r.version == doc["snowroll_version"]
    assert r.stop["reason"] == doc["stop"]["reason"]
    assert r.stop["description"] == doc["stop"]["description"]


@pytest.mark.parametrize(
    "model,kwargs",
    [("turns", {"turns": 30}), ("turns-exact", {"turns": 12, "alpha_deg": 40}), ("eq73", {"turns": 8, "collision": "charged"}),
     ("turns", {"turns": 4, "alpha_deg": 80, "on_hop": "continue"}),
     ("turns", {"turns": 10, "max_rows": 10, "max_steps": 1000000}),
     ("turns-exact", {"turns": 3, "shape": "cylinder"}),
     # Issue 13: the loss keywords and the ledger, as for simulate().
     ("turns", {"turns": 6, "ledger": True}),
     ("turns-exact", {"turns": 5, "collision": "charged", "ledger": True, "air_density": 1.1, "terminal_tol": 1e-6})],
)
def test_turns_equals_cli(cli, model, kwargs):
    t = snowroll.turns(model, **kwargs)
    stdout, _ = run_cli(cli, "turns", "--model", model, *flags(kwargs))
    meta, cols = parse_csv(stdout)
    assert t.columns == list(cols)
    assert ("kinetic_j" in cols) == kwargs.get("ledger", False)
    assert len(t) == kwargs["turns"]
    for name in cols:
        assert same_bits(t[name], cols[name]), name
    assert t.params["t_end"] == float(meta["t_end"]) == 1e9
    assert t.params["sampling"] == meta["sampling"]
    assert t.params["on_hop"] == meta["on_hop"] == kwargs.get("on_hop", "stop")
    assert t.params["shape"] == meta["shape"] == "cylinder"
    for key in ("max_rows", "max_steps"):
        assert t.params[key] == int(meta[key]), key
    # The summary's last checkpoint is the CSV's last `# summary: K, ...` line.
    lines = [line for line in stdout.splitlines() if line.startswith("# summary: ") and line[11].isdigit()]
    last = [float(v) for v in lines[-1][len("# summary: "):].split(", ")]
    c = t.summary["checkpoints"][-1]
    assert [c["turns"], c["mean_a_turn_over_g"], c["mean_a_with_collision_over_g"]] == last[:3]
    assert t.summary["turns"] == kwargs["turns"]


def test_turns_summary_equals_cli_json(cli):
    """`t.summary` is the `summary` object of the CLI's JSON output, key for
    key and bit for bit (the native module builds the dict itself, not
    through serde_json: a field it left out would show here)."""
    kwargs = {"turns": 120, "alpha_deg": 35}
    t = snowroll.turns("turns", **kwargs)
    stdout, _ = run_cli(cli, "turns", "--model", "turns", "--format", "json", *flags(kwargs))
    doc = json.loads(stdout)
    assert t.summary == doc["summary"]
    assert [c["turns"] for c in t.summary["checkpoints"]] == [1, 2, 5, 10, 20, 50, 100, 120]


def test_turns_default_count_equals_cli(cli):
    """With no `turns`, both run the CLI's default number of turns."""
    t = snowroll.turns()
    stdout, _ = run_cli(cli, "turns", "--model", "turns")
    _, cols = parse_csv(stdout)
    assert len(t) == len(cols["turn"]) == 100
    assert same_bits(t.v_after_m_s, cols["v_after_m_s"])


def test_models_equal_cli(cli):
    stdout, _ = run_cli(cli, "models", "--format", "json")
    listed = json.loads(stdout)["models"]
    ours = snowroll.models()
    assert [m["id"] for m in ours] == [m["id"] for m in listed]
    for a, b in zip(ours, listed):
        for key in ("alias", "equation", "description", "terminal_fraction", "stall_slope_deg", "stall_kind", "validity"):
            assert a[key] == b[key], (a["id"], key)


def test_models_with_a_body_and_losses_equal_cli(cli):
    """Issue 22: models() takes the flags of `snowroll models` and lists the
    same stall slopes, to the bit."""
    flags = ["--shape", "sphere", "--snow-depth", "0.02", "--r0", "0.15", "--rolling-resistance", "0.01"]
    stdout, _ = run_cli(cli, "models", "--format", "json", *flags)
    listed = json.loads(stdout)["models"]
    ours = snowroll.models(shape="sphere", snow_depth=0.02, r0=0.15, rolling_resistance=0.01)
    assert any(m["stall_slope_deg"] is not None for m in ours)
    for a, b in zip(ours, listed):
        assert a["stall_slope_deg"] == b["stall_slope_deg"], a["id"]
        assert a["stall_kind"] == b["stall_kind"], a["id"]
