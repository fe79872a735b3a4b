"""ReacherMuJoCo: Gymnasium's Reacher-v5 on ivy_robot.physics, step for step against Gymnasium's
own MuJoCo environment (observations, rewards, info, states, seeded resets, the elbow at its
limit; compiled on jax and tensorflow through the vector facade), check_env, the ivy reset's
distribution, float32 and broadcast batches, and gradients against finite differences."""

from __future__ import annotations

import functools

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import ivy
import ivy_gym
from tests.helpers import native, native_value_and_grads, numpy_of

pytestmark = pytest.mark.filterwarnings(
    "ignore:.*Box (observation|action) space.*:UserWarning",
    "ignore:.*symmetric and normalized space.*:UserWarning",
)

# seed 3's 50 steps of sampled actions keep the elbow inside its range [-3, 3]; seed 9's reach
# it at step 16 and stay at it for 7 steps (7 of the seeds 0 to 11 reach it), where MuJoCo's limit
# constraint acts
SEEDS = (3, 9)


@functools.cache
def _episode(seed: int):
    """Gymnasium's own Reacher-v5 over one whole episode of sampled float32 actions: rows of
    (action, observation, reward, truncated, qpos + qvel, info, number of constraint rows)."""
    ref = gymnasium.make("Reacher-v5")
    obs, info = ref.reset(seed=seed)
    ref.action_space.seed(seed)
    data = ref.unwrapped.data
    rows = [(None, obs, None, False, np.concatenate([data.qpos, data.qvel]), info, 0)]
    truncated = False
    while not truncated:
        action = ref.action_space.sample()
        assert action.dtype == np.float32
        obs, reward, terminated, truncated, info = ref.step(action)
        assert not terminated
        state = np.concatenate([data.qpos, data.qvel])
        rows.append((action, obs, reward, truncated, state, info, data.nefc))
    return rows


def test_reacher_follows_gymnasium(backend):
    # one environment of the vector facade: its step is compiled on jax and tensorflow (once for
    # both episodes; eager, a step of these dynamics costs ~0.2 s there), eager elsewhere
    core = ivy_gym.ReacherMuJoCo()
    env = ivy_gym.GymnasiumVectorEnv(
        core, 1, framework=backend, dtype="float64", max_episode_steps=50, device="cpu"
    )
    stale, limited = 0.0, 0
    for seed in SEEDS:
        rows = _episode(seed)
        assert len(rows) == 51  # Gymnasium's time limit: 50 steps
        obs, _ = env.reset(seed=seed)
        np.testing.assert_allclose(obs[0], rows[0][1], rtol=0, atol=1e-12)
        np.testing.assert_allclose(env.state[0], rows[0][4], rtol=0, atol=1e-15)
        for action, ref_obs, ref_reward, ref_truncated, ref_state, ref_info, nefc in rows[1:]:
            limited += nefc > 0  # the elbow at its limit: MuJoCo's constraint acts
            obs, reward, terminated, truncated, info = env.step(action[None])
            np.testing.assert_allclose(obs[0], ref_obs, rtol=0, atol=1e-8)
            np.testing.assert_allclose(env.state[0], ref_state, rtol=0, atol=1e-8)
            assert abs(reward[0] - ref_reward) < 1e-8
            assert not terminated[0] and truncated[0] == ref_truncated
            for key, value in ref_info.items():  # Gymnasium's info, stacked by the vector env
                assert info[key].dtype == np.dtype(type(value)) and info["_" + key][0]
                assert abs(info[key][0] - value) < 1e-8
            # the fingertip after a step is MuJoCo's stale one: the state's own differs
            fresh = core.observe(env.state[0], f="numpy")
            stale = max(stale, np.abs(fresh[8:] - obs[0, 8:]).max())
        assert truncated[0]
    assert stale > 1e-6  # 100 times the tolerance: the comparison tells stale from fresh
    assert limited >= 5


def _gymnasium_resets(seed: int, n: int) -> np.ndarray:
    """``n`` initial states of Gymnasium's own Reacher-v5, drawn in turn from one generator
    seeded with ``seed`` (what one seeded reset of a vector facade draws)."""
    ref = gymnasium.make("Reacher-v5").unwrapped
    ref.reset(seed=seed)
    states = [np.concatenate([ref.data.qpos, ref.data.qvel])]
    for _ in range(n - 1):
        ref.reset_model()
        states.append(np.concatenate([ref.data.qpos, ref.data.qvel]))
    return np.stack(states)


def test_reacher_seeded_resets_are_gymnasiums(backend):
    expected = _gymnasium_resets(11, 5)
    core = ivy_gym.ReacherMuJoCo()
    np.testing.assert_array_equal(core.draw_initial(np.random.default_rng(11), (5,)), expected)
    envs = ivy_gym.GymnasiumVectorEnv(core, 5, framework=backend, dtype="float64")
    obs, _ = envs.reset(seed=11)
    np.testing.assert_allclose(envs.unwrapped.state, expected, rtol=0, atol=1e-15)
    # the observation of a reset: Gymnasium's, after mj_forward (the fingertip at the state)
    ref = gymnasium.make("Reacher-v5")
    ref_obs, _ = ref.reset(seed=11)
    np.testing.assert_allclose(obs[0], ref_obs, rtol=0, atol=1e-12)
    env = gymnasium.make("ivy_gym/Reacher-v5", framework=backend, dtype="float64")
    np.testing.assert_allclose(env.reset(seed=11)[0], ref_obs, rtol=0, atol=1e-12)


def test_reacher_ivy_reset_draws_the_goal_in_its_disc(backend):
    core = ivy_gym.ReacherMuJoCo()
    ivy.seed(0)
    states = numpy_of(core.reset((4000,), dtype="float64", f=backend))
    assert states.shape == (4000, 8)
    assert (np.abs(states[:, :2]) <= 0.1).all() and (np.abs(states[:, 4:6]) <= 0.005).all()
    np.testing.assert_array_equal(states[:, 6:], 0.0)  # the target at rest
    r2 = np.sum(states[:, 2:4] ** 2, axis=-1) / 0.2**2
    assert (r2 < 1).all()
    # uniform on the disc: E[r^2] = R^2 / 2 (the square would give 2 R^2 / 3), any direction
    assert abs(r2.mean() - 0.5) < 0.03
    angle = np.arctan2(states[:, 3], states[:, 2])
    assert abs(np.cos(angle).mean()) < 0.06 and abs(np.sin(angle).mean()) < 0.06
    assert np.abs(states[:, :2]).max() > 0.09 and np.abs(states[:, 4:6]).max() > 0.0045


def test_reacher_check_env(backend):
    env = gymnasium.make("ivy_gym/Reacher-v5", framework=backend)
    check_env(env.unwrapped)
    assert env.spec.max_episode_steps == 50 and env.spec.reward_threshold == -3.75
    np.testing.assert_array_equal(env.action_space.low, [-1, -1])
    np.testing.assert_array_equal(env.action_space.high, [1, 1])


# a state away from the target, the target moving, and an action beyond the control range in
# its second component (the actuator clamps the control: only the control cost depends on it)
_STATE = np.array([[0.3, -0.8, 0.12, -0.05, 1.5, -2.0, 0.3, -0.2]])
_ACTION = np.array([[0.4, 1.3]])


def _one_step_return(state, action):
    """The reward of one step (two RK4 steps) and the squared fingertip-target distance of its
    observation."""
    _, obs, reward, _ = ivy_gym.ReacherMuJoCo().step(state, action)
    return ivy.sum(reward) + ivy.sum(obs[..., 8:] ** 2)


@functools.cache
def _finite_differences():
    """Central finite differences of the one-step return on numpy, float64."""
    eps = 1e-6
    grads = []
    for which in range(2):
        arrays = [_STATE, _ACTION]
        grad = np.zeros_like(arrays[which])
        for index in np.ndindex(grad.shape):
            plus, minus = [a.copy() for a in arrays], [a.copy() for a in arrays]
            plus[which][index] += eps
            minus[which][index] -= eps
            delta = float(_one_step_return(*plus)) - float(_one_step_return(*minus))
            grad[index] = delta / (2 * eps)
        grads.append(grad)
    return grads


def test_reacher_return_gradient_matches_finite_differences(diff_backend):
    value, (grad_state, grad_action) = native_value_and_grads(
        diff_backend, _one_step_return, [_STATE, _ACTION], 1.0
    )
    assert np.isclose(value, float(_one_step_return(_STATE, _ACTION)), rtol=1e-12)
    fd_state, fd_action = _finite_differences()
    assert np.abs(fd_state).min() > 1e-4  # every component of the state counts
    assert abs(fd_action[0, 1] + 2 * 1.3) < 1e-6 and abs(fd_action[0, 0]) > 1e-2
    np.testing.assert_allclose(grad_state, fd_state, rtol=1e-6, atol=1e-8)
    np.testing.assert_allclose(grad_action, fd_action, rtol=1e-6, atol=1e-8)


def test_reacher_float32_broadcasting_and_narrowed_resets(backend):
    core = ivy_gym.ReacherMuJoCo()
    state = np.array([[0.05, -0.02, 0.1, 0.08, 0.003, -0.001, 0.0, 0.0]])
    actions = np.array([[0.5, -0.5], [1.0, 0.2], [-0.3, 0.0]])
    # one state, three actions: the batch broadcasts; float32 throughout stays float32
    s, obs, reward, done = core.step(
        native(state.astype(np.float32), backend), native(actions.astype(np.float32), backend)
    )
    assert tuple(s.shape) == (3, 8) and tuple(obs.shape) == (3, 10)
    assert tuple(reward.shape) == (3,) and not numpy_of(done).any()
    assert numpy_of(s).dtype == np.float32 and numpy_of(reward).dtype == np.float32
    for b in range(3):  # each as its own batch of one, on numpy float64
        ref = core.step(state, actions[b : b + 1])
        np.testing.assert_allclose(numpy_of(s)[b], ref[0][0], rtol=1e-5, atol=1e-5)
        np.testing.assert_allclose(numpy_of(obs)[b], ref[1][0], rtol=1e-5, atol=1e-5)
        np.testing.assert_allclose(numpy_of(reward)[b], ref[2][0], rtol=1e-5, atol=1e-5)
    # a narrowed reset box shrinks every noise and the goal's disc
    draws = core.narrowed(0.5).draw_initial(np.random.default_rng(0), (200,))
    assert (np.abs(draws[:, :2]) <= 0.05).all() and (np.abs(draws[:, 4:6]) <= 0.0025).all()
    assert (np.hypot(draws[:, 2], draws[:, 3]) < 0.1).all()
    assert np.hypot(draws[:, 2], draws[:, 3]).max() > 0.09
