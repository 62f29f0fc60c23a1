"""Python's pieces as strict as the CLI (issue 33, item 3): shards joined as
`snowroll merge` joins them, MemoryError instead of an aborted interpreter,
a sweep's memory per row measured against the bound it is checked with,
TypeError for values simulate() refuses, and the nearest keyword named."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import snowroll

GRID = {"model": "torque-cm,energy", "alpha_deg": "5:60:12", "snow_depth": [0.01, 0.02], "t_end": 5}


def shards(grid, n):
    return [snowroll.sweep(grid, shard=(i, n)) for i in range(n)]


# SweepResult.concat, checked like `merge`.


def test_concat_of_every_shard_in_any_order_is_the_whole_sweep():
    whole = snowroll.sweep(GRID)
    parts = shards(GRID, 4)
    joined = snowroll.SweepResult.concat([parts[2], parts[0], parts[3], parts[1]])
    assert (len(joined), joined.shard, joined.rows) == (48, (0, 1), (0, 48))
    for name in whole.columns:
        assert np.array_equal(joined[name], whole[name], equal_nan=name not in snowroll.SweepResult.TEXT_COLUMNS), name
    # A joined sweep is itself the one shard of its grid.
    assert snowroll.SweepResult.concat([joined])["index"].tolist() == list(range(48))


def test_concat_refuses_a_missing_shard_naming_its_rows():
    parts = shards(GRID, 3)
    with pytest.raises(ValueError, match=r"^concat\(\): missing shards: 1/3 \(rows 16\.\.32\) of the 48 points$"):
        snowroll.SweepResult.concat([parts[0], parts[2]])
    # The case: one shard of two ("2 rows of 4" was returned).
    grid = {"model": "torque-cm", "alpha_deg": [10, 20, 30, 40]}
    with pytest.raises(ValueError, match=r"missing shards: 1/2 \(rows 2\.\.4\) of the 4 points"):
        snowroll.SweepResult.concat([snowroll.sweep(grid, shard=(0, 2))])


def test_concat_refuses_shards_of_two_grids_naming_each_difference():
    # The case: the same shape, other values (rows with alpha 10, 20,
    # 70, 80 were returned as one sweep).
    a = snowroll.sweep({"model": "torque-cm", "alpha_deg": [10, 20, 30, 40]}, shard=(0, 2))
    b = snowroll.sweep({"model": "torque-cm", "alpha_deg": [50, 60, 70, 80]}, shard=(1, 2))
    with pytest.raises(ValueError) as err:
        snowroll.SweepResult.concat([a, b])
    assert str(err.value) == (
        "concat(): parts 0 and 1 are not shards of the same sweep: "
        "alpha_deg: 10,20,30,40 in part 0, 50,60,70,80 in part 1"
    )
    # A setting left at its default equals the same value given; a method differs.
    c = snowroll.sweep({"model": "torque-cm", "alpha_deg": [10, 20, 30, 40], "t_end": 100}, shard=(1, 2))
    assert len(snowroll.SweepResult.concat([a, c])) == 4
    d = snowroll.sweep({"model": "torque-cm", "alpha_deg": [10, 20, 30, 40]}, shard=(1, 2), method="ode")
    with pytest.raises(ValueError, match="method: auto in part 0, ode in part 1"):
        snowroll.SweepResult.concat([a, d])


def test_concat_refuses_a_shard_twice_other_shard_counts_and_edited_parts():
    parts = shards(GRID, 3)
    with pytest.raises(ValueError, match=r"shard 1/3 is given twice: parts 1 and 2"):
        snowroll.SweepResult.concat([parts[0], parts[1], parts[1], parts[2]])
    with pytest.raises(ValueError, match="shards: 3 in part 0, 2 in part 1"):
        snowroll.SweepResult.concat([parts[0], snowroll.sweep(GRID, shard=(1, 2))])
    # A part whose rows were dropped since (a gap in the grid).
    parts[1]._columns = {k: v[:-1] for k, v in parts[1].to_dict().items()}
    with pytest.raises(ValueError, match=r"part 1 \(shard 1/3\) does not hold the rows 16\.\.32 .* 15 rows"):
        snowroll.SweepResult.concat(parts)
    with pytest.raises(TypeError, match="part 0 is a list"):
        snowroll.SweepResult.concat([[1, 2]])


# MemoryError, never an aborted interpreter.


def run_limited(code, headroom_mb):
    """Runs `code` in a fresh interpreter whose address space is capped at
    what it holds after importing snowroll plus `headroom_mb`: an allocation
    past the cap fails, as one past the machine's memory does."""
    script = textwrap.dedent(
        f"""
        import resource, snowroll
        snowroll.sweep({{"model": "eq4", "alpha_deg": "5:60:100"}})  # thread pool and numpy up
        snowroll.turns("turns", turns=20000)  # the pool of the turns computed ahead up (more than a block of 8192)
        size = [int(l.split()[1]) * 1024 for l in open("/proc/self/status") if l.startswith("VmSize:")][0]
        cap = size + {headroom_mb} * 2**20
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
        try:
        {textwrap.indent(textwrap.dedent(code), "    ")}
            print("no error")
        except MemoryError as e:
            print("MemoryError:", e)
        finally:
            # The limit lifted once the call has answered: a thread that first
            # touches the module's thread-local data after it (at exit) would
            # otherwise meet the C library's lazy allocation of that data under
            # the cap, which aborts the process instead of failing (status 127,
            # 'cannot allocate memory for thread-local data').
            resource.setrlimit(resource.RLIMIT_AS, (soft, hard))
        """
    )
    return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize(
    "call",
    [
        # 5e6 rows, about 1 GB, in 64 MB.
        'snowroll.sweep({"model": "eq4", "alpha_deg": "5:60:5000000"}, max_memory=10**12)',
        # 10^7 turns in 64 MB, their count known before the run.
        'snowroll.turns("turns", turns=10**7, max_memory=10**12)',
        # Every step of a run of unknown length (3.5 steps a turn, 150 bytes
        # a step), growing past 64 MB within a second.
        'snowroll.simulate("turns", turns=10**7, t_end=1e9, max_memory=10**12)',
    ],
)
def test_an_allocation_that_fails_is_a_memory_error(call):
    out = run_limited(call, 64)
    assert out.returncode == 0, f"status {out.returncode}: {out.stderr[-2000:]}"
    assert out.stdout.startswith("MemoryError: "), out.stdout + out.stderr[-2000:]
    assert "could not allocate" in out.stdout or "available" in out.stdout, out.stdout


def test_more_than_the_machine_has_is_refused_before_the_run():
    # 10^9 rows (the most a grid may have) hold about 200 GB: past any
    # machine these tests run on, whatever max_memory allows.
    import time

    t = time.monotonic()
    with pytest.raises(MemoryError, match="more than this machine has available"):
        snowroll.sweep({"model": "eq4", "alpha_deg": "5:60:1000000000"}, max_memory=2**62)
    with pytest.raises(MemoryError, match="more than this machine has available"):
        snowroll.turns("turns", turns=10**10, max_memory=2**62)
    assert time.monotonic() - t < 1.0


# The memory of a sweep's rows, measured against the bound.

PEAK = """
import json, snowroll
def status(key):
    return [int(l.split()[1]) * 1024 for l in open("/proc/self/status") if l.startswith(key)][0]
snowroll.sweep({"model": "eq4", "alpha_deg": "5:60:1000"})  # thread pool and numpy up
base = status("VmRSS:")
open("/proc/self/clear_refs", "w").write("5")  # the peak (VmHWM) starts again from now
r = snowroll.sweep(GRID, max_memory=MAX)
print(json.dumps({"rows": len(r), "peak": status("VmHWM:") - base}))
"""


def peak_of(grid, max_memory):
    code = PEAK.replace("GRID", repr(grid)).replace("MAX", str(max_memory))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    import json

    return json.loads(out.stdout)


def test_a_sweep_row_costs_what_max_memory_is_checked_with():
    """The peak resident memory of a sweep, less what the process held
    before, over its rows, is at most SWEEP_ROW_BYTES a row, and not far
    below it (the bound stays a measurement, not a guess). 10^6 rows: the
    constant costs (the rayon pool's chunk buffers, about 10 MB) are 10 bytes
    a row. With the bound wrong (448 bytes a row estimated where 737 were
    used) this failed; at max_memory the peak stays under max_memory."""
    per_row = snowroll._snowroll.SWEEP_ROW_BYTES
    n = 10**6
    got = peak_of({"model": "eq4", "alpha_deg": f"5:60:{n}"}, n * per_row)
    assert got["rows"] == n
    measured = got["peak"] / n
    assert 0.7 * per_row <= measured <= per_row + 16, f"{measured:.0f} bytes a row, bound {per_row}"
    # Four models, two stops (distance, does-not-start) and three kinds of
    # warnings (none, b-over-r0, snow-ignored): shared strings, not one each.
    grid = {"model": "eq4,energy,snowless,loney", "alpha_deg": "0.5:89:62500", "snow_depth": [0.01, 0.5], "x_end": 50.0}
    got = peak_of(grid, 5 * 10**5 * per_row)
    assert got["rows"] == 5 * 10**5
    assert got["peak"] / got["rows"] <= per_row + 32, got
    # The largest grid max_memory admits holds at most max_memory.
    limit = 100 * 2**20
    rows = limit // per_row
    got = peak_of({"model": "eq4", "alpha_deg": f"5:60:{rows}"}, limit)
    assert got["peak"] <= limit + 16 * 2**20, got
    with pytest.raises(MemoryError, match="max_memory"):
        snowroll.sweep({"model": "eq4", "alpha_deg": f"5:60:{rows + 1}"}, max_memory=limit)


# Values simulate() refuses, refused by sweep() too.


@pytest.mark.parametrize(
    "value,message",
    [
        (np.array([10.0, 20.0]) + 0j, "alpha_deg: expected numbers, got an array of complex128"),
        (np.array([True, False]), "alpha_deg: expected numbers, got an array of bool"),
        ([10.0, 1 + 2j], "alpha_deg: expected a number, got complex"),
        ([10.0, True], "alpha_deg: expected a number, got bool"),
        (True, "alpha_deg: expected a number, got bool"),
        (np.bool_(True), "alpha_deg: expected a number, got bool"),
        (30 + 0j, "alpha_deg: expected a number, got complex"),
        (np.zeros((2, 2)), "alpha_deg: expected a 1-D array, got 2 dimensions"),
    ],
)
def test_sweep_refuses_complex_and_bool_as_simulate_does(value, message):
    with pytest.raises(TypeError) as err:
        snowroll.sweep({"model": "eq4", "alpha_deg": value})
    assert str(err.value) == message
    if not isinstance(value, (np.ndarray, list)):
        with pytest.raises(TypeError, match="^alpha_deg: expected a number, got "):
            snowroll.simulate(alpha_deg=value)


def test_sweep_takes_integer_and_float_arrays_as_before():
    a = snowroll.sweep({"model": "eq4", "alpha_deg": np.array([10, 20], dtype=np.int32)})
    b = snowroll.sweep({"model": "eq4", "alpha_deg": [10.0, 20.0]})
    c = snowroll.sweep({"model": "eq4", "alpha_deg": np.float32(10.0)})
    assert a.alpha_deg.tolist() == b.alpha_deg.tolist() == [10.0, 20.0]
    assert np.array_equal(a.v_m_s, b.v_m_s) and c.alpha_deg.tolist() == [10.0]


# The nearest keyword, as the CLI's "tip: a similar argument exists".


@pytest.mark.parametrize(
    "call,near",
    [
        (lambda: snowroll.simulate(alpha_dg=30), "simulate() got an unexpected keyword argument 'alpha_dg'; a similar keyword exists: 'alpha_deg'"),
        (lambda: snowroll.simulate(snowdepth=0.1), "simulate() got an unexpected keyword argument 'snowdepth'; a similar keyword exists: 'snow_depth'"),
        (lambda: snowroll.simulate(max_memroy=10), "simulate() got an unexpected keyword argument 'max_memroy'; a similar keyword exists: 'max_memory'"),
        (lambda: snowroll.turns(turn=3), "turns() got an unexpected keyword argument 'turn'; a similar keyword exists: 'turns'"),
        (lambda: snowroll.models(density_kg=3), "models() got an unexpected keyword argument 'density_kg'; a similar keyword exists: 'density'"),
        (lambda: snowroll.sweep({"model": "eq4"}, shards=(0, 2)), "sweep() got an unexpected keyword argument 'shards'; a similar keyword exists: 'shard'"),
        (lambda: snowroll.sweep_chunks({"model": "eq4"}, row=10), "sweep_chunks() got an unexpected keyword argument 'row'; a similar keyword exists: 'rows'"),
        (lambda: snowroll.simulate(colour=1), "simulate() got an unexpected keyword argument 'colour'"),
    ],
)
def test_a_misspelled_keyword_names_the_nearest(call, near):
    with pytest.raises(TypeError) as err:
        next(iter(call())) if "chunks" in near else call()
    assert str(err.value) == near


def test_a_misspelled_grid_key_names_the_nearest():
    with pytest.raises(ValueError, match=r"^unknown axis 'alpha_dg': .*; a similar key exists: 'alpha_deg'$"):
        snowroll.sweep({"model": "eq4", "alpha_dg": [10]})
    with pytest.raises(ValueError, match=r"^unknown axis 'colour': expected model, collision, on_hop or one of alpha_deg, .*mu$"):
        snowroll.sweep({"model": "eq4", "colour": [1]})


def test_the_suggestion_is_the_cli_s():
    """clap suggests by Jaro similarity above 0.7: the CLI's own tip for
    --alpha-dg is --alpha-deg, and nothing for --colour."""
    from snowroll import _jaro, _nearest

    assert _jaro("martha", "marhta") == pytest.approx(0.944444, abs=1e-6)  # the textbook value
    assert _jaro("dixon", "dicksonx") == pytest.approx(0.766667, abs=1e-6)
    assert _nearest("alpha-dg", ["alpha-deg", "snow-depth"]) == "alpha-deg"
    assert _nearest("colour", ["alpha-deg", "snow-depth", "r0"]) is None
