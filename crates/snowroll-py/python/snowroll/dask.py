"""A sweep as a ``dask.dataframe``, its shards run as tasks of a Dask cluster.

    import snowroll, dask.distributed
    client = dask.distributed.Client("tcp://scheduler:8786")   # or a LocalCluster
    frame = snowroll.dask.sweep(grid, client, shards=64)
    frame.to_parquet("sweep/")          # or frame.compute(), frame.groupby(...)

Needs ``dask[dataframe]`` (and ``distributed`` for a client); dask is imported
only when :func:`sweep` is called, so ``import snowroll`` works without it.
"""

from __future__ import annotations

from typing import Any, List, Mapping, Optional, Tuple

from . import _count, _grid, _snowroll, _suggesting, _text
from . import sweep as _sweep

__all__ = ["sweep", "shard_bounds"]

# A shard count larger than any grid: its shard 0 holds no row, so running it
# costs nothing and still returns the grid's size.
_NO_ROWS = 2**64 - 1


@_suggesting
def shard_bounds(grid: Mapping[str, Any], shards: int) -> List[Tuple[int, int]]:
    """The ``(start, end)`` grid indices of each of ``shards`` shards of
    ``grid`` (end excluded), the split of ``snowroll.sweep(grid, shard=(i,
    shards))`` and of the CLI's ``--shard i/N``. Raises ``ValueError`` for a
    bad grid or ``shards`` outside ``1 <= shards <= points``, so that no
    shard is empty."""
    shards = _count("shards", shards, 1)
    points = _snowroll.grid_len(_grid(grid))
    if shards > points:
        raise ValueError(
            f"shards = {shards} is out of range: expected 1 <= shards <= {points} "
            "(the grid's points), so that no shard is empty"
        )
    cut = [points * k // shards for k in range(shards + 1)]
    return list(zip(cut[:-1], cut[1:]))


def _shard_frame(grid: Mapping[str, Any], i: int, n: int, method: str) -> Any:
    # One task, on a worker: shard i of n as a pandas frame indexed by the
    # grid index (the library runs the rows on the worker's threads, the GIL
    # released).
    return _sweep(grid, shard=(i, n), method=method).to_pandas().set_index("index")


@_suggesting
def sweep(
    grid: Mapping[str, Any],
    client: Optional[Any] = None,
    *,
    shards: int,
    method: str = "auto",
) -> Any:
    """The rows of :func:`snowroll.sweep` ``(grid, method=method)`` as a
    ``dask.dataframe.DataFrame`` of ``shards`` partitions, partition i being
    shard i of the grid. The frame is indexed by the grid index (``index``,
    uint64; its divisions are the shards' first indices and the last index),
    the columns and dtypes are those of ``snowroll.sweep(grid).to_pandas()``,
    and the rows are the same values bit for bit, whatever the number of
    shards or of threads per worker.

    ``client``: a ``dask.distributed.Client``; the shards are submitted to it
    at once (the frame holds their futures; a shard whose worker dies is run
    again by the scheduler). ``None``: the frame is lazy and runs on the
    current scheduler when computed. Raises ``ValueError`` for a bad grid or
    ``shards`` outside ``1 <= shards <= points``; ``ImportError`` without
    dask."""
    try:
        import dask.dataframe as dd
        from dask import delayed
        from dask.base import tokenize
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError('snowroll.dask needs dask: pip install "dask[dataframe,distributed]"') from e
    method = _text("method", method) or "auto"
    grid = dict(grid)
    bounds = shard_bounds(grid, shards)
    n = len(bounds)
    meta = _sweep(grid, shard=(0, _NO_ROWS), method=method).to_pandas().set_index("index")
    divisions = [start for start, _ in bounds] + [bounds[-1][1] - 1]
    if client is None:
        parts = [delayed(_shard_frame, pure=True)(grid, i, n, method) for i in range(n)]
    else:
        token = tokenize(grid, n, method, _snowroll.__version__)
        parts = [
            client.submit(_shard_frame, grid, i, n, method, key=f"snowroll-shard-{token}-{i}")
            for i in range(n)
        ]
    return dd.from_delayed(parts, meta=meta, divisions=divisions, verify_meta=False)
