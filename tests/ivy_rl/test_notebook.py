"""The sample-efficiency notebook runs headless, start to end, on a tiny budget (nbclient)."""

from __future__ import annotations

import pathlib

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "rl_sample_efficiency.ipynb"


def test_sample_efficiency_notebook_runs(request, monkeypatch):
    backends = [b for b in ("jax", "tensorflow", "torch") if b in request.config.ivy_backends]
    if not backends:
        pytest.skip("the notebook needs a differentiable backend")
    small = {
        "IVY_RL_NOTEBOOK_FRAMEWORK": backends[0],
        "IVY_RL_NOTEBOOK_BUDGET": "1200",
        "IVY_RL_NOTEBOOK_SEEDS": "0",
        "IVY_RL_NOTEBOOK_RUNS": "",
    }
    images, text = run_notebook(NOTEBOOK, monkeypatch, small)
    assert images
    assert f"backend {backends[0]}" in text
    for agent in ("PPO", "APG", "SHAC"):
        assert f"| {agent} |" in text
