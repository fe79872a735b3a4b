"""The two ivy_gym notebooks run headless, start to end, on a small budget (nbclient)."""

from __future__ import annotations

import os
import pathlib

import pytest

nbformat = pytest.importorskip("nbformat", reason="notebook tests need the [test] extra")
nbclient = pytest.importorskip("nbclient", reason="notebook tests need the [test] extra")

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
    for key, value in {**SMALL, "IVY_GYM_NOTEBOOK_FRAMEWORK": backends[0]}.items():
        monkeypatch.setenv(key, value)
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    book = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(
        book, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}
    ).execute()
    outputs = [o for cell in book.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) >= 3
    text = "".join(o.get("text", "") for o in outputs)
    assert f"backend {backends[0]}" in text
