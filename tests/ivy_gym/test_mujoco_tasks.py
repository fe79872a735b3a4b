"""InvertedPendulum-v5 on ivy_robot.physics: step for step against Gymnasium's MuJoCo environment
(the cart at the end of its rail included), check_env, gradients against finite differences,
batched compiled rollouts."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import ivy
import ivy_gym
from tests.helpers import native, numpy_of

pytestmark = pytest.mark.filterwarnings(
    "ignore:.*Box (observation|action) space.*:UserWarning",
    "ignore:.*symmetric and normalized space.*:UserWarning",
)


def _episode(seed: int, steps: int = 100):
    """Gymnasium's own InvertedPendulum-v5 over one episode of sampled float32 actions."""
    ref = gymnasium.make("InvertedPendulum-v5")
    obs, _ = ref.reset(seed=seed)
    ref.action_space.seed(seed)
    rows = [
        (None, obs, None, None, np.concatenate([ref.unwrapped.data.qpos, ref.unwrapped.data.qvel]))
    ]
    for _ in range(steps):
        action = ref.action_space.sample()
        assert action.dtype == np.float32
        obs, reward, terminated, _, info = ref.step(action)
        data = ref.unwrapped.data
        rows.append((action, obs, reward, terminated, np.concatenate([data.qpos, data.qvel]), info))
        if terminated:
            break
    return rows


def test_inverted_pendulum_follows_gymnasium(backend):
    # one facade for both episodes: its step is compiled once on jax and tensorflow
    env = gymnasium.make("ivy_gym/InvertedPendulum-v5", framework=backend)  # float64
    for seed in (0, 7):
        rows = _episode(seed)
        assert len(rows) > 3  # an episode of several steps
        obs, _ = env.reset(seed=seed)
        np.testing.assert_allclose(obs, rows[0][1], rtol=0, atol=1e-12)
        for action, ref_obs, ref_reward, ref_terminated, ref_state, ref_info in rows[1:]:
            obs, reward, terminated, truncated, info = env.step(action)
            np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-8)
            np.testing.assert_allclose(env.unwrapped.state, ref_state, rtol=0, atol=1e-8)
            assert type(reward) is type(ref_reward) and reward == ref_reward  # int: Gymnasium's
            assert info == ref_info and type(info["reward_survive"]) is int
            assert bool(terminated) == bool(ref_terminated)
            assert not truncated
        assert bool(terminated)  # the episode ended as Gymnasium's did


def test_inverted_pendulum_stops_at_the_end_of_its_rail(backend):
    """The cart pushed into the slider's limit (range [-1, 1]): MuJoCo's limit constraint
    stops it, as Gymnasium's environment does."""
    state = np.array([0.95, 0.0, 2.0, 0.0])
    ref = gymnasium.make("InvertedPendulum-v5").unwrapped
    ref.reset(seed=0)
    ref.set_state(state[:2], state[2:])
    env = gymnasium.make("ivy_gym/InvertedPendulum-v5", framework=backend).unwrapped
    env.reset(seed=0)
    env.set_state(state[:2], state[2:])
    for _ in range(3):
        ref_obs, *_ = ref.step(np.array([3.0], np.float32))
        obs, *_ = env.step(np.array([3.0], np.float32))
        np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-9)
    assert ref.data.nefc > 0 and obs[0] > 0.99  # at the limit


def test_inverted_pendulum_termination_and_reward(backend):
    env = ivy_gym.InvertedPendulum()
    states = np.array([[0.0, 0.0, 0.0, 0.0], [0.0, 0.25, 0.0, 0.0], [np.nan, 0, 0, 0]])
    if backend == "tensorflow":
        # tensorflow's matrix solve raises on a matrix that is not finite (the solver's
        # Newton step), where the other backends return NaN
        states = states[:2]
    n = len(states)
    state = native(states, backend)
    _, obs, reward, terminated = env.step(state, native(np.zeros((n, 1)), backend))
    np.testing.assert_array_equal(numpy_of(terminated), [False, True, True][:n])
    np.testing.assert_array_equal(numpy_of(reward), [1.0, 0.0, 0.0][:n])
    assert tuple(obs.shape) == (n, 4)


def test_inverted_pendulum_check_env(backend):
    check_env(gymnasium.make("ivy_gym/InvertedPendulum-v5", framework=backend).unwrapped)


def test_inverted_pendulum_return_gradient_matches_finite_differences(diff_backend):
    env = ivy_gym.InvertedPendulum()
    state = np.array([[0.1, 0.02, -0.05, 0.03]])
    actions = np.random.default_rng(1).uniform(-0.5, 0.5, (2, 1, 1))

    def total(actions):
        traj = ivy_gym.rollout(env, native(state, diff_backend), actions)
        return ivy.sum(traj.observations[..., 1] ** 2)

    def value_and_grad(actions):
        return ivy.execute_with_gradients(total, actions)

    if ivy.get_framework(f=diff_backend).capabilities.eager_compiles_ops:  # jax: one program
        value_and_grad = ivy.compile_fn(value_and_grad)

    grad = numpy_of(value_and_grad(native(actions, diff_backend))[1])

    def value(a):
        return float(numpy_of(total(native(a, diff_backend))))

    eps = 1e-6
    expected = np.zeros_like(actions)
    for index in np.ndindex(actions.shape):
        plus, minus = actions.copy(), actions.copy()
        plus[index] += eps
        minus[index] -= eps
        expected[index] = (value(plus) - value(minus)) / (2 * eps)
    assert np.abs(expected).max() > 1e-4
    np.testing.assert_allclose(grad, expected, rtol=1e-6, atol=1e-10)


def test_inverted_pendulum_batched_compiled_rollout(graph_backend):
    env = ivy_gym.InvertedPendulum()
    ivy.seed(0)
    state = env.reset((4,), dtype="float64", f=graph_backend)
    actions = native(np.random.default_rng(2).uniform(-3, 3, (5, 4, 1)), graph_backend)

    def run(state, actions):
        traj = ivy_gym.rollout(env, state, actions)
        return traj.states, traj.rewards

    compiled = ivy.compile_fn(run)(state, actions)
    # reference: each batch member stepped alone, eagerly, on numpy
    states = numpy_of(state)
    for b in range(4):
        s = states[b]
        for t in range(5):
            s, _, _, _ = env.step(s, numpy_of(actions)[t, b])
            np.testing.assert_allclose(numpy_of(compiled[0])[t, b], s, rtol=1e-10, atol=1e-12)
