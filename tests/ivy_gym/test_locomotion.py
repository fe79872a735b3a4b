"""Gymnasium's MuJoCo locomotion tasks on ivy_robot.physics (Hopper-v5, Walker2d-v5, HalfCheetah-v5,
Ant-v5, Humanoid-v5, Swimmer-v5) against Gymnasium's own environments.

- step by step: from Gymnasium's state (``qpos``, ``qvel``, and what the task carries: the
  solver's warm start, the stale position Gymnasium reads before a step), at states where
  contacts and joint limits act, the observation, reward, termination and every ``info`` value
  (float64, numpy; a batch of such states in one call);
- free-running from the same seed with sampled float32 actions, through the facades, for the
  horizon over which the trajectories agree to a stated tolerance (contacts make them chaotic);
  the facades' types (float64 observations, float32 action space, rewards and ``info`` values
  of Gymnasium's types) and ``check_env``;
- every backend: the facade (compiled on jax and tensorflow, eager on torch) against
  Gymnasium's steps and against the numpy core, ``check_env``, ``set_state``;
- a batch of 64 equals 64 single steps; Gymnasium's constructor arguments; rendering;
- gradients of a short rollout's return with respect to the actions and the initial state
  against central finite differences, where the contact set does not change.

Speed: numpy runs the physics eagerly at tens of milliseconds a step (Humanoid's PGS: ~2 s), so
the numpy tests use few steps; jax and tensorflow compile the facade's step once per test.
"""

from __future__ import annotations

import functools

import gymnasium
import mujoco
import numpy as np
import pytest
from gymnasium.envs.mujoco.humanoid_v5 import mass_center
from gymnasium.utils.env_checker import check_env
from gymnasium.utils.env_match import check_environments_match

import ivy
import ivy_gym
import ivy_gym.gymnasium  # noqa: F401  (registers the ivy_gym/... ids)
from tests.helpers import check_gradients, numpy_of

pytestmark = pytest.mark.filterwarnings(
    "ignore:.*Box (observation|action) space.*:UserWarning",
    "ignore:.*symmetric and normalized space.*:UserWarning",
    "ignore:.*out of date.*:DeprecationWarning",
)

TASKS = {
    "Hopper-v5": ivy_gym.Hopper,
    "Walker2d-v5": ivy_gym.Walker2d,
    "HalfCheetah-v5": ivy_gym.HalfCheetah,
    "Ant-v5": ivy_gym.Ant,
    "Humanoid-v5": ivy_gym.Humanoid,
    "Swimmer-v5": ivy_gym.SwimmerMuJoCo,
}
_LIMIT = int(mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT)


def _core_state(core, env) -> np.ndarray:
    """The core's state of Gymnasium's environment ``env`` as it stands (before a step)."""
    env = env.unwrapped
    d = env.data
    parts = [d.qpos, d.qvel]
    if core.carries_warmstart:
        parts.append(d.qacc_warmstart)
    if core.position_stale:
        if isinstance(core, ivy_gym.Ant):  # the torso's xpos the previous step left
            parts.append(d.body(core.params.main_body).xpos[:2])
        else:  # Humanoid: the centre of mass of that step's xipos
            parts.append(mass_center(env.model, d))
    return np.concatenate(parts).copy()


@functools.cache
def _gymnasium_run(task: str, seed: int = 0, steps: int = 40):
    """Gymnasium's ``task`` over ``steps`` sampled float32 actions (reset after a
    termination): per step ``(state before, action, obs, reward, terminated, info, contacts,
    limits)``, the state in the core's layout."""
    core = TASKS[task]()
    env = gymnasium.make(task).unwrapped
    env.reset(seed=seed)
    env.action_space.seed(seed)
    rows = []
    for t in range(steps):
        before = _core_state(core, env)
        action = env.action_space.sample()
        obs, reward, terminated, _, info = env.step(action)
        d = env.data
        limits = bool(np.any(np.asarray(d.efc_type) == _LIMIT))
        rows.append((before, action, obs, reward, terminated, info, d.ncon > 0, limits))
        if terminated:
            env.reset(seed=seed + t + 1)
    return rows


def _busy_steps(task: str, count: int):
    """Up to ``count`` recorded steps where contacts and limits act (Swimmer: limits only)."""
    rows = _gymnasium_run(task)
    both = [r for r in rows if r[6] and r[7]]
    some = [r for r in rows if (r[6] or r[7]) and not (r[6] and r[7])]
    chosen = (both + some)[:count]
    assert any(r[7] for r in chosen)  # a joint at its limit
    if task != "Swimmer-v5":  # the swimmer floats: no contacts
        assert any(r[6] for r in chosen)
    return chosen


def _assert_info_close(info: dict, expected: dict, index=None, atol=1e-9) -> None:
    assert set(info) == set(expected)
    for key, value in expected.items():
        ours = info[key] if isinstance(info[key], (int, float)) else numpy_of(info[key])
        ours = np.asarray(ours if index is None else ours[index])
        np.testing.assert_allclose(ours, value, rtol=1e-9, atol=atol, err_msg=key)


# ----------------------------------------------------------------------------------------------
# Step by step, numpy float64
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("task", sorted(TASKS))
def test_steps_follow_gymnasium_from_its_states(task):
    """A batch of Gymnasium's states where contacts and limits act, stepped in one call."""
    rows = _busy_steps(task, 2 if task == "Humanoid-v5" else 4)
    core = TASKS[task]()
    states = np.stack([r[0] for r in rows])
    actions = np.stack([r[1] for r in rows])  # float32, as Gymnasium's samples
    new, obs, reward, terminated, info = core.kernel_step_info(ivy.numpy, states, actions)
    for b, (_, _, ref_obs, ref_reward, ref_terminated, ref_info, _, _) in enumerate(rows):
        scale = max(1.0, np.abs(ref_obs).max())  # Humanoid's inertias and forces reach ~1e3
        np.testing.assert_allclose(obs[b], ref_obs, rtol=0, atol=1e-9 * scale)
        assert reward[b] == pytest.approx(ref_reward, rel=1e-9, abs=1e-9)
        assert bool(terminated[b]) == ref_terminated
        _assert_info_close(info, ref_info, b)
    assert new.shape == states.shape


# ----------------------------------------------------------------------------------------------
# Free-running through the facades from the same seed, numpy float64
# ----------------------------------------------------------------------------------------------

# steps over which the facade follows Gymnasium to 1e-9 from the same seed (seed 0), and the
# whole run measured (100 steps; Humanoid 40): where contacts come and go the trajectories part
# exponentially (rounding-level differences of the contact forces grow ~10x every few steps):
# Hopper 8e-15, Walker2d 3e-13 and Swimmer 3e-14 over 100 steps; HalfCheetah above 1e-9 from step
# 41 (1e-6: 52), Ant from step 31 (1e-6: 83), Humanoid (PGS) from step 18 (1e-6: 31)
FREE_RUN = {
    "Hopper-v5": 30,
    "Walker2d-v5": 25,
    "HalfCheetah-v5": 30,
    "Ant-v5": 20,
    "Humanoid-v5": 6,
    "Swimmer-v5": 30,
}


@pytest.mark.parametrize("task", sorted(TASKS))
def test_facade_free_runs_with_gymnasium_from_a_seed(task):
    steps = FREE_RUN[task]
    ref = gymnasium.make(task)
    env = gymnasium.make(f"ivy_gym/{task}", framework="numpy")
    # Gymnasium's own check: spaces, seeded resets, observations (1e-5), terminations, info keys;
    # its rewards are compared exactly (==), which rounding-level differences fail: below, to 1e-9
    check_environments_match(
        ref, env, num_steps=3, seed=0, skip_rew=True, info_comparison="keys-equivalence"
    )
    assert env.observation_space.dtype == np.float64 and env.action_space.dtype == np.float32
    ref_obs, ref_info = ref.reset(seed=0)
    obs, info = env.reset(seed=0)
    np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-12)  # Humanoid's: mj_forward's
    _assert_info_close(info, ref_info, atol=0)
    ref.action_space.seed(0)
    for t in range(steps):
        action = ref.action_space.sample()
        ref_obs, ref_reward, ref_terminated, _, ref_info = ref.step(action)
        obs, reward, terminated, _, info = env.step(action)
        scale = max(1.0, np.abs(ref_obs).max())
        np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-9 * scale, err_msg=f"step {t}")
        assert type(reward) is type(ref_reward) and abs(reward - ref_reward) < 1e-9
        assert terminated == ref_terminated
        for key, value in ref_info.items():  # Gymnasium's types: np.float32 control costs...
            assert type(info[key]) is type(value), key
        _assert_info_close(info, ref_info)
        if terminated:
            ref.reset(seed=t)
            env.reset(seed=t)


def test_facades_pass_check_env_and_render():
    for task in sorted(TASKS):
        env = gymnasium.make(f"ivy_gym/{task}", framework="numpy", render_mode="rgb_array")
        check_env(env.unwrapped, skip_render_check=task == "Humanoid-v5")
        frame = env.unwrapped.render()
        assert frame.shape == (400, 400, 3) and frame.dtype == np.uint8
        assert len(np.unique(frame.reshape(-1, 3), axis=0)) >= 3  # the robot on the floor
        spec = gymnasium.spec(task)
        assert env.spec.max_episode_steps == spec.max_episode_steps == 1000
        assert env.spec.reward_threshold == spec.reward_threshold


# ----------------------------------------------------------------------------------------------
# Every backend: the facade against Gymnasium's steps and the numpy core
# ----------------------------------------------------------------------------------------------

# one task per backend (a compiled step costs a compilation per task: seconds to a minute)
BACKEND_TASKS = {
    "numpy": "Walker2d-v5",
    "torch": "Ant-v5",
    "jax": "Ant-v5",
    "tensorflow": "Hopper-v5",
}


def test_facade_on_every_backend(backend):
    task = BACKEND_TASKS[backend]
    env = gymnasium.make(f"ivy_gym/{task}", framework=backend).unwrapped
    assert env.compiled == (backend in ("jax", "tensorflow"))
    core = env.core
    check_env(env, skip_render_check=True)
    check_environments_match(  # rewards: rounding apart, compared to 1e-9 below
        gymnasium.make(task), env, num_steps=2, skip_rew=True, info_comparison="keys-equivalence"
    )
    # set_state as Gymnasium's: then both step from the same state
    ref = gymnasium.make(task).unwrapped
    ref.reset(seed=1)
    env.reset(seed=1)
    for before, action, ref_obs, ref_reward, ref_terminated, ref_info, _, _ in _busy_steps(task, 3):
        nq, nv = core.model.nq, core.model.nv
        env.state = before  # qpos, qvel and what the task carries
        obs, reward, terminated, _, info = env.step(action)
        np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-9)
        assert abs(reward - ref_reward) < 1e-9 and terminated == ref_terminated
        _assert_info_close(info, ref_info)
        # the compiled (or torch) step equals the numpy core's eager one
        expected = core.kernel_step_info(ivy.numpy, before, action)
        np.testing.assert_allclose(env.state, expected[0], rtol=0, atol=1e-12)
        np.testing.assert_allclose(obs, expected[1], rtol=0, atol=1e-12)
        # Gymnasium's set_state: qpos and qvel, the stale readings as mj_forward leaves them
        ref.set_state(before[:nq], before[nq : nq + nv])
        env.set_state(before[:nq], before[nq : nq + nv])
        np.testing.assert_allclose(env.state, _core_state(core, ref), rtol=0, atol=1e-14)


# ----------------------------------------------------------------------------------------------
# Batches, arguments, rendering
# ----------------------------------------------------------------------------------------------


def test_a_batch_of_64_equals_64_single_steps():
    core = ivy_gym.Hopper(frame_skip=1)
    rng = np.random.default_rng(5)
    rows = _gymnasium_run("Hopper-v5")
    states = np.stack([rows[i % len(rows)][0] for i in range(64)])
    states[:, 6:] += rng.uniform(-0.5, 0.5, (64, 6))  # 64 different states, most in contact
    actions = rng.uniform(-1, 1, (64, 3)).astype(np.float32)
    batch = core.kernel_step_info(ivy.numpy, states, actions)
    for b in range(64):
        single = core.kernel_step_info(ivy.numpy, states[b], actions[b])
        for ours, one in zip(batch[:4], single[:4]):
            np.testing.assert_allclose(ours[b], one, rtol=0, atol=1e-13)
        for key, value in single[4].items():
            np.testing.assert_allclose(batch[4][key][b], value, rtol=0, atol=1e-13)


def test_humanoid_batch_keeps_each_solve_apart():
    """PGS stops at a tolerance per element: a batch steps each as it would alone."""
    core = ivy_gym.Humanoid(frame_skip=1)
    rows = _busy_steps("Humanoid-v5", 2)
    states = np.stack([r[0] for r in rows])
    actions = np.stack([r[1] for r in rows])
    batch = core.kernel_step(ivy.numpy, states, actions)
    for b in range(len(rows)):
        single = core.kernel_step(ivy.numpy, states[b], actions[b])
        np.testing.assert_allclose(batch[0][b], single[0], rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "task, kwargs",
    [
        (
            "Hopper-v5",
            dict(
                exclude_current_positions_from_observation=False,
                healthy_reward=2.0,
                terminate_when_unhealthy=False,
                healthy_z_range=(1.3, 2.0),
                ctrl_cost_weight=0.1,
                reset_noise_scale=0.05,
                frame_skip=2,
            ),
        ),
        (
            "Ant-v5",
            dict(
                include_cfrc_ext_in_observation=False,
                main_body="torso",
                contact_force_range=(-0.5, 0.5),
                exclude_current_positions_from_observation=False,
                healthy_z_range=(0.3, 0.9),
            ),
        ),
        (
            "HalfCheetah-v5",
            dict(forward_reward_weight=2.0, exclude_current_positions_from_observation=False),
        ),
        ("Swimmer-v5", dict(ctrl_cost_weight=0.5, reset_noise_scale=0.3)),
    ],
)
def test_constructor_arguments_are_gymnasiums(task, kwargs):
    ref = gymnasium.make(task, **kwargs)
    env = gymnasium.make(f"ivy_gym/{task}", framework="numpy", **kwargs)
    assert env.observation_space.shape == ref.observation_space.shape
    ref_obs, _ = ref.reset(seed=2)
    obs, _ = env.reset(seed=2)
    np.testing.assert_array_equal(obs, ref_obs)
    ref.action_space.seed(2)
    for _ in range(3):
        action = ref.action_space.sample()
        ref_obs, ref_reward, ref_terminated, _, ref_info = ref.step(action)
        obs, reward, terminated, _, info = env.step(action)
        np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-9)
        assert abs(reward - ref_reward) < 1e-9 and terminated == ref_terminated
        _assert_info_close(info, ref_info)


def test_humanoid_observation_selection():
    kwargs = dict(
        include_cinert_in_observation=False,
        include_cvel_in_observation=False,
        include_qfrc_actuator_in_observation=False,
        contact_cost_range=(-1.0, 1e-4),
    )
    ref = gymnasium.make("Humanoid-v5", **kwargs)
    env = gymnasium.make("ivy_gym/Humanoid-v5", framework="numpy", **kwargs)
    assert env.observation_space.shape == ref.observation_space.shape == (45 + 13 * 6,)
    ref_obs, ref_info = ref.reset(seed=4)
    obs, info = env.reset(seed=4)
    np.testing.assert_array_equal(obs, ref_obs)
    _assert_info_close(info, ref_info, atol=0)
    action = ref.action_space.sample()
    ref_obs, ref_reward, *_, ref_info = ref.step(action)
    obs, reward, *_, info = env.step(action)
    np.testing.assert_allclose(obs, ref_obs, rtol=0, atol=1e-9)
    assert abs(reward - ref_reward) < 1e-9
    _assert_info_close(info, ref_info)


def test_vector_facade_stacks_info_and_autoresets():
    # (a narrow healthy height, so that an episode ends within a few steps)
    envs = gymnasium.make_vec(
        "ivy_gym/Hopper-v5",
        num_envs=2,
        vectorization_mode="vector_entry_point",
        healthy_z_range=(1.22, float("inf")),
    )
    obs, info = envs.reset(seed=0)
    assert obs.dtype == np.float64 and set(info) == {
        "x_position",
        "_x_position",
        "z_distance_from_origin",
        "_z_distance_from_origin",
    }
    envs.action_space.seed(0)
    done = np.zeros(2, bool)
    for _ in range(20):
        restarting = done
        obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
        assert info["reward_ctrl"].dtype == np.float32  # Gymnasium's float32 control cost
        assert info["reward_survive"].dtype == np.float64
        if restarting.any():  # the reset's info, and no step info, for the restarted copy
            assert not info["_x_velocity"][restarting].any()
            assert info["_x_position"][restarting].all()
            break
        done = terminated | truncated
    else:
        pytest.fail("no episode ended in 20 steps of random actions")


def test_render_draws_the_robot_where_it_is():
    core = ivy_gym.Hopper()
    state = core.kernel_initial(ivy.numpy, core.draw_initial(np.random.default_rng(0)))
    frame = core.render(state, width=200, height=200)
    moved = state.copy()
    moved[1] += 0.5  # higher: the picture changes above the floor
    assert not np.array_equal(frame, core.render(moved, width=200, height=200))
    ant = ivy_gym.Ant()
    top = ant.render(ant.kernel_initial(ivy.numpy, ant.draw_initial(np.random.default_rng(0))))
    assert top.shape == (400, 400, 3) and len(np.unique(top.reshape(-1, 3), axis=0)) > 3


# ----------------------------------------------------------------------------------------------
# Gradients through steps with contacts
# ----------------------------------------------------------------------------------------------


@functools.cache
def _steady_contact_state():
    """A Hopper state from Gymnasium's run whose next two steps keep one contact set."""
    rows = _gymnasium_run("Hopper-v5")
    for i in range(len(rows) - 2):
        if all(r[6] for r in rows[i : i + 3]) and not any(r[4] for r in rows[i : i + 3]):
            return rows[i][0], np.stack([rows[i][1], rows[i + 1][1]]).astype(np.float64)
    raise AssertionError("no steady contact in the recorded run")


def test_rollout_return_gradient_equals_finite_differences(diff_backend):
    state, actions = _steady_contact_state()
    core = ivy_gym.Hopper(frame_skip=2)

    def total(state, actions):
        xp = ivy.get_framework(state)
        traj = ivy_gym.rollout(core, state, actions)
        return xp.sum(traj.rewards) + xp.sum(traj.observations[-1] ** 2)

    if ivy.get_framework(f=diff_backend).capabilities.eager_compiles_ops:
        total = ivy.compile_fn(total)  # jax: the finite differences' runs compile once

    check_gradients(diff_backend, total, [state, actions], n_directions=2, rtol=1e-5, step=1e-7)
