"""The notebook ``notebooks/robot_contacts.ipynb`` runs end to end through nbclient on a tiny
budget (numpy and torch, a few steps): Hopper-v5 and Ant-v5 on ivy_robot.physics follow
Gymnasium's own MuJoCo environments from the same seed and actions, both render headless, and
torch's gradient of the Hopper's return through its foot's contact equals central finite
differences; a few gradient steps raise the return, and Gymnasium's Hopper earns it too."""

from __future__ import annotations

import pathlib
import re

import pytest

from tests.helpers import run_notebook

ROOT = pathlib.Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "robot_contacts.ipynb"


def test_notebook_runs(monkeypatch):
    pytest.importorskip("torch")
    pytest.importorskip("mujoco")
    pytest.importorskip("gymnasium")
    settings = {
        "CONTACTS_NOTEBOOK_BACKENDS": "numpy,torch",
        "CONTACTS_NOTEBOOK_STEPS": "10",
        "CONTACTS_NOTEBOOK_GRAD_BACKENDS": "torch",
        "CONTACTS_NOTEBOOK_HORIZON": "3",
        "CONTACTS_NOTEBOOK_ITERATIONS": "1",
    }
    images, text = run_notebook(NOTEBOOK, monkeypatch, settings)
    # the divergence plot, one rendering per task, the gradient's figure
    assert len(images) == 4
    assert "backends: numpy, torch | steps: 10 | gradient backends: torch | horizon: 3" in text

    # both robots touch the floor within the 10 steps (the Hopper lands at its 8th)
    touching = dict(re.findall(r"(Hopper-v5|Ant-v5): 10 steps .* contacts at (\d+) of", text))
    assert set(touching) == {"Hopper-v5", "Ant-v5"} and min(map(int, touching.values())) > 0
    # every backend follows Gymnasium's MuJoCo: the Hopper to rounding, the Ant (its first
    # contacts) to ~1e-10; a wrong force or integrator is off by >1e-3
    rows = re.findall(
        r"(Hopper-v5|Ant-v5) +(numpy|torch): observations ([\d.e+-]+), rewards ([\d.e+-]+) \| "
        r"first step above 1e-9: (?:none|step \d+) \| terminations (agree|DIFFER)",
        text,
    )
    assert {(task, backend) for task, backend, *_ in rows} == {
        (task, backend) for task in ("Hopper-v5", "Ant-v5") for backend in ("numpy", "torch")
    }
    for task, _, obs, reward, terminations in rows:
        tolerance = 1e-12 if task == "Hopper-v5" else 1e-8
        assert float(obs) < tolerance and float(reward) < tolerance
        assert terminations == "agree"

    # the gradient through the contact: torch's autodiff against central differences
    assert re.search(r"contacts in MuJoCo: [\w, -]*foot_geom", text)
    error = re.search(r"torch against finite differences: relative error ([\d.e+-]+)", text)
    assert error and float(error.group(1)) < 1e-5
    ours = float(re.search(r"torch: return ([-\d.]+)", text).group(1))
    theirs = float(re.search(r"Gymnasium's MuJoCo Hopper: return ([-\d.]+)", text).group(1))
    assert abs(ours - theirs) < 1e-9
    contacts = re.search(r"return [-\d.]+; contacts at each step: ([\d ]+)", text).group(1)
    assert all(int(c) > 0 for c in contacts.split())  # the foot stays on the floor

    # gradient steps raise the return, and Gymnasium's Hopper earns it with those actions
    before, after = map(float, re.search(r"return ([-\d.]+) -> ([-\d.]+)", text).groups())
    assert after > before
    gap = re.search(
        r"optimised actions in Gymnasium's MuJoCo Hopper: return [-\d.]+ "
        r"\(difference ([\d.e+-]+)\)",
        text,
    )
    assert gap and float(gap.group(1)) < 1e-9
