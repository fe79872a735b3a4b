"""Gradients through rollouts: the gradients of 50-step rollouts with respect to the actions, the
initial states and a physical parameter equal central finite differences (float64) on torch, jax
and tensorflow; compiled rollouts equal eager ones; truncated windows and resets cut the
gradients where they should."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import ivy
import ivy_gym
from tests.conftest import require
from tests.helpers import check_gradients, native, numpy_of

pytestmark = pytest.mark.filterwarnings("ignore:`torch.jit.script_method`:DeprecationWarning")

STEPS = 50

# name: (core, the parameter differentiated, action scale); non-smooth dynamics stay away from
# their kinks (small actions: no clipped torque or speed; the mountain car in its valley).
CASES = {
    "CartPole": (ivy_gym.CartPole(), "masspole", 0.3),
    "CartPoleSwingUp": (ivy_gym.CartPoleSwingUp(), "length", 1.0),
    "Pendulum": (ivy_gym.Pendulum(), "g", 0.5),
    "PendulumSmooth": (ivy_gym.PendulumSmooth(), "m", 1.0),
    "MountainCarContinuous": (
        ivy_gym.MountainCarContinuous(float32_state=False),
        "power",
        0.8,
    ),
    "MountainCarShaped": (ivy_gym.MountainCarShaped(), "g", 1.0),
    "Reacher": (ivy_gym.Reacher(), "torque_scale", 1.0),
    "Swimmer": (ivy_gym.Swimmer(num_urchins=3), "urchin_sharpness", 1.0),
}


def _inputs(env, scale, batch=2, steps=STEPS, seed=0):
    rng = np.random.default_rng(seed)
    low, high = env.reset_bounds()
    state = rng.uniform(low, high, size=(batch, env.state_dim))
    if isinstance(env, ivy_gym.CartPole):
        state = state * 0.5  # stays up for a while
    actions = rng.uniform(-scale, scale, size=(steps, batch, env.action_dim))
    return actions, state


def rollout_outputs(env, name):
    """(actions, initial state, parameter) -> rewards and observations of the rollout, flat.
    The parameter multiplies the default value of the physical constant ``name`` (so that the
    finite differences' step is relative to it)."""
    default = getattr(env.params, name)

    def fn(actions, state, param):
        xp = ivy.get_framework(state)
        traj = ivy_gym.rollout(env.replace(**{name: param * default}), state, actions)
        flat = [xp.reshape(traj.rewards, (-1,)), xp.reshape(traj.observations, (-1,))]
        return xp.concat(flat, axis=0)

    return fn


@pytest.mark.parametrize("case", sorted(CASES))
def test_rollout_gradients_equal_finite_differences(case, diff_backend):
    env, name, scale = CASES[case]
    actions, state = _inputs(env, scale)
    param = np.float64(1.0)
    # the mountain car's rollout has a large third derivative: the central differences' error
    # is 2e-6 (relative) at the helper's step and 2e-8 at a tenth of it (checked by hand)
    rtol = 1e-5 if case == "MountainCarContinuous" else 1e-6
    check_gradients(diff_backend, rollout_outputs(env, name), [actions, state, param], rtol=rtol)


def test_policy_gradients_equal_finite_differences(diff_backend):
    env = ivy_gym.CartPoleSwingUp()
    _, state = _inputs(env, 1.0)
    w = np.random.default_rng(5).normal(size=(env.observation_dim, env.action_dim)) * 0.5

    def fn(w, state):
        traj = ivy_gym.rollout(
            env, state, policy=lambda obs, v: ivy.tanh(ivy.matmul(obs, v)), v=w, horizon=STEPS
        )
        return traj.rewards

    check_gradients(diff_backend, fn, [w, state])


def _value_and_grads(backend, fn, arrays):
    """fn's scalar output and its gradients, through ivy on ``backend`` (compiled on jax and
    tensorflow: an eager jax gradient compiles each operation of the rollout, slower here)."""

    def value_and_grads(arrays):
        return ivy.execute_with_gradients(lambda v: fn(*v), arrays)

    if backend in ("jax", "tensorflow"):
        value_and_grads = ivy.compile_fn(value_and_grads)
    loss, grads = value_and_grads([native(a, backend) for a in arrays])
    return float(numpy_of(loss)), [numpy_of(g) for g in grads]


def _forward_mode(backend):
    """The framework's own forward-mode transformations: ``jvp(fn, x, t) -> (fn(x), dfn(x) t)``
    and the vectorising map."""
    if backend == "jax":
        import jax

        return lambda fn, x, t: jax.jvp(fn, (x,), (t,)), jax.vmap
    import torch.func

    return lambda fn, x, t: torch.func.jvp(fn, (x,), (t,)), torch.func.vmap


def test_forward_mode_and_vmap_through_a_rollout(diff_backend):
    """jax.jvp and torch.func.jvp of the rewards along a direction of the actions, vectorised
    over directions, equal central finite differences (a traced action is converted without a
    device placement: jax cannot place a vmap tracer)."""
    require(diff_backend, "forward_vmap")
    jvp, vmap = _forward_mode(diff_backend)
    env = ivy_gym.Pendulum()
    actions, state = _inputs(env, 0.5, steps=8)
    directions = np.random.default_rng(3).standard_normal((2, *actions.shape))
    s0 = native(state, diff_backend)

    def rewards(a):
        return ivy_gym.rollout(env, s0, a).rewards

    tangents = vmap(lambda t: jvp(rewards, native(actions, diff_backend), t)[1])(
        native(directions, diff_backend)
    )
    h = 1e-6
    for t, got in zip(directions, numpy_of(tangents)):
        plus = numpy_of(rewards(native(actions + h * t, diff_backend)))
        minus = numpy_of(rewards(native(actions - h * t, diff_backend)))
        np.testing.assert_allclose(got, (plus - minus) / (2 * h), rtol=1e-6, atol=1e-8)


def test_windows_cut_gradients_every_window_steps(diff_backend):
    env = ivy_gym.CartPoleSwingUp()
    actions, state = _inputs(env, 1.0, steps=10)  # windows [0, 4), [4, 8), [8, 10)

    def total(actions, state, window=None):
        return ivy.sum(ivy_gym.rollout(env, state, actions, window=window).rewards)

    plain, (g_actions, g_state) = _value_and_grads(diff_backend, total, [actions, state])
    windowed, (w_actions, w_state) = _value_and_grads(
        diff_backend, lambda a, s: total(a, s, window=4), [actions, state]
    )
    assert windowed == pytest.approx(plain, rel=1e-12)  # values unchanged
    # the initial state reaches the first window only
    _, (_, first_window) = _value_and_grads(diff_backend, total, [actions[:4], state])
    np.testing.assert_allclose(w_state, first_window, rtol=1e-10, atol=1e-12)
    assert np.abs(g_state - w_state).max() > 1e-3
    # the actions of the last window act on a rollout from the (constant) state at step 8
    traj = ivy_gym.rollout(env, native(state, diff_backend), native(actions, diff_backend))
    start = numpy_of(traj.states)[7]
    _, (last_window, _) = _value_and_grads(diff_backend, total, [actions[8:], start])
    np.testing.assert_allclose(w_actions[8:], last_window, rtol=1e-10, atol=1e-12)


def test_no_gradient_crosses_a_reset(diff_backend):
    env = ivy_gym.CartPole()
    state = np.array([[0.0, 0.0, 0.19, 0.0]])
    actions = np.ones((30, 1, 1))
    traj = ivy_gym.rollout(env, native(state, "numpy"), actions, autoreset=True)
    t = int(np.argmax(numpy_of(traj.terminated)[:, 0]))
    assert 0 < t < 20

    def after_reset(state):
        traj = ivy_gym.rollout(env, state, native(actions, diff_backend), autoreset=True)
        return ivy.sum(traj.observations[t + 1 :] ** 2), ivy.sum(traj.observations[: t + 1] ** 2)

    ivy.seed(0)
    _, (grad,) = _value_and_grads(diff_backend, lambda s: after_reset(s)[0], [state])
    ivy.seed(0)
    _, (before,) = _value_and_grads(diff_backend, lambda s: after_reset(s)[1], [state])
    np.testing.assert_array_equal(grad, 0.0)
    assert np.abs(before).max() > 1.0


# ----------------------------------------------------------------------------------------------
# Compiled rollouts equal eager ones
# ----------------------------------------------------------------------------------------------


def _rollout_fn(env):
    def run(state, actions):
        traj = ivy_gym.rollout(env, state, actions)
        return traj.states, traj.rewards, traj.terminated

    return run


@pytest.mark.parametrize("case", ["CartPole", "Pendulum", "MountainCarContinuous", "Swimmer"])
def test_compiled_rollout_equals_eager(case, graph_backend):
    env, _, scale = CASES[case]
    actions, state = _inputs(env, scale)
    args = native(state, graph_backend), native(actions, graph_backend)
    eager = _rollout_fn(env)(*args)
    compiled = ivy.compile_fn(_rollout_fn(env))(*args)
    for c, e in zip(compiled, eager):
        np.testing.assert_allclose(numpy_of(c), numpy_of(e), rtol=1e-10, atol=1e-12)


@functools.cache
def _torch_compiled_rollout():
    return ivy.compile_fn(_rollout_fn(ivy_gym.CartPoleSwingUp()))


def test_torch_compiled_rollout_equals_eager(request):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch not selected")
    env = ivy_gym.CartPoleSwingUp()
    actions, state = _inputs(env, 1.0, steps=5)
    args = native(state, "torch"), native(actions, "torch")
    for c, e in zip(_torch_compiled_rollout()(*args), _rollout_fn(env)(*args)):
        np.testing.assert_allclose(numpy_of(c), numpy_of(e), rtol=1e-10, atol=1e-12)


def test_compiled_policy_rollout_with_resets_draws_fresh_states(graph_backend):
    env = ivy_gym.CartPole()

    def run(w):
        state = env.reset((8,), dtype="float64", f=graph_backend)
        traj = ivy_gym.rollout(
            env,
            state,
            policy=lambda o, v: ivy.tanh(ivy.matmul(o, v)),
            v=w,
            horizon=60,
            autoreset=True,
        )
        return traj.states, traj.terminated

    compiled = ivy.compile_fn(run)
    w = native(np.array([[0.0], [0.0], [-5.0], [0.0]]), graph_backend)  # drops it
    ivy.seed(3)
    s1, d1 = (numpy_of(a) for a in compiled(w))
    s2, _ = (numpy_of(a) for a in compiled(w))
    ivy.seed(3)
    s3, _ = (numpy_of(a) for a in compiled(w))
    assert d1.any()
    assert not np.array_equal(s1, s2)
    np.testing.assert_array_equal(s1, s3)
