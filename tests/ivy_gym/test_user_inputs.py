"""What users pass to ivy_gym, the same on every backend: jax as users run it (64-bit types off,
in a fresh process: the suite turns them on) takes Gymnasium's float64 and list actions and runs
the MuJoCo tasks; an integer dtype for a reset is refused by name; the MuJoCo base class is not a
task."""

from __future__ import annotations

import importlib.util
import subprocess
import sys

import pytest

import ivy.checks
import ivy_gym

JAX_DEFAULT = """
import warnings
warnings.filterwarnings("ignore")
import jax, numpy as np, gymnasium, ivy_gym.gymnasium
assert not jax.config.jax_enable_x64
for task in ("Pendulum-v1", "Reacher-v5"):
    env = gymnasium.make(f"ivy_gym/{task}", framework="jax")
    obs, _ = env.reset(seed=0)
    n = env.action_space.shape[0]
    for action in (np.full(n, 0.5), [0.5] * n, env.action_space.sample()):
        obs, reward, terminated, truncated, info = env.step(action)
        assert np.all(np.isfinite(obs)), (task, obs)
    print(task, obs.dtype, type(reward).__name__)
"""


def test_jax_without_64_bit_types_takes_gymnasiums_actions():
    if importlib.util.find_spec("jax") is None or importlib.util.find_spec("mujoco") is None:
        pytest.skip("needs jax and mujoco")
    out = subprocess.run(
        [sys.executable, "-c", JAX_DEFAULT], capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stderr[-3000:]
    lines = out.stdout.strip().splitlines()
    # float32 observations where jax cannot hold float64; rewards of Gymnasium's types
    assert lines == ["Pendulum-v1 float32 float", "Reacher-v5 float32 float64"], lines


def test_reset_refuses_an_integer_dtype(backend):
    with pytest.raises(ivy.checks.InputError, match="reset's dtype must be a floating dtype"):
        ivy_gym.Pendulum().reset((2,), dtype="int32", f=backend)


def test_the_mujoco_base_is_not_a_task():
    with pytest.raises(TypeError, match="base of the MuJoCo tasks"):
        ivy_gym.MuJoCoEnv()
