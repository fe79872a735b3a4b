"""What users pass to ivy_gym, the same on every backend: jax as users run it (64-bit types off,
in a fresh process: the suite turns them on) takes Gymnasium's float64 and list actions and runs
the MuJoCo tasks; an integer dtype for a reset is refused by name; the MuJoCo base class is not a
task."""

from __future__ import annotations

import importlib.util
import subprocess
import sys

import numpy as np
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
    assert lines == ["Pendulum-v1 float32 float64", "Reacher-v5 float32 float64"], lines


def test_reset_refuses_an_integer_dtype(backend):
    with pytest.raises(ivy.checks.InputError, match="reset's dtype must be a floating dtype"):
        ivy_gym.Pendulum().reset((2,), dtype="int32", f=backend)


def test_the_mujoco_base_is_not_a_task():
    with pytest.raises(TypeError, match="base of the MuJoCo tasks"):
        ivy_gym.MuJoCoEnv()


# the tasks whose physics Gymnasium's check can hold to its exact reward comparison; the MuJoCo
# locomotion tasks agree to rounding (1e-16), which its `==` on rewards fails: they are checked
# with skip_rew in tests/ivy_gym/test_locomotion.py
DROP_IN = ("CartPole-v1", "Pendulum-v1", "MountainCarContinuous-v0", "MountainCar-v0",
           "Acrobot-v1")  # fmt: skip


@pytest.mark.filterwarnings("ignore::UserWarning")
@pytest.mark.parametrize("task", DROP_IN)
def test_facades_with_their_defaults_are_gymnasiums_by_its_own_check(task, backend):
    """gymnasium.utils.env_match.check_environments_match: the same spaces and dtypes, seeded
    resets, observations, rewards (exactly, and their types), terminations and info over 50
    sampled steps, on every backend that can compute in float64, the step run eagerly.

    Compiled (the default of jax and tensorflow), XLA may keep float32 terms in float64
    (``xla_allow_excess_precision``) and fuse operations: Pendulum's rewards there are 1 ulp
    (jax) to 3e-11 (tensorflow's float32 action cost) from Gymnasium's, which its ``==``
    fails; they are compared to 1e-9 below."""
    gymnasium = pytest.importorskip("gymnasium")
    from gymnasium.utils.env_match import check_environments_match

    import ivy_gym.gymnasium  # noqa: F401  (registers the ids)
    from tests.conftest import require

    require(backend, "float64")
    eager = gymnasium.make(f"ivy_gym/{task}", framework=backend, compile=False)
    check_environments_match(gymnasium.make(task), eager, num_steps=50)
    default = gymnasium.make(f"ivy_gym/{task}", framework=backend)
    ref = gymnasium.make(task)
    for env in (ref, default):
        env.reset(seed=3)
        env.action_space.seed(3)
    for _ in range(50):
        action = ref.action_space.sample()
        ref_out, out = ref.step(action), default.step(action)
        np.testing.assert_allclose(out[0], ref_out[0], rtol=1e-6, atol=1e-6)  # float32 obs
        assert abs(out[1] - ref_out[1]) < 1e-9 and type(out[1]) is type(ref_out[1])
        assert out[2:4] == ref_out[2:4]
        if ref_out[2] or ref_out[3]:
            break
