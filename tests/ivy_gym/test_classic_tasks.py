"""Gymnasium's discrete classic-control tasks, Acrobot-v1 and MountainCar-v0, follow Gymnasium's
own environments step for step, on every backend, as users call them: ``reset(seed=...)``, then
``step(action_space.sample())`` (and a policy that reaches the goal, the mountain car's wall and
Acrobot's clipped speeds), leave ``unwrapped.state`` equal to Gymnasium's after every step, with
its rewards and terminations. The cores compile, and Acrobot's gradients through its
Runge-Kutta steps equal finite differences."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

import ivy
import ivy_gym
import ivy_gym.gymnasium  # registers the ivy_gym/... ids
from tests.helpers import check_gradients, native, numpy_of

TOL = dict(rtol=1e-10, atol=1e-10)
TASKS = {"Acrobot": "Acrobot-v1", "MountainCar": "MountainCar-v0"}


def _sampled(theirs, state):
    return theirs.action_space.sample()


def _pump(theirs, state):
    """Push along the velocity (Acrobot: torque along the second joint's): pumps energy in."""
    return np.int64(2 if state[-1] >= 0 else 0)


def _wraps(s, r, d):
    """Acrobot reached the goal and wrapped an angle."""
    return d[-1] and r[-1] == 0 and np.abs(np.diff(s[:, :2], axis=0)).max() > np.pi


def _clips(s, r, d):
    """Acrobot's speeds were clipped (both)."""
    return np.isclose(np.abs(s[:, 2]).max(), 4 * np.pi) and np.isclose(
        np.abs(s[:, 3]).max(), 9 * np.pi
    )


def _pump_left(theirs, state):
    """Push left when moving left (else nothing): swings up to the left wall."""
    return np.int64(0 if state[1] < 0 else 1)


#: name: (task, policy, steps, what the run must reach in Gymnasium)
RUNS = {
    "acrobot-sampled": ("Acrobot", _sampled, 150, lambda s, r, d: len(s) == 150),
    "acrobot-goal": ("Acrobot", _pump, 120, _wraps),
    "acrobot-fast": ("Acrobot", _sampled, 20, _clips),
    "mountaincar-sampled": ("MountainCar", _sampled, 150, lambda s, r, d: len(s) == 150),
    "mountaincar-goal": ("MountainCar", _pump, 200, lambda s, r, d: d[-1] and r[-1] == -1),
    "mountaincar-wall": (
        "MountainCar",
        _pump_left,
        160,
        lambda s, r, d: np.any((s[:, 0] == -1.2) & (s[:, 1] == 0)),
    ),
}


@pytest.mark.parametrize("name", sorted(RUNS))
def test_users_steps_follow_gymnasium(name, backend):
    task, policy, steps, expect = RUNS[name]
    ours = gymnasium.make(f"ivy_gym/{TASKS[task]}", framework=backend, dtype="float64")
    theirs = gymnasium.make(TASKS[task]).unwrapped
    ours = ours.unwrapped
    ours.reset(seed=3)
    theirs.reset(seed=3)
    theirs.action_space.seed(3)
    np.testing.assert_array_equal(ours.state, np.asarray(theirs.state, np.float64))
    if name == "acrobot-fast":  # spinning near both speed limits
        theirs.state = np.array([3.0, -3.0, 12.5, -28.2])
        ours.state = theirs.state.copy()
    states, rewards, terminations = [], [], []
    for _ in range(steps):
        action = policy(theirs, np.asarray(theirs.state, np.float64))
        obs, reward, terminated, truncated, _ = ours.step(action)
        expected_obs, expected_reward, expected_terminated, _, _ = theirs.step(action)
        expected = np.asarray(theirs.state, np.float64)
        np.testing.assert_allclose(ours.state, expected, **TOL)
        np.testing.assert_allclose(obs, expected_obs, rtol=1e-6, atol=1e-6)  # theirs: float32
        assert reward == expected_reward and terminated == expected_terminated
        assert not truncated
        states.append(expected)
        rewards.append(expected_reward)
        terminations.append(expected_terminated)
        if terminated:
            break
    assert expect(np.array(states), np.array(rewards), np.array(terminations))


@pytest.mark.parametrize("task", sorted(TASKS))
def test_spaces_and_reset_match_gymnasium(task):
    ours = gymnasium.make(f"ivy_gym/{TASKS[task]}", dtype="float64")
    theirs = gymnasium.make(TASKS[task])
    assert ours.action_space == theirs.action_space
    np.testing.assert_allclose(ours.observation_space.low, theirs.observation_space.low, 1e-7)
    np.testing.assert_allclose(ours.observation_space.high, theirs.observation_space.high, 1e-7)
    assert ours.spec.max_episode_steps == theirs.spec.max_episode_steps
    assert ours.spec.reward_threshold == theirs.spec.reward_threshold
    for seed in (0, 7):
        obs, _ = ours.reset(seed=seed)
        expected, _ = theirs.reset(seed=seed)
        np.testing.assert_allclose(obs, expected, rtol=1e-7, atol=1e-7)
        state = np.asarray(theirs.unwrapped.state, np.float64)
        np.testing.assert_array_equal(ours.unwrapped.state, state)
    with pytest.raises(ValueError, match=r"in \{0, \.\.\., 2\}"):
        ours.unwrapped.step(3)


def test_acrobot_nips_dynamics_follow_gymnasium():
    ours = ivy_gym.Acrobot(book_or_nips="nips")
    theirs = gymnasium.make("Acrobot-v1").unwrapped
    theirs.book_or_nips = "nips"
    theirs.reset(seed=0)
    state = np.array([0.5, -1.0, 2.0, -3.0])
    theirs.state = state.copy()
    s = state
    for action in [0, 2, 1, 2, 0]:
        theirs.step(action)
        s, _, _, _ = ours.step(s, np.array([action - 1.0]))
        np.testing.assert_allclose(s, theirs.state, **TOL)
    book = ivy_gym.Acrobot().step(state, np.array([1.0]))[0]
    assert np.abs(book - ours.step(state, np.array([1.0]))[0]).max() > 1e-3
    with pytest.raises(ValueError, match="book_or_nips"):
        ivy_gym.Acrobot(book_or_nips="paper")


def _steps(env, n):
    def run(state, actions):
        for t in range(n):
            state, _, reward, terminated = env.step(state, actions[t])
        return state, reward, terminated

    return run


@pytest.mark.parametrize("task", sorted(TASKS))
def test_compiled_core_equals_eager(task, graph_backend):
    env = getattr(ivy_gym, task)()
    rng = np.random.default_rng(1)
    state = rng.uniform(*env.reset_bounds(), size=(5, env.state_dim))
    state[:, 1] += 0.02 if task == "MountainCar" else 0.0
    actions = rng.integers(-1, 2, size=(3, 5, 1)).astype(np.float64)
    args = native(state, graph_backend), native(actions, graph_backend)
    eager = _steps(env, 3)(*args)
    compiled = ivy.compile_fn(_steps(env, 3))(*args)
    for c, e in zip(compiled, eager):
        np.testing.assert_allclose(numpy_of(c), numpy_of(e), rtol=1e-12, atol=1e-12)


def test_acrobot_gradients_equal_finite_differences(diff_backend):
    env = ivy_gym.Acrobot()
    state = np.array([[0.3, -0.4, 1.0, -1.5]])
    actions = np.array([[[1.0]], [[-1.0]]])
    check_gradients(
        diff_backend, lambda s: _steps(env, 2)(s, native(actions, diff_backend))[0], [state]
    )


@pytest.mark.parametrize("task", sorted(TASKS))
def test_batched_core_equals_gymnasium_state_by_state(task, backend):
    env = getattr(ivy_gym, task)()
    rng = np.random.default_rng(2)
    low, high = env.reset_bounds()
    states = rng.uniform(low, high, size=(2, 3, env.state_dim))
    states[..., -1] += rng.uniform(-0.05, 0.05, size=(2, 3)) if task == "MountainCar" else 0.0
    actions = rng.integers(0, 3, size=(4, 2, 3))
    state, ours = native(states, backend), []
    for t in range(4):  # eager steps, a batch (2, 3) at a time
        state, _, reward, terminated = env.step(state, native(actions[t, ..., None] - 1.0, backend))
        assert tuple(reward.shape) == (2, 3) and ivy.dtype(terminated, as_str=True) == "bool"
        ours.append((numpy_of(state), numpy_of(reward)))
    theirs = gymnasium.make(TASKS[task]).unwrapped
    theirs.reset(seed=0)
    for index in np.ndindex(2, 3):
        theirs.state = states[index].copy()
        for t in range(4):
            _, reward, _, _, _ = theirs.step(actions[(t, *index)])
            expected = np.asarray(theirs.state, np.float64)
            np.testing.assert_allclose(ours[t][0][index], expected, **TOL)
            assert ours[t][1][index] == reward
