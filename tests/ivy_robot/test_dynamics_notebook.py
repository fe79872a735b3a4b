"""The notebook ``notebooks/robot_dynamics.ipynb`` runs end to end through nbclient on a tiny
budget on jax: the dynamics equal MuJoCo's, both optimisations of the double pendulum's
swing-up run, the reacher's policy is optimised and then run in Gymnasium's own MuJoCo
Reacher-v5, and the three figures render headless."""

from __future__ import annotations

import os
import pathlib
import re

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "robot_dynamics.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("jax")
    pytest.importorskip("mujoco")
    pytest.importorskip("gymnasium")
    monkeypatch.setenv("DYNAMICS_NOTEBOOK_BACKEND", "jax")
    monkeypatch.setenv("DYNAMICS_NOTEBOOK_RESTARTS", "2")
    monkeypatch.setenv("DYNAMICS_NOTEBOOK_SWING_ITERATIONS", "3")
    monkeypatch.setenv("DYNAMICS_NOTEBOOK_REACHER_ITERATIONS", "3")
    path = os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    monkeypatch.setenv("PYTHONPATH", path)
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}
    )
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) == 3
    text = "".join(o.get("text", "") for o in outputs)
    assert "backend: jax | restarts: 2 | swing-up iterations: 3" in text
    gaps = re.search(r"qacc ([\d.e+-]+), mass matrix ([\d.e+-]+)", text)
    assert gaps and max(map(float, gaps.groups())) < 1e-10
    assert re.search(r"solved: \d+ of 2 restarts", text)
    scores = dict(re.findall(r"Reacher-v5 \(MuJoCo\), (learned policy|random actions): return "
                             r"(-[\d.]+)", text))
    assert set(scores) == {"learned policy", "random actions"}
