"""A segment replay for on-policy agents: the last ``size`` steps of every worker, and the
orders of the mini-batches drawn from them.

Buffers are numpy arrays ``[size, workers, ...]`` on the host. The agents compute λ-returns and
advantages from them inside their compiled update (:mod:`ivy_rl.returns`, with partial-episode
bootstrapping); the mini-batch orders come from the agent's numpy generator, so every backend
sees the same mini-batches.

Example:
    >>> seg = Segment(size=4, batch_size=8, batch_iterations=2)
    >>> seg.store(observations=obs, actions=a, rewards=r, resets=d, terminations=t)
    >>> seg.ready()
    False
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["Segment"]


class Segment:
    """The replay of on-policy agents.

    Args:
        size: steps per worker in a segment (the update happens when it is full).
        batch_size: transitions per mini-batch (None: the whole segment).
        batch_iterations: passes over the segment (epochs) per update.

    Example:
        >>> seg = Segment(size=2048, batch_size=64, batch_iterations=10)
    """

    def __init__(
        self,
        size: int = 2048,
        *,
        batch_size: int | None = None,
        batch_iterations: int = 10,
    ) -> None:
        if size < 1:
            raise ValueError(f"Segment: size must be >= 1, got {size}")
        if batch_size is not None and batch_size < 1:
            raise ValueError(f"Segment: batch_size must be >= 1 or None, got {batch_size}")
        self.size = int(size)
        self.batch_size = batch_size
        self.batch_iterations = int(batch_iterations)
        self.buffers: dict[str, np.ndarray] | None = None
        self.index = 0

    def ready(self) -> bool:
        """Whether the segment is full."""
        return self.index == self.size

    def store(self, **arrays: Any) -> None:
        """Store one step of every worker: arrays ``[workers, ...]`` by name."""
        if self.index >= self.size:
            raise RuntimeError("Segment is full: learn from it and clear() it before storing more")
        if self.buffers is None:
            self.buffers = {
                k: np.zeros((self.size,) + np.shape(v), np.asarray(v).dtype)
                for k, v in arrays.items()
            }
        for key, value in arrays.items():
            self.buffers[key][self.index] = value
        self.index += 1

    @property
    def workers(self) -> int:
        return 0 if self.buffers is None else next(iter(self.buffers.values())).shape[1]

    def batch_orders(self, rng: np.random.Generator) -> np.ndarray:
        """The mini-batches of all passes (epochs) of an update, as indices into the segment
        flattened to ``[size * workers]`` (index ``t * workers + w``): an int32 array
        ``[passes * batches_per_pass, batch_size]``. Each pass draws a permutation from ``rng``
        and cuts it into full mini-batches (the remainder is left out); without mini-batches
        (``batch_size`` None or at least the segment) each pass is one row ``0 .. N - 1`` and
        nothing is drawn.

        Example:
            >>> Segment(4, batch_size=3, batch_iterations=2).batch_orders(rng).shape  # 2 workers
            (4, 3)
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

    def state_dict(self) -> dict[str, np.ndarray]:
        """The buffers and the write position."""
        state = {"index": np.asarray(self.index, np.int64)}
        for key, value in (self.buffers or {}).items():
            state[f"buffers/{key}"] = value
        return state

    def load_state_dict(self, state: dict[str, Any]) -> None:
        self.index = int(state["index"])
        buffers = {k.split("/", 1)[1]: np.array(v) for k, v in state.items() if "/" in k}
        self.buffers = buffers or None
