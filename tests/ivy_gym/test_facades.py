"""The Gymnasium facades: registration, ``check_env`` on every task and backend, seeding, the
state in Gymnasium's layout, clear errors for bad actions, and the native vector environment
with Gymnasium's next-step autoreset."""

from __future__ import annotations

import subprocess
import sys

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from gymnasium.vector import AutoresetMode

import ivy_gym
import ivy_gym.gymnasium  # registers the ivy_gym/... ids
from tests.helpers import native, numpy_of

pytestmark = pytest.mark.filterwarnings(
    "ignore:.*Box (observation|action) space.*:UserWarning",
    "ignore:.*symmetric and normalized space.*:UserWarning",
    "ignore:.*os.fork.*:RuntimeWarning",
)

# the locomotion tasks' facades are checked in test_locomotion.py (their steps are heavier)
LOCOMOTION = {"Hopper-v5", "Walker2d-v5", "HalfCheetah-v5", "Ant-v5", "Humanoid-v5", "Swimmer-v5"}
IDS = sorted(set(ivy_gym.TASKS) - LOCOMOTION)


@pytest.mark.parametrize("task", IDS)
def test_check_env_passes(task, backend):
    env = gymnasium.make(f"ivy_gym/{task}", framework=backend, render_mode="rgb_array")
    check_env(env.unwrapped)
    frame = env.unwrapped.render()
    assert frame.shape == (400, 400, 3) and frame.dtype == np.uint8
    assert env.spec.max_episode_steps == ivy_gym.TASKS[task][0].max_episode_steps


def test_make_without_importing_and_no_framework_imported():
    code = (
        "import sys, gymnasium\n"
        "env = gymnasium.make('ivy_gym:ivy_gym/Pendulum-v1')\n"
        "obs, _ = env.reset(seed=0)\n"
        "env.step(env.action_space.sample())\n"
        "print(sorted(m for m in ('torch', 'jax', 'tensorflow') if m in sys.modules))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]", out.stderr


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_reset_seed_reproduces_observations(dtype, diff_backend):
    env = gymnasium.make("ivy_gym/Swimmer-v0", framework=diff_backend, dtype=dtype)
    first = [env.reset(seed=5)[0] for _ in range(2)]
    other = env.reset(seed=6)[0]
    np.testing.assert_array_equal(first[0], first[1])
    assert not np.array_equal(first[0], other)
    assert first[0].dtype == np.dtype(dtype) and env.observation_space.dtype == np.dtype(dtype)
    steps = []
    for _ in range(2):
        env.reset(seed=5)
        steps.append([env.step(np.array([0.5, -0.5]))[0] for _ in range(3)])
    np.testing.assert_array_equal(np.array(steps[0]), np.array(steps[1]))


def test_state_reads_and_writes_the_core_state(backend):
    env = gymnasium.make("ivy_gym/Pendulum-v1", framework=backend, dtype="float64").unwrapped
    env.reset(seed=0)
    env.state = np.array([0.5, -1.0])
    assert env.state.dtype == np.float64
    np.testing.assert_array_equal(env.state, [0.5, -1.0])
    obs, reward, *_ = env.step(np.array([1.0]))
    core = ivy_gym.Pendulum()
    state, expected, r, _ = core.step(np.array([0.5, -1.0]), np.array([1.0]))
    np.testing.assert_allclose(obs, expected, rtol=1e-14)
    np.testing.assert_allclose(env.state, state, rtol=1e-14)
    assert reward == pytest.approx(float(r), rel=1e-14)
    with pytest.raises(ValueError, match="shape"):
        env.state = np.zeros(3)


@pytest.mark.parametrize(
    "task,action,message",
    [
        ("Pendulum-v1", np.array([2.5]), "outside the action space"),
        ("Pendulum-v1", np.array([np.nan]), "outside the action space"),
        ("Pendulum-v1", np.array([0.5, 0.5]), "shape"),
        ("Pendulum-v1", 0.5, "shape"),
        ("Reacher-v0", np.array([0.5]), "shape"),
        ("MountainCarContinuous-v0", np.array([-1.01]), "outside the action space"),
        ("CartPole-v1", 2, "0 \\(push left\\) or 1"),
        ("CartPole-v1", -1, "0 \\(push left\\) or 1"),
        ("CartPole-v1", np.uint8(2), "0 \\(push left\\) or 1"),
        ("CartPole-v1", 0.5, "integer"),
        ("CartPole-v1", np.array([1]), "integer"),
    ],
)
def test_bad_actions_get_clear_errors(task, action, message):
    env = gymnasium.make(f"ivy_gym/{task}").unwrapped
    env.reset(seed=0)
    with pytest.raises(ValueError, match=message):
        env.step(action)


def test_step_before_reset_and_bad_options():
    env = gymnasium.make("ivy_gym/Pendulum-v1").unwrapped
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.array([0.0]))
    with pytest.raises(ValueError, match="float32"):
        gymnasium.make("ivy_gym/Pendulum-v1", dtype="int32")
    with pytest.raises(ValueError, match="render_mode"):
        gymnasium.make("ivy_gym/Pendulum-v1", render_mode="human")


def test_core_keyword_arguments_reach_the_core():
    env = gymnasium.make("ivy_gym/Reacher-v0", num_joints=3, dt=0.1).unwrapped
    assert env.core.num_joints == 3 and env.core.params.dt == 0.1
    assert env.action_space.shape == (3,) and env.observation_space.shape == (11,)
    pendulum = gymnasium.make("ivy_gym/Pendulum-v1", g=9.81, smooth=True).unwrapped
    assert pendulum.core.params.g == 9.81 and pendulum.core.smooth


# ----------------------------------------------------------------------------------------------
# The vector environment
# ----------------------------------------------------------------------------------------------


def _vec(task, n, backend="numpy", **kwargs):
    return gymnasium.make_vec(
        f"ivy_gym/{task}",
        num_envs=n,
        vectorization_mode="vector_entry_point",
        framework=backend,
        **kwargs,
    )


def test_vector_env_autoresets_at_the_next_step(backend):
    envs = _vec("CartPole-v1", 3, backend)
    assert envs.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
    assert isinstance(envs, ivy_gym.GymnasiumVectorEnv)
    obs, _ = envs.reset(seed=1)
    assert obs.shape == (3, 4) and envs.observation_space.contains(obs)
    done_before = np.zeros(3, bool)
    for _ in range(60):
        obs, reward, terminated, truncated, _ = envs.step(np.ones(3, np.int64))
        restarted = done_before
        np.testing.assert_array_equal(reward[restarted], 0.0)
        assert not terminated[restarted].any() and not truncated[restarted].any()
        assert np.all(np.abs(obs[restarted]) <= 0.05)  # a fresh initial observation
        np.testing.assert_array_equal(reward[~restarted], 1.0)
        if restarted.any():
            break
        done_before = terminated | truncated
    else:
        pytest.fail("no environment terminated")


def test_vector_env_truncates_at_the_time_limit():
    envs = _vec("Pendulum-v1", 2, max_episode_steps=4)
    envs.reset(seed=0)
    flags = [envs.step(np.zeros((2, 1), np.float32))[3] for _ in range(6)]
    np.testing.assert_array_equal(np.array(flags)[:, 0], [False, False, False, True, False, False])


def test_vector_env_steps_every_copy_in_one_call():
    calls = []

    class Counted(ivy_gym.PendulumSmooth):
        def kernel_step(self, xp, state, action):
            calls.append(tuple(state.shape))
            return super().kernel_step(xp, state, action)

    envs = ivy_gym.GymnasiumVectorEnv(Counted(), 64, framework="numpy")
    envs.reset(seed=0)
    for _ in range(5):
        envs.step(envs.action_space.sample())
    assert calls == [(64, 2)] * 5


def test_vector_env_reset_seed_and_errors(diff_backend):
    envs = _vec("Reacher-v0", 4, backend=diff_backend, dtype="float64")
    a = envs.reset(seed=3)[0]
    b = envs.reset(seed=3)[0]
    np.testing.assert_array_equal(a, b)
    assert len({tuple(row) for row in a}) == 4  # every copy draws its own state
    with pytest.raises(ValueError, match="shape"):
        envs.step(np.zeros((3, 2)))
    with pytest.raises(ValueError, match="outside"):
        envs.step(np.full((4, 2), 1.5))
    frames = _vec("Reacher-v0", 2, render_mode="rgb_array")
    frames.reset(seed=0)
    assert [f.shape for f in frames.render()] == [(400, 400, 3)] * 2


def test_vector_env_compiled_step_equals_eager(graph_backend):
    eager = _vec("CartPoleSwingUp-v0", 8, graph_backend, dtype="float64", compile=False)
    compiled = _vec("CartPoleSwingUp-v0", 8, graph_backend, dtype="float64", compile=True)
    actions = np.random.default_rng(0).uniform(-1, 1, size=(5, 8, 1))
    outs = []
    for envs in (eager, compiled):
        envs.reset(seed=4)
        outs.append([envs.step(a)[:2] for a in actions])
    for (o1, r1), (o2, r2) in zip(*outs):
        np.testing.assert_allclose(o1, o2, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(r1, r2, rtol=1e-12, atol=1e-12)


def test_vector_env_matches_the_core(backend):
    envs = _vec("MountainCarShaped-v0", 3, backend, dtype="float64")
    envs.reset(seed=0)
    start = envs.unwrapped.state.copy()
    actions = np.random.default_rng(1).uniform(-1, 1, size=(4, 3, 1))
    obs = [envs.step(a)[0] for a in actions]
    traj = ivy_gym.rollout(
        ivy_gym.MountainCarShaped(), native(start, backend), native(actions, backend)
    )
    np.testing.assert_allclose(np.array(obs), numpy_of(traj.observations), rtol=1e-13)


def test_vector_env_discrete_actions_and_fresh_observations():
    envs = _vec("CartPole-v1", 4)
    envs.reset(seed=0)
    with pytest.raises(ValueError, match="0 \\(push left\\) or 1"):
        envs.step(np.array([0, 1, -1, 0]))
    core = ivy_gym.CartPole()
    start = envs.unwrapped.state.copy()
    obs = envs.step(np.array([0, 1, 1, 0], np.uint8))[0]
    expected = core.step(start, np.array([[-1.0], [1.0], [1.0], [-1.0]]))[1]
    np.testing.assert_allclose(obs, expected, rtol=1e-6, atol=1e-7)
    obs[:] = 100.0  # the caller's array: changing it leaves the environments' state alone
    np.testing.assert_allclose(envs.unwrapped.state, expected, rtol=1e-6, atol=1e-7)


class _NormalStartPendulum(ivy_gym.Pendulum):
    """A core whose host reset draws otherwise than the uniform box: the facades must use it."""

    def draw_initial(self, rng, batch_shape=()):
        batch = (batch_shape,) if isinstance(batch_shape, int) else tuple(batch_shape)
        return np.stack([rng.standard_normal(batch), np.zeros(batch)], axis=-1) * 0.5


def test_facades_reset_through_the_core_host_draw(backend):
    core = _NormalStartPendulum()
    env = ivy_gym.GymnasiumEnv(core, framework=backend, dtype="float64")
    obs, _ = env.reset(seed=3)
    theta = 0.5 * np.random.default_rng(3).standard_normal()
    np.testing.assert_allclose(obs, [np.cos(theta), np.sin(theta), 0.0], atol=1e-12)
    envs = ivy_gym.GymnasiumVectorEnv(core, 4, framework=backend, dtype="float64")
    obs, _ = envs.reset(seed=5)
    thetas = 0.5 * np.random.default_rng(5).standard_normal(4)
    np.testing.assert_allclose(obs[:, 1], np.sin(thetas), atol=1e-12)
    np.testing.assert_array_equal(obs[:, 2], 0.0)


def test_default_host_draw_is_gymnasiums_uniform_box():
    core = ivy_gym.Pendulum()
    low, high = core.initial_bounds()
    draws = core.draw_initial(np.random.default_rng(0), (3,))
    np.testing.assert_array_equal(draws, np.random.default_rng(0).uniform(low, high, (3, 2)))
    assert core.draw_initial(np.random.default_rng(0)).shape == (2,)


def test_jax_facade_compiles_its_step_once():
    """The state that a reset draws is placed as the step's outputs are (jax compiles once per
    pattern of placed inputs): stepping and resetting again compile nothing more."""
    jax = pytest.importorskip("jax")
    env = gymnasium.make("ivy_gym/InvertedPendulum-v5", framework="jax")
    env.reset(seed=0)
    action = env.action_space.sample() * 0.0
    env.step(action)  # the first step compiles
    compiles = []

    def listener(event, duration, **kwargs):
        if "backend_compile" in event:
            compiles.append(event)

    jax.monitoring.register_event_duration_secs_listener(listener)
    try:
        for seed in (1, 2):
            env.reset(seed=seed)
            env.step(action)
            env.step(action)
    finally:
        jax.monitoring.unregister_event_duration_listener(listener)
    assert compiles == []


def test_facades_of_equal_tasks_share_their_compiled_step():
    """A vector environment's copies and a trainer's test environment compile the step once:
    facades of equal cores share it; other parameters get their own; each steps its state."""
    pytest.importorskip("jax")
    one, two = (gymnasium.make("ivy_gym/Pendulum-v1", framework="jax").unwrapped for _ in "ab")
    other = gymnasium.make("ivy_gym/Pendulum-v1", framework="jax", g=9.0).unwrapped
    assert one._step is two._step and one._fresh is two._fresh
    assert other._step is not one._step
    one.reset(seed=0)
    two.reset(seed=0)
    start = two.state
    one.step(np.array([2.0], np.float32))
    np.testing.assert_array_equal(two.state, start)
    assert not np.array_equal(one.state, start)


def test_vector_env_without_autoreset_resets_the_copies_asked(backend):
    """``autoreset_mode=Disabled``: a terminated copy is not restarted by the next step; a reset
    with a mask restarts only those copies, each from its seed as a single environment's reset,
    and leaves the others' states and observations."""
    envs = gymnasium.make_vec(
        "ivy_gym/CartPole-v1",
        num_envs=3,
        vectorization_mode="vector_entry_point",
        framework=backend,
        autoreset_mode=AutoresetMode.DISABLED,
    )
    assert envs.metadata["autoreset_mode"] is AutoresetMode.DISABLED
    single = gymnasium.make("ivy_gym/CartPole-v1", framework=backend)
    obs, _ = envs.reset(seed=[4, 5, 6])
    np.testing.assert_array_equal(obs, [single.reset(seed=s)[0] for s in (4, 5, 6)])
    push = np.array([1, 1, 0])
    for _ in range(60):  # pushed one way, the first two fall
        obs, _, terminated, _, _ = envs.step(push)
        if terminated[:2].all():
            break
    assert terminated[:2].all()
    after, _, still, _, _ = envs.step(push)  # no restart: the fallen keep falling
    assert still[:2].all() and np.all(np.abs(after[:2, 2]) > np.abs(obs[:2, 2]))
    kept = envs.unwrapped.state
    fresh, _ = envs.reset(seed=[None, 8, None], options={"reset_mask": [False, True, False]})
    np.testing.assert_array_equal(fresh[[0, 2]], after[[0, 2]])
    np.testing.assert_array_equal(envs.unwrapped.state[[0, 2]], kept[[0, 2]])
    np.testing.assert_array_equal(fresh[1], single.reset(seed=8)[0])
    with pytest.raises(ValueError, match="autoreset_mode must be one of"):
        gymnasium.make_vec(
            "ivy_gym/CartPole-v1",
            num_envs=2,
            vectorization_mode="vector_entry_point",
            autoreset_mode=AutoresetMode.SAME_STEP,
        )
