"""Models built from an encoder, a torso and a head: actors, critics, actor-critics with
target copies.

Each part is an ``ivy.Module`` (its variables are a nest ``v``; ``part(x, v=v)`` is pure, so it
differentiates and compiles). Observation statistics (``{'mean', 'std'}`` from
:class:`ivy_rl.normalizers.MeanStd`) and return statistics are passed in as arrays at each call,
not stored as variables: the optimisers never see them and a compiled function never needs
retracing when they change.

Initializers here draw from a numpy ``Generator``, so a seed gives the same initial weights on
every backend.

Example:
    >>> import numpy as np, gymnasium as gym
    >>> rng = np.random.default_rng(0)
    >>> model = actor_critic(gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2), rng=rng,
    ...                      f="torch")
    >>> dist = model.actor(torch.zeros(5, 3), None, v=model.v["actor"])
    >>> dist.mode().shape
    torch.Size([5])
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Framework, Nest
from ivy_rl import settings as _s
from ivy_rl.distributions import Categorical, Deterministic, Normal, SquashedNormal

__all__ = [
    "orthogonal_init",
    "glorot_init",
    "ObservationEncoder",
    "MLPTorso",
    "GaussianHead",
    "SquashedGaussianHead",
    "DeterministicHead",
    "CategoricalHead",
    "ValueHead",
    "Actor",
    "Critic",
    "ActorCritic",
    "ActorCriticWithTargets",
    "polyak_update",
    "actor_critic",
    "ActorCriticModel",
    "space_kind",
    "check_observation_space",
]


# ----------------------------------------------------------------------------------------------
# Initializers drawing from a numpy generator
# ----------------------------------------------------------------------------------------------


def orthogonal_init(rng: np.random.Generator, gain: float = 1.0) -> Callable:
    """An ``ivy.Module`` initializer: orthogonal matrices scaled by ``gain`` (zeros for 1-D
    shapes), drawn from ``rng`` in float64 and converted to the module's framework.

    Args:
        rng: a numpy generator.
        gain: the scale (``sqrt(2)`` for ReLU torsos, 0.01 for policy outputs...).

    Returns:
        ``init(shape, *, fan_in, fan_out, dtype, device, f)``.

    Example:
        >>> import numpy as np, ivy
        >>> layer = ivy.Linear(4, 2, weight_init=orthogonal_init(np.random.default_rng(0), 0.01),
        ...                    f="jax")
        >>> w = np.asarray(layer.v["w"]); w.shape
        (2, 4)
        >>> np.round(w @ w.T, 6)                        # orthogonal rows, of norm 0.01
        array([[ 0.0001, -0.    ],
               [-0.    ,  0.0001]], dtype=float32)
    """

    def init(shape, *, fan_in=None, fan_out=None, dtype=None, device=None, f=None):
        xp = ivy.get_framework(f=f)
        shape = tuple(shape)
        if len(shape) < 2:
            return xp.zeros(shape, dtype=dtype or "float32", device=device)
        rows, cols = shape[0], math.prod(shape[1:])
        a = rng.standard_normal((max(rows, cols), min(rows, cols)))
        q, r = np.linalg.qr(a)
        q = q * np.sign(np.diag(r))
        q = q if rows >= cols else q.T
        return xp.asarray(gain * q.reshape(shape), dtype=dtype or "float32", device=device)

    return init


def glorot_init(rng: np.random.Generator) -> Callable:
    """An ``ivy.Module`` initializer: Glorot uniform weights drawn from ``rng`` (zeros for 1-D).

    Example:
        >>> import numpy as np, torch
        >>> torso = MLPTorso(4, (64, 64), weight_init=glorot_init(np.random.default_rng(0)),
        ...                  f="torch")
        >>> torso(torch.zeros(5, 4)).shape
        torch.Size([5, 64])
    """

    def init(shape, *, fan_in=None, fan_out=None, dtype=None, device=None, f=None):
        xp = ivy.get_framework(f=f)
        shape = tuple(shape)
        if len(shape) < 2:
            return xp.zeros(shape, dtype=dtype or "float32", device=device)
        fan_in = fan_in or shape[1]
        fan_out = fan_out or shape[0]
        limit = math.sqrt(6.0 / (fan_in + fan_out))
        values = rng.uniform(-limit, limit, size=shape)
        return xp.asarray(values, dtype=dtype or "float32", device=device)

    return init


def _default_init(weight_init: Callable | None, gain: float) -> Callable:
    if weight_init is not None:
        return weight_init
    return orthogonal_init(np.random.default_rng(0), gain)


# ----------------------------------------------------------------------------------------------
# Encoders and torsos
# ----------------------------------------------------------------------------------------------


class ObservationEncoder:
    """Normalises observations with statistics passed at each call:
    ``clip((obs - mean) / std, -clip, clip)``; with ``stats=None`` they pass unchanged.

    It has no variables, so it is a plain callable rather than an ``ivy.Module``: a module's
    empty variable dict would be one more node in every nest of the model's variables (and an
    empty dict in a nest splits the graph of ``torch.compile`` in torch 2.13).

    Args:
        observation_size: number of features of a flattened observation.
        clip: bound of the normalised values (None: no clipping).
        f: framework name or namespace of the arrays.

    Called as ``encoder(obs, stats)``: ``obs`` of shape ``[..., observation_size]``.

    Example:
        >>> import jax.numpy as jnp
        >>> enc = ObservationEncoder(3, f="jax")
        >>> enc(jnp.array([[3.0, 1.0, 61.0]]), {"mean": jnp.ones(3), "std": jnp.full(3, 2.0)})
        Array([[ 1.,  0., 10.]], dtype=float32)
    """

    def __init__(
        self, observation_size: int, *, clip: float | None = 10.0, f: Framework = None
    ) -> None:
        self._f = f
        self.observation_size = int(observation_size)
        self.out_size = self.observation_size
        self.clip = clip

    def __call__(self, obs: Array, stats: Nest = None) -> Array:
        if stats is None:
            return obs
        out = (obs - stats["mean"]) / stats["std"]
        if self.clip is None:
            return out
        return ivy.get_framework(obs, f=self._f).clip(out, -self.clip, self.clip)


class MLPTorso(ivy.Module):
    """Dense layers with an activation after each: ``[..., in] -> [..., sizes[-1]]``.

    Args:
        in_size: input features.
        sizes: hidden sizes, e.g. ``(64, 64)``.
        activation: an ivy function name (``'tanh'``, ``'relu'``) or a callable.
        weight_init: initializer of the weights (default: orthogonal, gain ``sqrt(2)``).
        dtype, device, f: as for ``ivy.Module``.

    Example:
        >>> torso = MLPTorso(4, (64, 64), "tanh", f="torch"); torso.out_size
        64
    """

    def __init__(
        self,
        in_size: int,
        sizes: Sequence[int] = (64, 64),
        activation: str | Callable = "tanh",
        *,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        sizes = tuple(int(s) for s in sizes)
        if not sizes:
            raise ValueError("MLPTorso needs at least one hidden size, e.g. sizes=(64, 64)")
        self.mlp = ivy.MLP(
            in_size,
            sizes[:-1],
            sizes[-1],
            activation=activation,
            output_activation=activation,
            weight_init=_default_init(weight_init, math.sqrt(2.0)),
            **self.build_args,
        )
        self.out_size = sizes[-1]

    def _forward(self, v, x):
        return self.mlp(x, v=v["mlp"])


# ----------------------------------------------------------------------------------------------
# Heads
# ----------------------------------------------------------------------------------------------


class GaussianHead(ivy.Module):
    """A diagonal Gaussian policy: the mean from a dense layer (``tanh`` by default, so actions
    centre in ``[-1, 1]``), the scale from a learned state-independent log-std (default) or
    from a dense layer (``state_dependent_scale=True``), clipped to ``[scale_min, scale_max]``.

    Example:
        >>> import jax.numpy as jnp
        >>> head = GaussianHead(64, 2, f="jax")
        >>> dist = head(jnp.ones((5, 64)))              # the torso's features: a Normal
        >>> dist.loc.shape, dist.scale[0]
        ((5, 2), Array([1., 1.], dtype=float32))
    """

    def __init__(
        self,
        in_size: int,
        action_size: int,
        *,
        loc_activation: str | None = "tanh",
        state_dependent_scale: bool = False,
        log_std_init: float = 0.0,
        scale_min: float = 1e-4,
        scale_max: float = math.exp(2.0),
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = _default_init(weight_init, 0.01)
        self.loc = ivy.Linear(in_size, action_size, weight_init=init, **self.build_args)
        self.state_dependent_scale = state_dependent_scale
        if state_dependent_scale:
            self.scale_layer = ivy.Linear(in_size, action_size, weight_init=init, **self.build_args)
        else:
            self.add_variable(
                "log_std", ivy.stateful.initializers.constant(log_std_init), (action_size,)
            )
        self.loc_activation = None if loc_activation is None else getattr(self._f, loc_activation)
        self.log_scale_bounds = (math.log(scale_min), math.log(scale_max))
        self.action_size = action_size

    def _distribution(self, loc, scale):
        return Normal(self._f, loc, scale)

    def _forward(self, v, x):
        xp = self._f
        loc = self.loc(x, v=v["loc"])
        if self.loc_activation is not None:
            loc = self.loc_activation(loc)
        if self.state_dependent_scale:
            log_std = self.scale_layer(x, v=v["scale_layer"])
        else:
            log_std = v["log_std"]
        log_std = xp.clip(log_std, *self.log_scale_bounds)
        scale = xp.broadcast_to(xp.exp(log_std), tuple(loc.shape))
        return self._distribution(loc, scale)


class SquashedGaussianHead(GaussianHead):
    """A ``tanh``-squashed Gaussian (actions in ``(-1, 1)``) with a state-dependent scale and a
    linear mean, as soft actor-critics use.

    Example:
        >>> import torch
        >>> head = SquashedGaussianHead(64, 2, f="torch")
        >>> dist = head(torch.ones(5, 64))              # a SquashedNormal
        >>> dist.sample(torch.randn(5, 2)).abs().max() < 1
        tensor(True)
    """

    def __init__(self, in_size: int, action_size: int, **kwargs) -> None:
        kwargs.setdefault("loc_activation", None)
        kwargs.setdefault("state_dependent_scale", True)
        kwargs.setdefault("scale_min", math.exp(-20.0))
        kwargs.setdefault("scale_max", math.exp(2.0))
        super().__init__(in_size, action_size, **kwargs)

    def _distribution(self, loc, scale):
        return SquashedNormal(self._f, loc, scale)


class DeterministicHead(ivy.Module):
    """A deterministic policy ``tanh(dense(x))``; sampling adds Gaussian exploration noise of
    scale ``noise_scale`` (see :class:`ivy_rl.distributions.Deterministic`).

    Example:
        >>> import jax.numpy as jnp
        >>> head = DeterministicHead(64, 2, f="jax")
        >>> head(jnp.ones((5, 64))).mode().shape
        (5, 2)
    """

    def __init__(
        self,
        in_size: int,
        action_size: int,
        *,
        noise_scale: float = 0.1,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = _default_init(weight_init, 0.01)
        self.layer = ivy.Linear(in_size, action_size, weight_init=init, **self.build_args)
        self.noise_scale = noise_scale
        self.action_size = action_size

    def _forward(self, v, x):
        actions = self._f.tanh(self.layer(x, v=v["layer"]))
        return Deterministic(self._f, actions, self.noise_scale)


class CategoricalHead(ivy.Module):
    """A categorical policy over ``num_actions`` discrete actions (logits from a dense layer).

    Example:
        >>> import torch
        >>> head = CategoricalHead(64, 3, f="torch")
        >>> gumbel = torch.tensor([[0.0, 5.0, 0.0]])    # Gumbel noise that favours action 1
        >>> head(torch.ones(1, 64)).sample(gumbel)
        tensor([1])
    """

    def __init__(
        self,
        in_size: int,
        num_actions: int,
        *,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = _default_init(weight_init, 0.01)
        self.logits = ivy.Linear(in_size, num_actions, weight_init=init, **self.build_args)
        self.num_actions = num_actions

    def _forward(self, v, x):
        return Categorical(self._f, self.logits(x, v=v["logits"]))


class ValueHead(ivy.Module):
    """A scalar value per input: ``[..., in] -> [...]``.

    Example:
        >>> import jax.numpy as jnp
        >>> ValueHead(64, f="jax")(jnp.ones((5, 64))).shape
        (5,)
    """

    def __init__(
        self, in_size: int, *, weight_init: Callable | None = None, dtype=None, device=None, f=None
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = _default_init(weight_init, 1.0)
        self.layer = ivy.Linear(in_size, 1, weight_init=init, **self.build_args)

    def _forward(self, v, x):
        return self.layer(x, v=v["layer"])[..., 0]


# ----------------------------------------------------------------------------------------------
# Actors and critics
# ----------------------------------------------------------------------------------------------


class Actor(ivy.Module):
    """``head(torso(encoder(obs, stats)))``: a policy returning a distribution.

    Called as ``actor(obs, obs_stats, v=...)``.

    Example:
        >>> actor = Actor(ObservationEncoder(4, f="torch"), MLPTorso(4, f="torch"),
        ...               CategoricalHead(64, 2, f="torch"))
        >>> actor(torch.zeros(1, 4), None).mode()       # no observation statistics: None
        tensor([0])
    """

    def __init__(self, encoder: Callable, torso: ivy.Module, head: ivy.Module) -> None:
        super().__init__(dtype=torso.dtype, device=torso.device, f=torso.f)
        self.encoder, self.torso, self.head = encoder, torso, head

    def _forward(self, v, obs, obs_stats=None):
        x = self.encoder(obs, obs_stats)
        return self.head(self.torso(x, v=v["torso"]), v=v["head"])


class Critic(ivy.Module):
    """``head(torso(encoder(obs, stats)))``: a state-value function.

    With return statistics ``{'mean', 'std'}`` the head predicts normalised values and the
    critic returns ``head * std + mean``; :meth:`normalized` gives the head's output.

    Called as ``critic(obs, obs_stats, return_stats, v=...)``.

    Example:
        >>> import numpy as np, jax.numpy as jnp, gymnasium as gym
        >>> model = actor_critic(gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2),
        ...                      rng=np.random.default_rng(0), f="jax")
        >>> critic, obs = model.critic, jnp.zeros((5, 3))
        >>> critic(obs, None, None, v=model.v["critic"]).shape          # [batch]
        (5,)
        >>> critic(obs, None, {"mean": 10.0, "std": 0.0}, v=model.v["critic"])
        Array([10., 10., 10., 10., 10.], dtype=float32)
    """

    def __init__(self, encoder: Callable, torso: ivy.Module, head: ivy.Module) -> None:
        super().__init__(dtype=torso.dtype, device=torso.device, f=torso.f)
        self.encoder, self.torso, self.head = encoder, torso, head

    def normalized(self, v: Nest, obs: Array, obs_stats: Nest = None) -> Array:
        """The head's output (normalised values when return statistics are used)."""
        x = self.encoder(obs, obs_stats)
        return self.head(self.torso(x, v=v["torso"]), v=v["head"])

    def _forward(self, v, obs, obs_stats=None, return_stats=None):
        out = self.normalized(v, obs, obs_stats)
        if return_stats is None:
            return out
        return out * return_stats["std"] + return_stats["mean"]


class ActorCritic(ivy.Module):
    """An actor and a critic; ``v = {'actor': ..., 'critic': ...}``.

    Example:
        >>> import numpy as np, gymnasium as gym
        >>> model = actor_critic(gym.spaces.Box(-1, 1, (3,)), gym.spaces.Discrete(2),
        ...                      rng=np.random.default_rng(0), f="jax")
        >>> sorted(model.v)
        ['actor', 'critic']
    """

    def __init__(self, actor: Actor, critic: Critic) -> None:
        super().__init__(dtype=actor.dtype, device=actor.device, f=actor.f)
        self.actor, self.critic = actor, critic

    def _forward(self, v, obs, obs_stats=None, return_stats=None):
        return (
            self.actor(obs, obs_stats, v=v["actor"]),
            self.critic(obs, obs_stats, return_stats, v=v["critic"]),
        )


class ActorCriticWithTargets(ActorCritic):
    """An actor-critic with target copies of its variables, ``target_v``, moved towards ``v``
    by :meth:`update_targets` (Polyak averaging), as off-policy agents use.

    Example:
        >>> import numpy as np, gymnasium as gym, ivy
        >>> env = gym.make("Pendulum-v1")
        >>> ac = actor_critic(env.observation_space, env.action_space, head="deterministic",
        ...                   rng=np.random.default_rng(0), f="numpy")
        >>> model = ActorCriticWithTargets(ac.actor, ac.critic)
        >>> before = model.target_v["critic"]["head"]["layer"]["b"]
        >>> model.v = ivy.nest.map_nest(lambda x: x + 1.0, model.v)   # as if after updates
        >>> model.update_targets(tau=0.5)                # half-way towards v
        >>> model.target_v["critic"]["head"]["layer"]["b"] - before
        array([0.5], dtype=float32)
    """

    def __init__(self, actor: Actor, critic: Critic) -> None:
        super().__init__(actor, critic)
        self.target_v = ivy.nest.map_nest(lambda x: x, self.v)

    def update_targets(self, tau: float = 0.005) -> None:
        """``target_v = (1 - tau) * target_v + tau * v``, in place."""
        self.target_v = polyak_update(self.target_v, self.v, tau)


def polyak_update(target_v: Nest, v: Nest, tau: float, *, f: Framework = None) -> Nest:
    """``(1 - tau) * target_v + tau * v`` for every leaf of two nests of the same structure.

    Args:
        target_v: the target nest.
        v: the online nest.
        tau: the step towards ``v`` (1: copy).
        f: framework (default: inferred from the leaves).

    Returns:
        The new target nest.

    Example:
        >>> import numpy as np
        >>> polyak_update({"w": np.zeros(2)}, {"w": np.ones(2)}, 0.005)
        {'w': array([0.005, 0.005])}
    """
    leaves = ivy.nest.flatten_nest(v)[0]
    xp = ivy.get_framework(leaves[0], f=f) if leaves else None
    return ivy.nest.multi_map_nest(
        lambda t, o: xp.add(xp.multiply(t, 1.0 - tau), xp.multiply(o, tau)), target_v, v
    )


# ----------------------------------------------------------------------------------------------
# Builders from Gymnasium spaces
# ----------------------------------------------------------------------------------------------

SUPPORTED_SPACES = ("Box", "Discrete")


def space_kind(space: Any, supported: Sequence[str] = SUPPORTED_SPACES, *, who: str = "") -> str:
    """``'Box'`` or ``'Discrete'`` for a Gymnasium action space; a clear error otherwise.

    Example:
        >>> import gymnasium
        >>> space_kind(gymnasium.spaces.Discrete(2))
        'Discrete'
    """
    import gymnasium as gym

    kind = None
    if isinstance(space, gym.spaces.Box) and len(space.shape) == 1:
        kind = "Box"
    elif isinstance(space, gym.spaces.Discrete):
        kind = "Discrete"
    elif isinstance(space, gym.spaces.MultiDiscrete) and len(space.shape) == 1:
        kind = "MultiDiscrete"
    if kind is None or kind not in supported:
        prefix = f"{who} " if who else ""
        raise TypeError(
            f"{prefix}does not support the action space {space!r}; supported action spaces: "
            f"{', '.join(supported)} (Box of one dimension, Discrete)"
        )
    return kind


def check_observation_space(space: Any, *, who: str = "") -> None:
    """Raise a TypeError unless ``space`` is a Box (of any shape; models flatten it), listing
    what is supported.

    Example:
        >>> import gymnasium
        >>> check_observation_space(gymnasium.spaces.Box(-1, 1, (4, 4)), who="PPO")  # fine
        >>> check_observation_space(gymnasium.spaces.Discrete(16), who="PPO")
        Traceback (most recent call last):
        TypeError: PPO does not support the observation space Discrete(16); ...
    """
    import gymnasium as gym

    if not isinstance(space, gym.spaces.Box):
        prefix = f"{who} " if who else ""
        raise TypeError(
            f"{prefix}does not support the observation space {space!r}; supported observation "
            "spaces: Box (of any shape, flattened). Wrap the environment to give Box "
            "observations (e.g. gymnasium.wrappers.FlattenObservation, or a one-hot of "
            "Discrete states)"
        )


def actor_critic(
    observation_space: Any,
    action_space: Any,
    *,
    rng: np.random.Generator,
    actor_sizes: Sequence[int] = (64, 64),
    critic_sizes: Sequence[int] = (64, 64),
    activation: str = "tanh",
    head: str | None = None,
    observation_clip: float | None = 10.0,
    log_std_init: float = 0.0,
    with_targets: bool = False,
    dtype: Any = None,
    device: Any = None,
    f: Framework = None,
) -> ActorCritic:
    """An actor-critic for Gymnasium spaces, initialised from ``rng`` (orthogonal weights:
    gain ``sqrt(2)`` in the torsos, 0.01 in the policy head, 1 in the value head).

    Args:
        observation_space: a Box of observations (flattened).
        action_space: a Box of one dimension (Gaussian head with ``tanh`` mean by default) or
            Discrete (categorical head).
        rng: numpy generator for the initial weights.
        actor_sizes, critic_sizes: hidden sizes of the torsos.
        activation: activation of the torsos.
        head: ``'gaussian'``, ``'squashed_gaussian'``, ``'deterministic'`` (Box) or
            ``'categorical'`` (Discrete); default by action space.
        observation_clip: bound of normalised observations.
        log_std_init: initial log standard deviation of Gaussian heads.
        with_targets: build an :class:`ActorCriticWithTargets`.
        dtype, device, f: as for ``ivy.Module``.

    Returns:
        The model.

    Example:
        >>> import numpy as np, gymnasium as gym, torch
        >>> env = gym.make("Pendulum-v1")
        >>> model = actor_critic(env.observation_space, env.action_space,
        ...                      rng=np.random.default_rng(0), f="torch")
        >>> type(model.actor.head).__name__, model.actor(torch.zeros(1, 3), None).mode().shape
        ('GaussianHead', torch.Size([1, 1]))
    """
    kind = space_kind(action_space, who="actor_critic")
    check_observation_space(observation_space, who="actor_critic")
    build = {"dtype": dtype, "device": device, "f": f}
    obs_size = int(np.prod(observation_space.shape))
    default_head = "gaussian" if kind == "Box" else "categorical"
    head = head or default_head
    heads_by_space = {
        "Box": ("gaussian", "squashed_gaussian", "deterministic"),
        "Discrete": ("categorical",),
    }
    if head not in heads_by_space[kind]:
        raise ValueError(
            f"head {head!r} does not fit a {kind} action space; choose one of "
            f"{heads_by_space[kind]}"
        )
    policy_init, torso_init = orthogonal_init(rng, 0.01), orthogonal_init(rng, math.sqrt(2.0))

    def torso(sizes):
        return MLPTorso(obs_size, sizes, activation, weight_init=torso_init, **build)

    def encoder():
        return ObservationEncoder(obs_size, clip=observation_clip, f=f)

    actor_torso = torso(actor_sizes)
    if head == "categorical":
        actor_head = CategoricalHead(
            actor_torso.out_size, int(action_space.n), weight_init=policy_init, **build
        )
    elif head == "deterministic":
        actor_head = DeterministicHead(
            actor_torso.out_size, action_space.shape[0], weight_init=policy_init, **build
        )
    else:
        cls = GaussianHead if head == "gaussian" else SquashedGaussianHead
        actor_head = cls(
            actor_torso.out_size,
            action_space.shape[0],
            log_std_init=log_std_init,
            weight_init=policy_init,
            **build,
        )
    actor = Actor(encoder(), actor_torso, actor_head)
    critic_torso = torso(critic_sizes)
    critic = Critic(
        encoder(),
        critic_torso,
        ValueHead(critic_torso.out_size, weight_init=orthogonal_init(rng, 1.0), **build),
    )
    cls = ActorCriticWithTargets if with_targets else ActorCritic
    return cls(actor, critic)


class ActorCriticModel:
    """The model part of the on-policy agents (A2C, PPO, TRPO): what actor-critic to build
    (:func:`actor_critic`) and which normalisers to keep, once the spaces are known.

    After :meth:`initialize`, ``actor``, ``critic`` and ``v`` (the initial variables
    ``{'actor', 'critic'}``) are those of the built :class:`ActorCritic`.

    Args:
        hidden_sizes: hidden sizes of the actor's torso.
        critic_hidden_sizes: of the critic's torso (None: ``hidden_sizes``).
        activation: activation of the torsos.
        head: policy head (``'gaussian'``, ``'squashed_gaussian'`` for Box actions,
            ``'categorical'`` for Discrete); None: by action space.
        log_std_init: initial log standard deviation of Gaussian heads.
        normalize_observations: normalise observations by their running mean and std.
        normalize_returns: the critic predicts returns normalised by their running mean and std.

    Example:
        >>> model = ActorCriticModel(hidden_sizes=(64, 64), activation="tanh")
        >>> agent = ivy_rl.PPO(model=model)
    """

    settings = {
        "hidden_sizes": _s.Setting("sizes", meaning="hidden sizes of the actor's torso"),
        "critic_hidden_sizes": _s.CRITIC_SIZES,
        "activation": _s.ACTIVATION,
        "head": _s.Setting(
            "str",
            optional=True,
            choices=("gaussian", "squashed_gaussian", "categorical"),
            meaning="policy head (None: by action space)",
        ),
        "log_std_init": _s.Setting("float", meaning="initial log std of Gaussian heads"),
        "normalize_observations": _s.Setting(
            "bool", meaning="normalise observations by their running mean and std"
        ),
        "normalize_returns": _s.Setting("bool", meaning="the critic predicts normalised returns"),
    }

    def __init__(
        self,
        hidden_sizes: Sequence[int] = (64, 64),
        critic_hidden_sizes: Sequence[int] | None = None,
        activation: str = "tanh",
        head: str | None = None,
        log_std_init: float = 0.0,
        normalize_observations: bool = True,
        normalize_returns: bool = False,
    ) -> None:
        if head == "deterministic":
            raise ValueError(
                "ActorCriticModel: the on-policy agents need a stochastic policy head "
                "(log-probabilities); choose head='gaussian' or 'squashed_gaussian'"
            )
        self.hidden_sizes = tuple(hidden_sizes)
        self.critic_hidden_sizes = (
            None if critic_hidden_sizes is None else tuple(critic_hidden_sizes)
        )
        self.activation = activation
        self.head = head
        self.log_std_init = log_std_init
        self.normalize_observations = normalize_observations
        self.normalize_returns = normalize_returns

    def initialize(
        self,
        observation_space: Any,
        action_space: Any,
        *,
        rng: np.random.Generator,
        dtype: Any = None,
        device: Any = None,
        f: Framework = None,
    ) -> ActorCriticModel:
        """Build the actor-critic for the spaces, its weights drawn from ``rng``."""
        self.module = actor_critic(
            observation_space,
            action_space,
            rng=rng,
            actor_sizes=self.hidden_sizes,
            critic_sizes=self.critic_hidden_sizes or self.hidden_sizes,
            activation=self.activation,
            head=self.head,
            log_std_init=self.log_std_init,
            dtype=dtype,
            device=device,
            f=f,
        )
        self.actor, self.critic, self.v = self.module.actor, self.module.critic, self.module.v
        return self
