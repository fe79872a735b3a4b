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

Subclasses build their parts in :meth:`OffPolicyAgent._build_parts` (the variables ``v`` by part,
the optimisers by part, the targets), act in :meth:`OffPolicyAgent._policy_actions`, and learn
in :meth:`OffPolicyAgent._learn_step`.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np

import ivy
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.fusion import FUSION_LEVELS, compiled_scan_unrolls
from ivy_rl.buffers import TransitionReplay, n_step_batch
from ivy_rl.critics import soft_update
from ivy_rl.normalizers import MeanStd
from ivy_rl.schedules import as_schedule

__all__ = ["OffPolicyAgent"]


#: the setting of each part's learning rate (the parts of ``self.optimizers``)
_LEARNING_RATE_OF_PART = {
    "actor": "actor_lr",
    "critic": "critic_lr",
    "q": "critic_lr",
    "temperature": "temperature_lr",
    "dual": "dual_lr",
}


class OffPolicyAgent(Agent):
    """Base of the off-policy agents (DDPG, TD3, SAC, MPO, D4PG, DQN).

    Args (settings shared by every off-policy agent):
        hidden_sizes: hidden sizes of the actor's (or Q-network's) torso.
        critic_hidden_sizes: of the critics' torsos (default: ``hidden_sizes``).
        activation: activation of the torsos.
        replay_size: transitions kept (all workers together).
        return_steps: n of the n-step returns.
        batch_size: transitions per optimisation step.
        start_steps: environment steps of uniformly random actions at the start.
        update_after: environment steps before the first update.
        update_every: environment steps between updates.
        batch_iterations: optimisation steps per update.
        discount: γ.
        actor_lr, critic_lr: Adam learning rates.
        target_tau: step of the targets' soft updates (1: copy).
        gradient_clip: global norm of gradients (0: no clipping).
        normalize_observations: normalise observations by their running mean and std.
        fusion: ``'auto'``, ``'update'`` or ``'steps'`` (see :mod:`ivy_rl.agents.fusion`).
    """

    learns = True
    scheduled: tuple[str, ...] = ("actor_lr", "critic_lr")
    _defaults: dict[str, Any] = dict(
        hidden_sizes=(256, 256),
        critic_hidden_sizes=None,
        activation="relu",
        replay_size=1_000_000,
        return_steps=1,
        batch_size=256,
        start_steps=1000,
        update_after=1000,
        update_every=50,
        batch_iterations=50,
        discount=0.99,
        actor_lr=1e-3,
        critic_lr=1e-3,
        target_tau=0.005,
        gradient_clip=0.0,
        normalize_observations=True,
        fusion="auto",
    )

    def __init__(self, **settings: Any) -> None:
        config = self._checked_settings(settings)
        if config["fusion"] not in FUSION_LEVELS:
            raise ValueError(
                f"{type(self).__name__}: unknown fusion {config['fusion']!r}; choose one of "
                f"{', '.join(map(repr, FUSION_LEVELS))}"
            )
        self._check_config(config)
        super().__init__(**config)

    def _check_config(self, config: dict[str, Any]) -> None:
        """Checks of settings that depend on each other (subclasses add theirs)."""

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _build(self) -> None:
        c = self.config
        self.observation_size = int(np.prod(self.observation_space.shape))
        self.optimizers: dict[str, Any] = {}
        v, targets = self._build_parts()
        self.v = self._placed(v)
        self.targets = self._placed(targets)
        self.optimizer_states = {k: opt.init(self.v[k]) for k, opt in self.optimizers.items()}
        normalize = c["normalize_observations"]
        self.observation_normalizer = MeanStd((self.observation_size,)) if normalize else None
        self.replay = TransitionReplay(c["replay_size"], return_steps=c["return_steps"])
        self._build_exploration()
        self._pending: dict[str, np.ndarray] | None = None
        self.steps = self.updates = self._since_update = 0
        self._refresh_stats()
        self._act = self._compile(self._act_fn, "act")
        self._mode = self._compile(self._mode_fn, "mode")
        self.fusion = c["fusion"]
        if self.fusion == "auto":
            unrolls = self.compiled and compiled_scan_unrolls(f=self.xp)
            self.fusion = "steps" if unrolls else "update"
        self._fused = self.fusion == "update"
        if self._fused:
            self._update = self._compile(self._update_fn, "update")
        else:
            self._update = self._update_fn
            self._compiled_step = self._compile(self._scan_step, "learn_step")

    def _build_parts(self) -> tuple[dict[str, Any], dict[str, Any]]:
        """Models and optimisers: returns ``(v, targets)``, the variables by part and the
        targets' variables by part, and fills ``self.optimizers`` (one per part of ``v`` that
        learns by gradients)."""
        raise NotImplementedError

    def _build_exploration(self) -> None:
        """The exploration on the host (none by default)."""

    def _adam(self, lr: float | str) -> Any:
        """Adam at the start of ``lr`` (a number or a schedule); each step takes its scheduled
        learning rate as an array (:meth:`_minimize`)."""
        return ivy.Adam(as_schedule(lr)(0.0), f=self.xp)

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
        raise NotImplementedError

    def _mode_fn(self, v, obs_stats, observations):
        """Actions of the test policy."""
        raise NotImplementedError

    def _update_fn(self, carry, xs, arrays, obs_stats, scheduled):
        """The whole update: ``(carry, logs)`` after the steps of ``xs`` (leading axis: the
        optimisation steps), ``carry = {'v', 'targets', 'states'}``; ``scheduled``: the
        scheduled learning rates (scalar arrays, :meth:`Agent.set_progress`)."""
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
        # the learning rates of the step being traced, read by _minimize
        self._step_lrs = scheduled
        try:
            return self._learn_step(carry, x, arrays, obs_stats)
        finally:
            self._step_lrs = None

    def _learn_step(self, carry, x, arrays, obs_stats):
        """One optimisation step: ``(carry, scalars)``."""
        raise NotImplementedError

    def _batch(self, arrays, indices):
        """The n-step transitions of the windows ``indices`` ``[n, batch]``; constants."""
        batch = n_step_batch(self.xp, arrays, indices, discount=self.config["discount"])
        return {k: self.xp.stop_gradient(a) for k, a in batch.items()}

    def _minimize(self, part, loss_fn, v, state):
        """Gradients of ``loss_fn`` (returning ``loss`` or ``(loss, infos)``) on the part's
        variables ``v``, clipped, and a step of the part's optimiser."""
        xp = self.xp
        loss, grads, *aux = xp.execute_with_gradients(loss_fn, v)
        clip = self.config["gradient_clip"]
        if clip:
            grads = xp.clip_by_global_norm(grads, clip)[0]
        optimizer = self.optimizers[part]
        lr = (getattr(self, "_step_lrs", None) or {}).get(_LEARNING_RATE_OF_PART.get(part))
        if lr is not None:
            optimizer = copy.copy(optimizer)
            optimizer.lr = lr
        new_v, new_state = optimizer.step(v, grads, state)
        return new_v, new_state, {"loss": loss, **(aux[0] if aux else {})}

    def _soft_update(self, targets, v, parts):
        """The targets of ``parts`` moved towards ``v`` by ``target_tau``."""
        tau = self.config["target_tau"]
        moved = soft_update({p: targets[p] for p in parts}, {p: v[p] for p in parts}, tau)
        return {**targets, **moved}

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_noise(self, count: int) -> np.ndarray | None:
        """Noise that the behaviour policy's compiled function takes (None: none)."""
        return None

    def _random_actions(self, count: int) -> np.ndarray:
        """Uniformly random actions (``[-1, 1]`` for Box, indices for Discrete)."""
        if self.action_kind == "Discrete":
            return self.rng.integers(0, int(self.action_space.n), size=count)
        size = int(np.prod(self.action_space.shape))
        return self.rng.uniform(-1.0, 1.0, size=(count, size)).astype(self.np_dtype)

    def _policy_actions(self, observations: np.ndarray) -> np.ndarray:
        """Actions of the behaviour policy with the host's exploration (none here)."""
        return self._behaviour_actions(observations)

    def _behaviour_actions(self, observations: np.ndarray) -> np.ndarray:
        """Actions of the compiled acting function, before any noise added on the host."""
        noise = self._act_noise(observations.shape[0])
        args = (self.v, self.obs_stats, self._asarray(observations))
        out = self._act(*args, None if noise is None else self._asarray(noise))
        return np.asarray(self.xp.to_numpy(out))

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        obs = self._observations(observations)
        if self.steps < self.config["start_steps"]:
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

    def _reset_exploration(self, resets: np.ndarray) -> None:
        """Restart the exploration of the workers whose episode ended."""

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def update(self, observations, rewards, resets, terminations) -> dict[str, float]:
        self._check_initialized()
        if self._pending is None:
            raise RuntimeError(f"{type(self).__name__}.update called before step")
        dtype = self.np_dtype
        resets = np.asarray(resets, bool)
        self.replay.store(
            observations=self._pending["observations"],
            actions=self._pending["actions"],
            rewards=np.asarray(rewards, dtype),
            next_observations=self._observations(observations),
            resets=resets.astype(dtype),
            terminations=np.asarray(terminations, bool).astype(dtype),
        )
        if self.observation_normalizer is not None:
            self.observation_normalizer.record(self._pending["observations"])
        self._reset_exploration(resets)
        workers = self._pending["observations"].shape[0]
        self._pending = None
        self.steps += workers
        if self.steps < self.config["update_after"] or not self.replay.ready():
            return {}
        self._since_update += workers
        if self._since_update < self.config["update_every"]:
            return {}
        self._since_update -= self.config["update_every"]
        return self._learn()

    def _draw(self, iterations: int) -> dict[str, Any]:
        """The inputs of the optimisation steps drawn from the agent's generator: the batches'
        windows ``indices`` and the agent's noise, each with a leading ``[iterations]``."""
        c = self.config
        return {"indices": self.replay.windows(self.rng, iterations, c["batch_size"])}

    def _learn(self) -> dict[str, float]:
        xp, c = self.xp, self.config
        action_dtype = np.int32 if self.action_kind != "Box" else self.np_dtype
        self.replay.flush(
            xp,
            device=self.device,
            dtypes={"actions": action_dtype, "observations": self.np_dtype},
            chunk_steps=-(-c["update_every"] // self.replay.workers),
            # the replay's old arrays are donated: written in place on jax, never read again
            compile=lambda fn: self._compile(fn, "replay_write", donate_argnums=0),
        )
        xs = self._placed(self._draw(c["batch_iterations"]))
        carry = {"v": self.v, "targets": self.targets, "states": self.optimizer_states}
        scheduled = self._scheduled_arrays()
        carry, logs = self._update(carry, xs, self.replay.arrays, self.obs_stats, scheduled)
        self.v, self.targets = carry["v"], carry["targets"]
        self.optimizer_states = carry["states"]
        self.updates += 1
        out = {k: float(np.asarray(xp.to_numpy(x))) for k, x in logs.items()}
        out["critic/iterations"] = float(c["batch_iterations"])
        if self.observation_normalizer is not None:
            self.observation_normalizer.update()
            self._refresh_stats()
        return out

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _exploration_state(self) -> dict[str, Any]:
        return {}

    def _load_exploration_state(self, state: dict[str, Any]) -> None:
        pass

    def _arrays(self) -> dict[str, Any]:
        arrays: dict[str, Any] = {
            "v": self.v,
            "targets": self.targets,
            "optimizer": self.optimizer_states,
            "replay": self.replay.state_dict(),
        }
        if self.observation_normalizer is not None:
            arrays["observation_normalizer"] = self.observation_normalizer.state_dict()
        exploration = self._exploration_state()
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
        self._load_exploration_state(arrays.get("exploration", {}))
        self._pending = dict(arrays["pending"]) if "pending" in arrays else None
        self._refresh_stats()

    def _meta(self) -> dict[str, Any]:
        return {"steps": self.steps, "updates": self.updates, "since_update": self._since_update}

    def _load_meta(self, meta: dict[str, Any]) -> None:
        self.steps = int(meta.get("steps", 0))
        self.updates = int(meta.get("updates", 0))
        self._since_update = int(meta.get("since_update", 0))
