"""``Agent``: the interface between agents and the trainer, and what every agent shares.

The base contract (what the trainer and every agent rely on):

- ``Agent(**settings)``: settings are JSON values, all kept in ``agent.config`` (the values used,
  defaults included); :func:`ivy_rl.agents.make` builds agents by name with the defaults of a
  task family (:mod:`ivy_rl.agents.defaults`).
- ``initialize(observation_space, action_space, *, seed, f, dtype, compile, device)`` builds the
  models on a framework and a device, once: on an agent that is already initialized with the
  same spaces, framework, dtype and device it does nothing (the weights, for instance loaded
  from a checkpoint, are kept; :attr:`initialized` tells), and with other ones it raises a
  ValueError naming what differs.
- ``step(observations) -> actions`` and ``test_step(observations) -> actions`` act (numpy in,
  numpy actions of the environment's space out); ``update(observations, rewards, resets,
  terminations) -> dict of floats`` records the last step's transitions and learns.
- ``save(path, training=True)`` / ``load(path)``: ``load`` refuses a checkpoint of another class,
  or written with other settings (naming each setting that differs). ``training=False`` saves
  what acting needs (weights, normalisers, settings; no optimiser states, replay or pending
  transitions: the run's ``best/``), and ``load`` of such a folder keeps the agent's own.
- ``set_progress(fraction)``: the trainer tells the run's progress (the fraction of its steps
  done, in ``[0, 1]``) before each update; agents read their scheduled settings
  (:mod:`ivy_rl.schedules`, those named in ``scheduled``) at it and hand the values to their
  compiled updates as arrays, so a changing value never compiles anew.
- ``compiles``: how many compilations the agent's compiled functions made (one per distinct input
  signature of each function made by :meth:`Agent._compile`); it must not grow after the first
  update.

Subclass hooks: ``supported_action_spaces``, ``learns``, :meth:`_build` (models, optimisers,
replays, after :meth:`initialize` set ``xp``, ``rng``, ``dtype``, ``device`` and the spaces),
:meth:`_compile` / :meth:`_counted` (every compiled function goes through one of them, so that
it is counted),
:meth:`_asarray` / :meth:`_placed` (arrays on the agent's device), :meth:`_arrays` /
:meth:`_load_arrays` and :meth:`_meta` / :meth:`_load_meta` (checkpoints).

The trainer calls ``actions = agent.step(observations)`` during training,
``agent.update(observations, rewards, resets, terminations)`` after each step of the
environments (``observations`` are the true next observations, before any reset; ``resets``
mark the end of an episode for any reason, ``terminations`` the end in a terminal state, so a
time limit is a reset and not a termination), and ``agent.test_step(observations)`` in test
episodes. Actions are valid actions of the environment's action space.

Randomness comes from one numpy generator per agent (initial weights, exploration noise,
mini-batches), so a seed gives the same numbers on every backend, compiled functions draw
nothing, and a checkpoint restores the random state exactly.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = ivy_rl.agents.PPO().initialize(env.observation_space, env.action_space,
    ...                                         seed=0, f="jax")
    >>> observations = np.zeros((2, 3), np.float32)     # of 2 workers
    >>> actions = agent.step(observations)
    >>> agent.update(observations, np.zeros(2), np.zeros(2, bool), np.zeros(2, bool))
    {}
"""

from __future__ import annotations

import json
import os
from typing import Any

import numpy as np

import ivy
from ivy.stateful.checkpoint import flat_dict_to_nest, nest_to_flat_dict
from ivy.typing import Framework, Nest
from ivy_rl.models import check_observation_space, space_kind
from ivy_rl.schedules import as_schedule, is_schedule
from ivy_rl.settings import Setting, check, declared

__all__ = ["Agent"]

_MISSING = object()

#: the top-level entries of :meth:`Agent._arrays` that only training needs: an agent saved with
#: ``training=False`` leaves them out, and loading it keeps the agent's own
TRAINING_STATE = ("optimizer", "replay", "pending", "simulation")


class Agent:
    """Base class of agents.

    Subclasses set ``supported_action_spaces`` and implement :meth:`_build`, :meth:`step`,
    :meth:`test_step` and, if they learn, :meth:`update`, :meth:`_arrays` and
    :meth:`_load_arrays`.

    Constructor keyword arguments are the agent's settings (JSON values, so that the command
    line's ``--agent-kwargs`` can give them); they are kept in ``self.config``.
    """

    supported_action_spaces: tuple[str, ...] = ("Box", "Discrete")
    learns = False
    #: the settings this agent reads at the run's progress (a schedule or a number each)
    scheduled: tuple[str, ...] = ()

    #: the agent's parts, as in Tonic: ``{role: (factory, {flat setting: the factory's
    #: parameter})}``; a part given to the constructor (``SAC(model=...)``) replaces the one the
    #: flat settings would build. None: an agent without parts.
    parts: dict[str, tuple[Any, dict[str, str]]] | None = None

    #: settings the agent reads itself rather than a part (``fusion``, TD3's
    #: ``policy_delay``): ``{name: Setting}``, their defaults in ``_defaults``
    own_settings: dict[str, Setting] = {}

    #: the agent's defaults where they differ from its parts' (each part's default is its
    #: constructor's): ``{flat setting: value}``, merged along the class hierarchy
    _defaults: dict[str, Any] = {}

    @classmethod
    def settings(cls) -> dict[str, tuple[Setting, Any, str | None]]:
        """The agent's flat settings, derived from its parts: ``{name: (Setting, default,
        role)}`` (role: the part the setting builds, None for the agent's own settings).

        Each part declares its settings once (``settings`` of its class: type, bounds,
        meaning; the default is its constructor's); the agent maps them to flat names in
        :attr:`parts` and states the defaults that differ from its parts' in ``_defaults``.

        Example:
            >>> spec, default, role = SAC.settings()["batch_size"]
            >>> default, role
            (256, 'replay')
        """
        table: dict[str, tuple[Setting, Any, str | None]] = {}
        for role, (factory, names) in (cls.parts or {}).items():
            spec = declared(factory)
            for flat, param in names.items():
                if param not in spec:
                    raise TypeError(
                        f"{cls.__name__}: the {role}'s parameter {param!r} (setting {flat!r}) "
                        "is not declared in its class's settings"
                    )
                table.setdefault(flat, (*spec[param], role))
        defaults: dict[str, Any] = {}
        for klass in reversed(cls.__mro__):
            for name, spec in vars(klass).get("own_settings", {}).items():
                table[name] = (spec, None, None)
            defaults.update(vars(klass).get("_defaults", {}))
        for name, value in defaults.items():
            if name in table:
                table[name] = (table[name][0], value, table[name][2])
        return table

    @classmethod
    def _checked_settings(cls, settings: dict[str, Any], also: str = "") -> dict[str, Any]:
        """The defaults of :meth:`settings` overridden by ``settings`` (an unknown one is a
        TypeError that lists the known ones, then ``also``), each checked once
        (:func:`ivy_rl.settings.check`)."""
        table = cls.settings()
        unknown = sorted(set(settings) - set(table))
        if unknown:
            raise TypeError(
                f"{cls.__name__} got unknown settings {unknown}; its settings are "
                f"{sorted(table)}{also}"
            )
        config = {name: default for name, (_, default, _) in table.items()}
        config.update(settings)
        return {k: check(k, table[k][0], v) for k, v in config.items()}

    @classmethod
    def _composed(cls, settings: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
        """``(config, parts)``: the flat settings (defaults overridden by ``settings``, each
        checked) and the parts, each the one given in ``settings`` under its role or built
        by its factory from its flat settings. The flat settings of a given part are read back
        from it (``config`` always holds the values used); giving a part and one of its flat
        settings is a TypeError."""
        parts = cls.parts or {}
        settings = dict(settings)
        # a string under a role's name is the flat setting of that name (DDPG's
        # exploration='normal' chooses its exploration part by name)
        given = {
            role: settings.pop(role)
            for role in list(settings)
            if role in parts and not isinstance(settings[role], str)
        }
        config = cls._checked_settings(settings, f", and its parts {', '.join(parts)}")
        built = {}
        for role, (factory, names) in parts.items():
            part = given.get(role)
            if part is None:
                part = factory(**{param: config[flat] for flat, param in names.items()})
            else:
                clash = sorted(set(settings) & set(names))
                if clash:
                    raise TypeError(
                        f"{cls.__name__}: settings {clash} belong to the {role} given; set them "
                        "on it"
                    )
                for flat, param in names.items():
                    if hasattr(part, param):
                        config[flat] = getattr(part, param)
            built[role] = part
        return config, built

    def _part_rates(self, scheduled: dict[str, Any], role: str) -> dict[str, Any]:
        """The scheduled values (arrays) of a part's settings, by the part's parameter names
        (``{'lr': ...}`` for an updater whose ``lr`` is the flat ``actor_lr``)."""
        names = (self.parts or {})[role][1]
        return {param: scheduled[flat] for flat, param in names.items() if flat in scheduled}

    def __init__(self, **config: Any) -> None:
        name = type(self).__name__
        for key, value in config.items():
            if key in self.scheduled:
                schedule = as_schedule(value, name=f"{name}: setting {key!r}")
                config[key] = str(schedule) if is_schedule(value) else schedule(0.0)
            elif is_schedule(value):
                raise ValueError(
                    f"{name} does not schedule the setting {key!r} (it schedules "
                    f"{list(self.scheduled) or 'none'}); give it a number, got {value!r}"
                )
        self.config = dict(config)
        self.xp = None
        self.initialized = False
        self.progress = 0.0

    def set_progress(self, fraction: float) -> None:
        """Tell the agent the run's progress, the fraction of its steps done (clamped to
        ``[0, 1]``); the next updates read the scheduled settings at it.

        Example:
            >>> agent = PPO(actor_lr="linear:1e-3")
            >>> agent.set_progress(0.5)
            >>> agent.scheduled_values()["actor_lr"]   # "linear:1e-3" is 5e-4 half-way
            0.0005
        """
        fraction = float(fraction)
        if not np.isfinite(fraction):
            raise ValueError(f"set_progress: fraction must be a finite number, got {fraction}")
        self.progress = min(max(fraction, 0.0), 1.0)

    def scheduled_values(self, progress: float | None = None) -> dict[str, float]:
        """The scheduled settings' values at ``progress`` (default: the agent's progress).

        Example:
            >>> PPO(actor_lr="linear:1e-3").scheduled_values(0.5)["actor_lr"]
            0.0005
        """
        progress = self.progress if progress is None else progress
        return {
            key: as_schedule(self.config[key], name=key)(progress)
            for key in self.scheduled
            if key in self.config
        }

    def _scheduled_arrays(self) -> dict[str, Any]:
        """:meth:`scheduled_values` at the agent's progress, as scalars of its dtype on its
        device: inputs of the compiled updates, which never retrace for a new value."""
        return {
            key: self._asarray(np.asarray(value, dtype=self.np_dtype))
            for key, value in self.scheduled_values().items()
        }

    # ------------------------------------------------------------------------------------------
    # Set-up
    # ------------------------------------------------------------------------------------------

    def initialize(
        self,
        observation_space: Any,
        action_space: Any,
        *,
        seed: int = 0,
        f: Framework = None,
        dtype: str = "float32",
        compile: bool = True,
        device: str | None = None,
    ) -> Agent:
        """Build the agent's models, optimisers and replay for the spaces, on a framework.

        Args:
            observation_space: the environment's (single) observation space, a Box.
            action_space: the environment's (single) action space.
            seed: seed of the agent's numpy generator (initial weights, noise, mini-batches).
            f: framework name or namespace (``'torch'``, ``ivy.jax`` ...); default: the global
                framework, else numpy.
            dtype: float dtype of the models (``'float32'`` or ``'float64'``).
            compile: compile the agent's functions with ``ivy.compile_fn`` (False: eager, for
                debugging).
            device: where the agent's arrays live (``'cpu'``, ``'gpu:0'``; default ``'cpu'``).

        Returns:
            The agent itself.

        Example:
            >>> import gymnasium as gym
            >>> env = gym.make("Pendulum-v1")
            >>> agent = A2C().initialize(env.observation_space, env.action_space, f="torch")
            >>> agent.xp is ivy.torch, agent.dtype, agent.device
            (True, 'float32', 'cpu')
        """
        name = type(self).__name__
        if f is None:
            f = ivy.current_framework() or "numpy"
        xp = ivy.get_framework(f=f)
        device = "cpu" if device is None else str(device)
        if self.initialized:
            self._check_same_setup(observation_space, action_space, xp, dtype, device)
            return self
        self.action_kind = space_kind(action_space, self.supported_action_spaces, who=name)
        if self.learns:
            check_observation_space(observation_space, who=name)
        self.xp = xp
        if dtype not in ("float32", "float64"):
            raise ValueError(f"{name}: dtype must be 'float32' or 'float64', got {dtype!r}")
        if self.learns and not xp.capabilities.autodiff:
            raise ivy.errors.UnsupportedError(
                f"{name} learns with gradients, which {xp.backend} cannot compute; choose a "
                "framework with automatic differentiation: f='torch', 'jax' or 'tensorflow'"
            )
        self.observation_space, self.action_space = observation_space, action_space
        self.dtype, self.np_dtype = dtype, np.dtype(dtype)
        self.seed = int(seed)
        self.compiled = bool(compile)
        self.rng = np.random.default_rng(self.seed)
        self.device = device
        self._signatures: dict[str, set] = {}
        if self.action_kind == "Box":
            low, high = action_space.low.astype(np.float64), action_space.high.astype(np.float64)
            bounded = bool(np.all(np.isfinite(low)) and np.all(np.isfinite(high)))
            self._action_bounds = (low, high) if bounded else None
        self._build()
        self.initialized = True
        return self

    def _check_same_setup(self, observation_space, action_space, xp, dtype, device) -> None:
        """Refuse to initialize again with other spaces, framework, dtype or device."""
        differs = []
        for what, mine, given in (
            ("observation_space", self.observation_space, observation_space),
            ("action_space", self.action_space, action_space),
            ("framework", self.xp.backend, xp.backend),
            ("dtype", self.dtype, dtype),
            ("device", self.device, device),
        ):
            if mine != given:
                differs.append(f"{what}: {mine!r} here, {given!r} asked")
        if differs:
            raise ValueError(
                f"{type(self).__name__} is already initialized, differently ("
                + "; ".join(differs)
                + "): build a new agent for these, e.g. ivy_rl.agents.make(name, **agent.config)"
            )

    @property
    def compiles(self) -> int:
        """Compilations made by the agent's compiled functions so far: one per distinct input
        signature (nest structure, shapes, dtypes, devices and Python values of the arguments)
        that each function met, which is what ``jax.jit``, ``tf.function`` and
        ``torch.compile`` trace anew for. 0 when running eagerly.

        Example:
            A PPO agent on jax, with segments of 4 steps of 2 workers:

            >>> import gymnasium as gym, numpy as np
            >>> env = gym.make("Pendulum-v1")
            >>> agent = PPO(segment_size=4, batch_size=8, epochs=1).initialize(
            ...     env.observation_space, env.action_space, seed=0, f="jax")
            >>> obs, no = np.zeros((2, 3), np.float32), np.zeros(2, bool)
            >>> for _ in range(8):                      # two segments, two updates
            ...     actions = agent.step(obs)
            ...     logs = agent.update(obs, np.zeros(2), no, no)
            >>> agent.compiles                  # acting, and the update: none for the second
            2
        """
        return sum(len(seen) for seen in getattr(self, "_signatures", {}).values())

    def _build(self) -> None:
        """Create models, optimisers, replays (after :meth:`initialize` set the spaces)."""

    def _compile(self, fn: Any, name: str | None = None, *, donate_argnums: Any = None) -> Any:
        """``fn`` compiled with ``ivy.compile_fn`` for the agent's framework (or as it is, when
        the agent runs eagerly or the framework has no compiler), counted in :attr:`compiles`;
        ``donate_argnums`` as for ``ivy.compile_fn`` (jax reuses those arguments' buffers)."""
        if not self.compiled or not self.xp.capabilities.compilation:
            return fn
        compiled = ivy.compile_fn(fn, f=self.xp, donate_argnums=donate_argnums)
        return self._counted(compiled, name or fn.__name__)

    def _counted(self, compiled: Any, name: str) -> Any:
        """``compiled`` (a compiled callable, e.g. from ``ivy.compiled_scan``) counting the
        distinct input signatures of its calls in :attr:`compiles` under ``name``."""
        seen = self._signatures.setdefault(name, set())
        quick: set = set()
        calls = [0]
        xp = self.xp

        # The full signature flattens every argument (the weights, optimiser states and replay
        # of an update: hundreds of leaves, about a millisecond a call), which would cost more
        # than a small compiled step itself. So it is computed on the first two calls (the first
        # compilation, and the steady state that follows it), then whenever a cheap key of the
        # arguments (the shape and dtype of the arrays passed directly, the size of the nests,
        # other values as they are: what changes when a batch size or a setting changes) is new,
        # and on every _FULL_EVERY-th call, which catches a change deep inside a nest that
        # persists (a change that lasts fewer calls can be missed: it is counted when it recurs
        # at a checked call).
        def counted(*args: Any) -> Any:
            calls[0] += 1
            key = _quick_key(args)
            if calls[0] <= 2 or key not in quick or calls[0] % _FULL_EVERY == 0:
                quick.add(key)
                seen.add(_signature(xp, args))
            return compiled(*args)

        return counted

    def _check_initialized(self) -> None:
        if not self.initialized:
            raise RuntimeError(
                f"{type(self).__name__} is not initialized: call "
                "agent.initialize(observation_space, action_space, seed=..., f=...) first"
            )

    def _observations(self, observations: Any) -> np.ndarray:
        obs = np.asarray(observations, dtype=self.np_dtype)
        return obs.reshape(obs.shape[0], -1)

    def _env_actions(self, unit_actions: np.ndarray) -> np.ndarray:
        """Actions of the environment's space from actions in ``[-1, 1]`` (Box) or indices."""
        if self.action_kind == "Discrete":
            return np.asarray(unit_actions, dtype=np.int64) + int(self.action_space.start)
        actions = np.asarray(unit_actions, np.float64)
        if self._action_bounds is not None:
            low, high = self._action_bounds
            actions = low + (np.clip(actions, -1.0, 1.0) + 1.0) * 0.5 * (high - low)
        return actions.astype(self.action_space.dtype)

    # ------------------------------------------------------------------------------------------
    # The trainer's interface
    # ------------------------------------------------------------------------------------------

    def step(self, observations: Any) -> np.ndarray:
        """Actions for a batch of observations ``[workers, ...]`` during training."""
        raise NotImplementedError

    def test_step(self, observations: Any) -> np.ndarray:
        """Actions for a batch of observations during tests (no exploration)."""
        raise NotImplementedError

    def predict(
        self,
        observation: Any,
        state: Any = None,
        episode_start: Any = None,
        deterministic: bool = False,
    ) -> tuple[np.ndarray, None]:
        """The action for an observation (or a batch), as stable-baselines3's
        ``model.predict``: ``deterministic=True`` acts as in tests (:meth:`test_step`), False
        explores as in training (:meth:`step`). ``state`` and ``episode_start`` are accepted
        for stable-baselines3's signature (the agents keep no recurrent state).

        Returns:
            ``(action, None)``: one action for one observation, a batch for a batch.

        Example:
            >>> import gymnasium as gym
            >>> env = gym.make("Pendulum-v1")
            >>> agent = PPO().initialize(env.observation_space, env.action_space, f="jax")
            >>> obs, info = env.reset(seed=0)
            >>> action, _ = agent.predict(obs, deterministic=True)
            >>> obs, reward, terminated, truncated, info = env.step(action)
            >>> action.shape
            (1,)
        """
        self._check_initialized()
        obs = np.asarray(observation)
        single = obs.shape == tuple(self.observation_space.shape)
        batch = obs[None] if single else obs
        actions = self.test_step(batch) if deterministic else self.step(batch)
        return (actions[0] if single else actions), None

    def update(
        self, observations: Any, rewards: Any, resets: Any, terminations: Any
    ) -> dict[str, float]:
        """Record the transitions of the last :meth:`step` and learn when it is time.

        Args:
            observations: ``[workers, ...]`` true next observations (before resets).
            rewards: ``[workers]`` rewards.
            resets: ``[workers]`` the episode ended (termination or time limit).
            terminations: ``[workers]`` the episode ended in a terminal state.

        Returns:
            Scalars to log (losses...) when the agent learned, else an empty dict.
        """
        return {}

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def _arrays(self) -> dict[str, Any]:
        """Everything to save as a nest of arrays (any backend) and numpy arrays."""
        return {}

    def _load_arrays(self, arrays: dict[str, Any]) -> None:
        """Restore :meth:`_arrays` from a nest of numpy arrays."""

    def _meta(self) -> dict[str, Any]:
        return {}

    def _load_meta(self, meta: dict[str, Any]) -> None:
        pass

    def save(self, path: str | os.PathLike, *, training: bool = True) -> None:
        """Write the agent's state to the folder ``path``: ``arrays.npz`` (weights,
        optimiser states, normalisers, replay, pending transitions) and ``agent.json`` (its
        class, settings, random generator state and counters). Any backend loads it.

        Args:
            path: the folder.
            training: save what training goes on from (a checkpoint); False: only what acting
                needs (weights, normalisers, settings), without the optimiser states, the replay
                and the transitions pending an update (:data:`TRAINING_STATE`), as in a run's
                ``best/``.

        Example:
            >>> import gymnasium as gym, os
            >>> env = gym.make("Pendulum-v1")
            >>> agent = PPO().initialize(env.observation_space, env.action_space, f="jax")
            >>> agent.save("runs/ppo/checkpoints/step_0")
            >>> sorted(os.listdir("runs/ppo/checkpoints/step_0"))
            ['agent.json', 'arrays.npz']
        """
        self._check_initialized()
        os.makedirs(path, exist_ok=True)
        flat = {}
        for key, leaf in nest_to_flat_dict(self._arrays()).items():
            if not training and key.split("/")[0] in TRAINING_STATE:
                continue
            flat[key] = leaf if isinstance(leaf, np.ndarray) else np.asarray(ivy.to_numpy(leaf))
        with open(os.path.join(path, "arrays.npz"), "wb") as fh:
            np.savez(fh, **flat)
        meta = {
            "agent": type(self).__name__,
            "config": self.config,
            "seed": self.seed,
            "dtype": self.dtype,
            "rng": self.rng.bit_generator.state,
            "progress": self.progress,
            "training_state": bool(training),
            **self._meta(),
        }
        with open(os.path.join(path, "agent.json"), "w") as fh:
            json.dump(meta, fh, indent=1, default=_json_default)

    def load(self, path: str | os.PathLike) -> Agent:
        """Restore a state written by :meth:`save` on any backend into this initialized agent
        (same class, settings and spaces; its framework, dtype and device are kept). A
        checkpoint of another class, or written with other settings, is refused with a
        ValueError naming each setting that differs. A folder saved with ``training=False``
        (a run's ``best/``) holds no optimiser states, replay or pending transitions: the
        agent keeps its own (those of a new agent: its optimisers start afresh, its replay
        empty), and acts (``test_step``, ``predict``, ``play``) as the saved one.

        Returns:
            The agent itself.

        Example:
            Saved on jax, loaded on torch:

            >>> import gymnasium as gym, numpy as np
            >>> env = gym.make("Pendulum-v1")
            >>> saved = PPO().initialize(env.observation_space, env.action_space, seed=1, f="jax")
            >>> saved.save("ckpt")
            >>> agent = PPO().initialize(env.observation_space, env.action_space, f="torch")
            >>> agent = agent.load("ckpt")
            >>> agent.xp is ivy.torch, agent.rng.random() == saved.rng.random()  # the same state
            (True, True)
        """
        self._check_initialized()
        with open(os.path.join(path, "agent.json")) as fh:
            meta = json.load(fh)
        if meta["agent"] != type(self).__name__:
            raise ValueError(
                f"checkpoint {os.fspath(path)!r} holds a {meta['agent']}, not a "
                f"{type(self).__name__}"
            )
        saved = meta.get("config", {})
        mine = json.loads(json.dumps(self.config, default=_json_default))
        differs = [
            f"{key}: {saved.get(key, '(unset)')!r} in the checkpoint, "
            f"{mine.get(key, '(unset)')!r} here"
            for key in sorted(set(saved) | set(mine))
            if saved.get(key, _MISSING) != mine.get(key, _MISSING)
        ]
        if differs:
            raise ValueError(
                f"checkpoint {os.fspath(path)!r} was written with other settings ("
                + "; ".join(differs)
                + "): build the agent with the checkpoint's settings to load it"
            )
        with np.load(os.path.join(path, "arrays.npz"), allow_pickle=False) as data:
            flat = {key: data[key] for key in data.files}
        if not meta.get("training_state", True):
            saved_entries = {key.split("/")[0] for key in flat}
            for key, leaf in nest_to_flat_dict(self._arrays()).items():
                entry = key.split("/")[0]
                if entry in TRAINING_STATE and entry not in saved_entries:
                    flat[key] = leaf if isinstance(leaf, np.ndarray) else ivy.to_numpy(leaf)
        self._load_arrays(flat_dict_to_nest(flat) if flat else {})
        self.rng.bit_generator.state = meta["rng"]
        self.progress = float(meta.get("progress", 0.0))
        self._load_meta(meta)
        return self

    def _to_backend(self, stored: Nest, like: Nest) -> Nest:
        """Numpy arrays ``stored`` as arrays of the framework, dtype of the nest ``like``."""
        xp = self.xp

        def rebuild(old, new, path):
            if isinstance(old, dict):
                new = new if isinstance(new, dict) else {}
                return {k: rebuild(o, new.get(k), f"{path}/{k}") for k, o in old.items()}
            if new is None:
                raise KeyError(f"the checkpoint has no array {path}")
            if tuple(np.shape(new)) != tuple(xp.shape(old)):
                raise ValueError(
                    f"checkpoint array {path} of shape {np.shape(new)} does not fit "
                    f"{tuple(xp.shape(old))}"
                )
            return xp.asarray(new, dtype=xp.dtype(old), device=self.device)

        return rebuild(like, stored, "")

    def _asarray(self, value: Any) -> Any:
        """``value`` as an array of the framework on the agent's device.

        Every array an agent makes is placed explicitly, so that every input of its compiled
        functions is placed alike from the first call on: jax.jit compiles once per pattern of
        explicitly placed (committed) and unplaced inputs, and the outputs of compiled
        functions come back placed.
        """
        return self.xp.asarray(value, device=self.device)

    def _placed(self, nest: Nest) -> Nest:
        """The arrays of ``nest`` placed on the agent's device (see :meth:`_asarray`)."""
        return ivy.nest.map_nest(self._asarray, nest)

    def __repr__(self) -> str:
        where = f", f={self.xp.backend}" if self.xp is not None else ""
        return f"{type(self).__name__}({self.config}{where})"


#: calls between full signatures of a counted function (see Agent._counted)
_FULL_EVERY = 64


def _quick_key(args: tuple) -> tuple:
    """A cheap key of a call's arguments: the shape and dtype of each array passed directly, the
    size of each nest, the type and value of other hashable arguments."""
    parts = []
    for arg in args:
        if hasattr(arg, "shape") and hasattr(arg, "dtype"):
            parts.append((tuple(arg.shape), arg.dtype))
        elif isinstance(arg, (dict, list, tuple)):
            parts.append((type(arg), len(arg)))
        else:
            try:
                hash(arg)
                parts.append((type(arg), arg))
            except TypeError:
                parts.append(type(arg))
    return tuple(parts)


def _signature(xp: Any, args: Any) -> Any:
    """A hashable key of what a compiler specialises on: the nest structure of ``args``, the
    shape, dtype and device of each array, and the value of every other leaf."""
    leaves, structure = ivy.nest.flatten_nest(args)
    parts = []
    for leaf in leaves:
        if hasattr(leaf, "shape") and hasattr(leaf, "dtype"):
            parts.append((tuple(leaf.shape), str(leaf.dtype), str(xp.dev(leaf))))
        else:
            parts.append((type(leaf).__name__, repr(leaf)))
    return repr(structure), tuple(parts)


def _json_default(value: Any) -> Any:
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"cannot write {type(value).__name__} to JSON")
