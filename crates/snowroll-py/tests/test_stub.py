"""The type stub of the native module is the one the parameter table writes,
and the keywords of simulate() and turns() are the table's."""

import inspect
from pathlib import Path

import pytest

import snowroll
from snowroll import _stubgen

STUB = Path(__file__).resolve().parents[1] / "python" / "snowroll" / "_snowroll.pyi"


def test_committed_stub_is_the_one_the_table_writes():
    # A parameter added to, renamed in or removed from the table changes the
    # stub: write it again with `python -m snowroll._stubgen`.
    assert STUB.read_text() == _stubgen.stub(), (
        f"{STUB} is stale: python -m snowroll._stubgen > {STUB}"
    )


@pytest.mark.parametrize("function, scopes", [("simulate", {"shared", "sampling", "turns"}),
                                              ("turns", {"shared", "turns"})])
def test_keywords_are_the_table_s(function, scopes):
    want = {p["key"] for p in snowroll.PARAMS if p["scope"] in scopes}
    sig = inspect.signature(getattr(snowroll, function))
    # The table's keywords, and max_memory, the Python call's own bound.
    got = set(sig.parameters) - {"model", "max_memory"}
    assert got == want
    assert sig.parameters["max_memory"].default == snowroll.MAX_MEMORY
    doc = getattr(snowroll, function).__doc__
    for key in want:
        assert f"``{key}``" in doc, key


def test_unknown_keyword_is_a_type_error_naming_it():
    with pytest.raises(TypeError, match="unexpected keyword argument 'alpha'"):
        snowroll.simulate("energy", alpha=30)
    with pytest.raises(TypeError, match="unexpected keyword argument 'dt'"):
        snowroll.turns("turns", dt=0.1)


def test_table_defaults_are_those_the_runs_record():
    # The defaults the table states are the ones a run with no keyword records.
    r = snowroll.simulate("energy", t_end=1)
    for p in snowroll.PARAMS:
        if p["key"] in r.params and p["key"] != "t_end" and p["scope"] == "shared":
            assert r.params[p["key"]] == p["default"], p["key"]
