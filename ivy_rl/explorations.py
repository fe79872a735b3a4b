"""Exploration of off-policy agents, on the host in numpy: noise added to deterministic actions
(normal, Ornstein-Uhlenbeck, none) and epsilon-greedy choices for value-based agents.

Every random number comes from the agent's numpy generator (passed in), so a seed gives the same
actions on every backend and a checkpoint restores the exploration exactly (:meth:`state_dict`).
Actions of Box spaces are in ``[-1, 1]`` here (the agent rescales them to the space's bounds).

Example:
    >>> import numpy as np
    >>> rng = np.random.default_rng(0)              # the agent's generator
    >>> noise = make_exploration("ornstein_uhlenbeck", scale=0.2)
    >>> noise(np.zeros((2, 1)), rng)                # the policy's actions, [workers, action_size]
    array([[ 0.0025146],
           [-0.0026421]])
    >>> noise.reset(np.array([True, False]))        # worker 0's episode ended: its noise restarts
    >>> noise.state
    array([[ 0.       ],
           [-0.0026421]])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ivy_rl import settings as _s

__all__ = [
    "NoNoise",
    "NormalNoise",
    "OrnsteinUhlenbeckNoise",
    "EpsilonGreedy",
    "EXPLORATIONS",
    "make_exploration",
]


_START = _s.Setting("int", 0, meaning="steps of random actions at the start")
SCALE = _s.Setting("float", 0.0, meaning="scale of the exploration noise")


class NoNoise:
    """Actions as the policy gives them (the exploration part of agents whose policy samples:
    SAC, MPO).

    Args:
        start_steps: environment steps of uniformly random actions before the policy acts.

    Example:
        >>> import numpy as np
        >>> NoNoise()(np.zeros((2, 1)), np.random.default_rng(0))
        array([[0.],
               [0.]])
    """

    settings = {"start_steps": _START}

    #: the name of the exploration in the flat settings (``exploration='none'``)
    name = "none"

    def __init__(self, *, start_steps: int = 0) -> None:
        self.start_steps = _start_steps(start_steps, type(self).__name__)

    def __call__(
        self,
        actions: np.ndarray,
        rng: np.random.Generator,
        *,
        num_actions: Any = None,
        steps: int = 0,
    ) -> np.ndarray:
        """The actions to take given the policy's ``actions`` (``num_actions`` and ``steps``:
        read by ε-greedy explorations only)."""
        return np.asarray(actions)

    def reset(self, resets: Any) -> None:
        """Forget the state of the workers whose episode ended (nothing here)."""

    def state_dict(self) -> dict[str, np.ndarray]:
        return {}

    def load_state_dict(self, state: dict[str, Any]) -> None:
        pass


class NormalNoise(NoNoise):
    """``clip(a + scale * N(0, 1), -1, 1)``, independent at each step.

    Args:
        scale: standard deviation of the noise (actions are in ``[-1, 1]``).

    Example:
        >>> import numpy as np
        >>> NormalNoise(0.1)(np.array([[0.0], [0.98]]), np.random.default_rng(0))
        array([[0.01257302],
               [0.96678951]])
    """

    settings = {"scale": SCALE, "start_steps": _START}

    name = "normal"

    def __init__(self, scale: float = 0.1, *, start_steps: int = 0) -> None:
        if scale < 0:
            raise ValueError(f"NormalNoise: scale must be >= 0, got {scale}")
        super().__init__(start_steps=start_steps)
        self.scale = float(scale)

    def __call__(self, actions, rng, *, num_actions=None, steps=0):
        actions = np.asarray(actions)
        noise = rng.standard_normal(actions.shape)
        return np.clip(actions + self.scale * noise, -1.0, 1.0).astype(actions.dtype)


class OrnsteinUhlenbeckNoise(NoNoise):
    """Temporally correlated noise, one process per worker, restarted at each episode:
    ``x <- x - theta * x * dt + scale * sqrt(dt) * N(0, 1)``, actions ``clip(a + x, -1, 1)``.

    Args:
        scale: σ of the process.
        theta: the pull towards 0.
        dt: the time step.

    Example:
        >>> import numpy as np
        >>> noise = OrnsteinUhlenbeckNoise(scale=0.2, theta=0.15, dt=0.01)
        >>> noise(np.zeros((2, 1)), np.random.default_rng(0))
        array([[ 0.0025146],
               [-0.0026421]])
    """

    settings = {"scale": SCALE, "start_steps": _START}

    name = "ornstein_uhlenbeck"

    def __init__(
        self, scale: float = 0.1, *, theta: float = 0.15, dt: float = 1e-2, start_steps: int = 0
    ) -> None:
        if scale < 0 or theta < 0 or dt <= 0:
            raise ValueError(
                "OrnsteinUhlenbeckNoise: need scale >= 0, theta >= 0 and dt > 0, got "
                f"scale={scale}, theta={theta}, dt={dt}"
            )
        super().__init__(start_steps=start_steps)
        self.scale, self.theta, self.dt = float(scale), float(theta), float(dt)
        self.state: np.ndarray | None = None

    def __call__(self, actions, rng, *, num_actions=None, steps=0):
        actions = np.asarray(actions)
        if self.state is None or self.state.shape != actions.shape:
            self.state = np.zeros(actions.shape)
        noise = rng.standard_normal(actions.shape)
        self.state = (
            self.state - self.theta * self.state * self.dt + self.scale * np.sqrt(self.dt) * noise
        )
        return np.clip(actions + self.state, -1.0, 1.0).astype(actions.dtype)

    def reset(self, resets: Any) -> None:
        if self.state is not None:
            self.state[np.asarray(resets, bool)] = 0.0

    def state_dict(self) -> dict[str, np.ndarray]:
        return {} if self.state is None else {"state": self.state.copy()}

    def load_state_dict(self, state: dict[str, Any]) -> None:
        self.state = np.array(state["state"], np.float64) if "state" in state else None


class EpsilonGreedy(NoNoise):
    """For value-based agents: a uniformly random action with probability ε, else the greedy
    one; ε falls linearly from ``start`` to ``end`` over ``decay_steps`` environment steps.

    Args:
        start, end: ε at the first step and after ``decay_steps``.
        decay_steps: environment steps (all workers together) of the linear decay.
        start_steps: environment steps of uniformly random actions before the first greedy one.

    Example:
        >>> import numpy as np
        >>> explore = EpsilonGreedy(1.0, 0.05, 10_000)
        >>> explore.epsilon(0), explore.epsilon(5_000), explore.epsilon(20_000)
        (1.0, 0.525, 0.05)
        >>> greedy = np.zeros(6, int)                       # the greedy actions of 6 workers
        >>> explore(greedy, np.random.default_rng(0), num_actions=4, steps=0)   # ε = 1: random
        array([2, 2, 2, 3, 3, 0])
    """

    settings = {
        "start": _s.Setting("float", 0.0, 1.0, meaning="initial epsilon"),
        "end": _s.Setting("float", 0.0, 1.0, meaning="final epsilon"),
        "decay_steps": _s.Setting("int", 0, meaning="steps of epsilon's linear decay"),
        "start_steps": _START,
    }

    name = "epsilon_greedy"

    def __init__(
        self,
        start: float = 1.0,
        end: float = 0.05,
        decay_steps: int = 10_000,
        *,
        start_steps: int = 0,
    ) -> None:
        super().__init__(start_steps=start_steps)
        if not (0.0 <= end <= 1.0 and 0.0 <= start <= 1.0) or decay_steps < 0:
            raise ValueError(
                "EpsilonGreedy: need 0 <= start, end <= 1 and decay_steps >= 0, got "
                f"start={start}, end={end}, decay_steps={decay_steps}"
            )
        self.start, self.end, self.decay_steps = float(start), float(end), int(decay_steps)

    def epsilon(self, steps: int) -> float:
        """ε after ``steps`` environment steps."""
        if self.decay_steps == 0:
            return self.end
        fraction = min(steps / self.decay_steps, 1.0)
        return (1.0 - fraction) * self.start + fraction * self.end  # exactly end once decayed

    def __call__(
        self,
        greedy: np.ndarray,
        rng: np.random.Generator,
        *,
        num_actions: Any = None,
        steps: int = 0,
    ) -> np.ndarray:
        """``greedy`` actions ``[workers, *dims]`` (indices) with random ones mixed in; with
        several action dimensions (``num_actions`` a sequence), each is randomised alone."""
        greedy = np.asarray(greedy)
        sizes = np.broadcast_to(np.asarray(num_actions), greedy.shape[1:])
        explore = rng.random(greedy.shape) < self.epsilon(steps)
        random = np.floor(rng.random(greedy.shape) * sizes).astype(greedy.dtype)
        return np.where(explore, random, greedy)


EXPLORATIONS = {
    "normal": NormalNoise,
    "ornstein_uhlenbeck": OrnsteinUhlenbeckNoise,
    "none": NoNoise,
}


def make_exploration(name: str = "normal", scale: float = 0.1, *, start_steps: int = 0) -> NoNoise:
    """An exploration noise by name: ``'normal'``, ``'ornstein_uhlenbeck'`` or ``'none'``
    (``start_steps``: steps of uniformly random actions first).

    Example:
        >>> ivy_rl.explorations.make_exploration("normal", 0.1, start_steps=1000).start_steps
        1000
    """
    if name not in EXPLORATIONS:
        raise ValueError(
            f"unknown exploration {name!r}; choose one of {', '.join(map(repr, EXPLORATIONS))}"
        )
    cls = EXPLORATIONS[name]
    return cls(start_steps=start_steps) if cls is NoNoise else cls(scale, start_steps=start_steps)


def _start_steps(value: Any, who: str) -> int:
    if isinstance(value, bool) or int(value) != value or value < 0:
        raise ValueError(f"{who}: start_steps must be an integer >= 0, got {value!r}")
    return int(value)


make_exploration.settings = {
    "name": _s.Setting("str", choices=tuple(EXPLORATIONS), meaning="the exploration noise"),
    "scale": SCALE,
    "start_steps": _START,
}
