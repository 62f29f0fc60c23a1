"""No memory growth over 10^5 calls, and threads calling at once get the
same results as one thread (the GIL is released during the computation, so
the runs really overlap)."""

import threading

import numpy as np
import pytest

import snowroll


def rss_bytes():
    """Resident set size of this process, from /proc (Linux)."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    pytest.skip("no VmRSS in /proc/self/status")


def cheap_calls(n):
    # The cheapest run with every part of the result: a few steps, numpy
    # columns, stop and params dicts; every 10th call a ValueError.
    for i in range(n):
        if i % 10 == 9:
            try:
                snowroll.simulate("torque-cm", alpha_deg=95)
            except ValueError:
                pass
        else:
            r = snowroll.simulate("torque-cm", t_end=0.01, times=[0.0, 0.01])
            assert len(r) == 2


def test_no_memory_growth_over_1e5_calls():
    """After a warm-up (allocator pools, numpy caches), 10^5 more calls may
    not grow the RSS by more than 4 MiB. A leak of even the smallest object
    each call leaves behind (a dict of 7 keys, ~200 bytes; one column array,
    ~100 bytes) would grow it by 10 MiB or more."""
    cheap_calls(10_000)
    before = rss_bytes()
    cheap_calls(100_000)
    growth = rss_bytes() - before
    assert growth < 4 * 2**20, f"RSS grew by {growth / 2**20:.1f} MiB over 10^5 calls"


def test_threads_give_the_same_results():
    cases = [
        ("torque-cm", {"alpha_deg": 20 + k, "t_end": 30}) for k in range(4)
    ] + [("turns-exact", {"turns": 40, "alpha_deg": 35}), ("energy", {"dt": 0.01, "t_end": 60})]
    serial = [snowroll.simulate(m, **kw) for m, kw in cases]
    results = {}
    errors = []
    start = threading.Barrier(len(cases) * 2)

    def work(slot, model, kwargs):
        try:
            start.wait()
            results[slot] = snowroll.simulate(model, **kwargs)
        except Exception as e:  # reported below
            errors.append(e)

    threads = [
        threading.Thread(target=work, args=(2 * i + j, m, kw))
        for i, (m, kw) in enumerate(cases)
        for j in range(2)
    ]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for i, expected in enumerate(serial):
        for j in range(2):
            got = results[2 * i + j]
            assert got.columns == expected.columns
            for name in expected.columns:
                assert np.array_equal(got[name], expected[name]), (i, name)
            assert got.stop == expected.stop


# Issue 20, item 6: bounds on what a call holds, and Ctrl-C while it runs.


def test_a_result_that_cannot_fit_is_refused_before_it_starts():
    import time

    t = time.monotonic()
    with pytest.raises(MemoryError, match="max_memory"):
        snowroll.turns("turns", turns=10**8)
    with pytest.raises(MemoryError, match="max_memory"):
        snowroll.sweep({"model": "torque-cm", "alpha_deg": "1:80:20000", "snow_depth": "0.001:0.1:1000"})
    # Refused up front: no turn and no sweep row was computed (either would
    # take seconds).
    assert time.monotonic() - t < 1.0
    # The keyword moves the limit both ways: 1000 turns need ~0.4 MB.
    with pytest.raises(MemoryError):
        snowroll.turns("turns", turns=1000, max_memory=10_000)
    assert len(snowroll.turns("turns", turns=1000, max_memory=10**7).turn) == 1000


def test_a_run_of_unknown_length_stops_at_the_limit_with_memory_error():
    # Every accepted step is a row: the count is not known beforehand, so
    # the guard counts rows as they come.
    with pytest.raises(MemoryError, match="simulate"):
        snowroll.simulate("torque-cm", t_end=1e4, max_memory=10_000)


def test_ctrl_c_interrupts_a_long_run_within_a_second():
    import os
    import signal
    import time

    # Python's own Ctrl-C handler while the test runs: a process that a
    # non-interactive shell starts in the background (scripts/test.sh runs
    # pytest beside the browser tests) inherits SIGINT ignored, and Python
    # then leaves it ignored, so no KeyboardInterrupt could be raised.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        # 3x10^6 turns take about 20 s; SIGINT after 0.3 s must end the call
        # within a second of it (the guard looks every 0.1 s).
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        t = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            snowroll.turns("turns", turns=3 * 10**6, max_memory=10**10)
        assert time.monotonic() - t < 1.3
    finally:
        signal.signal(signal.SIGINT, previous)


def test_sweep_chunks_give_the_whole_sweep_bit_for_bit():
    grid = {"model": "torque-cm,energy", "alpha_deg": "5:60:12", "snow_depth": [0.01, 0.02], "t_end": 5}
    whole = snowroll.sweep(grid)
    parts = list(snowroll.sweep_chunks(grid, rows=10))
    assert len(parts) == 5  # 48 rows in chunks of about 10
    joined = snowroll.SweepResult.concat(parts)
    for name in ("index", "t_s", "x_m", "v_m_s", "a_over_g_sin_alpha"):
        assert np.array_equal(joined[name], whole[name], equal_nan=True), name
