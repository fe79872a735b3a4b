"""Rollouts: many steps of an environment as one ``ivy.scan``, so that they compile
(``jax.lax.scan``, ``tf.while_loop``, an unrolled loop under ``torch.compile``) and differentiate
with respect to the actions, a policy's parameters, the initial states and the environment's
parameters.

Example:
    >>> env = ivy_gym.Pendulum()
    >>> state = env.reset((64,), f="torch")
    >>> traj = ivy_gym.rollout(env, state, torch.zeros(100, 64, 1))
    >>> traj.rewards.shape
    torch.Size([100, 64])
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from typing import NamedTuple

import ivy
from ivy.typing import Array, Framework, Nest
from ivy_gym.base import check_action, check_state

__all__ = ["Trajectory", "rollout", "discounted_return"]


class Trajectory(NamedTuple):
    """What a rollout of ``T`` steps of a batch ``B`` returns (arrays of the state's backend).

    Attributes:
        observations: ``(T, *B, observation_dim)``, the observation returned by each step.
        actions: ``(T, *B, action_dim)``, the actions taken.
        rewards: ``(T, *B)``; 0 at steps after a termination (without ``autoreset``), as
            Gymnasium's episodes end there.
        terminated: ``(T, *B)`` bool, the step's termination flag.
        valid: ``(T, *B)`` bool: whether the step belongs to the episode (False after a
            termination, without ``autoreset``).
        states: ``(T, *B, state_dim)``, the state after each step (before an autoreset).
        final_state: ``(*B, state_dim)``, the state the next step would start from.
    """

    observations: Array
    actions: Array
    rewards: Array
    terminated: Array
    valid: Array
    states: Array
    final_state: Array


def rollout(
    env,
    state: Array,
    actions: Array | None = None,
    *,
    policy: Callable[[Array, Nest], Array] | None = None,
    v: Nest = None,
    horizon: int | None = None,
    autoreset: bool = False,
    window: int | None = None,
    f: Framework = None,
) -> Trajectory:
    """Run ``env`` from ``state`` for a sequence of actions, or a policy, as one ``ivy.scan``.

    Open loop, ``actions`` ``(T, *B, action_dim)``: step ``t`` applies ``actions[t]``. Closed
    loop, ``policy(obs, v)``: step ``t`` applies ``policy(observation, v)`` to the observation
    of the current state, for ``horizon`` steps.

    Without ``autoreset`` the states keep evolving after a termination, but those steps are
    outside the episode: their rewards are 0 and ``valid`` is False. With ``autoreset``, an
    environment that terminates restarts from a fresh ``env.reset`` draw at the next step; no
    gradient flows across the reset (the new state does not depend on the old one).

    ``window=K`` truncates gradients: the state is cut from the graph (``ivy.stop_gradient``)
    at steps ``K, 2K, ...``, so a reward's gradient reaches back to the start of its window at
    most (as in short-horizon actor-critic methods); the values are unchanged. The last window
    is shorter when ``K`` does not divide ``T``.

    Args:
        env: an :class:`ivy_gym.Env`.
        state: initial states ``(*B, state_dim)``.
        actions: ``(T, *B, action_dim)``, or None with ``policy``.
        policy: ``policy(observation, v) -> action`` (an ``ivy.Module`` is called as
            ``policy(observation, v=v)``), or None with ``actions``.
        v: the policy's parameters (any nest), passed to it unchanged.
        horizon: number of steps with ``policy``.
        autoreset: restart terminated environments from fresh initial states.
        window: cut gradients every ``window`` steps.
        f: framework name or namespace (the state and actions are converted to it); by
            default inferred from ``state``, ``actions``, ``v`` and the environment's array
            parameters, which must be of one framework (else ``ivy.errors.MixedFrameworksError``).

    Returns:
        A :class:`Trajectory` on the state's device.

    Example:
        >>> env = ivy_gym.CartPoleSwingUp()
        >>> mlp = ivy.MLP(5, (64, 64), 1, output_activation="tanh", f="jax")
        >>> traj = ivy_gym.rollout(env, env.reset((32,), f="jax"), policy=mlp, v=mlp.v,
        ...                        horizon=100)
    """
    xp = ivy.get_framework(state, actions, v, env.param_arrays, f=f)
    if (actions is None) == (policy is None):
        raise ValueError("rollout: give either actions (open loop) or policy= (closed loop).")
    check_state(env, state, "rollout")
    if f is not None:  # the chosen framework: convert, as the core's functions do
        state = xp.asarray(state)
    batch_shape = tuple(state.shape[:-1])
    if actions is not None:
        # the state's framework; a floating dtype is kept (the kernels follow Gymnasium's
        # arithmetic with float32 actions), anything else takes the state's dtype, once
        actions = check_action(
            env, xp, actions, state, "rollout", argument="actions", time_axis=True
        )
        steps = actions.shape[0]
        if horizon is not None and operator.index(horizon) != steps:
            raise ValueError(f"rollout: horizon={horizon} but actions has {steps} steps.")
    else:
        if horizon is None:
            raise ValueError("rollout: with policy=, give horizon= (the number of steps).")
        steps = operator.index(horizon)
    dtype = state.dtype
    device = xp.dev(state)
    masked = env.can_terminate and not autoreset
    if isinstance(policy, ivy.Module):
        module = policy

        def policy(obs, v):
            return module(obs, v=v)

    def step(carry, action):
        state, obs, alive = carry
        if action is None:
            action = check_action(
                env, xp, policy(obs, v), state, "rollout", argument="policy(obs, v)"
            )
        new_state, obs, reward, terminated = env.kernel_step(xp, state, action)
        valid = alive
        if masked:
            reward = xp.where(alive, reward, xp.zeros_like(reward))
            alive = xp.logical_and(alive, xp.logical_not(terminated))
        next_state = new_state
        if autoreset and env.can_terminate:
            fresh = env.reset(batch_shape, dtype=dtype, device=device, f=xp)
            cut = xp.expand_dims(terminated, axis=-1)
            next_state = xp.where(cut, fresh, new_state)
            obs_next = xp.where(cut, env.kernel_observe(xp, fresh), obs)
        else:
            obs_next = obs
        out = (obs, action, reward, terminated, valid, new_state)
        return (next_state, obs_next, alive), out

    alive0 = xp.ones(batch_shape, dtype="bool", device=device)
    carry = (state, env.kernel_observe(xp, state), alive0)
    if window is None or window >= steps:
        carry, outs = xp.scan(step, carry, actions, length=steps)
    else:
        carry, outs = _windowed_scan(xp, step, carry, actions, steps, operator.index(window))
    observations, actions_taken, rewards, terminated, valid, states = outs
    return Trajectory(observations, actions_taken, rewards, terminated, valid, states, carry[0])


def _windowed_scan(xp, step, carry, actions, steps, window):
    """``ivy.scan(step, ...)`` in windows of ``window`` steps (the last one may be shorter),
    cutting gradients between them."""
    if window < 1:
        raise ValueError(f"rollout: window must be a positive number of steps, got {window}.")
    full, rest = divmod(steps, window)

    def part(start, stop):
        return None if actions is None else actions[start:stop]

    def cut(carry):
        state, obs, alive = carry
        return (xp.stop_gradient(state), xp.stop_gradient(obs), alive)

    def run_window(carry, window_actions):
        return xp.scan(step, cut(carry), window_actions, length=window)

    carry, first = xp.scan(step, carry, part(0, window), length=window)
    pieces = [first]
    if full > 1:
        middle = part(window, full * window)
        if middle is not None:
            middle = xp.reshape(middle, (full - 1, window, *middle.shape[1:]))
        carry, outs = xp.scan(run_window, carry, middle, length=full - 1)
        pieces.append(
            ivy.nest.map_nest(lambda a: xp.reshape(a, ((full - 1) * window, *a.shape[2:])), outs)
        )
    if rest:
        carry, outs = xp.scan(step, cut(carry), part(full * window, steps), length=rest)
        pieces.append(outs)
    if len(pieces) == 1:
        return carry, first
    return carry, ivy.nest.multi_map_nest(lambda *a: xp.concat(a, axis=0), *pieces)


def discounted_return(rewards: Array, discount: float = 1.0, *, f: Framework = None) -> Array:
    """``sum_t discount**t * rewards[t]`` over the leading (time) axis.

    Args:
        rewards: ``(T, *B)``.
        discount: the discount factor.
        f: framework name or namespace; by default inferred from ``rewards``.

    Returns:
        ``(*B,)``.

    Example:
        >>> ivy_gym.discounted_return(np.ones((3, 2)), 0.5)
        array([1.75, 1.75])
    """
    xp = ivy.get_framework(rewards, f=f)
    if discount == 1.0:
        return xp.sum(rewards, axis=0)
    steps = rewards.shape[0]
    t = xp.arange(steps, dtype=rewards.dtype, device=xp.dev(rewards))
    weights = discount**t
    weights = xp.reshape(weights, (steps, *([1] * (len(rewards.shape) - 1))))
    return xp.sum(rewards * weights, axis=0)
