"""scripts/physics_accuracy.py on a small budget: the Hopper's trajectory under random controls
(with contacts and limits) agrees with MuJoCo's, and the table prints one row per model."""

from __future__ import annotations

import importlib.util
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _script():
    spec = importlib.util.spec_from_file_location(
        "physics_accuracy", ROOT / "scripts" / "physics_accuracy.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_accuracy_rows_on_the_hopper():
    pytest.importorskip("mujoco")
    pytest.importorskip("gymnasium")
    import ivy

    script = _script()
    row = script.measure("hopper", 40, ivy.numpy)
    assert row["with contacts"] > 0  # the states the table speaks of
    assert max(row["qacc"]) < 1e-9 and max(row["step"]) < 1e-9
    assert row["free run"][1] < 1e-9 and row["free run"][2] is None
    lines = script.table([row]).splitlines()
    assert len(lines) == 3 and lines[2].startswith("| hopper | Newton | 40 (")
