"""The faithful tasks follow Gymnasium's own environments step for step: from the same state and
the same actions, float32 (as Gymnasium's action spaces sample them) or float64, CartPole-v1,
Pendulum-v1 and MountainCarContinuous-v0 give Gymnasium's states, rewards and terminations
(float64, to 1e-10) for 200 steps or until termination, on every backend. The cases reach every
branch of Gymnasium's code: terminations, clipped actions, clipped speeds, the mountain car's
wall and goal, a mountain car from a float64 (freshly reset) state, and changed physical
constants. And as users call them: ``reset(seed=...)`` then ``step(action_space.sample())``
through the facades leave ``unwrapped.state`` equal to Gymnasium's after every step."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

import ivy
import ivy_gym
import ivy_gym.gymnasium  # registers the ivy_gym/... ids
from tests.helpers import native, numpy_of
from tests.ivy_gym._reference import FAITHFUL, gymnasium_trajectory

TOL = dict(rtol=1e-10, atol=1e-10)
STEPS = 200


def _random(low, high, dim=1, seed=0):
    rng = np.random.default_rng(seed)
    actions = rng.uniform(low, high, size=(STEPS, dim))
    return lambda t, s: actions[t]


def _push(t, s):
    """CartPole: push towards the falling side (keeps the pole up for a while)."""
    return np.array([1.0 if s[2] + 0.5 * s[3] > 0 else -1.0])


def _pump(scale):
    """Pendulum and mountain car: push along the velocity (pumps energy in)."""
    return lambda t, s: np.array([scale if s[1] >= 0 else -scale])


# name: (task, core kwargs, Gymnasium attributes, initial state, policy)
CASES = {
    "cartpole-random": ("CartPole", {}, {}, [0.01, -0.03, 0.04, 0.02], _random(-1, 1, seed=1)),
    "cartpole-balanced": ("CartPole", {}, {}, [0.0, 0.1, -0.05, 0.0], _push),
    "cartpole-heavy-pole": (
        "CartPole",
        {"masspole": 0.3, "length": 0.7, "force_mag": 12.0},
        {"masspole": 0.3, "length": 0.7, "force_mag": 12.0},
        [-0.04, 0.02, 0.03, -0.01],
        _push,
    ),
    "pendulum-random": ("Pendulum", {}, {}, [2.5, -0.5], _random(-2, 2, seed=2)),
    "pendulum-clipped-torque": ("Pendulum", {}, {}, [-1.0, 0.8], _random(-3.5, 3.5, seed=3)),
    "pendulum-clipped-speed": ("Pendulum", {}, {}, [3.0, 1.0], _pump(2.0)),
    "pendulum-g": ("Pendulum", {"g": 9.81}, {"g": 9.81}, [0.3, 0.0], _random(-2, 2, seed=4)),
    "mountaincar-random": ("MountainCarContinuous", {}, {}, [-0.5, 0.0], _random(-1, 1, seed=5)),
    "mountaincar-clipped-action": (
        "MountainCarContinuous",
        {},
        {},
        [-0.45, 0.01],
        _random(-1.6, 1.6, seed=6),
    ),
    "mountaincar-goal": ("MountainCarContinuous", {}, {}, [-0.55, 0.0], _pump(1.0)),
    "mountaincar-from-reset": (  # Gymnasium's reset state is float64 (not float32 numbers)
        "MountainCarContinuous",
        {},
        {},
        [-0.5123456789012345, 0.0],
        _random(-1.6, 1.6, seed=7),
    ),
    "mountaincar-wall": (
        "MountainCarContinuous",
        {},
        {},
        [-1.1, -0.05],
        lambda t, s: np.array([-1.0]),
    ),
    "mountaincar-clipped-speed": (
        "MountainCarContinuous",
        {"power": 0.0025, "goal_position": 0.58},
        {"power": 0.0025, "goal_position": 0.58},
        [-0.9, 0.0],
        _pump(1.0),
    ),
}

#: What each case must reach in Gymnasium, so that the branch it names is really exercised.
EXPECT = {
    "cartpole-random": lambda s, r, d, a: d[-1],
    "cartpole-balanced": lambda s, r, d, a: len(s) > 30,
    "pendulum-clipped-torque": lambda s, r, d, a: np.abs(a).max() > 2,
    "pendulum-clipped-speed": lambda s, r, d, a: np.isclose(np.abs(s[:, 1]).max(), 8.0),
    "mountaincar-clipped-action": lambda s, r, d, a: np.abs(a).max() > 1,
    "mountaincar-goal": lambda s, r, d, a: d[-1] and r[-1] > 99,
    "mountaincar-wall": lambda s, r, d, a: np.any((s[:, 0] == np.float32(-1.2)) & (s[:, 1] == 0)),
    "mountaincar-clipped-speed": lambda s, r, d, a: np.isclose(
        np.abs(s[:, 1]).max(), 0.07, rtol=1e-6
    ),
}


def _case(name, action_dtype=np.float64):
    task, kwargs, attrs, state, policy = CASES[name]
    state = np.asarray(state, np.float64)
    if task == "MountainCarContinuous" and name != "mountaincar-from-reset":
        state = state.astype(np.float32).astype(np.float64)  # Gymnasium's state after a step
    trajectory = gymnasium_trajectory(task, state, policy, STEPS, action_dtype, **attrs)
    return task, kwargs, state, trajectory


#: The cases that reach every branch of the arithmetic of float32 actions (clipped and
#: unclipped actions, clipped speeds, the wall, a float64 state from a reset).
FLOAT32_CASES = (
    "pendulum-clipped-torque",
    "pendulum-clipped-speed",
    "mountaincar-from-reset",
    "mountaincar-clipped-action",
    "mountaincar-clipped-speed",
    "mountaincar-wall",
)
#: (case, action dtype): every case with float64 actions, and those with float32 actions (as
#: Gymnasium's action spaces sample them).
DTYPE_CASES = [(name, "float64") for name in sorted(CASES)] + [
    (name, "float32") for name in FLOAT32_CASES
]


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_cases_reach_their_branch(name):
    _, _, _, expected = _case(name)
    if name in EXPECT:
        assert EXPECT[name](*expected)


@pytest.mark.parametrize("name, action_dtype", DTYPE_CASES)
def test_trajectory_equals_gymnasium(name, action_dtype, backend):
    task, kwargs, state, (states, rewards, terminated, actions) = _case(name, action_dtype)
    env = getattr(ivy_gym, task)(**kwargs)
    traj = ivy_gym.rollout(env, native(state, backend), native(actions, backend))
    np.testing.assert_allclose(numpy_of(traj.states), states, **TOL)
    np.testing.assert_allclose(numpy_of(traj.rewards), rewards, **TOL)
    np.testing.assert_array_equal(numpy_of(traj.terminated), terminated)
    observations = numpy_of(traj.observations)
    if task == "Pendulum":
        states = np.stack([np.cos(states[:, 0]), np.sin(states[:, 0]), states[:, 1]], -1)
    np.testing.assert_allclose(observations, states, **TOL)


@pytest.mark.parametrize("task", ["CartPole", "Pendulum", "MountainCarContinuous"])
def test_facade_reset_draws_gymnasiums_initial_state(task):
    ours = gymnasium.make(f"ivy_gym/{FAITHFUL[task]}", dtype="float64")
    theirs = gymnasium.make(FAITHFUL[task])
    for seed in (0, 7, 123):
        obs, _ = ours.reset(seed=seed)
        expected, _ = theirs.reset(seed=seed)
        np.testing.assert_allclose(obs, expected, rtol=1e-7, atol=1e-7)  # theirs is float32
        state = theirs.unwrapped.state  # float64 at reset, MountainCarContinuous's included
        np.testing.assert_array_equal(ours.unwrapped.state, np.asarray(state, np.float64))


@pytest.mark.parametrize("task", sorted(FAITHFUL))
@pytest.mark.parametrize("action_dtype", ["float32", "float64"])
def test_users_reset_and_sampled_steps_follow_gymnasium(task, action_dtype):
    """``reset(seed=...)`` then ``step(action_space.sample())``, as users call them: after every
    step ``unwrapped.state`` is Gymnasium's (float32 samples, and the same cast to float64)."""
    ours = gymnasium.make(f"ivy_gym/{FAITHFUL[task]}", dtype="float64").unwrapped
    theirs = gymnasium.make(FAITHFUL[task]).unwrapped
    for seed in (0, 1):
        ours.reset(seed=seed)
        theirs.reset(seed=seed)
        theirs.action_space.seed(seed)
        np.testing.assert_array_equal(ours.state, np.asarray(theirs.state, np.float64))
        for _ in range(STEPS):
            action = theirs.action_space.sample()
            if task != "CartPole":
                action = action.astype(action_dtype)
            _, reward, terminated, _, _ = ours.step(action)
            _, expected_reward, expected_terminated, _, _ = theirs.step(action)
            expected = np.asarray(theirs.state, np.float64)
            np.testing.assert_allclose(ours.state, expected, **TOL)
            assert reward == pytest.approx(float(expected_reward), rel=1e-10, abs=1e-10)
            assert terminated == expected_terminated
            if terminated:
                break


def test_float32_core_stays_close_to_gymnasium():
    _, _, state, (states, _, _, actions) = _case("pendulum-random")
    traj = ivy_gym.rollout(ivy_gym.Pendulum(), state.astype(np.float32), actions.astype(np.float32))
    np.testing.assert_allclose(numpy_of(traj.states)[:20], states[:20], rtol=1e-4, atol=1e-4)
    assert ivy.dtype(traj.states, as_str=True) == "float32"
