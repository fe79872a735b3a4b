"""The updaters of the off-policy agents: one optimisation step of a part (the actor, the
critics, the Q-network) on a mini-batch of n-step transitions, written once on the backend
namespace ``xp`` and pure (they run inside the agent's one compiled update).

Critic updaters: :class:`DeterministicQLearning` (DDPG), :class:`TwinCriticDeterministicQLearning`
(TD3: the smaller twin target and target policy smoothing), :class:`DistributionalDeterministicQLearning`
(D4PG: a categorical critic, cross-entropy on the projected target),
:class:`TwinCriticSoftQLearning` (SAC), :class:`ExpectedSARSA` (MPO) and :class:`QLearning` (DQN,
double or not, Huber loss). Actor updaters: :class:`DeterministicPolicyGradient` (DDPG; TD3 and
D4PG through :class:`TwinCriticDeterministicPolicyGradient` and
:class:`DistributionalDeterministicPolicyGradient`), :class:`TwinCriticSoftPolicyGradient` (SAC,
with its temperature) and :class:`MaximumAPosterioriPolicyOptimization` (MPO, with its duals).

Each takes ``step(v, targets, states, batch, obs_stats, x, rates) -> (v, states, infos)``: the
variables and optimiser states by part, the targets' variables, the batch
(:func:`ivy_rl.buffers.n_step_batch`), the observation statistics, the noise it drew with
:meth:`OffPolicyUpdater.draw` (from the agent's numpy generator, so the compiled update draws
nothing), and its scheduled learning rates (``{'lr': array, ...}``). Updaters that learn
variables of their own (SAC's temperature, MPO's duals) give them in
:meth:`OffPolicyUpdater.variables`.

Example:
    >>> from ivy_rl.off_policy_updaters import TwinCriticSoftPolicyGradient, TwinCriticSoftQLearning
    >>> agent = ivy_rl.agents.SAC(
    ...     actor_updater=TwinCriticSoftPolicyGradient(lr=3e-4, initial_temperature=0.1),
    ...     critic_updater=TwinCriticSoftQLearning(lr=3e-4))
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Nest
from ivy_rl import settings as _s
from ivy_rl.critics import project_categorical
from ivy_rl.schedules import as_schedule
from ivy_rl.updaters import GradientUpdater, at_rate

__all__ = [
    "OffPolicyUpdater",
    "DeterministicPolicyGradient",
    "TwinCriticDeterministicPolicyGradient",
    "DistributionalDeterministicPolicyGradient",
    "TwinCriticSoftPolicyGradient",
    "MaximumAPosterioriPolicyOptimization",
    "DeterministicQLearning",
    "TwinCriticDeterministicQLearning",
    "DistributionalDeterministicQLearning",
    "TwinCriticSoftQLearning",
    "ExpectedSARSA",
    "QLearning",
]


class OffPolicyUpdater(GradientUpdater):
    """Base of the off-policy updaters: Adam steps on the part ``part`` of the variables, with
    gradients clipped by their global norm.

    Args:
        lr: Adam's learning rate (a number or a schedule of the run's progress).
        gradient_clip: global norm of the gradients (0: no clipping).
    """

    #: the part of the variables this updater trains
    part = "actor"
    settings = {"lr": _s.LR, "gradient_clip": _s.CLIP}

    def initialize(
        self, xp: Any, model: Any = None, *, dtype: Any = None, device: Any = None
    ) -> OffPolicyUpdater:
        """Create the optimisers on the backend ``xp`` for the agent's built ``model``."""
        super().initialize(xp)
        self.model, self.dtype, self.device = model, dtype, device
        return self

    def variables(self) -> dict[str, Nest]:
        """Variables this updater learns besides the model's (by part; none here)."""
        return {}

    def optimizers(self) -> dict[str, Any]:
        """The optimiser of each part this updater steps."""
        return {self.part: self.optimizer}

    def draw(self, rng: np.random.Generator, iterations: int, batch_size: int) -> dict:
        """The noise of ``iterations`` steps, drawn from the agent's generator (none here)."""
        return {}

    def _normal(self, rng, shape):
        return rng.standard_normal(shape).astype(np.dtype(self.dtype))

    def _minimize_with(self, optimizer, loss_fn, v, state, lr=None):
        """A step of ``optimizer`` on ``loss_fn``'s clipped gradients (at the rate ``lr``)."""
        xp = self.xp
        loss, grads, *aux = xp.execute_with_gradients(loss_fn, v)
        if self.gradient_clip:
            grads = xp.clip_by_global_norm(grads, self.gradient_clip)[0]
        new_v, new_state = at_rate(optimizer, lr).step(v, grads, state)
        return new_v, new_state, {"loss": loss, **(aux[0] if aux else {})}

    def _step_part(self, loss_fn, v, states, rates):
        """``loss_fn`` minimised on ``v[part]``: the new ``v``, ``states`` and the infos."""
        part = self.part
        new, state, infos = self.minimize(loss_fn, v[part], states[part], rates.get("lr"))
        return {**v, part: new}, {**states, part: state}, infos

    def step(self, v, targets, states, batch, obs_stats, x, rates):
        raise NotImplementedError


# ----------------------------------------------------------------------------------------------
# Actor updaters
# ----------------------------------------------------------------------------------------------


class DeterministicPolicyGradient(OffPolicyUpdater):
    """DDPG's actor updater: ascend ``Q(s, π(s))``, the loss ``-mean(Q(s, π(s)))``.

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).

    Example:
        >>> updater = ivy_rl.off_policy_updaters.DeterministicPolicyGradient(lr=1e-4)
        >>> ivy_rl.agents.DDPG(actor_updater=updater).config["actor_lr"]
        0.0001
    """

    def __init__(self, lr: Any = 1e-3, gradient_clip: float = 0.0) -> None:
        super().__init__(lr, gradient_clip)

    def values(self, q: Any) -> Array:
        """What the actor ascends, from the critics' output."""
        return q

    def loss(self, actor_v, critic_v, batch, obs_stats, x):
        observations = batch["observations"]
        actions = self.model.actor(observations, obs_stats, v=actor_v).mode()
        return -self.xp.mean(self.values(self.model.q(critic_v, observations, actions, obs_stats)))

    def step(self, v, targets, states, batch, obs_stats, x, rates):
        critic_v = v["critic"]
        return self._step_part(
            lambda w: self.loss(w, critic_v, batch, obs_stats, x), v, states, rates
        )


class TwinCriticDeterministicPolicyGradient(DeterministicPolicyGradient):
    """TD3's actor updater: ascend the first twin critic's ``Q_1(s, π(s))``."""

    def values(self, q):
        return q[0]


class DistributionalDeterministicPolicyGradient(DeterministicPolicyGradient):
    """D4PG's actor updater: ascend the categorical critic's expected value."""

    def values(self, q):
        return q.mean()


class TwinCriticSoftPolicyGradient(OffPolicyUpdater):
    """SAC's actor updater, with the temperature: the actor minimises
    ``mean(α log π(a|s) - min_i Q_i(s, a))`` with ``a ~ π(s)`` (reparameterised), then
    ``log α`` takes a step on ``-log α (H* - H)`` so that the entropy ``H`` tracks
    ``target_entropy`` ``H*``.

    Args:
        lr: the actor's Adam learning rate.
        gradient_clip: global norm of the gradients (0: no clipping; the temperature's too).
        initial_temperature: α at the start (> 0).
        temperature_lr: Adam learning rate of ``log α`` (0: α stays fixed).
        target_entropy: H* (None: minus the number of action dimensions).

    Example:
        >>> updater = ivy_rl.off_policy_updaters.TwinCriticSoftPolicyGradient(
        ...     lr=3e-4, initial_temperature=0.1)
        >>> ivy_rl.agents.SAC(actor_updater=updater).config["initial_temperature"]
        0.1
    """

    settings = {
        **OffPolicyUpdater.settings,
        "initial_temperature": _s.Setting("float", 0.0, open_low=True, meaning="initial alpha"),
        "temperature_lr": _s.Setting("schedule", 0.0, meaning="learning rate of log alpha"),
        "target_entropy": _s.Setting(
            "float", optional=True, meaning="the entropy alpha steers to (None: -action size)"
        ),
    }

    def __init__(
        self,
        lr: Any = 1e-3,
        gradient_clip: float = 0.0,
        initial_temperature: float = 1.0,
        temperature_lr: Any = 1e-3,
        target_entropy: float | None = None,
    ) -> None:
        super().__init__(lr, gradient_clip)
        if not initial_temperature > 0:
            raise ValueError(f"SAC: initial_temperature must be > 0, got {initial_temperature}")
        as_schedule(temperature_lr, name="TwinCriticSoftPolicyGradient: temperature_lr")
        self.initial_temperature = initial_temperature
        self.temperature_lr, self.target_entropy = temperature_lr, target_entropy

    def initialize(self, xp, model=None, *, dtype=None, device=None):
        super().initialize(xp, model, dtype=dtype, device=device)
        self.temperature_optimizer = ivy.Adam(as_schedule(self.temperature_lr)(0.0), f=xp)
        entropy = self.target_entropy
        self.entropy_target = -float(model.action_size) if entropy is None else float(entropy)
        return self

    def variables(self):
        log_alpha = self.xp.asarray(
            math.log(self.initial_temperature), dtype=self.dtype, device=self.device
        )
        return {"temperature": {"log_alpha": log_alpha}}

    def optimizers(self):
        return {"actor": self.optimizer, "temperature": self.temperature_optimizer}

    def draw(self, rng, iterations, batch_size):
        return {"noise": self._normal(rng, (iterations, batch_size, self.model.action_size))}

    def loss(self, actor_v, critic_v, batch, obs_stats, noise, alpha):
        xp = self.xp
        observations = batch["observations"]
        dist = self.model.actor(observations, obs_stats, v=actor_v)
        raw = dist.sample_raw(noise)
        log_probs = dist.log_prob_raw(raw)
        q = self.model.q(critic_v, observations, dist.squash(raw), obs_stats)
        loss = xp.mean(alpha * log_probs - xp.min(q, axis=0))
        return loss, {"entropy": xp.stop_gradient(-xp.mean(log_probs))}

    def step(self, v, targets, states, batch, obs_stats, x, rates):
        xp = self.xp
        alpha = xp.stop_gradient(xp.exp(v["temperature"]["log_alpha"]))
        critic_v = v["critic"]
        v, states, infos = self._step_part(
            lambda w: self.loss(w, critic_v, batch, obs_stats, x["noise"], alpha),
            v,
            states,
            rates,
        )
        gap = xp.stop_gradient(self.entropy_target - infos["entropy"])
        temperature_v, temperature_state, _ = self._minimize_with(
            self.temperature_optimizer,
            lambda w: -w["log_alpha"] * gap,
            v["temperature"],
            states["temperature"],
            rates.get("temperature_lr"),
        )
        v = {**v, "temperature": temperature_v}
        states = {**states, "temperature": temperature_state}
        return v, states, {**infos, "temperature": xp.exp(temperature_v["log_alpha"])}


class MaximumAPosterioriPolicyOptimization(OffPolicyUpdater):
    """MPO's actor updater, with its dual variables: for each state, ``num_samples`` actions of
    the target policy are weighted by ``softmax(Q'(s, a_j) / η)`` (the E-step, the temperature
    η found by its dual under the KL bound ``epsilon``); the policy fits them by maximum
    likelihood (the M-step), its mean and its scale separately, each under a per-dimension KL
    bound to the target policy (``epsilon_mean``, ``epsilon_std``) kept by Lagrange
    multipliers.

    Args:
        lr: the actor's Adam learning rate.
        gradient_clip: global norm of the actor's gradients (0: no clipping).
        num_samples: actions sampled per state.
        epsilon: KL bound of the E-step.
        epsilon_mean, epsilon_std: per-dimension KL bounds of the mean and the scale.
        initial_log_temperature, initial_log_alpha_mean, initial_log_alpha_std: initial duals
            (before a softplus).
        min_log_dual: lower bound of the duals.
        dual_lr: Adam learning rate of the duals.

    Example:
        >>> updater = ivy_rl.off_policy_updaters.MaximumAPosterioriPolicyOptimization(epsilon=0.1)
        >>> agent = ivy_rl.agents.MPO(actor_updater=updater)
    """

    settings = {
        **OffPolicyUpdater.settings,
        "num_samples": _s.Setting("int", 1, meaning="actions sampled per state"),
        "epsilon": _s.Setting("float", 0.0, open_low=True, meaning="E-step's KL bound"),
        "epsilon_mean": _s.Setting("float", 0.0, open_low=True, meaning="KL bound of the mean"),
        "epsilon_std": _s.Setting("float", 0.0, open_low=True, meaning="KL bound of the scale"),
        "initial_log_temperature": _s.Setting("float", meaning="initial temperature dual"),
        "initial_log_alpha_mean": _s.Setting("float", meaning="initial dual of the mean"),
        "initial_log_alpha_std": _s.Setting("float", meaning="initial dual of the scale"),
        "min_log_dual": _s.Setting("float", meaning="lower bound of the duals"),
        "dual_lr": _s.Setting("schedule", 0.0, open_low=True, meaning="duals' learning rate"),
    }

    def __init__(
        self,
        lr: Any = 3e-4,
        gradient_clip: float = 0.0,
        num_samples: int = 20,
        epsilon: float = 0.1,
        epsilon_mean: float = 1e-3,
        epsilon_std: float = 1e-6,
        initial_log_temperature: float = 1.0,
        initial_log_alpha_mean: float = 1.0,
        initial_log_alpha_std: float = 10.0,
        min_log_dual: float = -18.0,
        dual_lr: Any = 1e-2,
    ) -> None:
        super().__init__(lr, gradient_clip)
        as_schedule(dual_lr, name="MaximumAPosterioriPolicyOptimization: dual_lr")
        self.num_samples, self.epsilon = int(num_samples), epsilon
        self.epsilon_mean, self.epsilon_std = epsilon_mean, epsilon_std
        self.initial_log_temperature = initial_log_temperature
        self.initial_log_alpha_mean = initial_log_alpha_mean
        self.initial_log_alpha_std = initial_log_alpha_std
        self.min_log_dual, self.dual_lr = min_log_dual, dual_lr

    def initialize(self, xp, model=None, *, dtype=None, device=None):
        super().initialize(xp, model, dtype=dtype, device=device)
        self.dual_optimizer = ivy.Adam(as_schedule(self.dual_lr)(0.0), f=xp)
        return self

    def variables(self):
        xp, build = self.xp, {"dtype": self.dtype, "device": self.device}
        size = self.model.action_size
        return {
            "dual": {
                "log_temperature": xp.asarray(self.initial_log_temperature, **build),
                "log_alpha_mean": xp.full((size,), self.initial_log_alpha_mean, **build),
                "log_alpha_std": xp.full((size,), self.initial_log_alpha_std, **build),
            }
        }

    def optimizers(self):
        return {"actor": self.optimizer, "dual": self.dual_optimizer}

    def draw(self, rng, iterations, batch_size):
        shape = (iterations, self.num_samples, batch_size, self.model.action_size)
        return {"noise": self._normal(rng, shape)}

    def loss(self, w, target_dist, actions, weights_logits, batch, obs_stats):
        xp = self.xp
        samples = int(actions.shape[0])
        dual = w["dual"]
        temperature = xp.softplus(dual["log_temperature"]) + 1e-8
        alpha_mean = xp.softplus(dual["log_alpha_mean"]) + 1e-8
        alpha_std = xp.softplus(dual["log_alpha_std"]) + 1e-8
        # E-step: the temperature's dual and the weights of the sampled actions
        scaled = weights_logits / temperature
        weights = xp.stop_gradient(xp.softmax(scaled, axis=0))
        log_mean_exp = xp.logsumexp(scaled, axis=0) - math.log(samples)
        temperature_loss = temperature * (self.epsilon + xp.mean(log_mean_exp))
        # M-step: the mean and the scale fitted separately (the other one from the target)
        dist = self.model.actor(batch["observations"], obs_stats, v=w["actor"])
        loc, scale = dist.loc, dist.scale
        target_loc, target_scale = target_dist.loc, target_dist.scale
        fixed_scale = _gaussian_log_prob(xp, actions, loc[None], target_scale[None])
        fixed_loc = _gaussian_log_prob(xp, actions, target_loc[None], scale[None])
        loss_mean = -xp.mean(xp.sum(weights * fixed_scale, axis=0))
        loss_std = -xp.mean(xp.sum(weights * fixed_loc, axis=0))
        # per-dimension KL(target || fitted), averaged over the batch: [actions]
        kl_mean = xp.mean(xp.square(target_loc - loc) / (2.0 * xp.square(target_scale)), axis=0)
        ratio = xp.square(target_scale / scale)
        kl_std = xp.mean(0.5 * (ratio - 1.0 - xp.log(ratio)), axis=0)
        alpha_mean_loss = xp.sum(alpha_mean * (self.epsilon_mean - xp.stop_gradient(kl_mean)))
        alpha_std_loss = xp.sum(alpha_std * (self.epsilon_std - xp.stop_gradient(kl_std)))
        policy_loss = (
            loss_mean
            + loss_std
            + xp.sum(xp.stop_gradient(alpha_mean) * kl_mean)
            + xp.sum(xp.stop_gradient(alpha_std) * kl_std)
        )
        total = policy_loss + temperature_loss + alpha_mean_loss + alpha_std_loss
        infos = {
            "loss": policy_loss,
            "temperature": temperature,
            "kl_mean": xp.sum(kl_mean),
            "kl_std": xp.sum(kl_std),
        }
        return total, infos

    def step(self, v, targets, states, batch, obs_stats, x, rates):
        xp = self.xp
        actions, values, target_dist = sampled_values(
            self.model,
            targets["actor"],
            targets["critic"],
            batch["observations"],
            x["noise"],
            obs_stats,
        )
        actions, values = xp.stop_gradient(actions), xp.stop_gradient(values)
        parts = {"actor": v["actor"], "dual": v["dual"]}
        _, grads, infos = xp.execute_with_gradients(
            lambda w: self.loss(w, target_dist, actions, values, batch, obs_stats), parts
        )
        clip = self.gradient_clip
        actor_grads = xp.clip_by_global_norm(grads["actor"], clip)[0] if clip else grads["actor"]
        actor_v, actor_state = at_rate(self.optimizer, rates.get("lr")).step(
            v["actor"], actor_grads, states["actor"]
        )
        dual_v, dual_state = at_rate(self.dual_optimizer, rates.get("dual_lr")).step(
            v["dual"], grads["dual"], states["dual"]
        )
        dual_v = {k: xp.maximum(a, self.min_log_dual) for k, a in dual_v.items()}
        v = {**v, "actor": actor_v, "dual": dual_v}
        states = {**states, "actor": actor_state, "dual": dual_state}
        return v, states, infos


def sampled_values(model, actor_v, critic_v, observations, noise, obs_stats):
    """Actions sampled (clipped to ``[-1, 1]``) from the Gaussian policy of ``actor_v``
    ``[samples, batch, actions]`` given standard normal ``noise``, their values under
    ``critic_v`` ``[samples, batch]``, and the policy."""
    xp = model.xp
    dist = model.actor(observations, obs_stats, v=actor_v)
    actions = xp.clip(dist.loc[None] + dist.scale[None] * noise, -1.0, 1.0)
    samples = int(noise.shape[0])
    tiled = xp.broadcast_to(observations[None], (samples, *tuple(observations.shape)))
    return actions, model.q(critic_v, tiled, actions, obs_stats), dist


def _gaussian_log_prob(xp, actions, loc, scale):
    """Log-density of a diagonal Gaussian, summed over the last axis."""
    z = (actions - loc) / scale
    per_dim = -0.5 * xp.square(z) - xp.log(scale) - 0.5 * math.log(2.0 * math.pi)
    return xp.sum(per_dim, axis=-1)


# ----------------------------------------------------------------------------------------------
# Critic updaters
# ----------------------------------------------------------------------------------------------


class DeterministicQLearning(OffPolicyUpdater):
    """DDPG's critic updater: regression of ``Q(s, a)`` on ``R + γ^k Q'(s', π'(s'))`` (the
    target networks; ``γ^k`` is 0 after a termination), mean squared error.

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).

    Example:
        >>> updater = ivy_rl.off_policy_updaters.DeterministicQLearning(lr=1e-3)
        >>> agent = ivy_rl.agents.DDPG(critic_updater=updater)
    """

    part = "critic"

    def __init__(self, lr: Any = 1e-3, gradient_clip: float = 0.0) -> None:
        super().__init__(lr, gradient_clip)

    def next_values(self, v, targets, batch, obs_stats, x):
        """``Q'(s', π'(s'))`` of the target networks ``[batch]``."""
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        return self.model.q(targets["critic"], following, actions, obs_stats)

    def goal(self, v, targets, batch, obs_stats, x):
        """What the critic regresses on (constants)."""
        next_values = self.next_values(v, targets, batch, obs_stats, x)
        return self.xp.stop_gradient(batch["returns"] + batch["discounts"] * next_values)

    def loss(self, critic_v, batch, goal, obs_stats):
        values = self.model.q(critic_v, batch["observations"], batch["actions"], obs_stats)
        return self.xp.mean(self.xp.square(values - goal))

    def step(self, v, targets, states, batch, obs_stats, x, rates):
        goal = self.goal(v, targets, batch, obs_stats, x)
        v, states, infos = self._step_part(
            lambda w: self.loss(w, batch, goal, obs_stats), v, states, rates
        )
        return v, states, {"loss": infos["loss"]}


class TwinCriticDeterministicQLearning(DeterministicQLearning):
    """TD3's critic updater: the target is the smaller of the twin target critics' values at
    the target policy's action smoothed by clipped Gaussian noise.

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).
        target_noise: scale of the target policy's smoothing noise.
        target_noise_clip: bound of that noise.

    Example:
        >>> updater = ivy_rl.off_policy_updaters.TwinCriticDeterministicQLearning(
        ...     target_noise=0.2, target_noise_clip=0.5)
        >>> agent = ivy_rl.agents.TD3(critic_updater=updater)
    """

    settings = {
        **OffPolicyUpdater.settings,
        "target_noise": _s.Setting("float", 0.0, meaning="target smoothing noise"),
        "target_noise_clip": _s.Setting("float", 0.0, meaning="bound of the target noise"),
    }

    def __init__(
        self,
        lr: Any = 1e-3,
        gradient_clip: float = 0.0,
        target_noise: float = 0.2,
        target_noise_clip: float = 0.5,
    ) -> None:
        super().__init__(lr, gradient_clip)
        self.target_noise, self.target_noise_clip = target_noise, target_noise_clip

    def draw(self, rng, iterations, batch_size):
        return {"noise": self._normal(rng, (iterations, batch_size, self.model.action_size))}

    def next_values(self, v, targets, batch, obs_stats, x):
        xp = self.xp
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        smoothing = xp.clip(
            self.target_noise * x["noise"], -self.target_noise_clip, self.target_noise_clip
        )
        actions = xp.clip(actions + smoothing, -1.0, 1.0)
        return xp.min(self.model.q(targets["critic"], following, actions, obs_stats), axis=0)


class DistributionalDeterministicQLearning(DeterministicQLearning):
    """D4PG's critic updater: the target critic's distribution at ``(s', π'(s'))``, shifted
    by the n-step return, scaled by the discount and projected onto the atoms
    (:func:`ivy_rl.critics.project_categorical`); cross-entropy."""

    def goal(self, v, targets, batch, obs_stats, x):
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        values = self.model.q(targets["critic"], following, actions, obs_stats)
        projected = project_categorical(
            self.xp, values.probs(), batch["returns"], batch["discounts"], values.support
        )
        return self.xp.stop_gradient(projected)

    def loss(self, critic_v, batch, goal, obs_stats):
        values = self.model.q(critic_v, batch["observations"], batch["actions"], obs_stats)
        return -self.xp.mean(self.xp.sum(goal * values.logits, axis=-1))


class TwinCriticSoftQLearning(DeterministicQLearning):
    """SAC's critic updater: the soft target ``R + γ^k (min_i Q'_i(s', a') - α log π(a'|s'))``
    with ``a' ~ π(s')`` of the current policy and α of the actor updater's temperature
    (``v['temperature']``)."""

    def draw(self, rng, iterations, batch_size):
        shape = (iterations, batch_size, self.model.action_size)
        return {"next_noise": self._normal(rng, shape)}

    def next_values(self, v, targets, batch, obs_stats, x):
        xp = self.xp
        following = batch["next_observations"]
        dist = self.model.actor(following, obs_stats, v=v["actor"])
        raw = dist.sample_raw(x["next_noise"])
        log_probs = dist.log_prob_raw(raw)
        values = self.model.q(targets["critic"], following, dist.squash(raw), obs_stats)
        alpha = xp.stop_gradient(xp.exp(v["temperature"]["log_alpha"]))
        return xp.min(values, axis=0) - alpha * log_probs


class ExpectedSARSA(DeterministicQLearning):
    """MPO's critic updater: the target ``R + γ^k mean_j Q'(s', a'_j)`` over ``num_samples``
    actions of the target policy.

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).
        num_samples: actions sampled per next state.
    """

    settings = {
        **OffPolicyUpdater.settings,
        "num_samples": MaximumAPosterioriPolicyOptimization.settings["num_samples"],
    }

    def __init__(self, lr: Any = 3e-4, gradient_clip: float = 0.0, num_samples: int = 20) -> None:
        super().__init__(lr, gradient_clip)
        self.num_samples = int(num_samples)

    def draw(self, rng, iterations, batch_size):
        shape = (iterations, self.num_samples, batch_size, self.model.action_size)
        return {"next_noise": self._normal(rng, shape)}

    def next_values(self, v, targets, batch, obs_stats, x):
        _, values, _ = sampled_values(
            self.model,
            targets["actor"],
            targets["critic"],
            batch["next_observations"],
            x["next_noise"],
            obs_stats,
        )
        return self.xp.mean(values, axis=0)


class QLearning(DeterministicQLearning):
    """DQN's updater: the Q-network's chosen values regress, by a Huber loss, on
    ``R + γ^k mean_d Q'_d(s', argmax_a Q_d(s', a))`` (``double``: the online network chooses,
    the target evaluates) or ``R + γ^k mean_d max_a Q'_d(s', a)``; a Discrete space is one
    branch ``d``.

    Args:
        lr: Adam's learning rate.
        gradient_clip: global norm of the gradients (0: no clipping).
        double: double Q-learning targets.

    Example:
        >>> updater = ivy_rl.off_policy_updaters.QLearning(lr=1e-3, double=False)
        >>> ivy_rl.agents.DQN(updater=updater).config["double"]
        False
    """

    settings = {**OffPolicyUpdater.settings, "double": _s.Setting("bool", meaning="double Q")}

    part = "q"

    def __init__(self, lr: Any = 1e-3, gradient_clip: float = 0.0, double: bool = True) -> None:
        super().__init__(lr, gradient_clip)
        self.double = bool(double)

    def next_values(self, v, targets, batch, obs_stats, x):
        xp, model = self.xp, self.model
        following = batch["next_observations"]
        target_branches = model.branches(targets["q"], following, obs_stats)
        if self.double:
            online = model.branches(v["q"], following, obs_stats)
            values = [
                xp.sum(
                    xp.one_hot(xp.argmax(o, axis=-1), int(t.shape[-1]), dtype=t.dtype) * t,
                    axis=-1,
                )
                for o, t in zip(online, target_branches)
            ]
        else:
            values = [xp.max(t, axis=-1) for t in target_branches]
        return xp.mean(xp.stack(values), axis=0)

    def loss(self, q_v, batch, goal, obs_stats):
        xp, model = self.xp, self.model
        branches = model.branches(q_v, batch["observations"], obs_stats)
        losses = []
        for values, actions in zip(branches, model.branch_actions(batch["actions"])):
            chosen = xp.one_hot(actions, int(values.shape[-1]), dtype=values.dtype)
            error = xp.sum(chosen * values, axis=-1) - goal
            size = xp.abs(error)
            losses.append(xp.mean(xp.where(size < 1.0, 0.5 * xp.square(error), size - 0.5)))
        return xp.mean(xp.stack(losses))
