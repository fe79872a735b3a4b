"""A2C: advantage actor-critic (also called vanilla policy gradient), the base of PPO and TRPO.

Each update uses one segment of ``segment_size`` steps of every worker: the critic evaluates
the observations and the true next observations, λ-returns and advantages follow with
partial-episode bootstrapping, then the actor and the critic are trained by
``ivy.compile_fn``-compiled iterations (one function per agent holding the losses, gradients
and optimiser updates of both models).

Example:
    >>> agent = A2C(segment_size=128).initialize(env.observation_space, env.action_space,
    ...                                         seed=0, f="torch")
"""

from __future__ import annotations

from typing import Any

import numpy as np

import ivy
from ivy_rl import updaters
from ivy_rl.agents.agent import Agent
from ivy_rl.models import actor_critic
from ivy_rl.normalizers import MeanStd, ReturnNormalizer
from ivy_rl.replays import Segment

__all__ = ["A2C"]


class A2C(Agent):
    """Advantage actor-critic (Mnih et al., 2016) in Tonic's form: one actor step on the whole
    segment, then ``critic_iterations`` passes of value regression on the λ-returns.

    Args:
        hidden_sizes: hidden sizes of the actor's torso.
        critic_hidden_sizes: of the critic's torso (default: ``hidden_sizes``).
        activation: activation of the torsos.
        head: policy head (``'gaussian'``, ``'squashed_gaussian'`` for Box;
            ``'categorical'`` for Discrete); default by action space.
        log_std_init: initial log standard deviation of Gaussian heads.
        segment_size: steps per worker between updates.
        discount: γ.
        trace_decay: λ of the λ-returns.
        actor_lr, critic_lr: Adam learning rates.
        critic_iterations: passes of critic regression per update.
        batch_size: transitions per critic mini-batch (None: the whole segment).
        entropy_coeff: weight of the entropy bonus.
        gradient_clip: global norm of gradients (0: no clipping).
        normalize_observations: normalise observations by their running mean and std.
        normalize_returns: the critic predicts returns normalised by their running mean and std.
        normalize_advantages: standardise the advantages of each segment.

    Example:
        >>> A2C(segment_size=64, actor_lr=1e-3)
    """

    learns = True
    _defaults: dict[str, Any] = dict(
        hidden_sizes=(64, 64),
        critic_hidden_sizes=None,
        activation="tanh",
        head=None,
        log_std_init=0.0,
        segment_size=256,
        discount=0.99,
        trace_decay=0.95,
        actor_lr=3e-4,
        critic_lr=1e-3,
        critic_iterations=40,
        batch_size=None,
        entropy_coeff=0.0,
        gradient_clip=0.0,
        normalize_observations=True,
        normalize_returns=False,
        normalize_advantages=True,
    )

    _unused: tuple[str, ...] = ()

    def __init__(self, **settings: Any) -> None:
        config = {}
        for cls in reversed(type(self).__mro__):
            config.update(getattr(cls, "_defaults", {}))
        for key in self._unused:
            config.pop(key, None)
        unknown = sorted(set(settings) - set(config))
        if unknown:
            raise TypeError(
                f"{type(self).__name__} got unknown settings {unknown}; its settings are "
                f"{sorted(config)}"
            )
        config.update(settings)
        super().__init__(**config)

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _build(self) -> None:
        c = self.config
        xp = self.xp
        self.model = actor_critic(
            self.observation_space,
            self.action_space,
            rng=self.rng,
            actor_sizes=tuple(c["hidden_sizes"]),
            critic_sizes=tuple(c["critic_hidden_sizes"] or c["hidden_sizes"]),
            activation=c["activation"],
            head=c["head"],
            log_std_init=c["log_std_init"],
            dtype=self.dtype,
            f=xp,
        )
        if c["head"] == "deterministic":
            raise ValueError(
                f"{type(self).__name__} needs a stochastic policy head (log-probabilities); "
                "choose 'gaussian' or 'squashed_gaussian'"
            )
        self.v = self.model.v
        self.actor_optimizer = ivy.Adam(c["actor_lr"], f=xp)
        self.critic_optimizer = ivy.Adam(c["critic_lr"], f=xp)
        self.optimizer_states = {
            "actor": self.actor_optimizer.init(self.v["actor"]),
            "critic": self.critic_optimizer.init(self.v["critic"]),
        }
        obs_size = int(np.prod(self.observation_space.shape))
        self.observation_normalizer = MeanStd((obs_size,)) if c["normalize_observations"] else None
        self.return_normalizer = ReturnNormalizer() if c["normalize_returns"] else None
        self.replay = Segment(
            c["segment_size"],
            discount=c["discount"],
            trace_decay=c["trace_decay"],
            batch_size=c["batch_size"],
            batch_iterations=self._passes(),
        )
        self._noise_shape = (
            (int(self.action_space.n),)
            if self.action_kind == "Discrete"
            else self.action_space.shape
        )
        self._pending: dict[str, np.ndarray] | None = None
        self.updates = 0
        self._refresh_stats()
        self._act = self._compile(self._act_fn)
        self._mode = self._compile(self._mode_fn)
        self._values = self._compile(self._values_fn)
        self._build_learning()

    def _passes(self) -> int:
        """Passes over a segment per update."""
        return self.config["critic_iterations"]

    def _build_learning(self) -> None:
        self._train_actor_critic = self._compile(self._actor_critic_iteration)
        self._train_critic = self._compile(self._critic_iteration)

    def _refresh_stats(self) -> None:
        """The normalisers' statistics as arrays of the framework, for the model's calls."""
        xp = self.xp

        def convert(norm):
            if norm is None:
                return None
            return {k: xp.asarray(a) for k, a in norm.stats(self.dtype).items()}

        self.stats = {
            "obs": convert(self.observation_normalizer),
            "ret": convert(self.return_normalizer),
        }

    # ------------------------------------------------------------------------------------------
    # Pure functions (compiled)
    # ------------------------------------------------------------------------------------------

    def _act_fn(self, actor_v, obs_stats, observations, noise):
        dist = self.model.actor(observations, obs_stats, v=actor_v)
        raw = dist.sample_raw(noise)
        out = {"actions": raw, "log_probs": dist.log_prob_raw(raw), "unit": dist.raw_to_action(raw)}
        out.update({f"dist_{k}": p for k, p in dist.params().items()})
        return out

    def _mode_fn(self, actor_v, obs_stats, observations):
        return self.model.actor(observations, obs_stats, v=actor_v).mode()

    def _values_fn(self, critic_v, stats, observations):
        return self.model.critic(observations, stats["obs"], stats["ret"], v=critic_v)

    def _minimize(self, name, loss_fn, v, state):
        """Gradients of ``loss_fn`` (returning ``(loss, infos)``), clipped, and an Adam step."""
        xp = self.xp
        optimizer = self.actor_optimizer if name == "actor" else self.critic_optimizer
        loss, grads, infos = xp.execute_with_gradients(loss_fn, v)
        clip = self.config["gradient_clip"]
        if clip:
            grads = xp.clip_by_global_norm(grads, clip)[0]
        new_v, new_state = optimizer.step(v, grads, state)
        return new_v, new_state, {"loss": loss, **infos}

    def _critic_loss(self, critic_v, stats, batch):
        xp = self.xp
        targets = batch["returns"]
        if stats["ret"] is not None:
            targets = (targets - stats["ret"]["mean"]) / stats["ret"]["std"]
        predictions = self.model.critic.normalized(critic_v, batch["observations"], stats["obs"])
        return updaters.value_loss(xp, predictions, targets), {}

    def _actor_loss(self, actor_v, stats, batch):
        dist = self.model.actor(batch["observations"], stats["obs"], v=actor_v)
        return updaters.policy_gradient_loss(
            self.xp, dist, batch["actions"], batch["advantages"], self.config["entropy_coeff"]
        )

    def _select(self, batch, indices):
        xp = self.xp
        return {k: xp.take(a, indices, axis=0) for k, a in batch.items()}

    def _critic_iteration(self, v, states, stats, batch, indices):
        part = self._select(batch, indices)
        critic_v, critic_state, infos = self._minimize(
            "critic",
            lambda w: self._critic_loss(w, stats, part),
            v["critic"],
            states["critic"],
        )
        new_v = {"actor": v["actor"], "critic": critic_v}
        new_states = {"actor": states["actor"], "critic": critic_state}
        return new_v, new_states, {f"critic/{k}": x for k, x in infos.items()}

    def _actor_critic_iteration(self, v, states, stats, batch, indices):
        part = self._select(batch, indices)
        actor_v, actor_state, actor_infos = self._minimize(
            "actor", lambda w: self._actor_loss(w, stats, part), v["actor"], states["actor"]
        )
        critic_v, critic_state, critic_infos = self._minimize(
            "critic",
            lambda w: self._critic_loss(w, stats, part),
            v["critic"],
            states["critic"],
        )
        infos = {f"actor/{k}": x for k, x in actor_infos.items()}
        infos.update({f"critic/{k}": x for k, x in critic_infos.items()})
        new_v = {"actor": actor_v, "critic": critic_v}
        return new_v, {"actor": actor_state, "critic": critic_state}, infos

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _noise(self, count: int) -> np.ndarray:
        shape = (count,) + tuple(self._noise_shape)
        if self.action_kind == "Discrete":
            return self.rng.gumbel(size=shape).astype(self.np_dtype)
        return self.rng.standard_normal(shape).astype(self.np_dtype)

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        xp = self.xp
        obs = self._observations(observations)
        noise = self._noise(obs.shape[0])
        out = self._act(self.v["actor"], self.stats["obs"], xp.asarray(obs), xp.asarray(noise))
        out = {k: np.asarray(xp.to_numpy(a)) for k, a in out.items()}
        self._pending = {
            "observations": obs,
            "actions": out["actions"],
            "log_probs": out["log_probs"],
            **{k: a for k, a in out.items() if k.startswith("dist_")},
        }
        return self._env_actions(out["unit"])

    def test_step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        xp = self.xp
        obs = self._observations(observations)
        mode = self._mode(self.v["actor"], self.stats["obs"], xp.asarray(obs))
        return self._env_actions(np.asarray(xp.to_numpy(mode)))

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def update(self, observations, rewards, resets, terminations) -> dict[str, float]:
        self._check_initialized()
        if self._pending is None:
            raise RuntimeError(f"{type(self).__name__}.update called before step")
        next_obs = self._observations(observations)
        self.replay.store(
            **self._pending,
            next_observations=next_obs,
            rewards=np.asarray(rewards, np.float64),
            resets=np.asarray(resets, bool),
            terminations=np.asarray(terminations, bool),
        )
        if self.observation_normalizer is not None:
            self.observation_normalizer.record(self._pending["observations"])
        self._pending = None
        if not self.replay.ready():
            return {}
        logs = self._learn()
        self.replay.clear()
        self.updates += 1
        return logs

    def _evaluate(self) -> None:
        """Values of the segment's observations and next observations, then the returns."""
        xp = self.xp
        b = self.replay.buffers
        size, workers = b["rewards"].shape
        obs = np.concatenate(
            [
                b["observations"].reshape(size * workers, -1),
                b["next_observations"].reshape(size * workers, -1),
            ]
        )
        values = np.asarray(
            xp.to_numpy(self._values(self.v["critic"], self.stats, xp.asarray(obs)))
        )
        values = values.astype(np.float64)
        self.replay.compute_returns(values[: size * workers], values[size * workers :])
        if self.return_normalizer is not None:
            self.return_normalizer.record(b["returns"])
            self.return_normalizer.update()
            self._refresh_stats()

    def _device_batch(self, *keys: str) -> dict[str, Any]:
        xp = self.xp
        full = self.replay.get_full(*keys, normalize_advantages=self.config["normalize_advantages"])
        out = {}
        for key, value in full.items():
            if value.dtype.kind == "f":
                value = value.astype(self.np_dtype)
            elif value.dtype.kind in "iu":
                value = value.astype(np.int32)  # jax without 64-bit types has no int64
            out[key] = xp.asarray(value)
        return out

    def _all_indices(self) -> Any:
        return self.xp.asarray(np.arange(self.replay.size * self.replay.workers, dtype=np.int32))

    def _learn(self) -> dict[str, float]:
        self._evaluate()
        batch = self._device_batch("observations", "actions", "advantages", "returns")
        logs = _Logs()
        v, states = self.v, self.optimizer_states
        v, states, infos = self._train_actor_critic(
            v, states, self.stats, batch, self._all_indices()
        )
        logs.add(infos)
        for indices in self.replay.batch_indices(self.rng):
            idx = (
                self._all_indices()
                if indices is None
                else self.xp.asarray(indices.astype(np.int32))
            )
            v, states, infos = self._train_critic(v, states, self.stats, batch, idx)
            logs.add(infos)
        self.v, self.optimizer_states = v, states
        self._after_learning()
        return logs.means(self.xp)

    def _after_learning(self) -> None:
        if self.observation_normalizer is not None:
            self.observation_normalizer.update()
        self._refresh_stats()

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        arrays: dict[str, Any] = {"v": self.v, "optimizer": self.optimizer_states}
        if self.observation_normalizer is not None:
            arrays["observation_normalizer"] = self.observation_normalizer.state_dict()
        if self.return_normalizer is not None:
            arrays["return_normalizer"] = self.return_normalizer.state_dict()
        arrays["replay"] = {k.replace("/", "."): a for k, a in self.replay.state_dict().items()}
        if self._pending is not None:
            arrays["pending"] = dict(self._pending)
        return arrays

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        self.v = self._to_backend(arrays["v"], self.v)
        self.optimizer_states = self._to_backend(arrays["optimizer"], self.optimizer_states)
        for name in ("observation_normalizer", "return_normalizer"):
            norm = getattr(self, name)
            if norm is not None:
                norm.load_state_dict(arrays[name])
        self.replay.load_state_dict(
            {k.replace(".", "/", 1): a for k, a in arrays["replay"].items()}
        )
        self._pending = dict(arrays["pending"]) if "pending" in arrays else None
        self._refresh_stats()

    def _meta(self) -> dict[str, Any]:
        return {"updates": self.updates}

    def _load_meta(self, meta: dict[str, Any]) -> None:
        self.updates = int(meta.get("updates", 0))


class _Logs:
    """Per-iteration scalars of an update, kept on the device until the update ends."""

    def __init__(self) -> None:
        self.values: dict[str, list] = {}

    def add(self, infos: dict[str, Any]) -> None:
        for key, value in infos.items():
            self.values.setdefault(key, []).append(value)

    def means(self, xp: Any) -> dict[str, float]:
        out = {}
        for key, values in self.values.items():
            out[key] = float(np.mean([np.asarray(xp.to_numpy(x)) for x in values]))
            prefix = key.split("/")[0]
            out.setdefault(f"{prefix}/iterations", float(len(values)))
        return out
