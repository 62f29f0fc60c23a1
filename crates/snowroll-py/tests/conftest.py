"""Shared fixtures: the release CLI binary the Python results are compared with."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def cli() -> pathlib.Path:
    """The `snowroll` CLI built from the same sources (scripts/test-python.sh builds it)."""
    target = ROOT / os.environ.get("CARGO_TARGET_DIR", "target")  # an absolute one replaces ROOT
    path = pathlib.Path(os.environ.get("SNOWROLL_CLI", target / "release" / "snowroll"))
    if not path.exists():
        pytest.fail(f"the CLI binary {path} is missing: run `cargo build --release -p snowroll-cli`")
    return path


def run_cli(cli, *args, ok=True):
    """Runs the CLI; returns (stdout, stderr)."""
    out = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, check=False)
    if ok:
        assert out.returncode == 0, out.stderr
    else:
        assert out.returncode == 1, f"{args} should fail"
    return out.stdout, out.stderr


def parse_csv(text):
    """A CSV output of the CLI: (header comments as `key -> value`, columns as
    float64 arrays; `turn` as uint64). The CLI writes floats in the shortest
    form that reads back to the same double (ryu), so `float()` recovers its
    values bit for bit. An empty cell (|F|/N where N <= 0, undefined) becomes
    a masked entry with 0.0 under the mask, as the binding returns it."""
    meta = {}
    lines = []
    for line in text.splitlines():
        if line.startswith("# "):
            key, sep, value = line[2:].partition(" = ")
            if sep:
                meta.setdefault(key, value)
        elif line:
            lines.append(line)
    names = lines[0].split(",")
    rows = [line.split(",") for line in lines[1:]]
    cols = {}
    for i, name in enumerate(names):
        values = [row[i] for row in rows]
        if name == "turn":
            cols[name] = np.array([int(v) for v in values], dtype=np.uint64)
        elif any(v == "" for v in values):
            data = np.array([float(v) if v else 0.0 for v in values], dtype=np.float64)
            cols[name] = np.ma.masked_array(data, mask=[v == "" for v in values])
        else:
            cols[name] = np.array([float(v) for v in values], dtype=np.float64)
    return meta, cols


def same_bits(a, b):
    """Equal element by element to the last bit (NaN equal to NaN of the same
    payload), and masked at the same entries (an unmasked array has none)."""
    if not np.array_equal(np.ma.getmaskarray(a), np.ma.getmaskarray(b)):
        return False
    a = np.ascontiguousarray(np.ma.getdata(a))
    b = np.ascontiguousarray(np.ma.getdata(b))
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()
