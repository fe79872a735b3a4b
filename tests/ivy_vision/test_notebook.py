"""The notebook ``notebooks/vision_multiview.ipynb`` runs end to end (at low resolution, on
torch) through nbclient; its cells assert that the fused grid renders the new view and that
the warp matches the target image."""

from __future__ import annotations

import os
import pathlib

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "vision_multiview.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("torch")
    monkeypatch.setenv("VISION_NOTEBOOK_BACKEND", "torch")
    monkeypatch.setenv("VISION_NOTEBOOK_WIDTH", "32")
    monkeypatch.setenv("VISION_NOTEBOOK_VOXELS", "24")
    monkeypatch.setenv(
        "PYTHONPATH", os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    )
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(ROOT)}}
    )
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(images) == 4
    text = "".join(o.get("text", "") for o in outputs)
    assert "occupied voxels of 24^3" in text and "seen by camera 1" in text
