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
