"""Updaters, the parts of an agent that learn, and the losses and update rules they use,
written once on a backend namespace ``xp``: policy gradients, PPO's clipped ratio, value
regression, and TRPO's natural gradient step (conjugate gradient on Fisher-vector products,
then a backtracking line search).

Updater classes (an agent's ``actor_updater`` and ``critic_updater``):
:class:`StochasticPolicyGradient` (A2C), :class:`ClippedRatio` (PPO),
:class:`TrustRegionPolicyGradient` (TRPO) and :class:`ValueRegression` (the critics). Each holds
its settings and, once :meth:`GradientUpdater.initialize` gave it a framework, its optimiser.

Everything here is pure and branch-free (choices are made with ``xp.where``), so it runs inside
one ``ivy.compile_fn``-compiled function per agent.

Example:
    PPO's loss where the policy now gives every action ``e^0.5`` times the probability it
    had when acting (all three ratios are beyond ``1 + 0.2``):

    >>> import torch, ivy
    >>> dist = ivy_rl.distributions.Normal(ivy.torch, torch.zeros(3, 1), torch.ones(3, 1))
    >>> actions = torch.tensor([[0.5], [-1.0], [2.0]])
    >>> old_log_probs = dist.log_prob(actions) - 0.5
    >>> advantages = torch.tensor([1.0, 1.0, -1.0])
    >>> loss, infos = clipped_ratio_loss(ivy.torch, dist, actions, old_log_probs, advantages, 0.2)
    >>> round(float(loss), 4), float(infos["clip_fraction"])      # -(1.2 + 1.2 - e^0.5) / 3
    (-0.2504, 1.0)

    An agent takes its updaters as parts:

    >>> agent = ivy_rl.PPO(actor_updater=ClippedRatio(lr=1e-3, ratio_clip=0.1))
    >>> agent.config["ratio_clip"]
    0.1
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import ivy
from ivy.nest import map_nest, multi_map_nest
from ivy.typing import Array, Nest
from ivy_rl import settings as _s
from ivy_rl.schedules import Schedule, as_schedule

__all__ = [
    "GradientUpdater",
    "StochasticPolicyGradient",
    "ClippedRatio",
    "TrustRegionPolicyGradient",
    "ValueRegression",
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
        TRPO's ``matvec`` is a Fisher-vector product; here a 2 x 2 matrix, solved exactly in
        two steps (``x = [1/11, 7/11]``):

        >>> import jax.numpy as jnp, ivy
        >>> A = jnp.array([[4.0, 1.0], [1.0, 3.0]])
        >>> b = {"w": jnp.array([1.0, 2.0])}
        >>> conjugate_gradient(ivy.jax, lambda p: {"w": A @ p["w"]}, b, steps=2)
        {'w': Array([0.09090909, 0.6363636 ], dtype=float32)}
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


# ----------------------------------------------------------------------------------------------
# Updaters: the parts of the agents that learn
# ----------------------------------------------------------------------------------------------


def at_rate(optimizer: Any, lr: Array | None) -> Any:
    """``optimizer`` taking its step at the learning rate ``lr`` (a scalar array: a scheduled
    value, an input of the compiled update, so a new value never compiles anew); itself when
    ``lr`` is None."""
    if lr is None:
        return optimizer
    optimizer = copy.copy(optimizer)
    optimizer.lr = lr
    return optimizer


class GradientUpdater:
    """An updater that takes Adam steps on gradients clipped by their global norm.

    Args:
        lr: Adam's learning rate: a number or a schedule of the run's progress
            (:mod:`ivy_rl.schedules`, e.g. ``"linear:1e-3"``); the agent passes its value at the
            current progress to :meth:`minimize` as an array.
        gradient_clip: the global norm gradients are clipped to (0: no clipping).

    Example:
        >>> import jax.numpy as jnp, ivy
        >>> updater = ValueRegression(lr=0.1).initialize(ivy.jax)
        >>> v = {"w": jnp.array(0.0)}
        >>> state = updater.init_state(v)
        >>> def loss_fn(v):
        ...     return updater.loss(v["w"] * jnp.ones(3), jnp.array([1.0, 2.0, 3.0]))
        >>> v, state, infos = updater.minimize(loss_fn, v, state)   # one Adam step of 0.1
        >>> v, infos
        ({'w': Array(0.1, dtype=float32)}, {'loss': Array(4.666667, dtype=float32)})
    """

    has_optimizer = True
    settings = {"lr": _s.LR, "gradient_clip": _s.CLIP}

    def __init__(self, lr: float | str | Schedule = 3e-4, gradient_clip: float = 0.0) -> None:
        schedule = as_schedule(lr, name=f"{type(self).__name__}: lr")
        if not (schedule(0.0) > 0 and schedule(1.0) >= 0):
            raise ValueError(
                f"{type(self).__name__}: lr must be > 0 (a schedule may end at 0), got {lr!r}"
            )
        if not gradient_clip >= 0:
            raise ValueError(
                f"{type(self).__name__}: gradient_clip must be >= 0 (0: none), "
                f"got {gradient_clip!r}"
            )
        self.lr, self.gradient_clip = lr, gradient_clip
        self.xp = None

    #: Adam's decay rates of its moment estimates (the updaters that declare them set them)
    beta1, beta2 = 0.9, 0.999

    def initialize(self, xp: Any) -> GradientUpdater:
        """Create the optimiser for the backend namespace ``xp``."""
        self.xp = xp
        lr = as_schedule(self.lr)(0.0)
        self.optimizer = ivy.Adam(lr, beta1=self.beta1, beta2=self.beta2, f=xp)
        return self

    def init_state(self, v: Nest) -> Nest:
        """The optimiser's state for the variables ``v``."""
        return self.optimizer.init(v)

    def minimize(
        self, loss_fn: Callable[[Nest], Any], v: Nest, state: Nest, lr: Array | None = None
    ) -> tuple[Nest, Nest, dict[str, Array]]:
        """One step on ``loss_fn(v)`` (returning ``loss`` or ``(loss, infos)``): gradients,
        clipped, and an Adam step.

        Args:
            lr: the learning rate of this step (a scalar array: a scheduled value); default:
                ``lr`` at the start of the run.

        Returns:
            ``(v, state, {'loss': ..., **infos})``.
        """
        xp = self.xp
        loss, grads, *aux = xp.execute_with_gradients(loss_fn, v)
        if self.gradient_clip:
            grads = xp.clip_by_global_norm(grads, self.gradient_clip)[0]
        new_v, new_state = at_rate(self.optimizer, lr).step(v, grads, state)
        return new_v, new_state, {"loss": loss, **(aux[0] if aux else {})}


class ValueRegression(GradientUpdater):
    """The critics' updater: regression of the values on their targets (mean squared error).

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).

    Example:
        >>> ivy_rl.A2C(critic_updater=ValueRegression(lr=1e-3)).config["critic_lr"]
        0.001
    """

    def __init__(self, lr: float = 1e-3, gradient_clip: float = 0.0) -> None:
        super().__init__(lr, gradient_clip)

    def loss(self, predictions: Array, targets: Array) -> Array:
        """``mean((predictions - targets)^2)``."""
        return value_loss(self.xp, predictions, targets)


class StochasticPolicyGradient(GradientUpdater):
    """A2C's actor updater: ``-mean(A log π(a|s)) - c mean(entropy)``.

    Args:
        lr: Adam's learning rate.
        entropy_coeff: weight ``c`` of the entropy bonus.
        gradient_clip: global norm of the gradients (0: no clipping).

    Example:
        >>> ivy_rl.A2C(actor_updater=StochasticPolicyGradient(lr=3e-3)).config["actor_lr"]
        0.003
    """

    needs_distribution = False  # whether the replay keeps the acting policy's parameters
    settings = {
        **GradientUpdater.settings,
        "entropy_coeff": _s.Setting("float", 0.0, meaning="weight of the entropy bonus"),
    }

    def __init__(
        self, lr: float = 3e-4, entropy_coeff: float = 0.0, gradient_clip: float = 0.0
    ) -> None:
        super().__init__(lr, gradient_clip)
        self.entropy_coeff = entropy_coeff

    def loss(self, dist: Any, batch: dict[str, Array]) -> tuple[Array, dict[str, Array]]:
        """The loss of the policy ``dist`` on ``batch`` (``actions``, ``advantages``)."""
        return policy_gradient_loss(
            self.xp, dist, batch["actions"], batch["advantages"], self.entropy_coeff
        )


class ClippedRatio(StochasticPolicyGradient):
    """PPO's actor updater: the clipped surrogate, and a KL threshold beyond which the actor
    stops for the rest of an update.

    Args:
        lr: Adam's learning rate (a number or a schedule).
        ratio_clip: ε of the clipped ratio ``[1 - ε, 1 + ε]`` (a number or a schedule).
        kl_threshold: KL estimate beyond which the actor stops (None: never).
        entropy_coeff: weight of the entropy bonus.
        gradient_clip: global norm of the gradients (0: no clipping).

    Example:
        >>> agent = ivy_rl.PPO(actor_updater=ClippedRatio(lr=1e-3, kl_threshold=None))
        >>> agent.config["kl_threshold"] is None                   # no early stop of the epochs
        True
    """

    settings = {
        **StochasticPolicyGradient.settings,
        "ratio_clip": _s.Setting("schedule", 0.0, open_low=True, meaning="PPO's epsilon"),
        "kl_threshold": _s.Setting(
            "float", optional=True, meaning="KL that stops PPO's actor (None: never)"
        ),
    }

    def __init__(
        self,
        lr: float = 3e-4,
        ratio_clip: float = 0.2,
        kl_threshold: float | None = 0.015,
        entropy_coeff: float = 0.0,
        gradient_clip: float = 0.0,
    ) -> None:
        super().__init__(lr, entropy_coeff, gradient_clip)
        as_schedule(ratio_clip, name=f"{type(self).__name__}: ratio_clip")
        self.ratio_clip, self.kl_threshold = ratio_clip, kl_threshold

    def loss(
        self, dist: Any, batch: dict[str, Array], ratio_clip: Array | None = None
    ) -> tuple[Array, dict[str, Array]]:
        """The clipped surrogate on ``batch`` (``actions``, ``log_probs``, ``advantages``);
        ``ratio_clip``: this step's ε (a scalar array: a scheduled value; default: at the
        start of the run)."""
        if ratio_clip is None:
            ratio_clip = as_schedule(self.ratio_clip)(0.0)
        return clipped_ratio_loss(
            self.xp,
            dist,
            batch["actions"],
            batch["log_probs"],
            batch["advantages"],
            ratio_clip,
            self.entropy_coeff,
        )


class TrustRegionPolicyGradient:
    """TRPO's actor updater: a natural gradient step within a KL trust region (no optimiser);
    the old policy of the KL is rebuilt from the parameters stored when acting
    (``needs_distribution``).

    Args:
        max_kl: the trust region's radius δ.
        cg_steps: conjugate-gradient iterations.
        damping: added to the Fisher-vector products.
        backtrack_steps: candidate steps of the line search.
        backtrack_coefficient: shrink factor between candidates.
        entropy_coeff: weight of the entropy bonus in the surrogate.

    Example:
        >>> ivy_rl.TRPO(actor_updater=TrustRegionPolicyGradient(max_kl=0.02)).config["max_kl"]
        0.02
    """

    has_optimizer = False
    needs_distribution = True
    settings = {
        "max_kl": _s.Setting("float", 0.0, open_low=True, meaning="trust-region radius"),
        "cg_steps": _s.Setting("int", 1, meaning="conjugate-gradient iterations"),
        "damping": _s.Setting("float", 0.0, meaning="damping of Fisher-vector products"),
        "backtrack_steps": _s.Setting("int", 1, meaning="candidate steps of the line search"),
        "backtrack_coefficient": _s.Setting(
            "float", 0.0, 1.0, open_low=True, open_high=True, meaning="shrink between candidates"
        ),
        "entropy_coeff": StochasticPolicyGradient.settings["entropy_coeff"],
    }

    def __init__(
        self,
        max_kl: float = 0.01,
        cg_steps: int = 10,
        damping: float = 0.1,
        backtrack_steps: int = 10,
        backtrack_coefficient: float = 0.8,
        entropy_coeff: float = 0.0,
    ) -> None:
        self.max_kl, self.cg_steps, self.damping = max_kl, cg_steps, damping
        self.backtrack_steps, self.backtrack_coefficient = backtrack_steps, backtrack_coefficient
        self.entropy_coeff = entropy_coeff
        self.xp = None

    def initialize(self, xp: Any) -> TrustRegionPolicyGradient:
        self.xp = xp
        return self

    def step(
        self,
        actor: Callable[[Nest], Any],
        v: Nest,
        old_distribution: dict[str, Array],
        batch: dict[str, Array],
    ) -> tuple[Nest, dict[str, Array]]:
        """The trust-region step of the policy ``actor(w) -> distribution`` from ``v``.

        Args:
            actor: the policy's distribution on the batch's observations, given variables.
            v: the policy's variables.
            old_distribution: the acting policy's parameters on the batch.
            batch: ``actions``, ``log_probs`` (of the acting policy), ``advantages``.

        Returns:
            ``(new_v, {'loss', 'kl', 'backtrack_steps'})``.
        """
        xp = self.xp
        old = actor(v).like(old_distribution)

        def surrogate(w):
            dist = actor(w)
            ratios = xp.exp(dist.log_prob_raw(batch["actions"]) - batch["log_probs"])
            loss = -xp.mean(ratios * batch["advantages"])
            if self.entropy_coeff:
                loss = loss - self.entropy_coeff * xp.mean(dist.entropy())
            return loss

        def kl(w):
            return xp.mean(old.kl(actor(w)))

        return trust_region_step(
            xp,
            v,
            surrogate,
            kl,
            max_kl=self.max_kl,
            cg_steps=self.cg_steps,
            damping=self.damping,
            backtrack_steps=self.backtrack_steps,
            backtrack_coefficient=self.backtrack_coefficient,
        )
