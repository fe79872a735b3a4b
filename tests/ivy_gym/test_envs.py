"""The environments' cores on every backend: the same trajectories as independent numpy float64
references written from the equations (the original ivy_gym's tasks and the smooth variants),
batch shapes and dtypes, initial states, parameters and rendering."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_gym
from tests.helpers import native, numpy_of
from tests.ivy_gym import _reference as ref

TOL = dict(rtol=1e-10, atol=1e-10)

# name: (core, numpy reference step, reference kwargs, action scale)
REFERENCES = {
    "CartPoleSwingUp": (ivy_gym.CartPoleSwingUp(), ref.cartpole_swing_up, {}, 1.0),
    "CartPoleSwingUp-heavy": (
        ivy_gym.CartPoleSwingUp(masspole=0.4, length=0.8),
        ref.cartpole_swing_up,
        {"mp": 0.4, "half": 0.8},
        1.0,
    ),
    "PendulumSmooth": (ivy_gym.PendulumSmooth(), ref.pendulum_smooth, {}, 1.0),
    "Pendulum-smooth": (
        ivy_gym.Pendulum(smooth=True),
        ref.pendulum_gymnasium_no_speed_clip,
        {},
        2.5,
    ),
    "MountainCarContinuous-smooth": (
        ivy_gym.MountainCarContinuous(smooth=True, float32_state=False),
        ref.mountain_car_no_walls,
        {},
        1.2,
    ),
    "MountainCarShaped": (ivy_gym.MountainCarShaped(), ref.mountain_car_shaped, {}, 1.0),
    "Reacher": (ivy_gym.Reacher(), ref.reacher, {}, 1.0),
    "Reacher-3": (ivy_gym.Reacher(num_joints=3, dt=0.04), ref.reacher, {"dt": 0.04}, 1.0),
    "Swimmer": (ivy_gym.Swimmer(), ref.swimmer, {}, 1.0),
    "Swimmer-no-urchins": (ivy_gym.Swimmer(num_urchins=0), ref.swimmer, {}, 1.0),
}

ALL_ENVS = {
    "CartPole": ivy_gym.CartPole(),
    "CartPoleSwingUp": ivy_gym.CartPoleSwingUp(),
    "Pendulum": ivy_gym.Pendulum(),
    "PendulumSmooth": ivy_gym.PendulumSmooth(),
    "MountainCarContinuous": ivy_gym.MountainCarContinuous(),
    "MountainCarShaped": ivy_gym.MountainCarShaped(),
    "Reacher": ivy_gym.Reacher(),
    "Swimmer": ivy_gym.Swimmer(),
}


def _inputs(env, batch=3, steps=60, scale=1.0, seed=0):
    rng = np.random.default_rng(seed)
    low, high = env.reset_bounds()
    states = rng.uniform(low, high, size=(batch, env.state_dim))
    actions = rng.uniform(-scale, scale, size=(steps, batch, env.action_dim))
    return states, actions


@pytest.mark.parametrize("name", sorted(REFERENCES))
def test_rollout_equals_numpy_reference(name, backend):
    env, step, kwargs, scale = REFERENCES[name]
    states, actions = _inputs(env, scale=scale)
    expected_s, expected_o, expected_r = ref.reference_rollout(step, states, actions, **kwargs)
    traj = ivy_gym.rollout(env, native(states, backend), native(actions, backend))
    np.testing.assert_allclose(numpy_of(traj.states), expected_s, **TOL)
    np.testing.assert_allclose(numpy_of(traj.observations), expected_o, **TOL)
    np.testing.assert_allclose(numpy_of(traj.rewards), expected_r, **TOL)
    np.testing.assert_allclose(numpy_of(traj.final_state), expected_s[-1], **TOL)
    assert not numpy_of(traj.terminated).any() and numpy_of(traj.valid).all()


@pytest.mark.parametrize("name", sorted(ALL_ENVS))
def test_step_keeps_batch_shape_and_dtype(name, backend):
    env = ALL_ENVS[name]
    for dtype, batch in [("float32", (2, 3)), ("float64", ())]:  # eager jax compiles per shape
        state = env.reset(batch, dtype=dtype, f=backend)
        action = native(np.zeros((*batch, env.action_dim), dtype), backend)
        new, obs, reward, terminated = env.step(state, action)
        for x, shape in [
            (new, (*batch, env.state_dim)),
            (obs, (*batch, env.observation_dim)),
            (reward, batch),
        ]:
            assert tuple(numpy_of(x).shape) == shape
            assert ivy.dtype(x, as_str=True) == dtype
        assert numpy_of(terminated).dtype == bool and numpy_of(terminated).shape == batch
        np.testing.assert_allclose(numpy_of(env.observe(new)), numpy_of(obs), rtol=1e-6)


@pytest.mark.parametrize("name", sorted(ALL_ENVS))
def test_reset_draws_in_the_box_and_seed_reproduces(name, backend):
    env = ALL_ENVS[name]
    ivy.seed(11)
    first = numpy_of(env.reset((500,), dtype="float64", f=backend))
    again = numpy_of(env.reset((500,), dtype="float64", f=backend))
    ivy.seed(11)
    repeated = numpy_of(env.reset((500,), dtype="float64", f=backend))
    low, high = env.reset_bounds()
    assert np.all(first >= low - 1e-7) and np.all(first <= high + 1e-7)
    random = low != high
    assert np.all(first.std(0)[random] > 0.2 * (high - low)[random])  # spread over the box
    assert not np.array_equal(first, again)
    np.testing.assert_array_equal(first, repeated)


def test_actions_broadcast_and_convert(backend):
    env = ivy_gym.PendulumSmooth()
    state = env.reset((4,), dtype="float64", f=backend)
    broadcast = env.step(state, native(np.full(1, 0.25), backend))[0]  # one action for all
    full = env.step(state, native(np.full((4, 1), 0.25), backend))[0]
    from_list = env.step(state, [[0.25]] * 4)[0]  # Python numbers: the state's dtype
    with_f = env.step(state, np.full((4, 1), 0.25), f=backend)[0]  # f= converts numpy
    for x in (broadcast, from_list, with_f):
        np.testing.assert_allclose(numpy_of(x), numpy_of(full), **TOL)
        assert ivy.dtype(x, as_str=True) == "float64"


def test_replace_changes_parameters_and_keeps_the_original():
    env = ivy_gym.Pendulum()
    heavy = env.replace(m=2.0, g=9.81)
    assert heavy.params.m == 2.0 and heavy.params.g == 9.81 and env.params.m == 1.0
    assert isinstance(heavy, ivy_gym.Pendulum) and "Pendulum" in repr(heavy)
    with pytest.raises(TypeError):
        ivy_gym.Pendulum(mass=2.0)  # not a parameter of the task
    with pytest.raises(AttributeError):
        env.params.m = 3.0  # frozen


def test_rollout_masks_steps_after_termination(backend):
    env = ivy_gym.CartPole()
    state = native(np.array([[0.0, 0.0, 0.2, 0.0], [0.0, 0.0, 0.0, 0.0]]), backend)
    actions = native(np.ones((30, 2, 1)), backend)
    traj = ivy_gym.rollout(env, state, actions)
    terminated, valid, rewards = (numpy_of(a) for a in (traj.terminated, traj.valid, traj.rewards))
    first = int(np.argmax(terminated[:, 0]))
    assert terminated[first, 0] and first < 25
    np.testing.assert_array_equal(valid[:, 0], np.arange(30) <= first)
    np.testing.assert_array_equal(rewards[:, 0], (np.arange(30) <= first).astype(float))
    assert rewards.dtype == np.float64


def test_autoreset_restarts_terminated_environments(backend):
    env = ivy_gym.CartPole()
    ivy.seed(2)
    state = native(np.array([[0.0, 0.0, 0.2, 0.0]] * 4), backend)
    traj = ivy_gym.rollout(env, state, native(np.ones((40, 4, 1)), backend), autoreset=True)
    terminated, states = numpy_of(traj.terminated), numpy_of(traj.states)
    assert terminated[:, 0].sum() >= 2  # restarted and fell again
    t = int(np.argmax(terminated[:, 0]))
    # the step after a termination starts from a fresh state in [-0.05, 0.05]^4: one Euler
    # step later, the positions have moved by tau * velocity at most
    assert np.all(np.abs(states[t + 1, 0, [0, 2]]) < 0.05 + 0.02 * 0.05 + 1e-12)
    assert np.abs(states[t, 0, 2]) > 0.2  # (it had fallen)
    assert numpy_of(traj.valid).all() and numpy_of(traj.rewards).min() == 1.0


def test_rollout_with_a_policy_equals_open_loop_with_its_actions(backend):
    env = ivy_gym.Reacher()
    states, _ = _inputs(env, batch=2)
    w = np.random.default_rng(3).normal(size=(env.observation_dim, env.action_dim))

    def policy(obs, v):
        return ivy.tanh(ivy.matmul(obs, v["w"]))

    closed = ivy_gym.rollout(
        env, native(states, backend), policy=policy, v={"w": native(w, backend)}, horizon=20
    )
    opened = ivy_gym.rollout(env, native(states, backend), closed.actions)
    np.testing.assert_allclose(numpy_of(closed.states), numpy_of(opened.states), **TOL)
    obs0 = numpy_of(env.observe(native(states, backend)))
    np.testing.assert_allclose(numpy_of(closed.actions)[0], np.tanh(obs0 @ w), **TOL)


def test_rollout_errors():
    env = ivy_gym.Pendulum()
    state = np.zeros((2, 2))
    with pytest.raises(ValueError, match="either actions"):
        ivy_gym.rollout(env, state)
    with pytest.raises(ValueError, match="shape"):
        ivy_gym.rollout(env, state, np.zeros((10, 2, 3)))
    with pytest.raises(ValueError, match="horizon"):
        ivy_gym.rollout(env, state, policy=lambda o, v: o[..., :1], v={})
    with pytest.raises(ValueError, match="components"):
        ivy_gym.rollout(env, np.zeros((2, 5)), np.zeros((10, 2, 1)))
    with pytest.raises(ValueError, match="positive"):
        ivy_gym.rollout(env, state, np.zeros((10, 2, 1)), window=0)
    with pytest.raises(ValueError, match="one state"):
        env.render(state)


def test_discounted_return(backend):
    rewards = native(np.arange(6.0).reshape(3, 2), backend)
    expected = np.arange(6.0).reshape(3, 2).T @ (0.9 ** np.arange(3))
    np.testing.assert_allclose(numpy_of(ivy_gym.discounted_return(rewards, 0.9)), expected)
    np.testing.assert_allclose(numpy_of(ivy_gym.discounted_return(rewards)), [6.0, 9.0])


@pytest.mark.parametrize("name", sorted(ALL_ENVS))
def test_render_draws_a_picture_of_the_state(name):
    env = ALL_ENVS[name]
    low, high = env.reset_bounds()
    a, b = (np.random.default_rng(i).uniform(low, high) for i in (0, 1))
    frame = env.render(a, width=120, height=80)
    assert frame.shape == (80, 120, 3) and frame.dtype == np.uint8
    assert (frame != 255).any(axis=-1).mean() > 0.005  # something is drawn
    assert not np.array_equal(frame, env.render(b, width=120, height=80))


def test_canvas_fills_shapes_where_they_are():
    canvas = ivy_gym.Canvas(100, 50, (0, 10, 0, 5))
    canvas.polygon([(1, 1), (3, 1), (3, 3), (1, 3)], (255, 0, 0))
    canvas.disc((7, 2.5), 1.0, (0, 0, 255))
    img = canvas.image
    assert tuple(img[29, 20]) == (255, 0, 0)  # x=2, y=2 (y up: row 50 - 20 - 1)
    assert tuple(img[5, 20]) == (255, 255, 255)
    assert tuple(img[25, 70]) == (0, 0, 255)
    area = (img == (255, 0, 0)).all(-1).sum()
    assert abs(area - 20 * 20) <= 40  # a 2x2 square at 10 px per unit


@pytest.mark.filterwarnings("ignore:os.fork:RuntimeWarning")  # imageio-ffmpeg's subprocess
def test_save_video_writes_gif_and_mp4(tmp_path):
    import imageio.v3 as iio

    env = ivy_gym.PendulumSmooth()
    traj = ivy_gym.rollout(env, np.array([[3.0, 0.0]]), np.zeros((6, 1, 1)))
    frames = ivy_gym.render_trajectory(env, traj.states, index=0, width=64, height=48)
    assert len(frames) == 6 and frames[0].shape == (48, 64, 3)
    gif = ivy_gym.save_video(frames, tmp_path / "out.gif", fps=10)
    back = iio.imread(gif)
    assert back.shape[0] == 6 and back.shape[1:3] == (48, 64)
    mp4 = ivy_gym.save_video(frames, tmp_path / "sub" / "out.mp4", fps=10)
    assert (tmp_path / "sub" / "out.mp4").stat().st_size > 0 and mp4.endswith(".mp4")
    with pytest.raises(ValueError, match="extension"):
        ivy_gym.save_video(frames, tmp_path / "out.avi")
    with pytest.raises(ValueError, match="index"):
        ivy_gym.render_trajectory(env, traj.states)
