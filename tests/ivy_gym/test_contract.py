"""The environment's public contract (kernels, action box, squashing) is enough to build a task
and run it; the checked calls reject arrays of two frameworks and bad shapes with errors that
say what to do; arrays stay on the device they were created on; ``import ivy_gym`` needs no
gymnasium."""

from __future__ import annotations

import dataclasses
import subprocess
import sys

import numpy as np
import pytest

import ivy
import ivy_gym
from ivy.errors import MixedFrameworksError
from tests.helpers import native, numpy_of

TOL = dict(rtol=1e-12, atol=1e-12)


@dataclasses.dataclass(frozen=True)
class _PointParams:
    dt: float = 0.1


class PointMass(ivy_gym.Env):
    """A task written on the public contract alone: a point on a line, pushed by the action."""

    Params = _PointParams
    state_names = ("x", "v")
    observation_names = ("x", "v")

    def reset_bounds(self):
        return np.array([-1.0, 0.0]), np.array([1.0, 0.0])

    def action_bounds(self):
        return np.array([-2.0]), np.array([2.0])

    def kernel_step(self, xp, state, action):
        x, v = ivy_gym.base.unstack_last(xp, state)
        a = ivy_gym.base.scalar_action(xp, ivy_gym.base.cast_like(xp, action, state))
        v = v + self.params.dt * a
        x = x + self.params.dt * v
        state = xp.stack([x, v], axis=-1)
        return state, state, -(x * x), xp.zeros_like(x) > 0

    def kernel_observe(self, xp, state):
        return state


def _point_mass_reference(x, v, actions, dt=0.1):
    rewards = []
    for a in actions:
        v = v + dt * a
        x = x + dt * v
        rewards.append(-(x**2))
    return x, v, np.array(rewards)


def test_a_task_on_the_public_contract_rolls_out_and_squashes(backend):
    env = PointMass()
    xp = getattr(ivy, backend)
    logits = np.linspace(-3.0, 3.0, 10)[:, None, None]
    actions = env.squash(xp, native(logits, backend))
    np.testing.assert_allclose(numpy_of(actions), 2.0 * np.tanh(logits), **TOL)
    low, high = env.action_box(xp, dtype="float64")
    np.testing.assert_array_equal(numpy_of(low), [-2.0])
    np.testing.assert_array_equal(numpy_of(high), [2.0])
    state = native(np.array([[0.5, -0.2]]), backend)
    traj = ivy_gym.rollout(env, state, actions)
    x, v, rewards = _point_mass_reference(0.5, -0.2, 2.0 * np.tanh(logits[:, 0, 0]))
    np.testing.assert_allclose(numpy_of(traj.final_state), [[x, v]], **TOL)
    np.testing.assert_allclose(numpy_of(traj.rewards)[:, 0], rewards, **TOL)
    same = env.kernel_step(xp, state, actions[0])
    checked = env.step(state, actions[0])
    for a, b in zip(same, checked):
        np.testing.assert_array_equal(numpy_of(a), numpy_of(b))


def test_squash_actions_uses_the_box(backend):
    env = ivy_gym.Reacher(num_joints=3)
    logits = np.array([[-1.0, 0.0, 2.0]])
    out = ivy_gym.squash_actions(native(logits, backend), env)
    np.testing.assert_allclose(numpy_of(out), np.tanh(logits), **TOL)


# ----------------------------------------------------------------------------------------------
# Arrays of two frameworks
# ----------------------------------------------------------------------------------------------


def test_step_and_rollout_reject_arrays_of_two_frameworks(diff_backend):
    env = ivy_gym.Pendulum()
    state = np.zeros((4, 2))
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        env.step(state, native(np.zeros((4, 1)), diff_backend))
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        env.step(native(state, diff_backend), np.zeros((4, 1)))
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        ivy_gym.rollout(env, state, native(np.zeros((3, 4, 1)), diff_backend))
    weights = {"w": native(np.zeros((3, 1)), diff_backend)}
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        ivy_gym.rollout(env, state, policy=lambda o, v: o @ v["w"], v=weights, horizon=2)
    heavy = env.replace(m=native(np.array(2.0), diff_backend))  # a parameter for gradients
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        heavy.step(state, np.zeros((4, 1)))
    with pytest.raises(MixedFrameworksError, match="two frameworks"):
        heavy.observe(state)
    # f= chooses the framework explicitly and converts, as the core's functions do
    out = env.step(state, native(np.zeros((4, 1)), diff_backend), f=diff_backend)[0]
    assert ivy.get_framework(out).backend == diff_backend


# ----------------------------------------------------------------------------------------------
# Errors that say what to do
# ----------------------------------------------------------------------------------------------


def test_an_action_without_its_last_axis_names_the_fix(backend):
    env = ivy_gym.Pendulum()
    state = native(np.zeros((4, 2)), backend)
    with pytest.raises(ValueError, match=r"action must have shape \(\*batch, 1\).*\(4, 1\)") as e:
        env.step(state, native(np.zeros(4), backend))
    assert "action[..., None]" in str(e.value)
    with pytest.raises(ValueError, match=r"does not broadcast.*\(4, 1\)"):
        env.step(state, native(np.zeros((3, 1)), backend))
    with pytest.raises(ValueError, match=r"actions must have shape \(T, \*batch, 1\)"):
        ivy_gym.rollout(env, state, native(np.zeros((5, 4)), backend))
    with pytest.raises(ValueError, match=r"policy\(obs, v\) must have shape"):
        ivy_gym.rollout(env, state, policy=lambda o, v: o, v={}, horizon=2)


def test_a_state_of_the_wrong_width_names_the_expected_shape(backend):
    env = ivy_gym.CartPole()
    bad = native(np.zeros((4, 3)), backend)
    message = r"state must have shape \(\*batch, 4\).*'theta_dot'.*got shape \(4, 3\)"
    with pytest.raises(ValueError, match=message):
        env.step(bad, native(np.zeros((4, 1)), backend))
    with pytest.raises(ValueError, match=message):
        env.observe(bad)
    with pytest.raises(ValueError, match=message):
        ivy_gym.rollout(env, bad, native(np.zeros((2, 4, 1)), backend))
    with pytest.raises(TypeError, match="must be an array"):
        env.step([0.0, 0.0, 0.0, 0.0], np.zeros(1))


def test_float_actions_keep_their_dtype_and_others_take_the_states(backend):
    env = ivy_gym.Pendulum()
    state = native(np.array([[0.3, -0.1]]), backend)
    f32 = env.step(state, native(np.array([[0.7]], np.float32), backend))
    ints = env.step(state, native(np.array([[1]]), backend))
    floats = env.step(state, native(np.array([[1.0]]), backend))
    for out in (f32, ints):
        assert ivy.dtype(out[0], as_str=True) == "float64"
        assert ivy.dtype(out[2], as_str=True) == "float64"
    np.testing.assert_allclose(numpy_of(ints[0]), numpy_of(floats[0]), **TOL)
    # Gymnasium's torque term, 3 / (m l**2) * u, in float32 before it meets the state
    u32 = np.float32(0.7)
    speed = -0.1 + (15.0 * np.sin(0.3) + float(np.float32(3.0) * u32)) * 0.05
    np.testing.assert_allclose(numpy_of(f32[0])[0, 1], speed, **TOL)


def test_render_trajectory_says_how_to_index_the_batch():
    env = ivy_gym.PendulumSmooth()
    with pytest.raises(ValueError, match=r"drop index= \(the trajectory is unbatched\)"):
        ivy_gym.render_trajectory(env, np.zeros((3, 2)), index=0)
    with pytest.raises(ValueError, match=r"index=\(0, 0\)"):
        ivy_gym.render_trajectory(env, np.zeros((3, 2, 4, 2)), index=1)
    with pytest.raises(ValueError, match=r"\(T, \*batch, 2\)"):
        ivy_gym.render_trajectory(env, np.zeros((3, 5)))
    assert len(ivy_gym.render_trajectory(env, np.zeros((3, 2)), width=8, height=8)) == 3


# ----------------------------------------------------------------------------------------------
# Devices
# ----------------------------------------------------------------------------------------------


def _requires_device(xp, device: str) -> None:
    if device.partition(":")[0] not in xp.capabilities.devices:
        pytest.skip(f"{xp.backend} places arrays on {xp.capabilities.devices} only")


def test_reset_step_and_rollout_keep_the_device(backend, target_device):
    xp = getattr(ivy, backend)
    _requires_device(xp, target_device)
    env = ivy_gym.MountainCarContinuous()
    state = env.reset((3,), dtype="float64", device=target_device, f=backend)
    assert xp.dev(state) == target_device
    action = xp.zeros((3, 1), dtype="float32", device=target_device)
    for out in env.step(state, action):
        assert xp.dev(out) == target_device
    traj = ivy_gym.rollout(env, state, policy=lambda o, v: env.squash(xp, o[..., :1]), horizon=3)
    assert xp.dev(traj.states) == target_device and xp.dev(traj.rewards) == target_device
    auto = ivy_gym.rollout(env, state, xp.zeros((2, 3, 1), device=target_device), autoreset=True)
    assert xp.dev(auto.final_state) == target_device


def test_facades_create_their_arrays_on_the_device(backend, target_device):
    import gymnasium

    import ivy_gym.gymnasium  # noqa: F401  (registers the ids)

    xp = getattr(ivy, backend)
    _requires_device(xp, target_device)
    env = gymnasium.make("ivy_gym/Pendulum-v1", framework=backend, device=target_device)
    env.reset(seed=0)
    env.step(env.action_space.sample())
    assert xp.dev(env.unwrapped.backend_state) == target_device
    envs = gymnasium.make_vec(
        "ivy_gym/CartPole-v1",
        num_envs=2,
        vectorization_mode="vector_entry_point",
        framework=backend,
        device=target_device,
    )
    envs.reset(seed=0)
    for _ in range(12):  # long enough for an autoreset or two
        envs.step(np.ones(2, np.int64))
    assert xp.dev(envs.unwrapped.backend_state) == target_device


# ----------------------------------------------------------------------------------------------
# Imports
# ----------------------------------------------------------------------------------------------


def test_import_ivy_gym_needs_no_gymnasium():
    code = (
        "import sys, ivy_gym\n"
        "env = ivy_gym.Pendulum()\n"
        "env.step(env.reset((2,), f='numpy'), [[0.0], [1.0]])\n"
        "print(sorted(m for m in ('gymnasium', 'torch', 'jax', 'tensorflow') if m in sys.modules))\n"
        "import gymnasium, ivy_gym.gymnasium\n"
        "print(gymnasium.make('ivy_gym/Pendulum-v1').unwrapped.core)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == "[]" and lines[1].startswith("Pendulum(")
