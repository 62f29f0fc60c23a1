"""Bad input raises ValueError with the library's message, the same text the
CLI prints after `error: `."""

import pytest

import snowroll
from conftest import run_cli


@pytest.mark.parametrize(
    "kwargs,flags",
    [
        ({"alpha_deg": 95}, ["--alpha-deg", "95"]),
        ({"alpha_deg": 0}, ["--alpha-deg", "0"]),
        ({"snow_depth": -0.01}, ["--snow-depth", "-0.01"]),
        ({"r0": 0}, ["--r0", "0"]),
        ({"g": -9.81}, ["--g", "-9.81"]),
        ({"density": float("nan")}, ["--density", "NaN"]),
        ({"length": -1}, ["--length", "-1"]),
        ({"v0": -2}, ["--v0", "-2"]),
        ({"t_end": 0}, ["--t-end", "0"]),
        ({"rtol": 1e-20}, ["--rtol", "1e-20"]),
        ({"dt": -0.5}, ["--dt", "-0.5"]),
        ({"times": [1.0, 0.5]}, ["--times", "1,0.5"]),
        ({"times": [-1.0]}, ["--times", "-1"]),
        ({"mu": -0.2}, ["--mu", "-0.2"]),
    ],
)
def test_value_error_with_the_cli_message(cli, kwargs, flags):
    with pytest.raises(ValueError) as err:
        snowroll.simulate("torque-cm", **kwargs)
    message = str(err.value)
    assert message
    _, stderr = run_cli(cli, "simulate", "--model", "torque-cm", *flags, ok=False)
    assert f"error: {message}" in stderr, (message, stderr)


def test_unknown_model():
    with pytest.raises(ValueError, match=r'unknown model "no-such-model": expected one of .*torque-cm \(eq4\)'):
        snowroll.simulate("no-such-model")


def test_model_ids_are_case_insensitive_like_the_cli():
    assert snowroll.simulate("EQ4", t_end=1).model == "torque-cm"


def test_unknown_collision():
    with pytest.raises(ValueError, match="unknown collision"):
        snowroll.simulate("turns", collision="elastic")


def test_unknown_on_hop():
    with pytest.raises(ValueError, match="unknown on_hop"):
        snowroll.turns("turns", on_hop="fly")


def test_times_and_dt_conflict():
    with pytest.raises(ValueError, match="conflict"):
        snowroll.simulate(times=[0.0, 1.0], dt=0.5)


def test_turns_only_for_turn_models():
    with pytest.raises(ValueError, match="turn models"):
        snowroll.simulate("energy", turns=3)
    with pytest.raises(ValueError, match="turn model"):
        snowroll.turns("energy")


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        snowroll.simulate(alpha_deg="thirty")
    with pytest.raises(TypeError):
        snowroll.simulate(30)  # the model is a string; parameters are keywords
    with pytest.raises(OverflowError):
        snowroll.turns(turns=-1)


def test_a_known_row_count_above_max_rows_is_refused_before_the_run(cli):
    # The grid 0, 0.01, ..., 10 has t_end/dt + 1 = 1001 rows; 20 turns make 20 rows.
    # The CLI refuses the same run, in its flags' words (`--max-rows 100`).
    with pytest.raises(ValueError, match="1001 rows, more than max_rows = 100"):
        snowroll.simulate("torque-cm", dt=0.01, t_end=10, max_rows=100)
    _, stderr = run_cli(cli, "simulate", "--model", "torque-cm", "--dt", "0.01", "--t-end", "10",
                        "--max-rows", "100", ok=False)
    assert "1001 rows, more than --max-rows 100" in stderr, stderr
    with pytest.raises(ValueError, match="20 rows, more than max_rows = 10"):
        snowroll.turns(turns=20, max_rows=10)
    with pytest.raises(ValueError, match="max_steps"):
        snowroll.simulate("torque-cm", max_steps=0)
    with pytest.raises(ValueError, match="max_rows"):
        snowroll.turns(max_rows=0)


@pytest.mark.parametrize("model", ["turns", "turns-exact"])
def test_turn_models_refuse_a_sphere_with_the_cli_message(cli, model):
    # A ball that picks up a swath in one turn gains a band, not a shell
    # (docs/snowball-and-losses.md section 1.2): the turn models take the log only.
    with pytest.raises(ValueError, match=f"model {model} does not support shape = sphere: ") as err:
        snowroll.turns(model, shape="sphere", turns=2)
    _, stderr = run_cli(cli, "turns", "--model", model, "--shape", "sphere", "--turns", "2", ok=False)
    # The CLI's message is the library's, after the run it names.
    assert stderr.startswith(f"error: running {model} ") and stderr.rstrip().endswith(f": {err.value}"), stderr
    with pytest.raises(ValueError, match="does not support shape = sphere"):
        snowroll.turns(model, shape="sphere", swath_width=0.05, turns=2)
