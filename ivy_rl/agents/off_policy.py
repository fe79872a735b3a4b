"""What the off-policy agents share: a transition replay in the backend's arrays, exploration on
the host, target networks, and an update that is one compiled function.

Every ``update_every`` environment steps (after ``update_after``), the agent writes its staged
transitions into the replay's arrays and runs ``batch_iterations`` optimisation steps. Their
numbers are one pure function of arrays, :meth:`OffPolicyAgent._update_fn` (the variables, the
targets, the optimiser states, the replay's arrays, the observation statistics, and the batches'
indices and noise drawn from the agent's numpy generator): an ``ivy.scan`` over the steps, each
reading its n-step transitions from the replay (:func:`ivy_rl.buffers.n_step_batch`) and making
the agent's step (:meth:`OffPolicyAgent._learn_step`). The fusion rule is that of the on-policy
agents (:mod:`ivy_rl.agents.fusion`): ``'update'`` compiles the whole scan where the backend
compiles loops as loops (``compiled_loops``), ``'steps'`` compiles one step and loops on the host
where the compiler would unroll the scan; both give the same numbers as running eagerly.

An agent is its parts, as in Tonic (:attr:`~ivy_rl.agents.Agent.parts`): a ``model``
(:mod:`ivy_rl.off_policy_models`: the networks, how they act, which have targets), a ``replay``
(:class:`ivy_rl.replays.Transitions`: the ring and when to learn from it), an ``exploration``
(:mod:`ivy_rl.explorations`, on the host) and updaters (:mod:`ivy_rl.off_policy_updaters`:
``critic_updater`` then ``actor_updater``, or DQN's ``updater``), each given to the constructor
or built from the flat settings. Each optimisation step reads its batch, runs each updater's
step and moves the targets (:meth:`OffPolicyAgent._learn_step`); a subclass is its ``parts``
table and what differs (TD3: the grouping of its critic steps).
"""

from __future__ import annotations

from typing import Any

import numpy as np

import ivy
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.fusion import FUSION, check_fusion, fusion_level
from ivy_rl.buffers import n_step_batch
from ivy_rl.models import polyak_update
from ivy_rl.normalizers import MeanStd

__all__ = ["OffPolicyAgent"]


class OffPolicyAgent(Agent):
    """Base of the off-policy agents (DDPG, TD3, SAC, MPO, D4PG, DQN).

    The settings they share are those of the parts they share (the model's torsos, the
    replay, the targets' soft updates, the updaters' learning rates and clipping), each declared
    once by its part (:mod:`ivy_rl.settings`), and ``fusion`` (:mod:`ivy_rl.agents.fusion`):
    ``DDPG.settings()``, ``python -m ivy_rl.agents.defaults DDPG Pendulum-v1`` list them.
    """

    learns = True
    scheduled: tuple[str, ...] = ("actor_lr", "critic_lr")
    own_settings = {"fusion": FUSION}
    #: the off-policy agents' defaults where they differ from their parts'
    _defaults: dict[str, Any] = dict(start_steps=1000, fusion="auto")

    #: the parts' roles and the prefix of their logs
    _updater_logs: dict[str, str] = {"critic_updater": "critic", "actor_updater": "actor"}

    def __init__(self, **settings: Any) -> None:
        config, parts = self._composed(settings)
        check_fusion(type(self).__name__, config["fusion"])
        self._check_config(config)
        for role, part in parts.items():
            setattr(self, role, part)
        self._parts = parts
        super().__init__(**config)

    def _check_config(self, config: dict[str, Any]) -> None:
        """Checks of settings that depend on each other (subclasses add theirs)."""

    @property
    def _updaters(self) -> dict[str, Any]:
        """The updaters by role, in the order of their steps."""
        return {role: self._parts[role] for role in self._updater_logs}

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _build(self) -> None:
        xp, model = self.xp, self.model
        self.observation_size = int(np.prod(self.observation_space.shape))
        model.initialize(
            self.observation_space,
            self.action_space,
            rng=self.rng,
            dtype=self.dtype,
            device=self.device,
            f=xp,
        )
        v = dict(model.v)
        self.optimizers: dict[str, Any] = {}
        for updater in self._updaters.values():
            updater.initialize(xp, model, dtype=self.dtype, device=self.device)
            v.update(updater.variables())
            self.optimizers.update(updater.optimizers())
        # the optimisers in the order of the variables (the checkpoints' layout)
        self.optimizers = {k: self.optimizers[k] for k in v if k in self.optimizers}
        self.v = self._placed(v)
        self.targets = self._placed(dict(model.target_v))
        self.optimizer_states = {k: opt.init(self.v[k]) for k, opt in self.optimizers.items()}
        normalize = model.normalize_observations
        self.observation_normalizer = MeanStd((self.observation_size,)) if normalize else None
        self._pending: dict[str, np.ndarray] | None = None
        self.steps = self.updates = self._since_update = 0
        self._refresh_stats()
        self._act = self._compile(self._act_fn, "act")
        self._mode = self._compile(self._mode_fn, "mode")
        self.fusion = fusion_level(self.config["fusion"], compiled=self.compiled, f=xp)
        self._fused = self.fusion == "update"
        if self._fused:
            self._update = self._compile(self._update_fn, "update")
        else:
            self._update = self._update_fn
            self._compiled_step = self._compile(self._scan_step, "learn_step")

    def _refresh_stats(self) -> None:
        norm = self.observation_normalizer
        self.obs_stats = (
            None
            if norm is None
            else {k: self._asarray(a) for k, a in norm.stats(self.dtype).items()}
        )

    # ------------------------------------------------------------------------------------------
    # Pure functions (compiled)
    # ------------------------------------------------------------------------------------------

    def _act_fn(self, v, obs_stats, observations, noise):
        """Actions of the behaviour policy (before the host's exploration)."""
        return self.model.act(v, obs_stats, observations, noise)

    def _mode_fn(self, v, obs_stats, observations):
        """Actions of the test policy."""
        return self.model.mode(v, obs_stats, observations)

    def _update_fn(self, carry, xs, arrays, obs_stats, scheduled):
        """The whole update: ``(carry, logs)`` after the steps of ``xs`` (leading axis: the
        optimisation steps), ``carry = {'v', 'targets', 'states'}``; ``scheduled``: the
        scheduled settings' values (scalar arrays, :meth:`Agent.set_progress`)."""
        xp = self.xp
        if self._fused:
            carry, ys = xp.scan(
                lambda c, x: self._scan_step(c, x, arrays, obs_stats, scheduled), carry, xs
            )
        else:
            steps = int(ivy.nest.flatten_nest(xs)[0][0].shape[0])
            outs = []
            for i in range(steps):
                x = ivy.nest.map_nest(lambda a, i=i: a[i], xs)
                carry, y = self._compiled_step(carry, x, arrays, obs_stats, scheduled)
                outs.append(y)
            ys = {k: xp.stack([y[k] for y in outs]) for k in outs[0]}
        return carry, {k: xp.mean(y) for k, y in ys.items()}

    def _scan_step(self, carry, x, arrays, obs_stats, scheduled):
        rates = {role: self._part_rates(scheduled, role) for role in self._updater_logs}
        return self._learn_step(carry, x, arrays, obs_stats, rates)

    def _learn_step(self, carry, x, arrays, obs_stats, rates):
        """One optimisation step: each updater's step on the batch of ``x['indices']`` (the
        critic's, then the actor's), then the targets' soft update: ``(carry, scalars)``."""
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        batch = self._batch(arrays, x["indices"])
        logs = {}
        for role, prefix in self._updater_logs.items():
            v, states, infos = self._parts[role].step(
                v, targets, states, batch, obs_stats, x, rates[role]
            )
            logs.update({f"{prefix}/{k}": a for k, a in infos.items()})
        targets = self._soft_update(targets, v)
        return {"v": v, "targets": targets, "states": states}, logs

    def _batch(self, arrays, indices):
        """The n-step transitions of the windows ``indices`` ``[n, batch]``; constants."""
        batch = n_step_batch(self.xp, arrays, indices, discount=self.replay.discount)
        return {k: self.xp.stop_gradient(a) for k, a in batch.items()}

    def _soft_update(self, targets, v):
        """Every target moved towards its part of ``v`` by the model's ``target_tau``."""
        parts = tuple(targets)
        tau = self.model.target_tau
        moved = polyak_update({p: targets[p] for p in parts}, {p: v[p] for p in parts}, tau)
        return {**targets, **moved}

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_noise(self, count: int) -> np.ndarray | None:
        """Noise that the behaviour policy's compiled function takes (None: none): standard
        normal where the model's policy samples."""
        if not self.model.samples:
            return None
        size = self.model.action_size
        return self.rng.standard_normal((count, size)).astype(self.np_dtype)

    def _random_actions(self, count: int) -> np.ndarray:
        """Uniformly random actions (``[-1, 1]`` for Box, indices for Discrete)."""
        if self.action_kind == "Discrete":
            return self.rng.integers(0, int(self.action_space.n), size=count)
        size = int(np.prod(self.action_space.shape))
        return self.rng.uniform(-1.0, 1.0, size=(count, size)).astype(self.np_dtype)

    def _num_actions(self) -> Any:
        """What an ε-greedy exploration draws from (None for Box actions)."""
        return None

    def _policy_actions(self, observations: np.ndarray) -> np.ndarray:
        """Actions of the behaviour policy with the host's exploration."""
        actions = self._behaviour_actions(observations)
        return self.exploration(
            actions, self.rng, num_actions=self._num_actions(), steps=self.steps
        )

    def _behaviour_actions(self, observations: np.ndarray) -> np.ndarray:
        """Actions of the compiled acting function, before any noise added on the host."""
        noise = self._act_noise(observations.shape[0])
        args = (self.v, self.obs_stats, self._asarray(observations))
        out = self._act(*args, None if noise is None else self._asarray(noise))
        return np.asarray(self.xp.to_numpy(out))

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        obs = self._observations(observations)
        if self.steps < self.exploration.start_steps:
            actions = self._random_actions(obs.shape[0])
        else:
            actions = self._policy_actions(obs)
        self._pending = {"observations": obs, "actions": actions}
        return self._env_actions(actions)

    def test_step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        obs = self._observations(observations)
        mode = self._mode(self.v, self.obs_stats, self._asarray(obs))
        return self._env_actions(np.asarray(self.xp.to_numpy(mode)))

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def update(self, observations, rewards, resets, terminations) -> dict[str, float]:
        self._check_initialized()
        if self._pending is None:
            raise RuntimeError(f"{type(self).__name__}.update called before step")
        dtype, replay = self.np_dtype, self.replay
        resets = np.asarray(resets, bool)
        replay.store(
            observations=self._pending["observations"],
            actions=self._pending["actions"],
            rewards=np.asarray(rewards, dtype),
            next_observations=self._observations(observations),
            resets=resets.astype(dtype),
            terminations=np.asarray(terminations, bool).astype(dtype),
        )
        if self.observation_normalizer is not None:
            self.observation_normalizer.record(self._pending["observations"])
        self.exploration.reset(resets)
        workers = self._pending["observations"].shape[0]
        self._pending = None
        self.steps += workers
        if self.steps < replay.update_after or not replay.ready():
            return {}
        self._since_update += workers
        if self._since_update < replay.update_every:
            return {}
        self._since_update -= replay.update_every
        return self._learn()

    def _draw(self, iterations: int) -> dict[str, Any]:
        """The inputs of the optimisation steps drawn from the agent's generator: the batches'
        windows ``indices``, then each updater's noise, each with a leading ``[iterations]``."""
        batch_size = self.replay.batch_size
        xs = {"indices": self.replay.windows(self.rng, iterations, batch_size)}
        for updater in self._updaters.values():
            xs.update(updater.draw(self.rng, iterations, batch_size))
        return xs

    def _learn(self) -> dict[str, float]:
        xp, replay = self.xp, self.replay
        action_dtype = np.int32 if self.action_kind != "Box" else self.np_dtype
        replay.flush(
            xp,
            device=self.device,
            dtypes={"actions": action_dtype, "observations": self.np_dtype},
            chunk_steps=-(-replay.update_every // replay.workers),
            # the replay's old arrays are donated: written in place on jax, never read again
            compile=lambda fn: self._compile(fn, "replay_write", donate_argnums=0),
        )
        xs = self._placed(self._draw(replay.batch_iterations))
        carry = {"v": self.v, "targets": self.targets, "states": self.optimizer_states}
        scheduled = self._scheduled_arrays()
        carry, logs = self._update(carry, xs, replay.arrays, self.obs_stats, scheduled)
        self.v, self.targets = carry["v"], carry["targets"]
        self.optimizer_states = carry["states"]
        self.updates += 1
        out = {k: float(np.asarray(xp.to_numpy(x))) for k, x in logs.items()}
        out["critic/iterations"] = float(replay.batch_iterations)
        if self.observation_normalizer is not None:
            self.observation_normalizer.update()
            self._refresh_stats()
        return out

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        arrays: dict[str, Any] = {
            "v": self.v,
            "targets": self.targets,
            "optimizer": self.optimizer_states,
            "replay": self.replay.state_dict(),
        }
        if self.observation_normalizer is not None:
            arrays["observation_normalizer"] = self.observation_normalizer.state_dict()
        exploration = self.exploration.state_dict()
        if exploration:
            arrays["exploration"] = exploration
        if self._pending is not None:
            arrays["pending"] = dict(self._pending)
        return arrays

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        self.v = self._to_backend(arrays["v"], self.v)
        self.targets = self._to_backend(arrays["targets"], self.targets)
        self.optimizer_states = self._to_backend(arrays["optimizer"], self.optimizer_states)
        self.replay.load_state_dict(arrays["replay"], self.xp, device=self.device)
        if self.observation_normalizer is not None:
            self.observation_normalizer.load_state_dict(arrays["observation_normalizer"])
        self.exploration.load_state_dict(arrays.get("exploration", {}))
        self._pending = dict(arrays["pending"]) if "pending" in arrays else None
        self._refresh_stats()

    def _meta(self) -> dict[str, Any]:
        return {"steps": self.steps, "updates": self.updates, "since_update": self._since_update}

    def _load_meta(self, meta: dict[str, Any]) -> None:
        self.steps = int(meta.get("steps", 0))
        self.updates = int(meta.get("updates", 0))
        self._since_update = int(meta.get("since_update", 0))
