"""The notebook ``notebooks/robot_dynamics.ipynb`` runs end to end through nbclient on a tiny
budget on jax: the dynamics equal MuJoCo's, the double pendulum's swing-up is optimised from
random restarts, the reacher's policy is optimised and then run in Gymnasium's own MuJoCo
Reacher-v5, and the three figures render headless."""

from __future__ import annotations

import pathlib
import re

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "robot_dynamics.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("jax")
    pytest.importorskip("mujoco")
    pytest.importorskip("gymnasium")
    settings = {
        "DYNAMICS_NOTEBOOK_BACKEND": "jax",
        "DYNAMICS_NOTEBOOK_RESTARTS": "2",
        "DYNAMICS_NOTEBOOK_SWING_ITERATIONS": "3",
        "DYNAMICS_NOTEBOOK_REACHER_ITERATIONS": "3",
    }
    images, text = run_notebook(NOTEBOOK, monkeypatch, settings)
    assert len(images) == 3
    assert "backend: jax | restarts: 2 | swing-up iterations: 3" in text
    gaps = re.search(r"qacc ([\d.e+-]+), mass matrix ([\d.e+-]+)", text)
    assert gaps and max(map(float, gaps.groups())) < 1e-10
    assert re.search(r"solved: \d+ of 2 restarts", text)
    scores = dict(
        re.findall(
            r"Reacher-v5 \(MuJoCo\), (learned policy|random actions): return "
            r"(-[\d.]+)",
            text,
        )
    )
    assert set(scores) == {"learned policy", "random actions"}
