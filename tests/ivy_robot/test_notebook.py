"""The notebook ``notebooks/robot_trajectory_optimisation.ipynb`` runs end to end through
nbclient, with few iterations, on jax: both planners run, MuJoCo checks both paths, and the three
figures (arm path, drone path, cost per iteration) render headless."""

from __future__ import annotations

import os
import pathlib
import re

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "robot_trajectory_optimisation.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("jax")
    pytest.importorskip("mujoco")
    monkeypatch.setenv("ROBOT_NOTEBOOK_BACKEND", "jax")
    monkeypatch.setenv("ROBOT_NOTEBOOK_ITERATIONS", "60")
    path = os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    monkeypatch.setenv("PYTHONPATH", path)
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}
    )
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) == 3
    text = "".join(o.get("text", "") for o in outputs)
    assert "backend: jax | iterations: 60" in text
    costs = [tuple(map(float, m)) for m in re.findall(r"cost: ([\d.]+) -> ([\d.]+)", text)]
    assert len(costs) == 2 and all(after < before for before, after in costs)
    contacts = re.findall(r"straight line (\d+), optimised (\d+)", text)
    assert len(contacts) == 2 and all(int(straight) > 0 for straight, _ in contacts)
