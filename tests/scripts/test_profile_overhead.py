"""scripts/profile_overhead.py: the pieces of its method, and a smoke run that writes the CSV, the
PNG and the summary (tiny repeat counts; timings are never asserted, only their consistency)."""

from __future__ import annotations

import csv
import importlib.util
import math
import sys
from pathlib import Path

import numpy as np
import pytest

import ivy

ROOT = Path(__file__).resolve().parents[2]


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


po = _load("profile_overhead", ROOT / "scripts" / "profile_overhead.py")
nt = sys.modules["_native_trace"]


@pytest.fixture
def other_backend(request):
    """numpy's partner in the smoke run: the first other installed backend under test."""
    others = [b for b in request.config.ivy_backends if b != "numpy"]
    if not others:
        pytest.skip("needs a backend besides numpy")
    return others[0]


# ----------------------------------------------------------------------------------------------
# Discovery and inputs
# ----------------------------------------------------------------------------------------------


def test_discovery_lists_every_core_name_once_with_skips_explained():
    entries, skipped = po.discover()
    names = [e.name for e in entries] + [s["function"] for s in skipped]
    assert sorted(names) == sorted(set(names))
    assert set(ivy.core.__all__) <= set(names)
    reasons = {s["function"]: s["reason"] for s in skipped}
    assert "alias of concat" in reasons["concatenate"]
    kinds = {e.name: e.kind for e in entries}
    assert kinds["sin"] == "function"
    assert kinds["lstm_update"] == "composition"


def test_inputs_come_from_the_signature_and_the_overrides():
    args, kwargs = po.input_spec("add", ivy.add)
    assert len(args) == 2 and all(isinstance(a, po.A) for a in args) and not kwargs
    assert math.prod(args[0].shape) == po.N_ELEMENTS
    args, kwargs = po.input_spec("clip", ivy.clip)  # min/max given: not a mere copy
    assert kwargs == {} and args[1:] == [0.2, 0.5]
    args, kwargs = po.input_spec("zeros", ivy.zeros)
    assert args == [po.SQUARE]
    with pytest.raises(po.Unbuildable, match="higher-order"):
        po.input_spec("compile_fn", ivy.compile_fn)


def test_primary_ops_are_those_named_like_the_function():
    def op(name):
        return nt.Op(name, name, None, (), {}, (), {}, [], True)

    chosen, matched = po.primary_ops("sign", [op("isnan"), op("sign"), op("where")])
    assert [o.name for o in chosen] == ["sign"] and matched
    chosen, matched = po.primary_ops("clip", [op("clamp")])
    assert [o.name for o in chosen] == ["clamp"] and matched
    assert po.primary_ops("mean", [op("Mean")])[1]
    assert po._matches("mean", "reduce_mean") and po._matches("concat", "ConcatV2")
    # nothing named like the function: every op is primary, and the row says so
    chosen, matched = po.primary_ops("trunc", [op("Less"), op("Ceil"), op("Floor")])
    assert len(chosen) == 3 and not matched


# ----------------------------------------------------------------------------------------------
# Tracing native ops and replaying them
# ----------------------------------------------------------------------------------------------


def _softmax_like(xp):
    def fn(x):
        e = xp.exp(xp.subtract(x, xp.max(x, axis=-1, keepdims=True)))
        return xp.divide(e, xp.sum(e, axis=-1, keepdims=True))

    return fn


@pytest.mark.parametrize("which", ["numpy", "other"])
def test_trace_records_native_ops_and_the_replay_computes_the_same(which, request):
    if which == "numpy":
        backend = "numpy"
    else:
        backend = request.getfixturevalue("other_backend")
    xp = getattr(ivy, backend)
    x = xp.asarray(np.linspace(-1, 1, 60, dtype=np.float32).reshape(6, 10))
    fn = _softmax_like(xp)
    tr, result = nt.trace(backend, fn, (x,), {})
    compute = [op for op in tr.ops if op.compute]
    assert len(compute) >= 4, tr.names()
    replay, arrays = nt.program(tr, compute)
    (out,) = replay(*arrays)
    expected = np.asarray(ivy.to_numpy(result))
    np.testing.assert_allclose(np.asarray(ivy.to_numpy(out)), expected, rtol=1e-5, atol=1e-6)
    # a subset reads what it needs from outside as arguments
    sub, sub_arrays = nt.program(tr, compute[-1:])
    assert len(sub_arrays) >= 1
    np.testing.assert_allclose(
        np.asarray(ivy.to_numpy(sub(*sub_arrays)[0])), expected, rtol=1e-5, atol=1e-6
    )


# ----------------------------------------------------------------------------------------------
# The smoke run
# ----------------------------------------------------------------------------------------------


def test_smoke_run_writes_csv_png_and_summary(tmp_path, other_backend, capsys):
    backends = ["numpy", other_backend]
    composition = next(n for n in ("linear", "lstm_update") if n in ivy.core.__all__)
    functions = ["add", "clip", composition, "compile_fn"]
    po.main(
        [
            "--functions",
            ",".join(functions),
            "--backends",
            ",".join(backends),
            "--library",
            "euler_to_rot_mat",
            "--out",
            str(tmp_path),
            "--repeats",
            "4",
            "--sample-ms",
            "0.3",
            "--torch-compile",
            "none",
            "--threads",
            "0",
            "--no-progress",
        ]
    )
    printed = capsys.readouterr().out

    with open(tmp_path / "overhead.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert set(rows[0]) == set(po.FIELDS)
    ok = {(r["function"], r["backend"]): r for r in rows if r["status"] == "ok"}
    library = "ivy_mechanics.euler_to_rot_mat"
    for name in ("add", "clip", composition, library):
        for backend in backends:
            assert (name, backend) in ok, [r for r in rows if r["function"] == name]
    skipped = [r for r in rows if r["status"] == "skipped"]
    assert [r["function"] for r in skipped] == ["compile_fn"]
    assert "higher-order" in skipped[0]["reason"]

    assert ok[("add", "numpy")]["native_source"] == "native object"
    assert ok[(composition, "numpy")]["native_source"] == "hand-written"
    assert ok[(library, other_backend)]["native_source"] == "hand-written"
    if other_backend == "torch":
        assert ok[("clip", "torch")]["native_ops"] == "torch.clamp"
    for row in ok.values():
        total = float(row["total_us"])
        groups = [float(row[c]) for c in ("backend_us", "ivy_compilable_us", "ivy_eager_us")]
        assert total > 0 and groups[0] > 0 and min(groups) >= 0
        # the groups partition the eager time (unless the native ops alone took longer)
        assert sum(groups) == pytest.approx(max(total, groups[0] + groups[1]), rel=1e-4)
        expected = 100 * (total - groups[0]) / groups[0]
        assert float(row["eager_overhead_pct"]) == pytest.approx(expected, rel=1e-4, abs=1e-3)
        assert row["compiled_source"] in ("measured", "estimated")
        assert float(row["noise_pct"]) >= 0
    if other_backend in ("jax", "tensorflow"):  # compilers that need no minutes
        assert ok[(composition, other_backend)]["compiled_source"] == "measured"
        assert float(ok[(composition, other_backend)]["compiled_ivy_us"]) > 0

    png = (tmp_path / "overhead.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    import matplotlib.image

    height, width, _ = matplotlib.image.imread(tmp_path / "overhead.png").shape
    assert width > 500 and height > 200

    summary = (tmp_path / "summary.md").read_text()
    assert summary in printed
    for backend in backends:
        assert f"| {backend} |" in summary
    assert "median eager overhead" in summary and "compile_fn [all]: takes a function" in summary
    assert library in summary
