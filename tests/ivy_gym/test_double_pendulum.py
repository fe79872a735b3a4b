"""InvertedDoublePendulum: Gymnasium's InvertedDoublePendulum-v5 step for step against Gymnasium's
MuJoCo environment (the reward's tip where MuJoCo's RK4 leaves ``site_xpos``, the slider limit's
force in the observation), its resets, check_env, the swing-up variant against a numpy
reference, and gradients of short returns against central finite differences."""

from __future__ import annotations

import functools

import gymnasium
import mujoco
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import ivy
import ivy_gym
import ivy_gym.gymnasium  # noqa: F401  (registers the ivy_gym/... ids)
from tests.helpers import native, numpy_of

pytestmark = pytest.mark.filterwarnings(
    "ignore:.*Box (observation|action) space.*:UserWarning",
    "ignore:.*symmetric and normalized space.*:UserWarning",
)

POLE = 0.6  # each pole's length in Gymnasium's inverted_double_pendulum.xml
# the batch of the batched tests: one shape for all (eager jax compiles each primitive per shape)
BATCH = 5


def _mj_steps(qpos, qvel, ctrl, n):
    """``n`` calls of MuJoCo's ``mj_step`` on Gymnasium's model: (qpos, qvel, site_xpos[0],
    qfrc_constraint[0])."""
    model = mujoco.MjModel.from_xml_path(ivy_gym.gymnasium_asset("inverted_double_pendulum.xml"))
    data = mujoco.MjData(model)
    data.qpos[:], data.qvel[:], data.ctrl[:] = qpos, qvel, ctrl
    for _ in range(n):
        mujoco.mj_step(model, data)
    return data.qpos.copy(), data.qvel.copy(), data.site_xpos[0].copy(), data.qfrc_constraint[0]


@functools.cache
def _episode(seed: int):
    """Gymnasium's own InvertedDoublePendulum-v5 over one episode of sampled float32 actions:
    ``(action, obs, reward, terminated, [qpos, qvel])`` after each step."""
    ref = gymnasium.make("InvertedDoublePendulum-v5")
    obs, _ = ref.reset(seed=seed)
    ref.action_space.seed(seed)
    data = ref.unwrapped.data
    rows = [(None, obs, None, None, np.concatenate([data.qpos, data.qvel]))]
    for _ in range(1000):
        action = ref.action_space.sample()
        assert action.dtype == np.float32
        obs, reward, terminated, truncated, _ = ref.step(action)
        state = np.concatenate([data.qpos, data.qvel])
        rows.append((action, obs, reward, terminated, state))
        if terminated or truncated:
            break
    return rows


def test_follows_gymnasium_step_for_step(backend):
    # one facade for both episodes: its step is compiled once on jax and tensorflow
    env = gymnasium.make("ivy_gym/InvertedDoublePendulum-v5", framework=backend, dtype="float64")
    for seed in (0, 7):
        rows = _episode(seed)
        assert len(rows) > 3  # an episode of several steps
        obs, _ = env.reset(seed=seed)
        np.testing.assert_allclose(obs, rows[0][1], rtol=0, atol=1e-12)
        np.testing.assert_allclose(env.unwrapped.state, rows[0][4], rtol=0, atol=1e-12)
        for action, ref_obs, ref_reward, ref_terminated, ref_state in rows[1:]:
            obs, reward, terminated, truncated, _ = env.step(action)
            np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-8)
            np.testing.assert_allclose(env.unwrapped.state, ref_state, rtol=0, atol=1e-8)
            assert reward == pytest.approx(ref_reward, rel=0, abs=1e-8)
            assert terminated == ref_terminated
            assert not truncated
        assert terminated  # the episode ended as Gymnasium's did


def test_the_reward_needs_the_last_rk4_stage_tip():
    """Gymnasium's rewards differ by more than the tolerance above from those of the tip at the
    final qpos: the comparison sees where the tip is read."""
    tree = ivy_gym.inverted_double_pendulum_tree()
    gaps = []
    for _, _, reward, terminated, state in _episode(0)[1:]:
        tip = numpy_of(tree.site_poses(state[:3]))[0, :3, 3]
        alive = 0.0 if terminated else 10.0
        penalties = 0.01 * tip[0] ** 2 + (tip[2] - 2) ** 2 + 1e-3 * state[4] ** 2
        gaps.append(abs(alive - penalties - 5e-3 * state[5] ** 2 - reward))
    assert max(gaps) > 1e-7


def test_frames_equal_mujoco(backend):
    """The environment's frames (``frame_skip`` calls of the pipeline's step, one scan) against
    ``mj_step``: the new state, the tip where the last RK4 stage leaves ``site_xpos`` and the
    slider limit's force, from states inside the slider's range and at its ends."""
    core = ivy_gym.InvertedDoublePendulum(frame_skip=2)
    rng = np.random.default_rng(3)
    qpos = rng.uniform(-0.5, 0.5, (BATCH, 3))
    qvel = rng.uniform(-2.0, 2.0, (BATCH, 3))
    qpos[:2, 0], qvel[:2, 0] = [0.995, -0.999], [3.0, -2.0]  # at the ends of the slider
    ctrl = rng.uniform(-1.0, 1.0, (BATCH, 1))
    expected = [_mj_steps(q, v, c, 2) for q, v, c in zip(qpos, qvel, ctrl)]
    xp = getattr(ivy, backend)
    data = core.simulate(
        xp, native(qpos, backend), native(qvel, backend), None, native(ctrl, backend)
    )
    forces = numpy_of(data.qfrc_constraint)[:, 0]
    assert np.abs(forces[:2]).min() > 1.0 and np.abs(forces[2:]).max() == 0.0
    for b, (q, v, site, force) in enumerate(expected):
        np.testing.assert_allclose(numpy_of(data.qpos)[b], q, rtol=0, atol=1e-12)
        np.testing.assert_allclose(numpy_of(data.qvel)[b], v, rtol=0, atol=1e-12)
        np.testing.assert_allclose(numpy_of(data.site_xpos)[b, 0], site, rtol=0, atol=1e-12)
        assert forces[b] == pytest.approx(force, rel=1e-10, abs=1e-10)


def _mujoco_step(state, action):
    """Gymnasium's env stepped from a given state: (obs, reward, terminated)."""
    ref = gymnasium.make("InvertedDoublePendulum-v5").unwrapped
    ref.reset(seed=0)
    ref.set_state(state[:3], state[3:])
    obs, reward, terminated, _, _ = ref.step(np.asarray(action, np.float32))
    return obs, reward, terminated


def test_termination_and_reward_of_chosen_states(backend):
    states = np.array(
        [
            [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],  # upright at rest
            [0.3, 0.05, -0.1, 0.5, 2.0, -3.0],  # upright, moving
            [0.0, 0.6, 0.3, 0.0, 0.0, 0.0],  # fallen: tip below 1
            [-0.2, -0.7, -0.5, -1.0, 1.0, -60.0],  # fallen, velocity beyond the clip
            [0.0, 0.15, 0.0, 0.0, 0.0, 0.0],  # leaning, still above the line
        ]
    )
    actions = np.array([[0.0], [0.4], [-1.0], [1.0], [-0.7]], np.float32)
    # and a state that is not finite, which ends the episode (Gymnasium's MuJoCo resets it
    # itself); not on tensorflow, whose matrix solve raises on a matrix that is not finite
    finite = backend == "tensorflow"
    inputs = states if finite else np.concatenate([states, np.full((1, 6), np.nan)])
    inputs_actions = actions if finite else np.concatenate([actions, np.zeros((1, 1), np.float32)])
    env = ivy_gym.InvertedDoublePendulum()
    state, obs, reward, terminated = env.step(
        native(inputs, backend), native(inputs_actions, backend)
    )
    if not finite:
        assert bool(numpy_of(terminated)[-1])
        obs, reward, terminated = (x[:-1] for x in (obs, reward, terminated))
    for b in range(len(states)):
        ref_obs, ref_reward, ref_terminated = _mujoco_step(states[b], actions[b])
        np.testing.assert_allclose(numpy_of(obs)[b], ref_obs, rtol=0, atol=1e-10)
        assert float(numpy_of(reward)[b]) == pytest.approx(ref_reward, rel=0, abs=1e-10)
        assert bool(numpy_of(terminated)[b]) == ref_terminated
    np.testing.assert_array_equal(numpy_of(terminated), [False, False, True, True, False])
    assert np.abs(numpy_of(obs)[:, 5:8]).max() == 10.0  # Gymnasium's clip of the velocities


def test_seeded_resets_draw_as_gymnasium(backend):
    ours = gymnasium.make("ivy_gym/InvertedDoublePendulum-v5", framework=backend, dtype="float64")
    ref = gymnasium.make("InvertedDoublePendulum-v5")
    for seed in (1, 2, 3):
        ref_obs, _ = ref.reset(seed=seed)
        obs, _ = ours.reset(seed=seed)
        np.testing.assert_array_equal(obs, ref_obs)
        data = ref.unwrapped.data
        np.testing.assert_array_equal(ours.unwrapped.state, np.concatenate([data.qpos, data.qvel]))
    # a batch: each state drawn as Gymnasium draws one, one after the other
    core = ivy_gym.InvertedDoublePendulum()
    rng, again = np.random.default_rng(4), np.random.default_rng(4)
    batch = core.draw_initial(rng, (2, 3))
    assert batch.shape == (2, 3, 6)
    for index in np.ndindex(2, 3):
        np.testing.assert_array_equal(batch[index], core.draw_initial(again))


def test_reset_draws_uniform_positions_and_normal_velocities(backend):
    env = ivy_gym.InvertedDoublePendulum()
    ivy.seed(11)
    draws = numpy_of(env.reset((4000,), dtype="float64", f=backend))
    ivy.seed(11)
    np.testing.assert_array_equal(numpy_of(env.reset((4000,), dtype="float64", f=backend)), draws)
    qpos, qvel = draws[:, :3], draws[:, 3:]
    assert np.abs(qpos).max() <= 0.1 and np.abs(qpos).max() > 0.099
    np.testing.assert_allclose(qpos.std(axis=0), 0.1 / np.sqrt(3), rtol=0.06)
    np.testing.assert_allclose(qvel.std(axis=0), 0.1, rtol=0.06)
    np.testing.assert_allclose(qvel.mean(axis=0), 0.0, atol=0.01)
    assert np.abs(qvel).max() > 0.25  # normal, not a box
    narrow = numpy_of(env.narrowed(0.5).reset((4000,), dtype="float64", f=backend))
    np.testing.assert_allclose(narrow[:, 3:].std(axis=0), 0.05, rtol=0.06)


def test_check_env_swing_up(backend):
    # (the registered task's own check_env on every backend is test_facades.py's, over TASKS)
    env = gymnasium.make("ivy_gym/InvertedDoublePendulum-v5", framework=backend, swing_up=True)
    check_env(env.unwrapped)
    assert env.spec.max_episode_steps == 1000


# ----------------------------------------------------------------------------------------------
# Swing-up
# ----------------------------------------------------------------------------------------------


def _swing_up_reward(state, action, b=0.8, weight=10.0):
    """The swing-up's reward of the new state, in numpy float64 (the tip from the poles'
    angles: hinge axes along y, so a pole at angle a points along (sin a, cos a) in x-z)."""
    x, a1, a2 = state[..., 0], state[..., 1], state[..., 2]
    height = POLE * np.cos(a1) + POLE * np.cos(a1 + a2)
    velocity = 1e-3 * np.sum(state[..., 3:] ** 2, axis=-1)
    effort = 1e-2 * action[..., 0] ** 2
    barrier = weight * (np.maximum(x - b, 0) ** 2 + np.maximum(-x - b, 0) ** 2) / (1 - b) ** 2
    return height / (2 * POLE) - velocity - effort - barrier


def test_swing_up_starts_hanging_down(backend):
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    assert not env.can_terminate and ivy_gym.InvertedDoublePendulum().can_terminate
    ivy.seed(5)
    draws = numpy_of(env.reset((500,), dtype="float64", f=backend))
    assert np.abs(draws[:, 1] - np.pi).max() <= 0.1 and np.abs(draws[:, [0, 2]]).max() <= 0.1
    host = env.draw_initial(np.random.default_rng(0), (500,))
    assert np.abs(host[:, 1] - np.pi).max() <= 0.1 and np.abs(host[:, [0, 2]]).max() <= 0.1
    heights = POLE * np.cos(draws[:, 1]) + POLE * np.cos(draws[:, 1] + draws[:, 2])
    assert heights.max() < -1.15  # the tip hangs below the cart


def test_swing_up_reward_and_no_termination(backend):
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    states = np.array(
        [
            [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],  # upright
            [0.0, np.pi, 0.0, 0.0, 0.0, 0.0],  # hanging
            [0.0, np.pi / 2, 0.0, 0.0, 0.0, 0.0],  # horizontal
            [0.95, 0.1, -0.1, 0.5, 1.0, -1.0],  # near the slider's end: the barrier
            [-1.2, 2.0, 1.0, -2.0, 3.0, 4.0],  # beyond it
        ]
    )
    actions = np.array([[0.0], [0.0], [0.5], [-1.0], [0.3]])
    new, obs, reward, terminated = env.step(native(states, backend), native(actions, backend))
    np.testing.assert_array_equal(numpy_of(terminated), [False] * 5)
    expected = _swing_up_reward(numpy_of(new), actions)
    np.testing.assert_allclose(numpy_of(reward), expected, rtol=0, atol=1e-10)
    r = numpy_of(reward)
    assert r[0] > 0.99 and r[1] < -0.99 and r[0] > r[2] > r[1]  # rewards the upright tip
    assert r[4] < -10.0  # the barrier
    # the dynamics of Gymnasium's task, five mj_step with the control held (the last state lies
    # beyond the slider's range: its limit pushes the cart back)
    for b in range(BATCH):
        qpos, qvel, _, _ = _mj_steps(states[b, :3], states[b, 3:], actions[b], 5)
        np.testing.assert_allclose(numpy_of(new)[b], np.concatenate([qpos, qvel]), atol=1e-10)


def test_swing_up_residuals(backend):
    """Upright, still and centred over the last ``hold`` states, the barrier's square root
    over all of them, batch first; in numpy float64 here."""
    env = ivy_gym.InvertedDoublePendulum(swing_up=True)
    states = np.random.default_rng(3).normal(size=(5, 2, 3, 6)) * [0.8, 3, 3, 1, 1, 1]
    states[0, 0, 0, 0] = 1.3  # beyond the barrier's start, before the held states
    traj = ivy_gym.Trajectory(*(None,) * 5, native(states, backend), None)
    x, a1, phi2 = states[..., 0], states[..., 1], states[..., 1] + states[..., 2]
    upright = np.stack([x, np.sin(a1), 1 - np.cos(a1), np.sin(phi2), 1 - np.cos(phi2)], axis=-1)
    upright = np.concatenate([upright, 0.2 * states[..., 3:]], axis=-1)[-2:]  # (2, 2, 3, 8)
    barrier = np.sqrt(10.0) / 0.2 * (np.maximum(x - 0.8, 0) + np.maximum(-x - 0.8, 0))
    expected = np.concatenate(
        [upright.transpose(1, 2, 0, 3).reshape(2, 3, 16), barrier.transpose(1, 2, 0)], axis=-1
    )
    assert expected[0, 0, 16] > 5  # the first state's barrier
    np.testing.assert_allclose(
        numpy_of(env.swing_up_residuals(traj, hold=2)), expected, rtol=1e-12, atol=1e-12
    )
    # upright at any whole turn of either pole, with the second pole's angle relative
    turned = np.zeros((1, 1, 6))
    turned[..., 1:3] = [2 * np.pi, -4 * np.pi]
    traj = ivy_gym.Trajectory(*(None,) * 5, native(turned, backend), None)
    np.testing.assert_allclose(numpy_of(env.swing_up_residuals(traj, hold=1)), 0, atol=1e-12)
    with pytest.raises(ValueError, match=r"hold must be in \[1, 1\]"):
        env.swing_up_residuals(traj, hold=2)


# ----------------------------------------------------------------------------------------------
# Gradients: analytic on the differentiable backends, central differences on numpy
# ----------------------------------------------------------------------------------------------

# frame_skip=2 keeps the tests short and runs two frames of the step's scan (the reward reads the
# last frame's last RK4 stage)
_FRAME_SKIP = 2
_STATE = np.array([0.1, 0.05, -0.08, 0.3, -0.4, 0.6])  # upright: no termination in 2 steps
_SWING_STATE = np.array([0.1, 3.0, 0.2, 0.3, -0.4, 0.6])
_ACTIONS = np.array([[0.3], [-0.5]])


def _return(env, state, actions):
    total = 0.0
    for t in range(actions.shape[0]):
        state, _, reward, _ = env.step(state, actions[t])
        total = total + reward
    return total


@functools.cache
def _finite_difference_gradient(swing_up: bool):
    env = ivy_gym.InvertedDoublePendulum(swing_up=swing_up, frame_skip=_FRAME_SKIP)
    state = _SWING_STATE if swing_up else _STATE
    x = np.concatenate([state, _ACTIONS.ravel()])

    def value(x):
        return float(_return(env, x[:6], x[6:].reshape(2, 1)))

    eps = 1e-6
    grad = np.zeros_like(x)
    for i in range(x.size):
        step = np.zeros_like(x)
        step[i] = eps
        grad[i] = (value(x + step) - value(x - step)) / (2 * eps)
    return grad


@pytest.mark.parametrize("swing_up", [False, True])
def test_return_gradient_matches_finite_differences(swing_up, diff_backend):
    env = ivy_gym.InvertedDoublePendulum(swing_up=swing_up, frame_skip=_FRAME_SKIP)
    state = _SWING_STATE if swing_up else _STATE

    def total(xs):
        return _return(env, xs[0], xs[1])

    def value_and_grad(xs):
        return ivy.execute_with_gradients(total, xs)

    if ivy.get_framework(f=diff_backend).capabilities.eager_compiles_ops:  # jax: one program
        value_and_grad = ivy.compile_fn(value_and_grad)
    xs = [native(state, diff_backend), native(_ACTIONS, diff_backend)]
    _, grads = value_and_grad(xs)
    grad = np.concatenate([numpy_of(grads[0]), numpy_of(grads[1]).ravel()])
    expected = _finite_difference_gradient(swing_up)
    assert np.abs(expected[6:]).min() > 1e-3 and np.abs(expected[:6]).max() > 1e-2
    np.testing.assert_allclose(grad, expected, rtol=1e-6, atol=1e-7)
