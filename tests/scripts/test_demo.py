"""The README's main demo (scripts/demo.py) on a small budget: the swing-up is optimised on every
installed differentiable backend from the same initial actions, the result replays identically
on every backend, and the plot and the GIF are written."""

from __future__ import annotations

import importlib.util
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.filterwarnings("ignore:`torch.jit.script_method`:DeprecationWarning")


def _demo():
    spec = importlib.util.spec_from_file_location("demo", ROOT / "scripts" / "demo.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_demo_runs_on_a_small_budget(tmp_path, request):
    if not any(b in request.config.ivy_backends for b in ("torch", "jax", "tensorflow")):
        pytest.skip("the demo needs a differentiable backend")
    out = _demo().main(iterations=4, horizon=15, out_dir=str(tmp_path))
    returns = {name: r.final_return for name, r in out["results"].items()}
    for result in out["results"].values():
        assert result.final_return > result.returns[0]  # Adam improved the return
    values = list(returns.values()) + list(out["replays"].values())
    np.testing.assert_allclose(values, values[0], rtol=1e-3)  # the same on every backend
    assert pathlib.Path(out["plot"]).stat().st_size > 0
    assert pathlib.Path(out["gif"]).stat().st_size > 0
