"""The faithful tasks follow Gymnasium's own environments step for step: from the same state and
the same actions, CartPole-v1, Pendulum-v1 and MountainCarContinuous-v0 give Gymnasium's states,
rewards and terminations (float64, to 1e-10) for 200 steps or until termination, on every
backend. The cases reach every branch of Gymnasium's code: terminations, clipped actions,
clipped speeds, the mountain car's wall and goal, and changed physical constants."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_gym
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


def _case(name):
    task, kwargs, attrs, state, policy = CASES[name]
    state = np.asarray(state, np.float64)
    if task == "MountainCarContinuous":  # Gymnasium's own state is float32
        state = state.astype(np.float32).astype(np.float64)
    return task, kwargs, state, gymnasium_trajectory(task, state, policy, STEPS, **attrs)


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_cases_reach_their_branch(name):
    _, _, _, expected = _case(name)
    if name in EXPECT:
        assert EXPECT[name](*expected)


@pytest.mark.parametrize("name", sorted(CASES))
def test_trajectory_equals_gymnasium(name, backend):
    task, kwargs, state, (states, rewards, terminated, actions) = _case(name)
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
    import gymnasium

    ours = gymnasium.make(f"ivy_gym/{FAITHFUL[task]}", dtype="float64")
    theirs = gymnasium.make(FAITHFUL[task])
    for seed in (0, 7, 123):
        obs, _ = ours.reset(seed=seed)
        expected, _ = theirs.reset(seed=seed)
        np.testing.assert_allclose(obs, expected, rtol=1e-7, atol=1e-7)  # theirs is float32
        state = theirs.unwrapped.state  # float64 at reset, MountainCarContinuous's included
        np.testing.assert_array_equal(ours.unwrapped.state, np.asarray(state, np.float64))


def test_float32_core_stays_close_to_gymnasium():
    _, _, state, (states, _, _, actions) = _case("pendulum-random")
    traj = ivy_gym.rollout(ivy_gym.Pendulum(), state.astype(np.float32), actions.astype(np.float32))
    np.testing.assert_allclose(numpy_of(traj.states)[:20], states[:20], rtol=1e-4, atol=1e-4)
    assert ivy.dtype(traj.states, as_str=True) == "float32"
