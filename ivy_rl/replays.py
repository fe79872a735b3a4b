"""A segment replay for on-policy agents: the last ``size`` steps of every worker, how their
returns are computed, and the orders of the mini-batches drawn from them.

Buffers are numpy arrays ``[size, workers, ...]`` on the host (a stored value may also be a
dict of arrays, e.g. the parameters of the acting policy, kept as a dict of buffers). The
agents copy a full segment to their device once per update and compute λ-returns and
advantages from it inside their compiled update (:mod:`ivy_rl.returns`, with partial-episode
bootstrapping, with the replay's ``discount`` and ``trace_decay``); the mini-batch orders come
from the agent's numpy generator, so every backend sees the same mini-batches.

Example:
    >>> import numpy as np
    >>> seg = Segment(size=4, batch_size=4, batch_iterations=2)
    >>> for t in range(4):                              # one step of 2 workers at a time
    ...     seg.store(observations=np.zeros((2, 3)), actions=np.zeros((2, 1)),
    ...               rewards=np.ones(2), resets=np.zeros(2), terminations=np.zeros(2))
    >>> seg.ready(), seg.buffers["observations"].shape  # full: [size, workers, ...]
    (True, (4, 2, 3))
    >>> seg.batch_orders(np.random.default_rng(0)).shape   # 2 passes of 2 mini-batches of 4
    (4, 4)
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ivy_rl import settings as _s
from ivy_rl.buffers import TransitionReplay

__all__ = ["Segment", "Transitions", "Rollouts"]


class Rollouts:
    """The replay part of the agents that learn through ivy_gym's gradients (APG, SHAC): no
    stored data (the differentiable rollouts are the data), but their shape and cadence.

    Args:
        batch_size: rollouts per update (SHAC: simulated environments carried across updates).
        horizon: steps per rollout.
        update_every: trainer steps between updates.
        discount: γ of the rollouts' returns.

    Example:
        >>> replay = ivy_rl.replays.Rollouts(batch_size=16, horizon=32, update_every=1)
        >>> ivy_rl.agents.APG(replay=replay).config["horizon"]
        32
    """

    settings = {
        "batch_size": _s.Setting("int", 1, meaning="rollouts per update"),
        "horizon": _s.Setting("int", 1, meaning="steps of the differentiable rollouts"),
        "update_every": _s.Setting("int", 1, meaning="trainer steps between updates"),
        "discount": _s.DISCOUNT,
    }

    def __init__(
        self,
        batch_size: int = 64,
        horizon: int = 32,
        update_every: int = 16,
        discount: float = 0.99,
    ) -> None:
        for name, value in (
            ("batch_size", batch_size),
            ("horizon", horizon),
            ("update_every", update_every),
        ):
            if not isinstance(value, int) or isinstance(value, bool) or value < 1:
                raise ValueError(f"Rollouts: {name} must be a positive integer, got {value!r}")
        if not 0.0 <= discount <= 1.0:
            raise ValueError(f"Rollouts: discount must be in [0, 1], got {discount}")
        self.batch_size, self.horizon, self.update_every = batch_size, horizon, update_every
        self.discount = float(discount)


class Transitions(TransitionReplay):
    """The replay part of the off-policy agents (DDPG, TD3, SAC, MPO, D4PG, DQN): a
    :class:`~ivy_rl.buffers.TransitionReplay` of the last ``size`` transitions, with when and
    how the agent learns from it.

    Args:
        size: transitions kept (all workers together).
        return_steps: n of the n-step returns.
        batch_size: transitions per optimisation step.
        batch_iterations: optimisation steps per update.
        discount: γ of the n-step returns.
        update_after: environment steps before the first update.
        update_every: environment steps between updates.

    Example:
        >>> replay = ivy_rl.replays.Transitions(100_000, batch_size=128, update_every=50)
        >>> ivy_rl.agents.SAC(replay=replay).config["batch_size"]
        128
    """

    settings = {
        "size": _s.Setting("int", 1, meaning="transitions kept by the replay"),
        "return_steps": _s.Setting("int", 1, meaning="n of the n-step returns"),
        "batch_size": _s.Setting("int", 1, meaning="transitions per optimisation step"),
        "batch_iterations": _s.Setting("int", 1, meaning="optimisation steps per update"),
        "discount": _s.DISCOUNT,
        "update_after": _s.Setting("int", 0, meaning="steps before the first update"),
        "update_every": _s.Setting("int", 1, meaning="environment steps between updates"),
    }

    def __init__(
        self,
        size: int = 1_000_000,
        *,
        return_steps: int = 1,
        batch_size: int = 256,
        batch_iterations: int = 50,
        discount: float = 0.99,
        update_after: int = 1000,
        update_every: int = 50,
    ) -> None:
        super().__init__(size, return_steps=return_steps)
        for name, value, low in (
            ("batch_size", batch_size, 1),
            ("batch_iterations", batch_iterations, 1),
            ("update_after", update_after, 0),
            ("update_every", update_every, 1),
        ):
            if isinstance(value, bool) or int(value) != value or value < low:
                raise ValueError(f"Transitions: {name} must be an integer >= {low}, got {value!r}")
        if not 0.0 <= discount <= 1.0:
            raise ValueError(f"Transitions: discount must be in [0, 1], got {discount}")
        self.batch_size, self.batch_iterations = int(batch_size), int(batch_iterations)
        self.discount = float(discount)
        self.update_after, self.update_every = int(update_after), int(update_every)


class Segment:
    """The replay of on-policy agents.

    Args:
        size: steps per worker in a segment (the update happens when it is full).
        batch_size: transitions per mini-batch (None: the whole segment).
        batch_iterations: passes over the segment (epochs) per update.
        discount: γ of the returns.
        trace_decay: λ of the λ-returns.
        normalize_advantages: standardise the advantages of each segment.

    Example:
        >>> seg = Segment(size=2048, batch_size=64, batch_iterations=10)
    """

    settings = {
        "size": _s.Setting("int", 1, meaning="steps per worker between updates"),
        "batch_size": _s.Setting(
            "int", 1, optional=True, meaning="transitions per mini-batch (None: the segment)"
        ),
        "batch_iterations": _s.Setting("int", 1, meaning="passes over the segment per update"),
        "discount": _s.DISCOUNT,
        "trace_decay": _s.TRACE_DECAY,
        "normalize_advantages": _s.Setting("bool", meaning="standardise each segment's advantages"),
    }

    def __init__(
        self,
        size: int = 2048,
        *,
        batch_size: int | None = None,
        batch_iterations: int = 10,
        discount: float = 0.99,
        trace_decay: float = 0.95,
        normalize_advantages: bool = True,
    ) -> None:
        if size < 1:
            raise ValueError(f"Segment: size must be >= 1, got {size}")
        if batch_size is not None and batch_size < 1:
            raise ValueError(f"Segment: batch_size must be >= 1 or None, got {batch_size}")
        if batch_iterations < 1:
            raise ValueError(f"Segment: batch_iterations must be >= 1, got {batch_iterations}")
        for name, value in (("discount", discount), ("trace_decay", trace_decay)):
            if not 0.0 <= value <= 1.0:
                raise ValueError(f"Segment: {name} must be in [0, 1], got {value}")
        self.size = int(size)
        self.batch_size = batch_size
        self.batch_iterations = int(batch_iterations)
        self.discount, self.trace_decay = float(discount), float(trace_decay)
        self.normalize_advantages = bool(normalize_advantages)
        self.buffers: dict[str, Any] | None = None
        self.index = 0

    def ready(self) -> bool:
        """Whether the segment is full."""
        return self.index == self.size

    def store(self, **arrays: Any) -> None:
        """Store one step of every worker: arrays ``[workers, ...]`` (or dicts of them) by
        name."""
        if self.index >= self.size:
            raise RuntimeError("Segment is full: learn from it and clear() it before storing more")
        if self.buffers is None:
            self.buffers = {k: _allocate(self.size, v) for k, v in arrays.items()}
        for key, value in arrays.items():
            if isinstance(value, dict):
                for name, part in value.items():
                    self.buffers[key][name][self.index] = part
            else:
                self.buffers[key][self.index] = value
        self.index += 1

    @property
    def workers(self) -> int:
        if self.buffers is None:
            return 0
        return next(b for b in self.buffers.values() if not isinstance(b, dict)).shape[1]

    def batch_orders(self, rng: np.random.Generator) -> np.ndarray:
        """The mini-batches of all passes (epochs) of an update, as indices into the segment
        flattened to ``[size * workers]`` (index ``t * workers + w``): an int32 array
        ``[passes * batches_per_pass, batch_size]``. Each pass draws a permutation from ``rng``
        and cuts it into full mini-batches (the remainder is left out); without mini-batches
        (``batch_size`` None or at least the segment) each pass is one row ``0 .. N - 1`` and
        nothing is drawn.

        Example:
            Two passes over 4 steps of 2 workers, in mini-batches of 3 (2 per pass, the
            remaining 2 transitions left out):

            >>> import numpy as np
            >>> seg = Segment(4, batch_size=3, batch_iterations=2)
            >>> for t in range(4):
            ...     seg.store(rewards=np.ones(2))
            >>> seg.batch_orders(np.random.default_rng(0))
            array([[2, 4, 3],
                   [6, 5, 0],
                   [6, 2, 7],
                   [4, 5, 1]], dtype=int32)
        """
        total = self.size * self.workers
        rows = []
        for _ in range(self.batch_iterations):
            if self.batch_size is None or self.batch_size >= total:
                rows.append(np.arange(total))
                continue
            order = rng.permutation(total)
            count = total // self.batch_size
            rows.extend(order[: count * self.batch_size].reshape(count, self.batch_size))
        width = total if self.batch_size is None else min(self.batch_size, total)
        return np.asarray(rows, np.int32).reshape(len(rows), width)

    def clear(self) -> None:
        """Start a new segment."""
        self.index = 0

    def state_dict(self) -> dict[str, Any]:
        """The buffers (a nest of numpy arrays) and the write position."""
        state: dict[str, Any] = {"index": np.asarray(self.index, np.int64)}
        if self.buffers is not None:
            state["buffers"] = self.buffers
        return state

    def load_state_dict(self, state: dict[str, Any]) -> None:
        """Restore :meth:`state_dict`."""
        self.index = int(state["index"])
        buffers = state.get("buffers")
        self.buffers = None if not buffers else _copy(buffers)


def _allocate(size: int, value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _allocate(size, v) for k, v in value.items()}
    value = np.asarray(value)
    return np.zeros((size,) + value.shape, value.dtype)


def _copy(buffers: dict[str, Any]) -> dict[str, Any]:
    return {k: _copy(v) if isinstance(v, dict) else np.array(v) for k, v in buffers.items()}
