"""snowroll.sweep equals the CLI's `snowroll sweep` row for row, bit for bit;
shards joined equal the whole sweep; bad grids raise ValueError."""

import concurrent.futures
import csv
import importlib.util
import io
import pathlib

import numpy as np
import pytest

import snowroll
from conftest import run_cli, same_bits

TEXT_COLUMNS = ("model", "on_hop", "collision", "stop", "error", "warnings")


def parse_sweep_csv(text):
    lines = [line for line in text.splitlines() if line and not line.startswith("#")]
    rows = list(csv.reader(io.StringIO("\n".join(lines))))
    names, body = rows[0], rows[1:]
    cols = {}
    for i, name in enumerate(names):
        cells = [row[i] for row in body]
        if name in TEXT_COLUMNS:
            cols[name] = [c if c else None for c in cells]
        elif name == "index":
            cols[name] = np.array([int(c) for c in cells], dtype=np.uint64)
        else:
            cols[name] = np.array([float(c) if c else np.nan for c in cells])
    return cols


GRID = {
    "model": "torque-cm,energy,loney,turns",
    "alpha_deg": "1:41:5",
    "snow_depth": [0.005, 0.02],
    "t_end": 8,
}


# The settings a regime map varies: friction (slips), hop handling and the
# collision law (hops of the turn models).
SETTINGS_GRID = {
    "model": "snowless,turns",
    "alpha_deg": [30.0, 70.0],
    "mu": [0.1, 0.5],
    "on_hop": "stop,continue",
    "collision": ["note", "charged"],
    "t_end": 3,
}


def cli_flags(grid):
    out = []
    for key, value in grid.items():
        if isinstance(value, (list, tuple)):
            value = ",".join(v if isinstance(v, str) else repr(float(v)) for v in value)
        out += ["--" + key.replace("_", "-"), str(value)]
    return out


@pytest.mark.parametrize("method", ["auto", "ode"])
def test_sweep_equals_cli(cli, method):
    s = snowroll.sweep(GRID, method=method)
    stdout, _ = run_cli(cli, "sweep", "--quiet", "--method", method, *cli_flags(GRID))
    cols = parse_sweep_csv(stdout)
    assert s.columns == list(cols)
    assert len(s) == s.grid_len == 4 * 5 * 2
    for name in cols:
        if name in TEXT_COLUMNS:
            assert list(s[name]) == cols[name], name
        else:
            assert same_bits(s[name], cols[name]), name


def test_settings_axes_equal_cli(cli):
    s = snowroll.sweep(SETTINGS_GRID)
    stdout, _ = run_cli(cli, "sweep", "--quiet", *cli_flags(SETTINGS_GRID))
    cols = parse_sweep_csv(stdout)
    assert s.columns == list(cols)
    assert len(s) == 2 * 2 * 2 * 2 * 2
    for name in cols:
        if name in TEXT_COLUMNS:
            assert list(s[name]) == cols[name], name
        else:
            assert same_bits(s[name], cols[name]), name
    # Model, then collision, then on_hop, then the numeric axes.
    assert list(s["collision"][:16]) == ["note"] * 8 + ["charged"] * 8
    assert list(s["on_hop"][:8]) == ["stop"] * 4 + ["continue"] * 4


def test_shards_join_to_the_whole():
    whole = snowroll.sweep(GRID)
    parts = [snowroll.sweep(GRID, shard=(i, 3)) for i in (2, 0, 1)]
    assert sum(len(p) for p in parts) == len(whole)
    joined = snowroll.SweepResult.concat(parts)
    for name in whole.columns:
        if name in TEXT_COLUMNS:
            assert list(joined[name]) == list(whole[name])
        else:
            assert same_bits(joined[name], whole[name]), name


def test_late_time_fraction_of_eq_4():
    """Eq. (4) tends to a = (1/5) g sin alpha (the `terminal_fraction` of
    models()); after 200 s at alpha = 30 deg the approach is within 1e-3."""
    s = snowroll.sweep({"model": ["torque-cm"], "alpha_deg": [20, 30, 45], "t_end": 200})
    frac = next(m["terminal_fraction"] for m in snowroll.models() if m["id"] == "torque-cm")
    assert frac == pytest.approx(0.2, abs=1e-15)
    assert np.allclose(s.a_over_g_sin_alpha, frac, rtol=1e-3)


@pytest.mark.parametrize(
    "grid,match",
    [
        ({"alpha_deg": [30]}, "model"),
        ({"model": "torque-cm", "alpha_deg": "5:60"}, "alpha_deg"),
        ({"model": "torque-cm", "alpha_deg": [95]}, "alpha"),
        ({"model": "torque-cm", "colour": [1]}, "unknown axis"),
        ({"model": "no-such"}, "unknown model"),
    ],
)
def test_bad_grid(grid, match):
    with pytest.raises(ValueError, match=match):
        snowroll.sweep(grid)


def test_bad_shard():
    with pytest.raises(ValueError, match="shard"):
        snowroll.sweep({"model": "torque-cm"}, shard=(3, 3))


def test_every_column_is_a_numpy_array():
    s = snowroll.sweep(SETTINGS_GRID)
    assert set(TEXT_COLUMNS) <= set(s.columns)
    assert tuple(snowroll.SweepResult.TEXT_COLUMNS) == TEXT_COLUMNS
    for name in s.columns:
        col = s[name]
        assert isinstance(col, np.ndarray), (name, type(col))
        assert len(col) == len(s), name
        assert col.dtype == (object if name in TEXT_COLUMNS else np.uint64 if name == "index" else np.float64), name
    # Each column named in the docstring (the axes' columns by SWEEP_AXES,
    # the parameter table's numeric sweep parameters), and reachable as an
    # attribute (`s.model` and `s.stop` are the columns, not metadata).
    doc = snowroll.SweepResult.__doc__
    assert ":data:`SWEEP_AXES`" in doc
    for name in s.columns:
        assert name in snowroll.SWEEP_AXES or f"``{name}``" in doc, name
        assert getattr(s, name) is s[name], name
    axes = [c for c in s.columns if c in snowroll.SWEEP_AXES]
    assert axes == list(snowroll.SWEEP_AXES)


@pytest.mark.parametrize(
    "shard,error,match",
    [
        ((-1, 3), ValueError, r"^shard = -1 is out of range: expected an integer 0 <= shard"),
        ((0, 0), ValueError, r"^shard = 0 is out of range: expected an integer 1 <= shard"),
        ((3, 3), ValueError, r"^shard = \(3, 3\) is out of range: expected 0 <= i < n$"),
        ((0.0, 3), TypeError, r"^shard: expected an integer, got float$"),
        (5, TypeError, r"^shard: expected a pair \(i, n\) of integers, got int$"),
    ],
)
def test_bad_shard_names_the_keyword(shard, error, match):
    with pytest.raises(error, match=match):
        snowroll.sweep({"model": "torque-cm"}, shard=shard)


def test_a_list_setting_of_the_wrong_type_names_its_key():
    with pytest.raises(TypeError, match="^on_hop: expected a string"):
        snowroll.sweep({"model": "turns", "on_hop": 1})
    with pytest.raises(TypeError, match="^model: expected a string"):
        snowroll.sweep({"model": 4})


def load_dask_example():
    path = pathlib.Path(__file__).resolve().parents[3] / "examples" / "python" / "dask_sweep.py"
    spec = importlib.util.spec_from_file_location("dask_sweep_example", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class ThreadClient:
    """The two methods of a Dask client the example uses, on a local thread
    pool, so the example's core runs where dask is not installed."""

    def __init__(self, pool):
        self.pool = pool

    def submit(self, fn, *args, pure=True):
        return self.pool.submit(fn, *args)

    def gather(self, futures):
        return [f.result() for f in futures]


@pytest.mark.parametrize("shards", [1, 3, 7])
def test_dask_example_core_merges_shards_into_the_single_run(shards):
    example = load_dask_example()
    with concurrent.futures.ThreadPoolExecutor(max_workers=3) as pool:
        merged = example.check_merge(ThreadClient(pool), example.SMALL_GRID, shards)
    models = len(snowroll.models())
    assert len(merged) == merged.grid_len == models * 5 * 2
    assert np.array_equal(merged.index, np.arange(len(merged), dtype=np.uint64))


def test_dask_example_on_a_local_dask_cluster():
    pytest.importorskip(
        "dask.distributed",
        reason="dask is not installed (scripts/test-python.sh installs it)",
    )
    from dask.distributed import Client, LocalCluster

    example = load_dask_example()
    # Two worker processes, as the example runs them.
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, Client(cluster) as client:
        merged = example.check_merge(client, example.SMALL_GRID, 3)
    assert len(merged) == merged.grid_len


def sweep_with_an_empty_text_column():
    # No run fails, so every cell of `error` is empty.
    s = snowroll.sweep({"model": "snowless,turns", "alpha_deg": [30, 89.9], "t_end": 3})
    assert all(e is None for e in s.error)
    return s


def test_text_columns_are_pandas_strings():
    pd = pytest.importorskip("pandas", reason="pandas is optional and not installed")
    s = sweep_with_an_empty_text_column()
    frame = s.to_pandas()
    for name in TEXT_COLUMNS:
        assert isinstance(frame[name].dtype, pd.StringDtype), (name, frame[name].dtype)
        assert list(frame[name].isna()) == [v is None for v in s[name]], name
    assert list(frame["model"]) == list(s.model)
    assert frame.attrs == {"grid_len": len(s), "shard": (0, 1), "version": snowroll.__version__}


def test_text_columns_are_polars_strings():
    pl = pytest.importorskip("polars", reason="polars is optional and not installed")
    s = sweep_with_an_empty_text_column()
    frame = s.to_polars()
    for name in TEXT_COLUMNS:
        assert frame.schema[name] == pl.String, (name, frame.schema[name])
        assert frame[name].to_list() == list(s[name]), name


def test_sweep_rows_carry_the_warnings_of_their_points():
    """b/r0 = 5 is past the thin-snow limit 0.1 (b-over-r0), rtol = 0.5 looser
    than the claims' 1e-6 (loose-tolerance); b/r0 = 0.1 at rtol 1e-10 has none.
    Each expectation is computed here from the row's own parameters."""
    s = snowroll.sweep({"model": "eq4,turns", "snow_depth": [0.01, 0.5], "rtol": [1e-10, 0.5], "t_end": 5})
    for b, r0, rtol, cell in zip(s.snow_depth, s.r0, s.rtol, s.warnings):
        want = [c for c, bad in (("b-over-r0", b / r0 > 0.1 * (1 + 1e-12)), ("loose-tolerance", rtol > 1e-6)) if bad]
        assert (cell.split(";") if cell else []) == want
    assert sum(w is not None for w in s.warnings) == 6
