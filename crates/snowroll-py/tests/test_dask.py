"""snowroll.dask.sweep on a real Dask LocalCluster of worker processes: the
frame's partitions are the shards, its rows those of snowroll.sweep bit for
bit, also when a worker is killed mid-sweep (the scheduler runs its shard
again); to_parquet writes them. snowroll imports without dask."""

import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import snowroll

pd = pytest.importorskip("pandas", reason="pandas is not installed (scripts/test-python.sh installs it)")
pytest.importorskip("dask.dataframe", reason="dask is not installed (scripts/test-python.sh installs it)")
distributed = pytest.importorskip("dask.distributed")

# 4 models x 9 slopes x 3 snow depths = 108 runs (missing cells must come
# through too: `x_end` is NaN and `error` missing in every row).
GRID = {
    "model": "torque-cm,energy,turns,loney",
    "alpha_deg": "1:81:9",
    "snow_depth": [0.001, 0.01, 0.05],
    "t_end": 8,
}

# Large enough that each shard runs for a second or more on one thread.
SLOW_GRID = {
    "model": "torque-cm,torque-contact,energy,quasi-circular",
    "alpha_deg": "1:89:300",
    "snow_depth": "0.0001:0.1:100",
    "t_end": 100,
}


@pytest.fixture(scope="module")
def client():
    # Worker processes (not threads), one thread each, as on a cluster.
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def same_frames(got, want):
    """Same index, columns, dtypes and cells: numbers by their bytes (NaN
    cells included), text cells equal or both missing."""
    assert list(got.columns) == list(want.columns)
    assert got.index.name == want.index.name == "index"
    assert got.index.dtype == want.index.dtype == np.uint64
    assert np.array_equal(got.index.to_numpy(), want.index.to_numpy())
    for name in want.columns:
        a, b = got[name], want[name]
        assert a.dtype == b.dtype, (name, a.dtype, b.dtype)
        if b.dtype.kind == "f":
            assert a.to_numpy().tobytes() == b.to_numpy().tobytes(), name
        else:
            assert a.isna().equals(b.isna()), name
            assert (a[~a.isna()] == b[~b.isna()]).all(), name


def whole(grid):
    return snowroll.sweep(grid).to_pandas().set_index("index")


@pytest.mark.parametrize("shards", [1, 3, 7])
def test_partitions_are_the_shards_and_the_rows_those_of_one_sweep(client, shards):
    frame = snowroll.dask.sweep(GRID, client, shards=shards)
    points = 4 * 9 * 3
    assert frame.npartitions == shards
    # Divisions: each shard's first index (points * i // shards, the split
    # of --shard i/N), then the last index.
    starts = [points * i // shards for i in range(shards)]
    assert list(frame.divisions) == starts + [points - 1]
    want = whole(GRID)
    assert dict(frame.dtypes) == dict(want.dtypes)
    same_frames(frame.compute(), want)
    # Each partition holds exactly its shard's indices.
    for i in range(shards):
        part = frame.get_partition(i).compute()
        end = points * (i + 1) // shards
        assert np.array_equal(part.index.to_numpy(), np.arange(starts[i], end, dtype=np.uint64))
    assert want["x_end"].isna().all() and want["error"].isna().all()


def test_lazy_without_a_client_and_to_parquet(client, tmp_path):
    frame = snowroll.dask.sweep(GRID, shards=4)
    frame.to_parquet(tmp_path / "sweep")
    back = pd.read_parquet(tmp_path / "sweep")
    want = whole(GRID)
    assert len(list((tmp_path / "sweep").glob("*.parquet"))) == 4
    # Parquet keeps the values; pandas reads text back as its `string` or
    # object dtype depending on the writer, so text is compared by value.
    assert np.array_equal(back.index.to_numpy(), want.index.to_numpy())
    for name in want.columns:
        if want[name].dtype.kind == "f":
            assert back[name].to_numpy().tobytes() == want[name].to_numpy().tobytes(), name
        else:
            got = back[name].astype("string")
            assert got.isna().equals(want[name].isna()), name
            assert (got[~got.isna()] == want[name][~want[name].isna()]).all(), name


def test_a_worker_killed_mid_sweep_leaves_the_result_complete_and_identical(client):
    frame = snowroll.dask.sweep(SLOW_GRID, client, shards=4)
    futures = frame.dask  # the graph holds the submitted futures
    assert futures is not None
    pids = client.run(os.getpid)
    victim = None
    deadline = time.monotonic() + 60
    while victim is None and time.monotonic() < deadline:
        for address, keys in client.processing().items():
            if any(str(k).startswith("snowroll-shard-") for k in keys):
                victim = address
                break
        else:
            time.sleep(0.01)
    assert victim is not None, "no shard started within 60 s"
    os.kill(pids[victim], signal.SIGKILL)
    got = frame.compute()
    # The nanny started a new worker process in place of the killed one.
    assert pids[victim] not in client.run(os.getpid).values()
    same_frames(got, whole(SLOW_GRID))


@pytest.mark.parametrize(
    "shards, error, match",
    [
        (0, ValueError, "shards = 0 is out of range"),
        (109, ValueError, r"shards = 109 is out of range: expected 1 <= shards <= 108"),
        (2.5, TypeError, "shards: expected an integer"),
    ],
)
def test_bad_shard_counts_name_the_keyword_and_the_range(shards, error, match):
    with pytest.raises(error, match=match):
        snowroll.dask.sweep(GRID, shards=shards)


def test_snowroll_imports_without_dask(tmp_path):
    # A module named `dask` that fails to import stands first on the path.
    (tmp_path / "dask").mkdir()
    (tmp_path / "dask" / "__init__.py").write_text("raise ImportError('no dask here')\n")
    code = (
        "import snowroll\n"
        "snowroll.sweep({'model': 'torque-cm', 't_end': 1})\n"
        "try:\n"
        "    snowroll.dask.sweep({'model': 'torque-cm'}, shards=1)\n"
        "except ImportError as e:\n"
        "    print(e)\n"
    )
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=False)
    assert out.returncode == 0, out.stderr
    assert "snowroll.dask needs dask" in out.stdout
