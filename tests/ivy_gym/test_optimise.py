"""Optimisation through rollouts, on small budgets: open-loop actions and policies improve their
return on torch, jax and tensorflow; the options (windows, discount, clipping) run; the
diagnostics have the right shapes; numpy refuses clearly."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_gym
from ivy.errors import UnsupportedError
from tests.helpers import native, numpy_of

pytestmark = pytest.mark.filterwarnings("ignore:`torch.jit.script_method`:DeprecationWarning")


def test_optimise_actions_improves_the_return(diff_backend):
    env = ivy_gym.PendulumSmooth()
    state = native(np.array([[2.5, 0.0], [-2.0, 0.5]]), diff_backend)
    result = ivy_gym.optimise_actions(env, 30, 25, initial_state=state, lr=0.2, seed=0)
    assert numpy_of(result.actions).shape == (30, 2, 1)
    assert np.all(np.abs(numpy_of(result.actions)) <= 1.0)
    assert result.returns.shape == (25,) and result.grad_norms.shape == (25,)
    assert np.all(np.isfinite(result.grad_norms)) and np.all(result.grad_norms > 0)
    assert result.final_return > result.returns[0] + 1.0
    # the final actions, replayed, give the final return
    traj = ivy_gym.rollout(env, state, result.actions)
    assert float(numpy_of(ivy.mean(ivy.sum(traj.rewards, axis=0)))) == pytest.approx(
        result.final_return, rel=1e-5
    )


def _quick_backend(request):
    """torch if selected (it runs eagerly by default: no compilation), else another
    differentiable backend."""
    for backend in ("torch", "jax", "tensorflow"):
        if backend in request.config.ivy_backends:
            return backend
    pytest.skip("needs a differentiable backend")


def test_optimise_actions_options_run_and_seed_repeats(request):
    backend = _quick_backend(request)
    env = ivy_gym.CartPoleSwingUp()
    options = dict(batch_shape=(3,), discount=0.95, window=5, max_grad_norm=1.0, dtype="float64")
    result = ivy_gym.optimise_actions(env, 20, 5, f=backend, seed=1, **options)
    assert numpy_of(result.initial_state).shape == (3, 4)
    assert numpy_of(result.actions).dtype == np.float64
    again = ivy_gym.optimise_actions(env, 20, 5, f=backend, seed=1, **options)
    np.testing.assert_allclose(again.returns, result.returns, rtol=1e-10)


def test_callback_sees_the_actions_and_can_stop(request):
    backend = _quick_backend(request)
    env = ivy_gym.Pendulum()
    seen = []

    def callback(iteration, actions):
        seen.append((iteration, numpy_of(actions).shape, float(np.abs(numpy_of(actions)).max())))
        return iteration == 2

    result = ivy_gym.optimise_actions(env, 10, 50, f=backend, callback=callback, seed=0)
    assert [s[0] for s in seen] == [0, 1, 2] and result.returns.shape == (3,)
    assert all(shape == (10, 1) and largest <= 2.0 for _, shape, largest in seen)


def test_optimise_policy_improves_the_mean_return(request):
    backend = _quick_backend(request)
    env = ivy_gym.CartPoleSwingUp()
    ivy.seed(0)
    mlp = ivy.MLP(5, (8,), 1, activation="tanh", output_activation="tanh", f=backend)

    def evaluate(v):
        ivy.seed(1)  # the same initial states before and after
        return ivy_gym.mean_return(env, 20, policy=mlp, v=v, batch_size=64)

    before = evaluate(mlp.v)
    result = ivy_gym.optimise_policy(env, mlp, 20, 30, batch_size=16, lr=0.03, seed=0)
    assert evaluate(result.variables) > before + 0.3  # of at most 20, seeded
    assert ivy.nest.nest_structure(result.variables) == ivy.nest.nest_structure(mlp.v)


def test_optimise_policy_on_every_differentiable_backend(diff_backend):
    env = ivy_gym.CartPoleSwingUp()
    ivy.seed(0)
    mlp = ivy.MLP(5, (8,), 1, activation="tanh", output_activation="tanh", f=diff_backend)
    result = ivy_gym.optimise_policy(env, mlp, 10, 3, batch_size=4)
    assert result.returns.shape == (3,) and np.all(np.isfinite(result.grad_norms))
    changed = [
        not np.allclose(numpy_of(a), numpy_of(b))
        for a, b in zip(ivy.nest.nest_leaves(result.variables), ivy.nest.nest_leaves(mlp.v))
    ]
    assert all(changed)


def test_gradient_norms_per_horizon(diff_backend):
    env = ivy_gym.CartPoleSwingUp()
    ivy.seed(1)
    open_loop = ivy_gym.gradient_norms(env, [5, 10], batch_size=4, f=diff_backend)
    assert open_loop["horizon"].tolist() == [5, 10]
    assert np.all(open_loop["grad_norm"] > 0) and np.all(np.isfinite(open_loop["grad_norm"]))
    w = native(np.random.default_rng(0).normal(size=(5, 1)), diff_backend)

    def policy(obs, v):
        return ivy.tanh(ivy.matmul(obs, v))

    closed = ivy_gym.gradient_norms(
        env, [10], policy=policy, v=w, batch_size=4, window=5, dtype="float64"
    )
    assert closed["grad_norm"].shape == (1,) and closed["return"].shape == (1,)


def test_numpy_refuses_to_optimise():
    with pytest.raises(UnsupportedError, match="torch"):
        ivy_gym.optimise_actions(ivy_gym.PendulumSmooth(), 10, 2, f="numpy")
    with pytest.raises(UnsupportedError):
        ivy_gym.gradient_norms(ivy_gym.PendulumSmooth(), [5], f="numpy")


def test_squash_actions_maps_to_the_action_box(backend):
    env = ivy_gym.Pendulum()  # [-2, 2]
    logits = native(np.array([[-50.0], [0.0], [0.5], [50.0]]), backend)
    np.testing.assert_allclose(
        numpy_of(ivy_gym.squash_actions(logits, env)), [[-2.0], [0.0], [2 * np.tanh(0.5)], [2.0]]
    )


def test_torch_compiled_optimisation_equals_eager(request):
    """compile=True on torch (torch.compile; not the default, it takes ~20 s even for a tiny
    horizon): the same return, gradient norm and updated actions as eagerly. One iteration:
    the second recompiles (torch.compile guards on ivy's cache of array types)."""
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch not selected")
    env = ivy_gym.CartPoleSwingUp()
    state = native(np.array([[0.0, 0.0, 3.0, 0.0]]), "torch")
    logits = np.random.default_rng(0).uniform(-1, 1, size=(3, 1, 1))
    results = [
        ivy_gym.optimise_actions(
            env, 3, 1, initial_state=state, initial_logits=logits, compile=compile
        )
        for compile in (False, True)
    ]
    eager, compiled = results
    np.testing.assert_allclose(compiled.returns, eager.returns, rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(compiled.grad_norms, eager.grad_norms, rtol=1e-4, atol=1e-7)
    np.testing.assert_allclose(numpy_of(compiled.actions), numpy_of(eager.actions), atol=1e-5)


def test_narrowed_env_draws_from_the_shrunk_box(backend):
    env = ivy_gym.CartPoleSwingUp()
    near = env.narrowed(0.1)
    assert near.params == env.params and env.reset_scale == 1.0 and near.reset_scale == 0.1
    low, high = near.initial_bounds()
    np.testing.assert_allclose(high, [0.1, 0.03, np.pi / 10, 0.03])
    np.testing.assert_allclose(low, -high)
    ivy.seed(0)
    states = numpy_of(near.reset((500,), dtype="float64", f=backend))
    assert np.all((states >= low) & (states <= high))
    assert np.all(states.max(0) > 0.8 * high)  # the whole shrunk box, not a corner of it
    assert near.replace(masscart=2.0).reset_scale == 0.1
    with pytest.raises(ValueError, match="scale"):
        env.narrowed(0.0)


def test_optimise_policy_curriculum_stages(request):
    backend = _quick_backend(request)
    env = ivy_gym.PendulumSmooth()
    ivy.seed(0)
    mlp = ivy.MLP(3, (8,), 1, activation="tanh", output_activation="tanh", f=backend)
    seen = []
    result = ivy_gym.optimise_policy(
        env, mlp, 10, 3, batch_size=4, curriculum=[(0.1, 2), (0.5, 2)], seed=0,
        callback=lambda i, v: seen.append(i),
    )  # fmt: skip
    assert seen == list(range(7)) and result.returns.shape == (7,)
    # near upright (a 10% box) the smooth reward is close to 1 per step; from anywhere it is not
    assert result.returns[:2].min() > 8.5 and result.returns[4:].mean() < 8.5
    stopped = ivy_gym.optimise_policy(
        env, mlp, 10, 3, batch_size=4, curriculum=[(0.1, 2), (0.5, 2)],
        callback=lambda i, v: i == 2,
    )  # fmt: skip
    assert stopped.returns.shape == (3,)


def test_a_globally_set_framework_gives_the_same_numbers(diff_backend):
    """``ivy.set_framework`` binds the backend's functions into ``ivy``: the rollouts and the
    optimisations (which pass ``f`` on) run under it and give what ``f=`` gives."""
    env = ivy_gym.CartPoleSwingUp()
    options = dict(batch_shape=(2,), window=5, dtype="float64", seed=3)

    def run():
        ivy.seed(0)
        mlp = ivy.MLP(5, (8,), 1, output_activation="tanh", f=diff_backend)
        policy = ivy_gym.optimise_policy(env, mlp, 10, 2, batch_size=4, seed=2, f=diff_backend)
        actions = ivy_gym.optimise_actions(env, 10, 3, f=diff_backend, **options)
        roll = ivy_gym.rollout(env, actions.initial_state, actions.actions, f=diff_backend)
        return [*policy.returns, *actions.returns, *numpy_of(roll.rewards).ravel()]

    expected = run()
    with ivy.set_framework(diff_backend):
        np.testing.assert_allclose(run(), expected, rtol=1e-6)


# ----------------------------------------------------------------------------------------------
# Levenberg-Marquardt shooting (optimise_actions_least_squares)
# ----------------------------------------------------------------------------------------------


def _reach_residuals(traj):
    """Reach the pendulum's upright, still state over the last 2 of the rollout's states:
    ``(*B, 2 * 2)`` residuals (angle from upright and velocity at each), for any batch ``B``."""
    return ivy.concat([traj.states[-2], traj.states[-1]], axis=-1)


def _numpy_levenberg_marquardt(env, state, logits, iterations, logit_cost, mu0, eps=1e-6):
    """The reference: each initial state on its own, the rollout on numpy float64, the
    Jacobian by central differences, the damped Gauss-Newton step and its acceptance written
    out; returns the final logits ``(T, B, 1)``, the costs and how many steps were rejected."""
    horizon, batch, _ = logits.shape
    out, costs, rejected = np.empty_like(logits), np.empty(batch), 0

    def residual(i, u):
        actions = 2.0 * np.tanh(u)[:, None, None]  # the Pendulum's torque box [-2, 2]
        traj = ivy_gym.rollout(env, state[i : i + 1], actions, f="numpy")
        return np.asarray(_reach_residuals(traj))[0]

    def cost(i, u):
        r = residual(i, u)
        return r @ r + logit_cost * u @ u

    for i in range(batch):
        u, mu = logits[:, i, 0].copy(), mu0
        current = cost(i, u)
        for _ in range(iterations):
            r = residual(i, u)
            jac = np.stack(
                [
                    (residual(i, u + eps * e) - residual(i, u - eps * e)) / (2 * eps)
                    for e in np.eye(horizon)
                ],
                axis=1,
            )
            hess = jac.T @ jac + (logit_cost + mu) * np.eye(horizon)
            trial = u - np.linalg.solve(hess, jac.T @ r + logit_cost * u)
            trial_cost = cost(i, trial)
            if trial_cost < current:
                u, current, mu = trial, trial_cost, max(0.3 * mu, 1e-6)
            else:
                mu, rejected = min(4.0 * mu, 1e8), rejected + 1
        out[:, i, 0], costs[i] = u, current
    return out, costs, rejected


@pytest.mark.parametrize("jacobian_method", ["native", "replicate"])
def test_least_squares_steps_equal_a_numpy_levenberg_marquardt(diff_backend, jacobian_method):
    env = ivy_gym.Pendulum()
    start = np.array([[2.8, 0.0], [-2.5, 1.0], [0.3, -2.0]])
    logits = np.random.default_rng(0).uniform(-0.5, 0.5, (8, 3, 1))
    # a small initial damping: some first steps overshoot and are rejected
    options = dict(logit_cost=1e-3, damping=1e-3)
    expected, costs, rejected = _numpy_levenberg_marquardt(env, start, logits, 4, **_lm(options))
    assert rejected > 0
    result = ivy_gym.optimise_actions_least_squares(
        env,
        8,
        4,
        _reach_residuals,
        initial_state=native(start, diff_backend),
        initial_logits=logits,
        jacobian_method=jacobian_method,
        **options,
    )
    np.testing.assert_allclose(numpy_of(result.variables), expected, rtol=1e-6, atol=1e-7)
    np.testing.assert_allclose(result.costs, costs, rtol=1e-6)
    np.testing.assert_allclose(numpy_of(result.actions), 2.0 * np.tanh(expected), rtol=1e-6)
    assert result.returns.shape == (4,) and result.grad_norms.shape == (4,)


def _lm(options):
    return dict(logit_cost=options["logit_cost"], mu0=options["damping"])


def test_least_squares_reaches_the_pendulums_upright_state(request):
    """From where its torque can hold it (under 0.42 rad), 15 steps of the Pendulum reach
    upright and still: the objective falls to nearly zero and the replayed actions reach the
    target."""
    backend = _quick_backend(request)
    env = ivy_gym.Pendulum()
    start = native(np.array([[0.3, 0.0], [-0.25, 0.5]]), backend)
    result = ivy_gym.optimise_actions_least_squares(
        env, 15, 25, _reach_residuals, initial_state=start, seed=0, logit_cost=1e-6
    )
    assert result.costs.shape == (2,) and np.all(result.costs < 1e-4)
    final = numpy_of(ivy_gym.rollout(env, start, result.actions).states[-1])
    np.testing.assert_allclose(final, 0.0, atol=1e-2)


def test_least_squares_refuses_bad_input(request):
    backend = _quick_backend(request)
    env = ivy_gym.Pendulum()
    start = native(np.array([[0.6, 0.0]]), backend)

    def run(residuals=_reach_residuals, **options):
        return ivy_gym.optimise_actions_least_squares(
            env, 5, 1, residuals, initial_state=start, **options
        )

    with pytest.raises(ValueError, match=r"residuals\(traj\) must have shape \(\*B, R\)"):
        run(lambda traj: ivy.sum(traj.rewards, axis=0))
    with pytest.raises(ValueError, match="initial_logits must have shape"):
        run(initial_logits=np.zeros((4, 1, 1)))
    with pytest.raises(ValueError, match="damping > 0"):
        run(damping=0.0)
    with pytest.raises(ValueError, match="logit_cost must be >= 0"):
        run(logit_cost=-1.0)
    with pytest.raises(UnsupportedError, match="gradients"):
        ivy_gym.optimise_actions_least_squares(env, 5, 1, _reach_residuals, f="numpy")
