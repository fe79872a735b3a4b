"""scripts/profile_overhead.py: a smoke run that writes the CSV, the PNG and the summary (tiny
repeat counts; timings are never asserted, only that the groups are measured differences that
partition the total)."""

from __future__ import annotations

import csv
import importlib.util
import math
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


po = _load("profile_overhead", ROOT / "scripts" / "profile_overhead.py")


def test_native_references_are_found_by_name_and_synonym():
    import numpy as np

    assert po.native_function("sin", "numpy") is np.sin
    assert po.native_function("inv", "numpy") is np.linalg.inv
    assert po.native_function("gather_nd", "numpy") is None  # no native: attribution none


def test_a_smoke_run_writes_csv_png_and_summary(tmp_path, request):
    backends = [b for b in ("numpy", "torch") if b in request.config.ivy_backends] or ["numpy"]
    rows = po.main(
        [
            "--functions", "sin,clip,gather_nd,safe_norm,cast,scan",
            "--backends", ",".join(backends),
            "--out", str(tmp_path),
            "--repeats", "2",
            "--sample-ms", "0.2",
            "--quiet",
        ]
    )  # fmt: skip
    for name in ("overhead.csv", "overhead.png", "summary.md"):
        assert (tmp_path / name).stat().st_size > 0, name
    with (tmp_path / "overhead.csv").open() as fh:
        written = list(csv.DictReader(fh))
    assert len(written) == len(rows) == 6 * len(backends)
    skipped = {r["function"]: r["skipped"] for r in rows if r["skipped"]}
    assert skipped["cast"].startswith("alias of astype")
    assert "function" in skipped["scan"]
    for row in rows:
        if row["skipped"]:
            continue
        total = row["backend_us"] + row["ivy_compilable_us"] + row["ivy_eager_us"]
        # the groups partition the total, up to the differences clipped at 0 (noise)
        assert total >= row["total_us"] - 1e-9 or math.isclose(total, row["total_us"])
        assert row["attribution"] == (
            "none" if row["function"] in ("gather_nd", "safe_norm") else "direct"
        )
    numpy_sin = next(r for r in rows if r["function"] == "sin" and r["backend"] == "numpy")
    assert numpy_sin["native"] == "sin" and numpy_sin["ivy_compilable_us"] >= 0.0
    assert "| numpy |" in (tmp_path / "summary.md").read_text()


@pytest.mark.parametrize("name", ["sin", "lstm_update", "conv2d"])
def test_inputs_are_built_from_the_signature(name):
    import ivy

    args, kwargs = po.input_spec(name, getattr(ivy.core, name))
    assert args or kwargs


def test_every_bar_is_inside_the_figure(tmp_path):
    """A bar far shorter than the others (jax's sin at 27 us beside calls of milliseconds) lay
    below the log axis' minimum, invisible."""

    def row(function, backend_us, compilable_us, eager_us):
        return dict(
            function=function, backend="jax", skipped="", attribution="direct",
            backend_us=backend_us, ivy_compilable_us=compilable_us, ivy_eager_us=eager_us,
        )  # fmt: skip

    rows = [row("sin", 20.0, 2.0, 5.0), row("conv2d", 3000.0, 900.0, 40.0)]
    rows += [row(f"f{i}", 800.0 + i, 300.0, 30.0) for i in range(5)]
    ((low, high),) = po.plot(rows, tmp_path / "overhead.png", ["jax"], top=30)
    totals = [r["backend_us"] + r["ivy_compilable_us"] + r["ivy_eager_us"] for r in rows]
    assert low < min(totals) / 1.5 and high > max(totals)
    assert (tmp_path / "overhead.png").stat().st_size > 0
