"""The parts of the agents that learn through ivy_gym's gradients (APG, SHAC): the model
(:class:`ActorValueModel`), the updaters (:class:`AnalyticPolicyGradient`,
:class:`TargetValueRegression`); their replay is :class:`ivy_rl.replays.Rollouts` and their
exploration :class:`ivy_rl.explorations.NormalNoise`.

Example:
    >>> from ivy_rl.differentiable_parts import (
    ...     ActorValueModel, AnalyticPolicyGradient, TargetValueRegression)
    >>> from ivy_rl.replays import Rollouts
    >>> agent = ivy_rl.agents.SHAC(
    ...     model=ActorValueModel((64, 64), critic=True),
    ...     replay=Rollouts(batch_size=64, horizon=32),
    ...     actor_updater=AnalyticPolicyGradient(lr=2e-3),
    ...     critic_updater=TargetValueRegression(lr=2e-3, iterations=8))
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

import ivy
from ivy.typing import Framework, Nest
from ivy_rl import settings as _s
from ivy_rl import updaters
from ivy_rl.models import (
    Actor,
    Critic,
    DeterministicHead,
    MLPTorso,
    ObservationEncoder,
    ValueHead,
    orthogonal_init,
    polyak_update,
)
from ivy_rl.updaters import GradientUpdater, at_rate

__all__ = ["ActorValueModel", "AnalyticPolicyGradient", "TargetValueRegression"]


class ActorValueModel:
    """A deterministic policy ``tanh(dense(MLP(obs)))`` and, for SHAC, a state-value critic
    with a target copy.

    Args:
        hidden_sizes: hidden sizes of the policy's MLP.
        activation: activation of the MLPs.
        critic: whether there is a critic (SHAC: yes; APG: no).
        critic_hidden_sizes: of the critic's MLP (None: ``hidden_sizes``).
        normalize_returns: the critic predicts its targets normalised by their running mean
            and standard deviation.
        normalize_observations: the policy and the critic see observations normalised by the
            running mean and standard deviation of the rollouts' observations (SHAC's paper).

    Example:
        >>> model = ivy_rl.differentiable_parts.ActorValueModel((64, 64), critic=True)
        >>> agent = ivy_rl.agents.SHAC(model=model)
    """

    settings = {
        "hidden_sizes": _s.SIZES,
        "activation": _s.ACTIVATION,
        "critic_hidden_sizes": _s.CRITIC_SIZES,
        "normalize_returns": _s.Setting("bool", meaning="the critic predicts normalised returns"),
        "normalize_observations": _s.Setting(
            "bool", meaning="normalise observations by the rollouts' running mean and std"
        ),
    }

    def __init__(
        self,
        hidden_sizes: Sequence[int] = (64, 64),
        activation: str = "tanh",
        critic: bool = False,
        critic_hidden_sizes: Sequence[int] | None = None,
        normalize_returns: bool = True,
        normalize_observations: bool = False,
    ) -> None:
        self.hidden_sizes, self.activation = tuple(hidden_sizes), activation
        self.has_critic = bool(critic)
        self.critic_hidden_sizes = (
            None if critic_hidden_sizes is None else tuple(critic_hidden_sizes)
        )
        self.normalize_returns = bool(normalize_returns)
        self.normalize_observations = bool(normalize_observations)

    def initialize(
        self,
        observation_dim: int,
        action_dim: int,
        *,
        rng: np.random.Generator,
        dtype: Any = None,
        device: Any = None,
        f: Framework = None,
    ) -> ActorValueModel:
        """Build the networks (weights from ``rng``: the policy's MLP, its head, then the
        critic's MLP and head); then ``actor``, ``critic`` (or None) and ``v``
        (``{'actor'}``, with ``'critic'`` and ``'target'`` for a critic)."""
        xp = ivy.get_framework(f=f)
        build = {"dtype": dtype, "device": device, "f": xp}

        def torso(sizes):
            init = orthogonal_init(rng, math.sqrt(2.0))
            return MLPTorso(observation_dim, sizes, self.activation, weight_init=init, **build)

        actor_torso = torso(self.hidden_sizes)
        head = DeterministicHead(
            actor_torso.out_size, action_dim, weight_init=orthogonal_init(rng, 0.01), **build
        )
        self.actor = Actor(ObservationEncoder(observation_dim, f=xp), actor_torso, head)
        self.v = {"actor": self.actor.v}
        self.critic = None
        if self.has_critic:
            critic_torso = torso(self.critic_hidden_sizes or self.hidden_sizes)
            value = ValueHead(critic_torso.out_size, weight_init=orthogonal_init(rng, 1.0), **build)
            self.critic = Critic(ObservationEncoder(observation_dim, f=xp), critic_torso, value)
            self.v.update(critic=self.critic.v, target=self.critic.v)
        return self


class AnalyticPolicyGradient(GradientUpdater):
    """The policy's updater of APG and SHAC: an Adam step on the gradient of a loss computed
    through differentiable rollouts, its global norm logged and clipped.

    Args:
        lr: Adam's learning rate (a number or a schedule).
        gradient_clip: global norm of the gradient (0: no clipping).
        beta1, beta2: Adam's decay rates (SHAC's paper: 0.7 and 0.95).

    Example:
        >>> updater = ivy_rl.differentiable_parts.AnalyticPolicyGradient(lr=1e-2)
        >>> ivy_rl.agents.APG(actor_updater=updater).config["actor_lr"]
        0.01
    """

    settings = {"lr": _s.LR, "gradient_clip": _s.CLIP, "beta1": _s.BETA1, "beta2": _s.BETA2}

    def __init__(
        self, lr: Any = 1e-3, gradient_clip: float = 1.0, beta1: float = 0.9, beta2: float = 0.999
    ) -> None:
        super().__init__(lr, gradient_clip)
        self.beta1, self.beta2 = float(beta1), float(beta2)

    def minimize(self, loss_fn: Callable, v: Nest, state: Nest, lr: Any = None):
        """A step on ``loss_fn(v) -> (loss, infos)``: ``(v, state, {'loss', 'gradient_norm',
        'skipped', **infos})``.

        A gradient that is not finite (a rollout through a contact whose derivative overflowed)
        is not applied: the weights and the optimiser's state stay as they were, and
        ``skipped`` is 1 (else 0), so that one bad rollout does not turn every weight into NaN.
        """
        xp = self.xp
        loss, grads, aux = xp.execute_with_gradients(loss_fn, v)
        norm = _global_norm(xp, grads)
        finite = xp.isfinite(norm)
        grads = ivy.nest.map_nest(lambda g: xp.where(finite, g, xp.zeros_like(g)), grads)
        if self.gradient_clip:
            grads = xp.clip_by_global_norm(grads, self.gradient_clip)[0]
        new_v, new_state = at_rate(self.optimizer, lr).step(v, grads, state)

        def keep(new, old):
            return xp.where(finite, new, old)

        kept = ivy.nest.multi_map_nest(keep, new_v, v)
        kept_state = ivy.nest.multi_map_nest(keep, new_state, state)
        skipped = 1.0 - xp.astype(finite, norm.dtype)
        return kept, kept_state, {"loss": loss, "gradient_norm": norm, "skipped": skipped, **aux}


class TargetValueRegression(GradientUpdater):
    """SHAC's critic updater: weighted regression of the critic on TD(λ) targets of a rollout
    (values of the target critic), in ``iterations`` passes of ``batches`` mini-batches, then
    the target critic moved towards the critic by ``target_update``.

    Args:
        lr: Adam's learning rate (a number or a schedule).
        gradient_clip: global norm of the gradients (0: no clipping).
        trace_decay: λ of the TD(λ) targets.
        iterations: passes over a rollout's transitions per update.
        batches: mini-batches per pass.
        target_update: step of the target critic per update (1: copy).
        beta1, beta2: Adam's decay rates.

    Example:
        >>> updater = ivy_rl.differentiable_parts.TargetValueRegression(iterations=8, batches=4)
        >>> agent = ivy_rl.agents.SHAC(critic_updater=updater)
    """

    settings = {
        "lr": _s.LR,
        "gradient_clip": _s.CLIP,
        "trace_decay": _s.TRACE_DECAY,
        "iterations": _s.Setting("int", 1, meaning="passes of critic regression per update"),
        "batches": _s.Setting("int", 1, meaning="critic mini-batches per pass"),
        "target_update": _s.Setting("float", 0.0, 1.0, meaning="step of the target critic"),
        "beta1": _s.BETA1,
        "beta2": _s.BETA2,
    }

    def __init__(
        self,
        lr: Any = 2e-3,
        gradient_clip: float = 0.0,
        trace_decay: float = 0.95,
        iterations: int = 8,
        batches: int = 4,
        target_update: float = 0.8,
        beta1: float = 0.9,
        beta2: float = 0.999,
    ) -> None:
        super().__init__(lr, gradient_clip)
        self.beta1, self.beta2 = float(beta1), float(beta2)
        self.trace_decay, self.target_update = trace_decay, target_update
        self.iterations, self.batches = int(iterations), int(batches)

    def orders(self, rng: np.random.Generator, total: int) -> np.ndarray:
        """``[iterations * batches, total // batches]`` indices of the mini-batches."""
        rows = [rng.permutation(total).reshape(self.batches, -1) for _ in range(self.iterations)]
        return np.concatenate(rows).astype(np.int32)

    def step(self, critic: Any, carry: Any, indices: Any, batch: dict, lr: Any = None):
        """A step on the mini-batch ``indices`` of ``batch`` (``observations``, ``targets``,
        ``weights``): ``((critic_v, state), {'loss'})``."""
        xp = self.xp
        critic_v, critic_state = carry
        part = {k: xp.take(a, indices, axis=0) for k, a in batch.items()}

        def loss_fn(w):
            values = critic.normalized(w, part["observations"], None)
            weights = part["weights"]
            return updaters.value_loss(xp, values * weights, part["targets"] * weights)

        loss, grads = xp.execute_with_gradients(loss_fn, critic_v)[:2]
        if self.gradient_clip:
            grads = xp.clip_by_global_norm(grads, self.gradient_clip)[0]
        critic_v, critic_state = at_rate(self.optimizer, lr).step(critic_v, grads, critic_state)
        return (critic_v, critic_state), {"loss": loss}

    def update_target(self, target_v: Nest, critic_v: Nest) -> Nest:
        return polyak_update(target_v, critic_v, self.target_update, f=self.xp)


def _global_norm(xp, grads):
    leaves = ivy.nest.nest_leaves(grads)
    return xp.sqrt(sum(xp.sum(g * g) for g in leaves))
