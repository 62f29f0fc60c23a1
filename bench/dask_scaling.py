"""Trajectories per second of a large sweep through snowroll.dask.sweep on a
LocalCluster of 1, 2 and 4 worker processes (one thread each; on a 2-core
machine 4 workers share the 2 cores), and the fixed cost of a shard (the
same small grid in 1 shard and in 64). Each line ends with the load average
at its end: the machine may be shared, so compare the ratios within one run.

    python bench/dask_scaling.py [ALPHA_COUNT]

Each partition is reduced to its length on its worker (`map_partitions(len)`),
so the time is the shards' computation and conversion to pandas, not the
transfer of the rows to the client. Needs the snowroll package, dask[dataframe,
distributed] and pandas (scripts/test-python.sh's venv has them).
"""

import os
import sys
import time

import snowroll


def grid(alpha_count):
    return {
        "model": "torque-cm,torque-contact,energy,quasi-circular",
        "alpha_deg": f"1:89:{alpha_count}",
        "snow_depth": "0.0001:0.1:500",
        "t_end": 100,
    }


def load():
    return "load " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def timed(frame):
    t0 = time.perf_counter()
    rows = int(frame.map_partitions(len).compute().sum())
    return rows, time.perf_counter() - t0


def main():
    from dask.distributed import Client, LocalCluster

    alpha_count = int(sys.argv[1]) if len(sys.argv) > 1 else 500
    big = grid(alpha_count)
    tiny = {"model": "torque-cm", "alpha_deg": "1:89:64", "t_end": 100}
    for workers in (1, 2, 4):
        with LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster, Client(cluster) as client:
            timed(snowroll.dask.sweep(tiny, shards=2))  # warm the workers up
            for shards in (workers, 4 * workers):
                rows, seconds = timed(snowroll.dask.sweep(big, shards=shards))
                print(
                    f"{workers} worker(s), {shards} shards: {rows} trajectories in "
                    f"{seconds:.2f} s, {rows / seconds:,.0f} per second ({load()})"
                )
            _, one = timed(snowroll.dask.sweep(tiny, shards=1))
            _, many = timed(snowroll.dask.sweep(tiny, shards=64))
            print(
                f"{workers} worker(s): 64 rows in 1 shard {one * 1e3:.0f} ms, in 64 shards "
                f"{many * 1e3:.0f} ms: {(many - one) / 63 * workers * 1e3:.1f} ms per extra shard "
                f"and worker ({load()})"
            )


if __name__ == "__main__":
    main()
