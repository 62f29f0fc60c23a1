"""A large sweep spread over a Dask local cluster by shards, then merged.

    pip install ./crates/snowroll-py "dask[distributed]" pandas
    python examples/python/dask_sweep.py [SHARDS] [WORKERS]

Each task runs one shard of the grid, `snowroll.sweep(grid, shard=(i, n))`
(the same split as the CLI's `--shard i/n`); the rows of the shards, joined
in grid order, are exactly the rows of the whole sweep run at once (this
script checks it on a small grid first). On a real cluster, point `Client`
at its scheduler instead of starting a local one; with Ray, replace
`client.submit(run_shard, ...)` by a `@ray.remote` function and
`client.gather` by `ray.get`. The package does this sharding itself as a
`dask.dataframe`, one partition per shard: `snowroll.dask.sweep(grid,
client, shards=n)` (then `.compute()`, `.to_parquet(...)`).
"""

import sys

import numpy as np

import snowroll

# 11 models x 60 slopes x 40 snow depths x 5 radii = 132,000 trajectories.
GRID = {
    "model": [m["id"] for m in snowroll.models()],
    "alpha_deg": "2:60:60",
    "snow_depth": "0.001:0.04:40",
    "r0": [0.05, 0.1, 0.2, 0.5, 1.0],
    "t_end": 60,
}

# The grid of the merge check: every model at 5 slopes and 2 snow depths.
SMALL_GRID = dict(GRID, alpha_deg="5:45:5", snow_depth=[0.01, 0.02], r0=[0.1])


def run_shard(grid, i, n):
    """One task: the rows of shard i of n (the library runs them on the
    worker's threads, the GIL released)."""
    return snowroll.sweep(grid, shard=(i, n))


def distributed_sweep(client, grid, shards):
    """The whole sweep of `grid`, its shards run as tasks of `client` (any
    object with Dask's `submit(fn, *args, pure=...)` and `gather(futures)`)."""
    futures = [client.submit(run_shard, grid, i, shards, pure=False) for i in range(shards)]
    return snowroll.SweepResult.concat(client.gather(futures))


def check_merge(client, grid, shards):
    """Checks that `grid` run in `shards` shards and merged equals the same
    grid run in one call, column by column, bit for bit (every column is a
    numpy array: the text ones of dtype object, compared element by element;
    the numbers by their bytes, so NaN cells must match too). Returns the
    merged rows."""
    whole = snowroll.sweep(grid)
    merged = distributed_sweep(client, grid, shards)
    assert merged.columns == whole.columns, (merged.columns, whole.columns)
    for name in whole.columns:
        a, b = whole[name], merged[name]
        assert a.dtype == b.dtype, name
        same = (a == b).all() if a.dtype == object else a.tobytes() == b.tobytes()
        assert same, name
    return merged


def main():
    from dask.distributed import Client, LocalCluster

    shards = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    workers = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    # One thread per worker process: each shard already uses every core of
    # its worker through the library's own thread pool.
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True) as cluster, Client(
        cluster
    ) as client:
        # The merge is exact: a small grid, sharded and joined, equals the
        # same grid run in one call, column by column, bit for bit.
        merged = check_merge(client, SMALL_GRID, 3)
        print(f"check: {len(merged)} rows from 3 shards equal the single run")

        rows = distributed_sweep(client, GRID, shards)
    print(f"{len(rows)} trajectories in {shards} shards on {workers} workers")

    frame = rows.to_pandas()
    ok = frame[frame["error"].isna()]
    late = ok[ok["stop"] == "end-time"]
    table = late.groupby("model")["a_over_g_sin_alpha"].agg(["count", "median", "min", "max"])
    print("a / (g sin alpha) at t_end = 60 s, runs that reached it:")
    print(table.to_string(float_format=lambda x: f"{x:.4f}"))
    stops = ok.groupby(["model", "stop"]).size().unstack(fill_value=0)
    print("how the runs ended:")
    print(stops.to_string())
    assert np.all(np.diff(rows.index.astype(np.int64)) == 1), "rows in grid order"


if __name__ == "__main__":
    main()
