"""The stub python/asperity/_native.pyi against the classes the extension builds: every public
attribute the stub declares exists on a sample result and every one the result has is in the
stub, each value has the stub's type (what mypy reads: ``r.a_r`` is a float), and each value
is the number of ``to_dict()`` under the same key (the CLI's JSON)."""

from __future__ import annotations

import ast
import inspect
import math
import typing
from pathlib import Path
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Set, Tuple

import numpy as np
import numpy.typing as npt
import pytest

import asperity
from asperity import _native

if TYPE_CHECKING:
    from typing_extensions import assert_type

    def _mypy_reads_the_types(r: asperity.Report) -> None:
        """Checked by mypy only (CI's `mypy python/tests`): an attribute typed Any fails."""
        assert_type(r.a_r, float)
        assert_type(r.mean_gap_rel, Optional[float])
        assert_type(r.iterations, int)
        assert_type(r.pr.sigma, npt.NDArray[np.float64])
        assert_type(r.branches[0].a_r, float)
        assert_type(r.window, Tuple[float, float])

    def _mypy_reads_the_records(g: asperity.GfmdResult, c: asperity.GfmdCycleResult, p: asperity.PsdResult) -> None:
        assert_type(g.a_r, float)
        assert_type(g.pr.sigma, npt.NDArray[np.float64])
        assert_type(c.pull_off_bracket, Optional[Tuple[float, float]])
        assert_type(c.theory_cycle, Optional[asperity.CycleResult])
        assert_type(p.rms_gradient, float)


STUB = Path(asperity.__file__).with_name("_native.pyi")

# the result classes built in Rust (python/src/report.rs, python/src/record.rs)
CLASSES = ("Report", "Pr", "Resolution", "BranchReport", "Record")


def _stub_classes() -> Dict[str, Tuple[Dict[str, str], Set[str]]]:
    """Per class of the stub: its properties' return annotations and its public methods (its
    stub-only bases' included)."""
    tree = ast.parse(STUB.read_text())
    found: Dict[str, Tuple[Dict[str, str], Set[str]]] = {}
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        props: Dict[str, str] = {}
        methods: Set[str] = set()
        for base in node.bases:
            if isinstance(base, ast.Name) and base.id in found:
                props.update(found[base.id][0])
                methods |= found[base.id][1]
        for f in node.body:
            if not isinstance(f, ast.FunctionDef) or f.name.startswith("_"):
                continue
            if any(isinstance(d, ast.Name) and d.id == "property" for d in f.decorator_list):
                assert f.returns is not None, f"{node.name}.{f.name} has no type"
                props[f.name] = ast.unparse(f.returns)
            else:
                methods.add(f.name)
        found[node.name] = (props, methods)
    return found


def _runtime(cls: type) -> Tuple[Set[str], Set[str]]:
    """The public attributes (getters) and methods of a class of the extension."""
    names = [n for n in dir(cls) if not n.startswith("_")]
    attrs = {n for n in names if inspect.isdatadescriptor(getattr(cls, n))}
    return attrs, set(names) - attrs


def _type(annotation: str) -> Any:
    """An annotation of the stub as a typing object."""
    names: Dict[str, Any] = {k: getattr(typing, k) for k in ("Any", "Dict", "List", "Optional", "Tuple")}
    names.update({k: getattr(_native, k) for k in CLASSES})
    names.update(FloatArray=npt.NDArray[np.float64], np=np, npt=npt)
    return eval(annotation, names)


def _conforms(v: Any, t: Any) -> bool:
    """Whether `v` has type `t` (the typing forms the stub uses)."""
    origin, args = typing.get_origin(t), typing.get_args(t)
    if t is type(None):
        return v is None
    if origin is typing.Union:
        return any(_conforms(v, a) for a in args)
    if origin is list:
        return isinstance(v, list) and all(_conforms(x, args[0]) for x in v)
    if origin is tuple:
        return isinstance(v, tuple) and len(v) == len(args) and all(_conforms(x, a) for x, a in zip(v, args))
    if origin is dict:
        return isinstance(v, dict) and all(_conforms(k, args[0]) and _conforms(x, args[1]) for k, x in v.items())
    if origin is np.ndarray:
        # a float64 array, made once and read-only
        return isinstance(v, np.ndarray) and v.dtype == np.float64 and not v.flags.writeable
    if t is float:
        return isinstance(v, float)
    if t is int:
        return isinstance(v, int) and not isinstance(v, bool)
    return isinstance(v, t)


def _same(v: Any, plain: Any) -> bool:
    """Whether an attribute is the number (or list, or object) `to_dict()` has for it."""
    if isinstance(v, np.ndarray):
        return isinstance(plain, list) and np.array_equal(v, [math.nan if x is None else x for x in plain], equal_nan=True)
    if isinstance(v, tuple):
        return list(v) == plain
    if isinstance(v, list):
        return [x.to_dict() if hasattr(x, "to_dict") else x for x in v] == plain
    if hasattr(v, "to_dict"):
        return bool(v.to_dict() == plain)
    if isinstance(v, float) and plain is None:
        return not math.isfinite(v)
    return bool(v == plain)


@pytest.fixture(scope="module")
def reports() -> List[Any]:
    # adhesive (branches, a gap bracket) and adhesionless at a load beside its neighbours
    return [
        asperity.evaluate(asperity.Scene.preset("system-2")),
        asperity.evaluate(asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0, pressure=0.02)),
    ]


def _samples(reports: List[Any]) -> Dict[str, List[Any]]:
    return {
        "Report": reports,
        "Pr": [r.pr for r in reports],
        "Resolution": [r.resolution for r in reports],
        "BranchReport": [b for r in reports for b in r.branches],
        "Record": [x for r in reports for x in (r.scene, r.trust)],
    }


def test_asperity_report_is_the_extensions_class():
    assert asperity.Report is _native.Report
    assert _native.evaluate.__name__ == "evaluate"


@pytest.mark.parametrize("name", CLASSES)
def test_stub_declares_every_attribute_and_method(name):
    props, methods = _stub_classes()[name]
    attrs, runtime_methods = _runtime(getattr(_native, name))
    assert set(props) == attrs, f"stub only: {set(props) - attrs}; runtime only: {attrs - set(props)}"
    assert methods == runtime_methods, f"stub only: {methods - runtime_methods}; runtime only: {runtime_methods - methods}"


@pytest.mark.parametrize("name", CLASSES)
def test_values_have_the_stubs_types(name, reports):
    props, _ = _stub_classes()[name]
    samples = _samples(reports)[name]
    assert samples, name
    for obj in samples:
        assert type(obj) is getattr(_native, name)
        for attr, annotation in props.items():
            v = getattr(obj, attr)
            assert _conforms(v, _type(annotation)), f"{name}.{attr} = {v!r} is not {annotation}"


@pytest.mark.parametrize("name", CLASSES)
def test_attributes_are_the_dicts_values(name, reports):
    props, _ = _stub_classes()[name]
    for obj in _samples(reports)[name]:
        plain = obj.to_dict()
        # every key of the CLI's JSON is an attribute (a record's attributes are its keys)
        assert name == "Record" or set(plain) <= set(props), set(plain) - set(props)
        for key, x in plain.items():
            assert _same(getattr(obj, key), x), f"{name}.{key}: {getattr(obj, key)!r} != {x!r}"


def test_results_are_frozen(reports):
    r = reports[0]
    for obj, attr in ((r, "a_r"), (r, "other"), (r.pr, "sigma"), (r.branches[0], "a_r"), (r.scene, "pressure")):
        with pytest.raises(AttributeError):
            setattr(obj, attr, 1.0)
    assert r.scene is r.scene and r.trust.nearest is r.trust.nearest
    assert r.to_dict() is not r.to_dict() and r.to_dict() == r.to_dict()
    assert "a_r" in r and r["a_r"] == r.a_r and list(r) == r.keys()
    with pytest.raises(AttributeError, match="has no field or column 'nope'"):
        r.scene.nope
    with pytest.raises(KeyError):
        r["nope"]
    assert repr(r).startswith("Report(preset='system-2', a_r=")


@pytest.fixture(scope="module")
def load_sweep() -> Any:
    # an adhesive load sweep with the theory's cycle: columns of floats, bools and strings
    return asperity.sweep(asperity.Scene.preset("system-2"), np.geomspace(1e-3, 1e-2, 3), cycle=True)


@pytest.fixture(scope="module")
def records(load_sweep) -> Dict[str, Any]:
    """A sample of each result class over a Rust record, on small grids."""
    s1 = asperity.Scene.preset("system-1").replace(pressure=0.05, surface_energy_j_m2=0.0)
    s2 = asperity.Scene.preset("system-2")
    g = asperity.gfmd(s1, grid=32)
    with pytest.warns(asperity.ResolutionWarning):
        cyc = asperity.gfmd_cycle(s2, 1e-3, 4e-3, points=3, grid=32)
    return {
        "SweepResult": load_sweep,
        "CycleResult": load_sweep.cycle,
        "PullOffResult": load_sweep.pull_off,
        "GfmdResult": g,
        "GfmdCycleResult": cyc,
        "GfmdSweepResult": asperity.gfmd_sweep(s1, 0.02, 0.05, points=2, grid=32),
        "PsdResult": asperity.psd(g.heights, g.system_size_m),
        "GaugeResult": asperity.gauge(s1, ["c1"], "eq18", from_=1e-3, to=0.3, points=6),
    }


def _hints(cls: type) -> Dict[str, Any]:
    return {k: t for k, t in typing.get_type_hints(cls).items() if not k.startswith("_")}


RECORDS = ("SweepResult", "CycleResult", "PullOffResult", "GfmdResult", "GfmdCycleResult", "GfmdSweepResult", "PsdResult", "GaugeResult")


@pytest.mark.parametrize("name", RECORDS)
def test_records_have_their_annotated_types(name, records):
    """The Python classes over a Rust record: every key of `to_dict()` is annotated (a type
    checker never sees Any), each annotated field has its type, every key and every row key
    is an attribute with the dict's numbers, made once, every array is read-only."""
    obj = records[name]
    cls = getattr(asperity, name)
    assert isinstance(obj, _native.Record) and isinstance(obj, asperity.Result) and type(obj) is cls
    hints = _hints(cls)
    plain = obj.to_dict()
    assert set(plain) <= set(hints), f"not annotated: {set(plain) - set(hints)}"
    for attr, t in hints.items():
        if attr in plain or attr in dir(obj):
            v = getattr(obj, attr)
            assert _conforms(v, t), f"{name}.{attr} = {v!r} is not {t}"
            assert v is getattr(obj, attr), attr
    for key, x in plain.items():
        assert _same(getattr(obj, key), x), f"{name}.{key}"
    rows = plain.get("rows") or plain.get("table") or []
    for key in [k for k in (rows[0] if rows else ()) if k not in plain]:
        col = getattr(obj, key)
        assert isinstance(col, np.ndarray) and not col.flags.writeable and len(col) == len(rows), key
        want = [r[key] for r in rows]
        assert _same(col, want) if col.dtype == np.float64 else col.tolist() == want, key
    with pytest.raises(AttributeError):
        obj.a_r = None


def test_gfmd_results_keep_their_map_out_of_the_dict_and_through_pickle(records):
    import pickle

    for name in ("GfmdResult", "GfmdCycleResult", "GfmdSweepResult"):
        g = records[name]
        assert isinstance(g.heights, np.ndarray) and g.heights.shape == (32, 32) and g.heights is g.heights
        assert "heights" not in g.to_dict() and "heights" not in g
        again = pickle.loads(pickle.dumps(g))
        assert type(again) is type(g) and again.to_dict() == g.to_dict()
        assert np.array_equal(again.heights, g.heights)
    c = records["GfmdCycleResult"]
    assert isinstance(c.theory_cycle, asperity.CycleResult) and c.theory_cycle is c.theory_cycle
    assert isinstance(records["GfmdResult"].pr, _native.Pr) and records["PsdResult"].modes.dtype.kind == "i"


def test_a_record_from_a_plain_dict_is_the_same(load_sweep):
    d = load_sweep.cycle.to_dict()
    again = asperity.CycleResult(d)
    assert again.to_dict() == d and np.array_equal(again.a_r, load_sweep.cycle.a_r)
    assert asperity.SweepResult(load_sweep).values is load_sweep.values


def test_results_pickle_and_rebuild_from_their_dicts(reports, load_sweep):
    """Every result class is made again from its `to_dict()` (`Report(d)`), and so pickles
    (a process pool returns results through pickle)."""
    import pickle

    r = reports[0]
    for obj in (r, r.pr, r.resolution, r.branches[0], r.scene, load_sweep, load_sweep.cycle):
        again = pickle.loads(pickle.dumps(obj))
        assert type(again) is type(obj) and again.to_dict() == obj.to_dict()
        assert type(obj)(obj.to_dict()).to_dict() == obj.to_dict()
    again = pickle.loads(pickle.dumps(r))
    assert again.a_r == r.a_r and np.array_equal(again.pr.sigma, r.pr.sigma) and again.branches[0].a_r == r.branches[0].a_r
    assert np.array_equal(pickle.loads(pickle.dumps(load_sweep)).values, load_sweep.values)
