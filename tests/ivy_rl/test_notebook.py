"""The sample-efficiency notebook runs headless, start to end, on a tiny budget (nbclient)."""

from __future__ import annotations

import os
import pathlib

import pytest

nbformat = pytest.importorskip("nbformat", reason="notebook tests need the [test] extra")
nbclient = pytest.importorskip("nbclient", reason="notebook tests need the [test] extra")

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
    for key, value in small.items():
        monkeypatch.setenv(key, value)
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    book = nbformat.read(NOTEBOOK, as_version=4)
    nbclient.NotebookClient(
        book, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}
    ).execute()
    outputs = [o for cell in book.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert [o for o in outputs if "image/png" in o.get("data", {})]
    text = "".join(o.get("text", "") for o in outputs)
    assert f"backend {backends[0]}" in text
    for agent in ("PPO", "APG", "SHAC"):
        assert f"| {agent} |" in text
