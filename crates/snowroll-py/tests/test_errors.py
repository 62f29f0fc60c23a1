"""Bad input raises ValueError with the library's message, the same text the
CLI prints after `error: `."""

import re

import numpy as np
import pytest

import snowroll
from conftest import run_cli


def python_words(cli_message):
    """The CLI's message as a Python caller should read it: every flag
    `--kebab-name` as the keyword `kebab_name=` (written here independently of
    the binding, with a regular expression)."""
    return re.sub(
        r"--([a-z](?:[a-z0-9-]*[a-z0-9])?)",
        lambda m: m.group(1).replace("-", "_") + "=",
        cli_message,
    )


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
    assert "--" not in message, message
    _, stderr = run_cli(cli, "simulate", "--model", "torque-cm", *flags, ok=False)
    assert f"error: {message}" in python_words(stderr), (message, stderr)


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
    with pytest.raises(ValueError):
        snowroll.turns(turns=-1)


@pytest.mark.parametrize(
    "call,kwargs,lowest",
    [
        ("simulate", {"max_rows": -1}, 1),
        ("simulate", {"max_steps": -5}, 1),
        ("turns", {"turns": -3}, 1),
        ("turns", {"max_rows": -1}, 1),
        ("turns", {"turns": 2**64}, 1),
    ],
)
def test_a_count_out_of_range_names_its_keyword_and_range(call, kwargs, lowest):
    ((name, value),) = kwargs.items()
    expected = f"{name} = {value} is out of range: expected an integer {lowest} <= {name} <= 2^64 - 1"
    with pytest.raises(ValueError) as err:
        getattr(snowroll, call)(**kwargs)
    assert str(err.value) == expected


@pytest.mark.parametrize(
    "call,kwargs,expected",
    [
        ("simulate", {"alpha_deg": "30"}, "alpha_deg: expected a number, got str"),
        ("simulate", {"snow_depth": [0.01]}, "snow_depth: expected a number, got list"),
        ("simulate", {"t_end": None, "v0": True}, "v0: expected a number, got bool"),
        ("simulate", {"times": "0,1"}, "times: expected a sequence of numbers, got str"),
        ("simulate", {"times": [0.0, "1"]}, "times: expected a number, got str"),
        ("simulate", {"max_rows": 10.0}, "max_rows: expected an integer, got float"),
        ("simulate", {"shape": 1}, "shape: expected a str, got int"),
        ("simulate", {"ledger": "yes"}, "ledger: expected True or False, got str"),
        ("turns", {"turns": "3"}, "turns: expected an integer, got str"),
        ("turns", {"collision": ["note"]}, "collision: expected a str, got list"),
        ("models", {"r0": "0.1"}, "r0: expected a number, got str"),
    ],
)
def test_a_wrong_type_names_its_keyword(call, kwargs, expected):
    with pytest.raises(TypeError) as err:
        getattr(snowroll, call)(**kwargs)
    assert str(err.value) == expected


def test_a_model_that_is_not_a_string_names_the_keyword():
    with pytest.raises(TypeError, match="^model: expected a str, got int$"):
        snowroll.simulate(4)


def test_python_ints_and_numpy_scalars_are_numbers():
    """An int, a float and a numpy float of the same value give the same run,
    bit for bit (each is converted to the same double)."""
    runs = [
        snowroll.simulate("torque-cm", alpha_deg=a, r0=r, t_end=t, dt=0.5)
        for a, r, t in [(30, 0.25, 4), (30.0, 0.25, 4.0), (np.float64(30), np.float32(0.25), np.int64(4))]
    ]
    for r in runs[1:]:
        assert r.params == runs[0].params
        assert r.v_m_s.tobytes() == runs[0].v_m_s.tobytes()
    assert len(runs[0]) == 9  # t = 0, 0.5, ..., 4
    turned = snowroll.turns(turns=np.int64(3), max_rows=3)
    assert len(turned) == 3


def test_flags_in_library_messages_become_keywords(cli):
    # The library's hint names the CLI's flags; Python names the keywords.
    with pytest.raises(ValueError) as err:
        snowroll.simulate("torque-cm", swath_width=0.05)
    message = str(err.value)
    assert message.endswith("give shape='sphere' or drop swath_width="), message
    _, stderr = run_cli(cli, "simulate", "--model", "torque-cm", "--swath-width", "0.05", ok=False)
    assert "give --shape sphere or drop --swath-width" in stderr, stderr
    cli_words = stderr.replace("--shape sphere", "shape='sphere'")
    assert f"error: {message}" in python_words(cli_words), (message, stderr)


@pytest.mark.parametrize(
    "kwargs,flags,keywords",
    [
        # Out of the program's scale: the hint names what to change.
        ({"snow_depth": 1e200}, ["--snow-depth", "1e200"], ["snow_depth="]),
        ({"density": 1e140, "r0": 1e6}, ["--density", "1e140", "--r0", "1e6"],
         ["density=", "length=", "r0="]),
        # Output times after t_end: raise t_end=.
        ({"t_end": 1.0, "times": [0.5, 2.0]}, ["--t-end", "1", "--times", "0.5,2"], ["t_end="]),
    ],
)
def test_library_messages_name_keywords_where_the_cli_names_flags(cli, kwargs, flags, keywords):
    """The library names a parameter by its key; Python writes the keyword
    (`snow_depth=`), the CLI its flag (`--snow-depth`), in the same sentence."""
    with pytest.raises(ValueError) as err:
        snowroll.simulate("torque-cm", **kwargs)
    message = str(err.value)
    assert "--" not in message, message
    for k in keywords:
        assert k in message, (k, message)
    _, stderr = run_cli(cli, "simulate", "--model", "torque-cm", *flags, ok=False)
    for k in keywords:
        assert "--" + k[:-1].replace("_", "-") in stderr, (k, stderr)
    assert f"error: {message}" in python_words(stderr), (message, stderr)


def test_a_sweep_without_models_asks_for_the_grid_key():
    with pytest.raises(ValueError) as err:
        snowroll.sweep({})
    assert 'put "model"' in str(err.value) and "--" not in str(err.value), err.value


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
    # The CLI's message is the library's (checked before the run starts).
    assert f"error: {err.value}" in stderr, stderr
    with pytest.raises(ValueError, match="does not support shape = sphere"):
        snowroll.turns(model, shape="sphere", swath_width=0.05, turns=2)


@pytest.mark.parametrize(
    "kwargs,flags",
    [
        ({"drag_coefficient": 1.0}, ["--drag-coefficient", "1"]),
        ({"rolling_resistance": 0.1, "ledger": True}, ["--rolling-resistance", "0.1", "--ledger"]),
        ({"compaction_energy": 2.0}, ["--compaction-energy", "2"]),
    ],
)
def test_turns_refuses_losses_with_the_cli_message(cli, kwargs, flags):
    """turns() takes the loss keywords of simulate(); the turn models refuse
    any loss (docs/snowball-and-losses.md §3.2), with the CLI's message."""
    with pytest.raises(ValueError, match="energy integral") as err:
        snowroll.turns("turns", turns=3, **kwargs)
    message = str(err.value)
    _, stderr = run_cli(cli, "turns", "--model", "turns", "--turns", "3", *flags, ok=False)
    # The CLI's message is the library's, with the flags where Python names
    # the keywords (--drag-coefficient for drag_coefficient).
    cli_message = message
    for key in ("drag_coefficient", "rolling_resistance", "compaction_energy", "ledger"):
        cli_message = cli_message.replace(key + "=", "--" + key.replace("_", "-"))
    assert message.startswith("model turns does not support " + next(iter(kwargs))), message
    assert f"error: {cli_message}" in stderr, (cli_message, stderr)
