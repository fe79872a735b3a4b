"""Returns of segments of experience: λ-returns, generalised advantage estimates (GAE) and
n-step returns, with partial-episode bootstrapping (PEB).

Every function takes time-major arrays ``[time, *batch]`` of one segment collected by parallel
workers: ``rewards[t]`` of the transition from ``s_t`` to ``s'_t``, ``next_values[t] = V(s'_t)``
(``s'_t`` is the true next observation, before any reset), ``resets[t]`` true when the episode
ended after transition ``t`` for any reason (termination or time limit) and ``terminations[t]``
true when it ended in a terminal state. After a termination nothing is bootstrapped; after a
reset that is not a termination (a time limit, or the end of the segment) the value of the last
state ``next_values[t]`` is bootstrapped: partial-episode bootstrapping (Pardo et al., 2018).

The recursions run backwards in time with ``ivy.scan`` (one step per time step), on any
backend, eagerly or inside a compiled function (jax: ``jax.lax.scan``; tensorflow graphs:
``tf.while_loop``; torch: a loop that ``torch.compile`` unrolls).

Example:
    >>> import numpy as np, ivy_rl
    >>> r = np.ones((3, 1)); nv = np.zeros((3, 1)); no = np.zeros((3, 1))
    >>> ivy_rl.lambda_returns(r, nv, no, no, discount=0.5, trace_decay=1.0)[:, 0]
    array([1.75, 1.5 , 1.  ])
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework

__all__ = ["lambda_returns", "generalized_advantages", "n_step_returns"]


def _flags(xp, flags, like):
    """Boolean or 0/1 flags as floats of the dtype of ``like``."""
    return xp.astype(flags, like.dtype)


def _check_fractions(function: str, **values) -> None:
    """``discount`` (γ) and ``trace_decay`` (λ) are fractions in [0, 1], as the agents' settings
    say (``ivy_rl/agents/defaults.py``): outside, the returns grow or change sign with the
    horizon, numbers that look like returns and are none. Arrays are not read (that would
    cost a transfer from the device, and compiled code has no values)."""
    for name, value in values.items():
        if isinstance(value, (int, float)) and not 0.0 <= value <= 1.0:
            raise ValueError(
                f"{function}: {name} must be in [0, 1], got {value!r} (a {name} outside it "
                "makes returns that grow or alternate with the horizon)."
            )


def _check(rewards, *others):
    shape = tuple(rewards.shape)
    if len(shape) < 1 or shape[0] < 1:
        raise ValueError(f"expected time-major arrays [time, *batch] with time >= 1, got {shape}")
    for name, other in others:
        if tuple(other.shape) != shape:
            raise ValueError(
                f"{name} has shape {tuple(other.shape)} but rewards has {shape}; every input "
                "must be a time-major array [time, *batch] of the same shape"
            )


def _reverse_scan(xp, step, init, xs):
    """``ivy.scan`` of ``step`` backwards in time over the leading axis of the arrays ``xs``."""
    _, out = xp.scan(step, init, [xp.flip(a, axis=0) for a in xs])
    return xp.flip(out, axis=0)


def _lambda_returns(xp, rewards, next_values, resets, terminations, discount, trace_decay):
    resets = _flags(xp, resets, rewards)
    continues = 1.0 - _flags(xp, terminations, rewards)

    def step(following, x):
        reward, next_value, reset, cont = x
        mixed = (1.0 - trace_decay) * next_value + trace_decay * following
        bootstrap = reset * next_value + (1.0 - reset) * mixed
        current = reward + discount * cont * bootstrap
        return current, current

    # at the end of the segment G_T = V'_{T-1}: mixed = V'_{T-1} whatever λ
    init = next_values[rewards.shape[0] - 1]
    return _reverse_scan(xp, step, init, [rewards, next_values, resets, continues])


def lambda_returns(
    rewards: Array,
    next_values: Array,
    resets: Array,
    terminations: Array,
    *,
    discount: float = 0.99,
    trace_decay: float = 0.95,
    f: Framework = None,
) -> Array:
    """λ-returns ``G_t = r_t + γ (1 - term_t) [(1 - reset_t)((1 - λ) V'_t + λ G_{t+1})
    + reset_t V'_t]``, with ``G_T = V'_{T-1}`` at the end of the segment.

    Args:
        rewards: ``[time, *batch]`` rewards.
        next_values: ``[time, *batch]`` values of the true next states.
        resets: ``[time, *batch]`` episode ended after this transition (bool or 0/1).
        terminations: ``[time, *batch]`` the episode ended in a terminal state.
        discount: the discount factor γ.
        trace_decay: λ (0: one-step TD targets, 1: Monte-Carlo returns bootstrapped at
            time limits and at the end of the segment).
        f: framework (default: inferred from ``rewards``).

    Returns:
        ``[time, *batch]`` λ-returns, in the dtype of ``rewards``.

    Example:
        One worker, three steps; the episode terminates after the second:

        >>> import numpy as np
        >>> r = np.ones((3, 1)); nv = np.full((3, 1), 2.0)
        >>> resets = terms = np.array([[0.0], [1.0], [0.0]])
        >>> ivy_rl.lambda_returns(r, nv, resets, terms, discount=0.5, trace_decay=1.0)[:, 0]
        array([1.5, 1. , 2. ])
    """
    xp = ivy.get_framework(rewards, f=f)
    _check_fractions("lambda_returns", discount=discount, trace_decay=trace_decay)
    _check(
        rewards, ("next_values", next_values), ("resets", resets), ("terminations", terminations)
    )
    return _lambda_returns(xp, rewards, next_values, resets, terminations, discount, trace_decay)


def _advantages(xp, rewards, values, next_values, resets, terminations, discount, trace_decay):
    cont = 1.0 - _flags(xp, resets, rewards)
    alive = 1.0 - _flags(xp, terminations, rewards)

    def step(following, x):
        reward, value, next_value, carry_on, not_terminal = x
        delta = reward + discount * not_terminal * next_value - value
        current = delta + discount * trace_decay * carry_on * following
        return current, current

    init = xp.zeros_like(rewards[0])
    return _reverse_scan(xp, step, init, [rewards, values, next_values, cont, alive])


def generalized_advantages(
    rewards: Array,
    values: Array,
    next_values: Array,
    resets: Array,
    terminations: Array,
    *,
    discount: float = 0.99,
    trace_decay: float = 0.95,
    f: Framework = None,
) -> Array:
    """Generalised advantage estimates (Schulman et al., 2016):
    ``δ_t = r_t + γ (1 - term_t) V'_t - V_t`` and ``A_t = δ_t + γ λ (1 - reset_t) A_{t+1}``.

    Where ``next_values[t] == values[t + 1]`` within episodes, ``A = lambda_returns - values``.

    Args:
        rewards: ``[time, *batch]`` rewards.
        values: ``[time, *batch]`` values of the states the actions were taken in.
        next_values: ``[time, *batch]`` values of the true next states.
        resets, terminations: as for :func:`lambda_returns`.
        discount: γ.
        trace_decay: λ.
        f: framework (default: inferred from ``rewards``).

    Returns:
        ``[time, *batch]`` advantages.

    Example:
        >>> import numpy as np
        >>> r = np.ones((3, 1)); v = nv = np.full((3, 1), 2.0)
        >>> resets = terms = np.array([[0.0], [1.0], [0.0]])
        >>> adv = ivy_rl.generalized_advantages(r, v, nv, resets, terms, discount=0.5,
        ...                                     trace_decay=1.0)
        >>> adv[:, 0]
        array([-0.5, -1. ,  0. ])
    """
    xp = ivy.get_framework(rewards, f=f)
    _check_fractions("generalized_advantages", discount=discount, trace_decay=trace_decay)
    _check(
        rewards,
        ("values", values),
        ("next_values", next_values),
        ("resets", resets),
        ("terminations", terminations),
    )
    return _advantages(
        xp, rewards, values, next_values, resets, terminations, discount, trace_decay
    )


def _n_step(xp, rewards, next_values, resets, terminations, discount, steps):
    cut = _flags(xp, resets, rewards)
    alive = 1.0 - _flags(xp, terminations, rewards)
    # G^(0) shifted by one step gives V'_t: the one-step target's bootstrap.
    returns = xp.concat([next_values[:1], next_values[:-1]], axis=0)
    for _ in range(steps):
        following = xp.concat([returns[1:], next_values[-1:]], axis=0)
        bootstrap = cut * next_values + (1.0 - cut) * following
        returns = rewards + discount * alive * bootstrap
    return returns


def n_step_returns(
    rewards: Array,
    next_values: Array,
    resets: Array,
    terminations: Array,
    *,
    discount: float = 0.99,
    steps: int = 1,
    f: Framework = None,
) -> Array:
    """n-step returns ``G_t = Σ_{k<n} γ^k r_{t+k} + γ^n V(s_{t+n})``, cut short at the end of
    an episode (bootstrapped from ``next_values`` at a time limit, not at a termination) and at
    the end of the segment (bootstrapped from the last ``next_values``).

    Args:
        rewards, next_values, resets, terminations: as for :func:`lambda_returns`.
        discount: γ.
        steps: n >= 1.
        f: framework (default: inferred from ``rewards``).

    Returns:
        ``[time, *batch]`` n-step returns.

    Example:
        >>> import numpy as np
        >>> r = np.ones((3, 1)); nv = no = np.zeros((3, 1))
        >>> ivy_rl.n_step_returns(r, nv, no, no, discount=0.5, steps=2)[:, 0]
        array([1.5, 1.5, 1. ])
    """
    if int(steps) != steps or steps < 1:
        raise ValueError(f"n_step_returns: steps must be an integer >= 1, got {steps!r}")
    _check_fractions("n_step_returns", discount=discount)
    xp = ivy.get_framework(rewards, f=f)
    _check(
        rewards, ("next_values", next_values), ("resets", resets), ("terminations", terminations)
    )
    return _n_step(xp, rewards, next_values, resets, terminations, discount, int(steps))
