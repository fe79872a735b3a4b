"""The notebook ``notebooks/robot_trajectory_optimisation.ipynb`` runs end to end through
nbclient, with few iterations, on jax: both planners run, MuJoCo checks both paths, and the three
figures (arm path, drone path, cost per iteration) render headless."""

from __future__ import annotations

import pathlib
import re

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "robot_trajectory_optimisation.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("jax")
    pytest.importorskip("mujoco")
    settings = {"ROBOT_NOTEBOOK_BACKEND": "jax", "ROBOT_NOTEBOOK_ITERATIONS": "60"}
    images, text = run_notebook(NOTEBOOK, monkeypatch, settings, timeout=300)
    assert len(images) == 3
    assert "backend: jax | iterations: 60" in text
    costs = [tuple(map(float, m)) for m in re.findall(r"cost: ([\d.]+) -> ([\d.]+)", text)]
    assert len(costs) == 2 and all(after < before for before, after in costs)
    contacts = re.findall(r"straight line (\d+), optimised (\d+)", text)
    assert len(contacts) == 2 and all(int(straight) > 0 for straight, _ in contacts)
