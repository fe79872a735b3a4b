"""Optimisation through differentiable rollouts, written once for torch, jax and tensorflow.

- :func:`optimise_actions`: an open-loop action sequence (``tanh`` of logits, scaled to the
  action space) optimised with Adam for the return of one rollout (or of a batch of rollouts).
- :func:`optimise_actions_least_squares`: an open-loop action sequence optimised for a
  least-squares objective of its rollout (e.g. reach and hold a target state) with
  Levenberg-Marquardt steps, each from the Jacobian of the residuals; it solves what Adam's
  first-order steps do not where the dynamics are chaotic (the double pendulum's swing-up).
- :func:`optimise_policy`: the parameters of a policy (e.g. ``ivy.MLP``) optimised with Adam for
  the mean return of rollouts from a fresh batch of initial states at every iteration.
- :func:`gradient_norms`: the norm of the gradient of the return against the horizon, the
  diagnostic of the known failure of long horizons (gradients that explode or vanish).

Both optimisers take ``discount``, ``window`` (truncated gradients: the state is cut from the
graph every ``window`` steps, as in short-horizon actor-critic methods) and ``max_grad_norm``,
run their iterations through ``ivy.compiled_scan`` (by default where the compiler keeps loops:
on jax and tensorflow all the iterations are one compiled loop, or one compiled iteration per
call with a ``callback``; torch runs eagerly by default, because torch.compile unrolls the
rollout and takes minutes for 100 steps and their gradients; ``compile=True`` compiles each
iteration there), and return the history: the return and the gradient's norm at every
iteration.

Example:
    >>> result = ivy_gym.optimise_actions(ivy_gym.PendulumSmooth(), 100, 20, seed=0, f="jax")
    >>> bool(result.returns[-1] > result.returns[0])  # (200 iterations swing it up)
    True
"""

from __future__ import annotations

import dataclasses
import operator
import time
from collections.abc import Callable, Sequence

import numpy as np

import ivy
from ivy.errors import UnsupportedError
from ivy.typing import Array, Dtype, Framework, Nest
from ivy_gym.base import Env, check_state
from ivy_gym.rollouts import Trajectory, discounted_return, rollout

__all__ = [
    "OptimisationResult",
    "squash_actions",
    "optimise_actions",
    "optimise_actions_least_squares",
    "optimise_policy",
    "mean_return",
    "gradient_norms",
]


@dataclasses.dataclass
class OptimisationResult:
    """What an optimisation returns.

    Attributes:
        variables: the optimised variables (the logits of the actions, or the policy's nest).
        returns: ``(iterations,)`` numpy: the mean (undiscounted) return of the rollouts of each
            iteration, before its update.
        grad_norms: ``(iterations,)`` numpy: the global norm of each iteration's gradient
            (before clipping).
        final_return: the mean return after the last update.
        seconds: wall time of all iterations; ``first_seconds`` of the first call of the
            compiled loop, its compilation included: the first iteration with a callback, else
            all of them where the compiler keeps loops (jax, tensorflow).
        actions: the optimised actions ``(T, *B, action_dim)`` (:func:`optimise_actions`).
        initial_state: the initial states of the action sequence (:func:`optimise_actions`).
        costs: ``(*B,)`` numpy: each initial state's final least-squares objective
            (:func:`optimise_actions_least_squares`).
    """

    variables: Nest
    returns: np.ndarray
    grad_norms: np.ndarray
    final_return: float
    seconds: float
    first_seconds: float
    actions: Array | None = None
    initial_state: Array | None = None
    costs: np.ndarray | None = None


def squash_actions(logits: Array, env: Env, *, f: Framework = None) -> Array:
    """Actions in the action space from unbounded logits: ``mid + half_width * tanh(logits)``.

    Args:
        logits: ``(..., action_dim)``.
        env: the environment whose action bounds apply.
        f: framework name or namespace; by default inferred from ``logits``.

    Returns:
        Actions of the shape and dtype of ``logits``.

    Example:
        >>> ivy_gym.squash_actions(np.zeros((3, 1)), ivy_gym.Pendulum())
        array([[0.], [0.], [0.]])
    """
    xp = ivy.get_framework(logits, f=f)
    return env.squash(xp, logits)


def _device_of(xp, nest) -> str | None:
    """The device of the first array in ``nest`` (None when it has none)."""
    leaves = ivy.nest.nest_leaves(nest) if nest is not None else []
    return xp.dev(leaves[0]) if leaves else None


def _global_norm(xp, grads) -> Array:
    leaves = ivy.nest.nest_leaves(grads)
    return xp.sqrt(sum(xp.sum(g * g) for g in leaves))


def _differentiable(f: Framework, name: str):
    xp = ivy.get_framework(f=f)
    if not xp.capabilities.autodiff:
        raise UnsupportedError(
            f"ivy_gym.{name} needs gradients, which the {xp.backend} backend does not have; "
            f"pass a framework with automatic differentiation (f='torch', 'jax' or "
            f"'tensorflow')."
        )
    return xp


def _compile_by_default(xp) -> bool:
    """Whether an iteration (a rollout and its gradient) is compiled when ``compile=None``:
    where the compiler keeps loops (jax, tensorflow). A compiler that unrolls them
    (torch.compile) takes minutes for a 100-step rollout and its backward pass."""
    return xp.capabilities.compilation and xp.capabilities.compiled_loops


def _run(xp, step, carry, iterations, compile, callback=None, to_user=lambda v: v):
    """Run ``ret, norm, *carry = step(*carry)`` ``iterations`` times, or until ``callback(
    iteration, variables)`` returns True; returns the final carry, the returns, the gradient
    norms and the timings (all, and of the first call).

    Compiled, the iterations are an ``ivy.compiled_scan``: where the compiler keeps loops (jax,
    tensorflow) all of them are one compiled loop (one iteration per call with a callback);
    where it unrolls loops (torch.compile) each iteration is compiled on its own and a host
    loop calls it. Eager, a host loop calls ``step``."""
    carry = tuple(carry)
    if iterations == 0:
        return carry, np.zeros(0), np.zeros(0), 0.0, 0.0

    def body(carry, _):
        ret, norm, *carry = step(*carry)
        return tuple(carry), (ret, norm)

    block = iterations if callback is None else 1
    if compile:
        run = ivy.compiled_scan(body, length=block, f=xp)
    else:

        def run(carry, _):
            outs = []
            for _ in range(block):
                carry, out = body(carry, None)
                outs.append(out)
            return carry, tuple(xp.stack(list(column)) for column in zip(*outs))

    returns, norms = [], []
    start = time.perf_counter()
    first = None
    for i in range(0, iterations, block):
        carry, (ret, norm) = run(carry, None)
        returns.append(ret)
        norms.append(norm)
        if first is None:
            first = time.perf_counter() - start
        if callback is not None and callback(i, to_user(carry[0])):
            break
    returns = np.concatenate([np.asarray(ivy.to_numpy(r), np.float64) for r in returns])
    norms = np.concatenate([np.asarray(ivy.to_numpy(n), np.float64) for n in norms])
    return carry, returns, norms, time.perf_counter() - start, first


def _update(xp, opt, loss_fn, v, opt_state, max_grad_norm):
    loss, grads, mean_ret = ivy.execute_with_gradients(loss_fn, v)
    if max_grad_norm is None:
        norm = _global_norm(xp, grads)
    else:
        grads, norm = xp.clip_by_global_norm(grads, max_grad_norm)
    v, opt_state = opt.step(v, grads, opt_state)
    return mean_ret, norm, v, opt_state


def _action_problem(
    name,
    env,
    horizon,
    initial_state,
    batch_shape,
    init_scale,
    initial_logits,
    seed,
    dtype,
    device,
    f,
):
    """The backend, the initial states (checked, or drawn with ``env.reset``) and the initial
    logits ``(T, *B, action_dim)`` (checked, or uniform in ``[-init_scale, init_scale]``) of an
    open-loop action optimisation."""
    if initial_state is not None and f is None:
        f = ivy.get_framework(initial_state)
    xp = _differentiable(f, name)
    if seed is not None:
        xp.seed(seed)
    if initial_state is None:
        initial_state = env.reset(tuple(batch_shape), dtype=dtype, device=device, f=xp)
    check_state(env, initial_state, name, argument="initial_state")
    device = xp.dev(initial_state) if device is None else device
    dtype = initial_state.dtype
    shape = (horizon, *initial_state.shape[:-1], env.action_dim)
    if initial_logits is None:
        return (
            xp,
            initial_state,
            xp.random_uniform(-init_scale, init_scale, shape, dtype=dtype, device=device),
        )
    logits = xp.asarray(ivy.to_numpy(initial_logits), dtype=dtype, device=device)
    if tuple(logits.shape) != shape:
        raise ValueError(
            f"{name}: initial_logits must have shape {shape}, got {tuple(logits.shape)}."
        )
    return xp, initial_state, logits


def optimise_actions(
    env: Env,
    horizon: int,
    iterations: int,
    *,
    initial_state: Array | None = None,
    batch_shape: Sequence[int] = (),
    lr: float = 0.1,
    discount: float = 1.0,
    window: int | None = None,
    max_grad_norm: float | None = None,
    init_scale: float = 1.0,
    initial_logits: Array | None = None,
    seed: int | None = None,
    dtype: Dtype = "float32",
    compile: bool | None = None,
    callback: Callable[[int, Array], bool | None] | None = None,
    device: str | None = None,
    f: Framework = None,
) -> OptimisationResult:
    """Optimise an open-loop action sequence through a differentiable rollout (Adam).

    The actions are ``squash_actions(logits)``; the loss is minus the mean discounted return of
    the rollouts from ``initial_state``.

    Args:
        env: the environment.
        horizon: number of steps ``T``.
        iterations: number of Adam updates.
        initial_state: ``(*B, state_dim)``; by default ``env.reset(batch_shape)``.
        batch_shape: the batch of initial states to draw when ``initial_state`` is None.
        lr: Adam's learning rate.
        discount: discount factor of the return.
        window: cut gradients every ``window`` steps (a divisor of ``horizon``), or None.
        max_grad_norm: clip the gradient's global norm, or None.
        init_scale: initial logits are uniform in ``[-init_scale, init_scale]``.
        initial_logits: the initial logits ``(T, *B, action_dim)`` instead (any backend's array
            or numpy), e.g. the same on every backend.
        seed: ``ivy.seed`` for the backend first (None: leave the generator as it is).
        dtype: dtype of the states and actions.
        compile: run each iteration compiled; by default where the compiler keeps loops
            (jax, tensorflow; torch.compile unrolls them, see the module's docstring).
        callback: ``callback(iteration, actions)`` after each update (the actions after it);
            returning True stops the optimisation (e.g. once the task is solved).
        device: where to create the states and logits; by default ``initial_state``'s
            device, or the backend's default.
        f: framework (torch, jax or tensorflow); by default the global framework or that of
            ``initial_state``.

    Returns:
        An :class:`OptimisationResult` with ``actions`` ``(T, *B, action_dim)``.

    Example:
        >>> env = ivy_gym.CartPoleSwingUp()
        >>> r = ivy_gym.optimise_actions(env, 100, 10, seed=0, f="jax")  # (300 swing it up)
        >>> r.actions.shape, ivy_gym.rollout(env, r.initial_state, r.actions).states.shape
        ((100, 1), (100, 4))
    """
    xp, initial_state, logits = _action_problem(
        "optimise_actions",
        env,
        horizon,
        initial_state,
        batch_shape,
        init_scale,
        initial_logits,
        seed,
        dtype,
        device,
        f,
    )
    opt = ivy.Adam(lr, f=xp)

    def loss_fn(logits):
        traj = rollout(env, initial_state, squash_actions(logits, env, f=xp), window=window, f=xp)
        ret = discounted_return(traj.rewards, discount, f=xp)
        return -xp.mean(ret), xp.mean(xp.sum(traj.rewards, axis=0))

    def step(logits, opt_state):
        return _update(xp, opt, loss_fn, logits, opt_state, max_grad_norm)

    if compile is None:
        compile = _compile_by_default(xp)
    carry = (logits, opt.init(logits))
    (logits, _), returns, norms, seconds, first = _run(
        xp, step, carry, iterations, compile, callback, lambda v: squash_actions(v, env, f=xp)
    )
    actions = squash_actions(logits, env, f=xp)
    final = rollout(env, initial_state, actions, f=xp)
    final_return = float(ivy.to_numpy(xp.mean(xp.sum(final.rewards, axis=0))))
    return OptimisationResult(
        logits, returns, norms, final_return, seconds, first, actions, initial_state
    )


def optimise_actions_least_squares(
    env: Env,
    horizon: int,
    iterations: int,
    residuals: Callable[[Trajectory], Array],
    *,
    initial_state: Array | None = None,
    batch_shape: Sequence[int] = (),
    logit_cost: float = 1e-4,
    damping: float = 1.0,
    init_scale: float = 0.5,
    initial_logits: Array | None = None,
    seed: int | None = None,
    dtype: Dtype = "float32",
    compile: bool | None = None,
    jacobian_method: str | None = None,
    callback: Callable[[int, Array], bool | None] | None = None,
    device: str | None = None,
    f: Framework = None,
) -> OptimisationResult:
    """Optimise an open-loop action sequence for a least-squares objective of its rollout,
    with Levenberg-Marquardt steps (damped Gauss-Newton).

    Each initial state of the batch has its own actions ``squash_actions(logits)`` and its own
    objective ``|residuals(traj)|^2 + logit_cost |logits|^2``; every iteration computes the
    Jacobian ``J`` of its residuals with respect to its logits through the rollout and tries
    ``logits - (J^T J + (logit_cost + mu) I)^-1 (J^T r + logit_cost logits)``, kept where it
    lowers that initial state's objective (then ``mu *= 0.3``), else discarded (``mu *= 4``).
    Where a chaotic rollout (the double pendulum's swing-up) makes the return's gradient
    useless to Adam (:func:`optimise_actions`), these steps reach and hold a target state:
    the residuals are the distances to it over the last steps. For the double pendulum, two
    stages work where one does not: reach (the last state's residuals), then extend the actions
    and hold (``benchmarks/double_pendulum_swing_up.py``; ``docs/ivy_gym.md`` has the figures).

    The cost of an iteration grows with the residuals' count ``R``: the Jacobian takes ``R``
    backward passes, vectorised over the residuals on every backend: by ``jax.jacrev`` on jax,
    and on torch and tensorflow by one backward pass of the rollout over ``R`` copies of the
    batch (``ivy.execute_with_jacobian(..., method="replicate")``: 0.6 times torch's vectorised
    backward pass on the swing-up, and pfor through tensorflow's ``tf.while_loop`` grows to
    gigabytes). ``residuals`` must therefore treat every leading axis of the trajectory as
    batch.

    Args:
        env: the environment.
        horizon: number of steps ``T``.
        iterations: number of Levenberg-Marquardt iterations.
        residuals: ``residuals(traj) -> (*B, R)`` of the :class:`~ivy_gym.Trajectory` of the
            rollout, each initial state's residuals depending on its own rollout alone (e.g.
            :meth:`ivy_gym.InvertedDoublePendulum.swing_up_residuals`), for a trajectory of any
            batch shape ``B``.
        initial_state: ``(*B, state_dim)``; by default ``env.reset(batch_shape)``.
        batch_shape: the batch of initial states (restarts) when ``initial_state`` is None.
        logit_cost: weight of ``|logits|^2`` in the objective (keeps the actions off the
            saturated ends of ``tanh``, where their gradient vanishes).
        damping: the initial ``mu`` of every initial state.
        init_scale: initial logits are uniform in ``[-init_scale, init_scale]``.
        initial_logits: the initial logits ``(T, *B, action_dim)`` instead.
        seed: ``ivy.seed`` for the backend first (None: leave the generator as it is).
        dtype: dtype of the states and actions.
        compile: run each iteration compiled; by default where the compiler keeps loops
            (jax, tensorflow).
        jacobian_method: ``"native"`` or ``"replicate"`` (:func:`ivy.execute_with_jacobian`);
            by default ``"native"`` on jax, ``"replicate"`` on torch and tensorflow (the
            faster).
        callback: ``callback(iteration, actions)`` after each iteration; True stops.
        device: where to create the states and logits.
        f: framework (torch, jax or tensorflow); by default the global framework or that of
            ``initial_state``.

    Returns:
        An :class:`OptimisationResult`: ``actions`` ``(T, *B, action_dim)``, ``returns`` the
        mean return of the rollouts before each iteration, ``grad_norms`` the norm of the
        objective's gradient, ``costs`` each initial state's final objective.

    Example:
        >>> env = ivy_gym.InvertedDoublePendulum(swing_up=True)
        >>> r = ivy_gym.optimise_actions_least_squares(
        ...     env, 10, 2, lambda traj: env.swing_up_residuals(traj, hold=1),
        ...     batch_shape=(2,), seed=0, f="torch")  # reach upright, the first of two stages
        >>> r.costs.shape  # (40 steps, 60 iterations, 32 restarts reach it: docs/ivy_gym.md)
        (2,)
        >>> best = int(np.argmin(r.costs))
    """
    if logit_cost < 0.0 or damping <= 0.0:
        raise ValueError(
            "optimise_actions_least_squares: logit_cost must be >= 0 and damping > 0, got "
            f"logit_cost={logit_cost!r}, damping={damping!r}."
        )
    xp, initial_state, logits = _action_problem(
        "optimise_actions_least_squares",
        env,
        horizon,
        initial_state,
        batch_shape,
        init_scale,
        initial_logits,
        seed,
        dtype,
        device,
        f,
    )
    device, dtype = xp.dev(logits), logits.dtype
    batch = tuple(initial_state.shape[:-1])
    nb, a = len(batch), env.action_dim
    # the variables batch first, one row of T * action_dim per initial state
    to_rows = (*range(1, nb + 1), 0, nb + 1)
    to_time = (nb, *range(nb), nb + 1)
    u = xp.reshape(xp.permute_dims(logits, to_rows), (*batch, horizon * a))

    def actions_of(u):  # u: (*lead, T * a), lead the batch or (copies, *batch)
        lead = tuple(u.shape[:-1])
        n = len(lead)
        logits = xp.permute_dims(xp.reshape(u, (*lead, horizon, a)), (n, *range(n), n + 1))
        return squash_actions(logits, env, f=xp)

    def residuals_of(u):
        lead = tuple(u.shape[:-1])
        state = initial_state
        if lead != batch:  # the replicated Jacobian's copies of the batch
            state = xp.broadcast_to(state, (*lead, env.state_dim))
        r = residuals(rollout(env, state, actions_of(u), f=xp))
        if tuple(r.shape[:-1]) != lead or len(r.shape) != len(lead) + 1:
            raise ValueError(
                "optimise_actions_least_squares: residuals(traj) must have shape (*B, R) for "
                f"a trajectory of batch B = {lead}, got {tuple(r.shape)}."
            )
        return r

    def objective(u, r):
        return xp.sum(r * r, axis=-1) + logit_cost * xp.sum(u * u, axis=-1)

    def mean_ret(u):
        traj = rollout(env, initial_state, actions_of(u), f=xp)
        return xp.mean(xp.sum(traj.rewards, axis=0))

    eye = xp.eye(horizon * a, dtype=dtype, device=device)
    if jacobian_method is None:
        # the faster, measured on the swing-up (benchmarks/jacobian_methods.py)
        jacobian_method = "native" if xp.capabilities.vectorised_jacobian else "replicate"

    def step(u, mu, cost):
        r, jac = xp.execute_with_jacobian(residuals_of, u, batch_dims=nb, method=jacobian_method)
        jt = xp.matrix_transpose(jac)
        grad = xp.matmul(jt, r[..., None])[..., 0] + logit_cost * u
        hess = xp.matmul(jt, jac) + (logit_cost + mu)[..., None, None] * eye
        trial = u - xp.linalg.solve(hess, grad[..., None])[..., 0]
        trial_cost = objective(trial, residuals_of(trial))
        better = trial_cost < cost
        ret = mean_ret(u)
        u = xp.where(better[..., None], trial, u)
        mu = xp.clip(xp.where(better, 0.3 * mu, 4.0 * mu), 1e-6, 1e8)
        return ret, _global_norm(xp, [grad]), u, mu, xp.where(better, trial_cost, cost)

    if compile is None:
        compile = _compile_by_default(xp)
    mu = xp.full(batch, damping, dtype=dtype, device=device)
    carry = (u, mu, objective(u, residuals_of(u)))
    (u, _, cost), returns, norms, seconds, first = _run(
        xp, step, carry, iterations, compile, callback, actions_of
    )
    actions = actions_of(u)
    logits = xp.permute_dims(xp.reshape(u, (*batch, horizon, a)), to_time)
    final_return = float(ivy.to_numpy(mean_ret(u)))
    costs = np.asarray(ivy.to_numpy(cost), np.float64)
    return OptimisationResult(
        logits, returns, norms, final_return, seconds, first, actions, initial_state, costs
    )


def optimise_policy(
    env: Env,
    policy: Callable[[Array, Nest], Array],
    horizon: int,
    iterations: int,
    *,
    v: Nest = None,
    batch_size: int = 64,
    lr: float = 1e-3,
    discount: float = 1.0,
    window: int | None = None,
    max_grad_norm: float | None = None,
    autoreset: bool = False,
    curriculum: Sequence[tuple[float, int]] = (),
    seed: int | None = None,
    dtype: Dtype = "float32",
    compile: bool | None = None,
    callback: Callable[[int, Nest], bool | None] | None = None,
    device: str | None = None,
    f: Framework = None,
) -> OptimisationResult:
    """Optimise a policy's parameters through differentiable rollouts (Adam): at every
    iteration, a fresh batch of ``batch_size`` initial states, ``horizon`` steps of
    ``policy(obs, v)``, and minus the mean discounted return as the loss.

    Args:
        env: the environment.
        policy: ``policy(obs, v) -> action`` in the action space (an ``ivy.Module`` such as
            ``ivy.MLP(env.observation_dim, (64, 64), env.action_dim,
            output_activation="tanh")`` is called as ``policy(obs, v=v)``).
        horizon: steps per rollout.
        iterations: number of Adam updates.
        v: the initial parameters; by default ``policy.v`` (for a module).
        batch_size: initial states per iteration.
        lr, discount, window, max_grad_norm: as for :func:`optimise_actions`.
        autoreset: restart environments that terminate within the horizon.
        curriculum: stages ``(scale, iterations)`` run first, each on ``env.narrowed(scale)``
            (initial states from the reset box shrunk about its centre: near-upright starts
            for the swing-up tasks), e.g. ``[(0.1, 150), (0.3, 150), (0.6, 200)]``; then the
            ``iterations`` on the whole reset box. Adam's state carries across the stages.
        seed: ``ivy.seed`` for the backend first (None: leave the generator as it is).
        dtype: dtype of the states.
        compile: run each iteration compiled; by default where the compiler keeps loops
            (jax, tensorflow; torch.compile unrolls them, see the module's docstring).
        callback: ``callback(iteration, v)`` after each update (iterations counted across the
            stages); True stops the optimisation.
        device: where to draw the initial states; by default the device of ``v``.
        f: framework; by default that of ``v``.

    Returns:
        An :class:`OptimisationResult` whose ``variables`` are the optimised parameters.

    Example:
        >>> env = ivy_gym.PendulumSmooth()
        >>> mlp = ivy.MLP(3, (64, 64), 1, activation="tanh", output_activation="tanh", f="jax")
        >>> result = ivy_gym.optimise_policy(env, mlp, 100, 5)  # (500 learn the swing-up)
        >>> mlp.v = result.variables
    """
    if v is None:
        v = getattr(policy, "v", None)
        if v is None:
            raise ValueError("optimise_policy: give v= (the policy's parameters).")
    if f is None:
        f = ivy.get_framework(v)
    xp = _differentiable(f, "optimise_policy")
    device = _device_of(xp, v) if device is None else device
    if seed is not None:
        xp.seed(seed)
    opt = ivy.Adam(lr, f=xp)
    if compile is None:
        compile = _compile_by_default(xp)
    stages = [(env.narrowed(scale), operator.index(n)) for scale, n in curriculum]
    stages.append((env, operator.index(iterations)))
    carry = (v, opt.init(v))
    returns, norms, seconds, first, done = [], [], 0.0, None, 0
    for stage_env, stage_iterations in stages:
        step = _policy_step(
            xp, opt, stage_env, policy, horizon, batch_size, dtype, device, discount, window,
            max_grad_norm, autoreset,
        )  # fmt: skip
        stage_callback = None
        if callback is not None:
            stopped = []

            def stage_callback(i, variables, offset=done, stopped=stopped):
                stopped.append(bool(callback(offset + i, variables)))
                return stopped[-1]

        carry, stage_returns, stage_norms, stage_seconds, stage_first = _run(
            xp, step, carry, stage_iterations, compile, stage_callback
        )
        returns.append(stage_returns)
        norms.append(stage_norms)
        seconds += stage_seconds
        first = stage_first if first is None else first
        done += len(stage_returns)
        if callback is not None and stopped and stopped[-1]:
            break
    v = carry[0]
    returns, norms = np.concatenate(returns), np.concatenate(norms)
    final_return = mean_return(
        env, horizon, policy=policy, v=v, batch_size=batch_size, device=device, f=xp
    )
    return OptimisationResult(v, returns, norms, final_return, seconds, first)


def _policy_step(
    xp, opt, env, policy, horizon, batch_size, dtype, device, discount, window, max_grad_norm,
    autoreset,
):  # fmt: skip
    """One Adam update of the policy's parameters from a fresh batch of rollouts of ``env``."""

    def loss_fn(v):
        state = env.reset((batch_size,), dtype=dtype, device=device, f=xp)
        traj = rollout(
            env,
            state,
            policy=policy,
            v=v,
            horizon=horizon,
            autoreset=autoreset,
            window=window,
            f=xp,
        )
        ret = discounted_return(traj.rewards, discount, f=xp)
        return -xp.mean(ret), xp.mean(xp.sum(traj.rewards, axis=0))

    def step(v, opt_state):
        return _update(xp, opt, loss_fn, v, opt_state, max_grad_norm)

    return step


def mean_return(
    env: Env,
    horizon: int,
    *,
    policy: Callable[[Array, Nest], Array] | None = None,
    v: Nest = None,
    batch_size: int = 64,
    autoreset: bool = False,
    dtype: Dtype = "float32",
    compile: bool | None = None,
    device: str | None = None,
    f: Framework = None,
) -> float:
    """The mean return of ``batch_size`` rollouts of ``horizon`` steps from fresh initial states,
    under ``policy(obs, v)``, or under uniformly random actions when ``policy`` is None.

    Args:
        env: the environment.
        horizon: steps per rollout.
        policy, v: the policy and its parameters, or None for random actions.
        batch_size: number of rollouts.
        autoreset: restart environments that terminate within the horizon.
        dtype: dtype of the states.
        compile: run the rollouts compiled; by default where the compiler keeps loops (jax,
            tensorflow: an eager jax rollout compiles each of its operations at its first call).
        device: where to draw the states; by default the device of ``v``.
        f: framework; by default that of ``v`` or the global framework.

    Returns:
        The mean undiscounted return, a float.

    Example:
        >>> score = ivy_gym.mean_return(ivy_gym.PendulumSmooth(), 100, f="torch")  # a random policy
    """
    xp = ivy.get_framework(v, f=f) if v is not None else ivy.get_framework(f=f)
    device = _device_of(xp, v) if device is None else device
    if compile is None:
        compile = _compile_by_default(xp)

    def run(v):
        state = env.reset((batch_size,), dtype=dtype, device=device, f=xp)
        if policy is None:
            shape = (horizon, batch_size, env.action_dim)
            u = xp.random_uniform(shape=shape, dtype=dtype, device=device)
            low, high = env.action_box(xp, dtype=dtype, device=device)
            actions = low + (high - low) * u
            traj = rollout(env, state, actions, autoreset=autoreset, f=xp)
        else:
            traj = rollout(
                env, state, policy=policy, v=v, horizon=horizon, autoreset=autoreset, f=xp
            )
        return xp.mean(xp.sum(traj.rewards, axis=0))

    if compile:
        run = ivy.compile_fn(run, f=xp)
    return float(ivy.to_numpy(run(v)))


def gradient_norms(
    env: Env,
    horizons: Sequence[int],
    *,
    policy: Callable[[Array, Nest], Array] | None = None,
    v: Nest = None,
    batch_size: int = 16,
    discount: float = 1.0,
    window: int | None = None,
    dtype: Dtype = "float32",
    compile: bool | None = None,
    device: str | None = None,
    f: Framework = None,
) -> dict[str, np.ndarray]:
    """The norm of the gradient of the mean return against the horizon.

    With ``policy``, the gradient is taken with respect to its parameters ``v`` (the rollouts
    follow the policy); without, with respect to an open-loop action sequence of zero logits
    (zero-centred actions). The same batch of initial states serves every horizon. Long horizons
    of chaotic dynamics give gradients whose norm grows exponentially with the horizon (or
    vanishes): this measures it.

    Args:
        env: the environment.
        horizons: the horizons to measure, e.g. ``[10, 20, 50, 100, 200]``.
        policy, v: the policy and its parameters (or None for open-loop actions).
        batch_size: initial states.
        discount, window: as for :func:`rollout` and :func:`optimise_actions`.
        dtype: dtype of the states.
        compile: compile each horizon's gradient; by default where the compiler keeps loops
            (jax, tensorflow).
        device: where to draw the states; by default the device of ``v``.
        f: framework (torch, jax or tensorflow).

    Returns:
        ``{"horizon": (H,), "grad_norm": (H,), "return": (H,)}`` numpy arrays (the return is the
        mean undiscounted return at that horizon).

    Example:
        >>> d = ivy_gym.gradient_norms(ivy_gym.CartPoleSwingUp(), [10, 50, 100], f="jax")
    """
    if v is not None and f is None:
        f = ivy.get_framework(v)
    xp = _differentiable(f, "gradient_norms")
    device = _device_of(xp, v) if device is None else device
    if compile is None:
        compile = _compile_by_default(xp)
    state = env.reset((batch_size,), dtype=dtype, device=device, f=xp)
    norms, rets = [], []
    for horizon in horizons:
        use_window = window if window is not None and window < horizon else None

        def loss_fn(variables, horizon=horizon, use_window=use_window):
            if policy is None:
                actions = squash_actions(variables, env, f=xp)
                traj = rollout(env, state, actions, window=use_window, f=xp)
            else:
                traj = rollout(
                    env, state, policy=policy, v=variables, horizon=horizon, window=use_window, f=xp
                )
            ret = discounted_return(traj.rewards, discount, f=xp)
            return -xp.mean(ret), xp.mean(xp.sum(traj.rewards, axis=0))

        def measure(variables, loss_fn=loss_fn):
            _, grads, ret = ivy.execute_with_gradients(loss_fn, variables)
            return _global_norm(xp, grads), ret

        if policy is None:
            shape = (horizon, batch_size, env.action_dim)
            variables = xp.zeros(shape, dtype=dtype, device=device)
        else:
            variables = v
        if compile:
            measure = ivy.compile_fn(measure, f=xp)
        norm, ret = measure(variables)
        norms.append(float(ivy.to_numpy(norm)))
        rets.append(float(ivy.to_numpy(ret)))
    return {
        "horizon": np.asarray(horizons),
        "grad_norm": np.asarray(norms),
        "return": np.asarray(rets),
    }
