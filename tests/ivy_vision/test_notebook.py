"""The notebook ``notebooks/vision_multiview.ipynb`` runs end to end (at low resolution, on
torch) through nbclient; its cells assert that the fused grid renders the new view and that
the warp matches the target image."""

from __future__ import annotations

import pathlib

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "vision_multiview.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("torch")
    settings = {
        "VISION_NOTEBOOK_BACKEND": "torch",
        "VISION_NOTEBOOK_WIDTH": "32",
        "VISION_NOTEBOOK_VOXELS": "24",
    }
    images, text = run_notebook(NOTEBOOK, monkeypatch, settings, timeout=300)
    assert len(images) == 4
    assert "occupied voxels of 24^3" in text and "seen by camera 1" in text
