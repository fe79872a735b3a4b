"""The two ivy_gym notebooks run headless, start to end, on a small budget (nbclient)."""

from __future__ import annotations

import pathlib

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
SMALL = {
    "IVY_GYM_NOTEBOOK_ITERATIONS": "3",
    "IVY_GYM_NOTEBOOK_HORIZON": "20",
    "IVY_GYM_NOTEBOOK_BATCH": "8",
    "IVY_GYM_NOTEBOOK_HORIZONS": "5,10",
}


NOTEBOOKS = [
    ROOT / "notebooks" / "gym_trajectory_optimisation.ipynb",
    ROOT / "notebooks" / "gym_policy_optimisation.ipynb",
]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs(path, request, monkeypatch):
    # torch runs eagerly by default (no compilation): the quickest on a small budget
    backends = [b for b in ("torch", "jax", "tensorflow") if b in request.config.ivy_backends]
    if not backends:
        pytest.skip("the notebooks need a differentiable backend")
    settings = {**SMALL, "IVY_GYM_NOTEBOOK_FRAMEWORK": backends[0]}
    images, text = run_notebook(path, monkeypatch, settings)
    assert len(images) >= 3
    assert f"backend {backends[0]}" in text
