"""snowroll.fit on SYNTHETIC data made here (a model's run plus Gaussian
noise of known sigma, fixed seed): the same records as the CLI's
``snowroll fit --format json``, the model that made the data first, the
result's table and figure, bad input refused."""

import json

import numpy as np
import pytest

import snowroll

from conftest import run_cli


def _track(model="energy", sigma=0.003, seed=7):
    t = np.linspace(0.05, 3.0, 60)
    x = snowroll.simulate(model, alpha_deg=30, snow_depth=0.01, times=t, t_end=3.0).x_m
    return t, x + np.random.default_rng(seed).normal(0.0, sigma, t.size)


def test_fit_equals_the_cli(cli, tmp_path):
    t, x = _track()
    path = tmp_path / "track.csv"
    path.write_text("t,x\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(t, x)))
    out, _ = run_cli(cli, "fit", str(path), "--model", "energy,torque-cm", "--free", "snow_depth,t0,x0",
                  "--alpha-deg", "30", "--format", "json")
    cli_fits = json.loads(out)["fits"]
    py = snowroll.fit(t, x, models=["energy", "torque-cm"], free=["snow_depth", "t0", "x0"], alpha_deg=30)
    assert [f["model"] for f in py.fits] == [f["model"] for f in cli_fits]
    for a, b in zip(py.fits, cli_fits):
        for key in ("params", "rms_m", "aic", "bic", "rank", "converged", "unseparated"):
            assert a[key] == b[key], key


@pytest.mark.parametrize("truth", ["energy", "torque-contact"])
def test_the_model_that_made_the_data_ranks_first(truth):
    t, x = _track(truth)
    f = snowroll.fit(t, x, alpha_deg=30)
    assert f.best["model"] == truth, repr(f)
    b = f.best["params"]["snow_depth"]
    assert abs(b["value"] - 0.01) < 5 * b["stderr"]
    assert f.best["residuals_m"].shape == t.shape


def test_to_pandas_and_plot():
    pytest.importorskip("pandas")
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    t, x = _track()
    f = snowroll.fit(t, x, models=["energy", "snowless"], alpha_deg=30)
    frame = f.to_pandas()
    assert list(frame["model"]) == [g["model"] for g in f.fits]
    assert {"snow_depth", "snow_depth_stderr", "t0", "x0", "rms_m", "aic"} <= set(frame.columns)
    # snowless does not depend on the snow depth: no standard error, NaN in the table.
    row = frame[frame["model"] == "snowless"].iloc[0]
    assert np.isnan(row["snow_depth_stderr"])
    fig = f.plot()
    assert len(fig.axes) == 2


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="point 3"):
        snowroll.fit([0, 1, 0.5, 2, 3], [0, 1, 2, 3, 4])
    with pytest.raises(ValueError, match="at least 5"):
        snowroll.fit([0, 1], [0, 1])
    t, x = _track()
    with pytest.raises(TypeError, match="bogus"):
        snowroll.fit(t, x, bogus=1)
    with pytest.raises(ValueError, match="no such parameter"):
        snowroll.fit(t, x, free=["nope"])
