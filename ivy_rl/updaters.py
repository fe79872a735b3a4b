"""Losses and update rules of the agents, written once on a backend namespace ``xp``:
policy gradients, PPO's clipped ratio, value regression, and TRPO's natural gradient step
(conjugate gradient on Fisher-vector products, then a backtracking line search).

Everything here is pure and branch-free (choices are made with ``xp.where``), so it runs inside
one ``ivy.compile_fn``-compiled function per agent.

Example:
    >>> loss, infos = clipped_ratio_loss(ivy.torch, dist, actions, old_log_probs, adv, 0.2)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import ivy
from ivy.nest import map_nest, multi_map_nest
from ivy.typing import Array, Nest

__all__ = [
    "policy_gradient_loss",
    "clipped_ratio_loss",
    "value_loss",
    "nest_dot",
    "conjugate_gradient",
    "trust_region_step",
]


def _log_prob(dist, actions):
    return dist.log_prob(actions)


def policy_gradient_loss(
    xp: Any, dist: Any, actions: Array, advantages: Array, entropy_coeff: float = 0.0
) -> tuple[Array, dict[str, Array]]:
    """``-mean(A * log π(a|s)) - c * mean(entropy)`` (A2C's actor loss).

    Returns:
        ``(loss, {'entropy': ...})``.
    """
    entropy = xp.mean(dist.entropy())
    loss = -xp.mean(advantages * _log_prob(dist, actions))
    if entropy_coeff:
        loss = loss - entropy_coeff * entropy
    return loss, {"entropy": entropy}


def clipped_ratio_loss(
    xp: Any,
    dist: Any,
    actions: Array,
    old_log_probs: Array,
    advantages: Array,
    ratio_clip: float = 0.2,
    entropy_coeff: float = 0.0,
) -> tuple[Array, dict[str, Array]]:
    """PPO's clipped surrogate ``-mean(min(r A, clip(r, 1 - ε, 1 + ε) A))`` with
    ``r = π(a|s) / π_old(a|s)``.

    Returns:
        ``(loss, {'kl', 'clip_fraction', 'entropy'})`` where ``kl`` is the sample estimate
        ``mean(log π_old - log π)`` before the step.
    """
    log_probs = _log_prob(dist, actions)
    ratios = xp.exp(log_probs - old_log_probs)
    clipped = xp.clip(ratios, 1.0 - ratio_clip, 1.0 + ratio_clip)
    loss = -xp.mean(xp.minimum(ratios * advantages, clipped * advantages))
    entropy = xp.mean(dist.entropy())
    if entropy_coeff:
        loss = loss - entropy_coeff * entropy
    outside = xp.logical_or(ratios > 1.0 + ratio_clip, ratios < 1.0 - ratio_clip)
    infos = {
        "kl": xp.mean(old_log_probs - log_probs),
        "clip_fraction": xp.mean(xp.astype(outside, ratios.dtype)),
        "entropy": entropy,
    }
    return loss, infos


def value_loss(xp: Any, values: Array, targets: Array) -> Array:
    """Mean squared error ``mean((values - targets)^2)``."""
    return xp.mean(xp.square(values - targets))


def nest_dot(xp: Any, a: Nest, b: Nest) -> Array:
    """``Σ a·b`` over every leaf of two nests of the same structure."""
    products = ivy.nest.flatten_nest(multi_map_nest(lambda x, y: xp.sum(x * y), a, b))[0]
    total = products[0]
    for p in products[1:]:
        total = total + p
    return total


def conjugate_gradient(
    xp: Any, matvec: Callable[[Nest], Nest], b: Nest, steps: int = 10, eps: float = 1e-8
) -> Nest:
    """Approximately solve ``A x = b`` for a symmetric positive definite ``A`` given as
    ``matvec``, on nests, with ``steps`` unrolled conjugate-gradient iterations from ``x = 0``.

    Example:
        >>> x = conjugate_gradient(ivy.jax, lambda p: fisher_vector_product(p), grads, 10)
    """
    x = map_nest(xp.zeros_like, b)
    r = b
    p = b
    r_dot = nest_dot(xp, r, r)
    for _ in range(steps):
        z = matvec(p)
        alpha = xp.safe_divide(r_dot, nest_dot(xp, p, z) + eps)
        x = multi_map_nest(lambda xi, pi, a=alpha: xi + a * pi, x, p)
        r = multi_map_nest(lambda ri, zi, a=alpha: ri - a * zi, r, z)
        new_r_dot = nest_dot(xp, r, r)
        beta = xp.safe_divide(new_r_dot, r_dot)
        p = multi_map_nest(lambda ri, pi, b=beta: ri + b * pi, r, p)
        r_dot = new_r_dot
    return x


def trust_region_step(
    xp: Any,
    v: Nest,
    loss_fn: Callable[[Nest], Array],
    kl_fn: Callable[[Nest], Array],
    *,
    max_kl: float = 0.01,
    cg_steps: int = 10,
    damping: float = 0.1,
    backtrack_steps: int = 10,
    backtrack_coefficient: float = 0.8,
) -> tuple[Nest, dict[str, Array]]:
    """One TRPO step: the natural gradient direction ``x = F⁻¹ g`` by conjugate gradient on
    Fisher-vector products (Hessian-vector products of the KL, plus ``damping * x``), the
    largest step ``sqrt(2 max_kl / xᵀFx)``, then the first of ``backtrack_steps`` shrinking
    steps whose KL is at most ``max_kl`` and whose loss is not above the current loss (no
    step if none is).

    Args:
        xp: backend namespace.
        v: the policy's variables.
        loss_fn: surrogate loss of the variables (to minimise).
        kl_fn: mean ``KL(π_old || π_v)`` of the variables (zero at ``v``).
        max_kl, cg_steps, damping, backtrack_steps, backtrack_coefficient: the step's settings.

    Returns:
        ``(new_v, {'loss', 'kl', 'backtrack_steps'})`` (``backtrack_steps`` is the number of
        candidates tried; ``backtrack_steps + 1`` when no step was taken).
    """
    start_loss, grads = xp.execute_with_gradients(loss_fn, v)[:2]

    def fisher_vector_product(x):
        def directional(w):
            kl_grads = xp.execute_with_gradients(kl_fn, w, retain_grads=True)[1]
            return nest_dot(xp, kl_grads, x)

        hx = xp.execute_with_gradients(directional, v)[1]
        return multi_map_nest(lambda h, xi: h + damping * xi, hx, x)

    direction = conjugate_gradient(xp, fisher_vector_product, grads, cg_steps)
    curvature = nest_dot(xp, direction, fisher_vector_product(direction))
    step_size = xp.sqrt(xp.safe_divide(2.0 * max_kl, curvature + 1e-8))
    chosen, found = v, None
    chosen_loss, chosen_kl = start_loss, xp.zeros_like(start_loss)
    tries = xp.zeros_like(start_loss) + float(backtrack_steps + 1)
    for i in range(backtrack_steps):
        scale = step_size * backtrack_coefficient**i
        candidate = multi_map_nest(lambda p, d, s=scale: p - s * d, v, direction)
        loss, kl = loss_fn(candidate), kl_fn(candidate)
        ok = xp.logical_and(kl <= max_kl, loss <= start_loss)
        take = ok if found is None else xp.logical_and(ok, xp.logical_not(found))
        chosen = multi_map_nest(lambda c, n, t=take: xp.where(t, n, c), chosen, candidate)
        chosen_loss = xp.where(take, loss, chosen_loss)
        chosen_kl = xp.where(take, kl, chosen_kl)
        tries = xp.where(take, xp.zeros_like(tries) + float(i + 1), tries)
        found = ok if found is None else xp.logical_or(found, ok)
    infos = {"loss": chosen_loss, "kl": chosen_kl, "backtrack_steps": tries}
    return chosen, infos
