"""A transition replay for off-policy agents, held in the backend's arrays on the agent's
device, with n-step returns computed where the batches are read (inside the compiled update).

Each environment step of every worker is one row of arrays ``[capacity * workers, ...]``
(row ``r``, worker ``w`` at index ``r * workers + w``): a ring over the last ``capacity`` steps of
each worker. Steps are staged on the host (in preallocated arrays, written in place) and written
to the backend's arrays at :meth:`TransitionReplay.flush` (before each update), so that acting
costs no device write. A flush costs what the new rows cost, whatever the replay's size: where
the backend's arrays are mutable (torch, numpy) it assigns them in place; elsewhere (jax,
tensorflow) a pure writer, :func:`put_ring_rows`, replaces those rows with ``ivy.put_rows``,
which a compiler that reuses the donated buffers (``ivy.compile_fn(..., donate_argnums=0)`` on
jax) writes in place.

A batch is drawn as windows of ``return_steps`` consecutive rows of one worker
(:meth:`TransitionReplay.windows`, from the agent's numpy generator, so every backend reads the
same transitions); :func:`n_step_batch` turns them into n-step transitions inside compiled code:
the rewards summed with discounts until the window or the episode ends, and the observation and
discount to bootstrap from. An episode cut by a time limit (a reset that is not a termination)
is bootstrapped from its last true next observation; one that terminated is not
(partial-episode bootstrapping, Pardo et al., 2018).

Example:
    Four steps of two workers, each with reward 1, then 3-step transitions:

    >>> import numpy as np, ivy
    >>> replay = TransitionReplay(1000, return_steps=3)
    >>> for t in range(4):
    ...     replay.store(observations=np.full((2, 1), float(t)), actions=np.zeros((2, 1)),
    ...                  rewards=np.ones(2), next_observations=np.full((2, 1), t + 1.0),
    ...                  resets=np.zeros(2), terminations=np.zeros(2))
    >>> replay.flush(ivy.numpy, device="cpu")           # or ivy.torch, ivy.jax, ...
    >>> indices = replay.windows(np.random.default_rng(0), batches=5, batch_size=4)
    >>> indices.shape                                   # [batches, return_steps, batch_size]
    (5, 3, 4)
    >>> batch = n_step_batch(ivy.numpy, replay.arrays, indices[0], discount=0.5)
    >>> batch["returns"], batch["discounts"]            # 1 + 0.5 + 0.25, and 0.5 ** 3
    (array([1.75, 1.75, 1.75, 1.75]), array([0.125, 0.125, 0.125, 0.125]))
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Framework

__all__ = ["TransitionReplay", "n_step_batch", "put_ring_rows", "held_dtype"]

_FLAGS = ("resets", "terminations")


class TransitionReplay:
    """The last ``size`` transitions (all workers together) in the backend's arrays.

    Args:
        size: transitions kept in total (``size // workers`` steps of each worker; the oldest
            are overwritten).
        return_steps: n of the n-step returns (the length of the windows drawn).

    Stored per step (``[workers, ...]``): ``observations``, ``actions``, ``rewards``,
    ``next_observations`` (true next observations, before resets), ``resets`` (the episode
    ended for any reason) and ``terminations`` (it ended in a terminal state).

    Example:
        >>> replay = TransitionReplay(1_000_000, return_steps=1)
        >>> replay.ready()                              # nothing stored yet
        False
    """

    def __init__(self, size: int = 1_000_000, *, return_steps: int = 1) -> None:
        if int(size) != size or size < 1:
            raise ValueError(f"TransitionReplay: size must be an integer >= 1, got {size!r}")
        if int(return_steps) != return_steps or return_steps < 1:
            raise ValueError(
                f"TransitionReplay: return_steps must be an integer >= 1, got {return_steps!r}"
            )
        self.size = int(size)
        self.return_steps = int(return_steps)
        self.workers = 0
        self.capacity = 0
        self.arrays: dict[str, Array] | None = None  # the backend's arrays, after flush
        # staged steps: preallocated host arrays [room, workers, ...], filled in place
        self._staging: dict[str, np.ndarray] = {}
        self._count = 0  # staged steps
        self._specs: dict[str, tuple[tuple[int, ...], np.dtype]] = {}
        self.position = 0  # the ring row that the next step goes to
        self.stored = 0  # steps of each worker in the ring (at most capacity)
        self._writer: Callable | None = None

    # ------------------------------------------------------------------------------------------
    # Writing
    # ------------------------------------------------------------------------------------------

    def store(self, **arrays: Any) -> None:
        """Stage one step of every worker: arrays ``[workers, ...]`` by name (always the same
        names, shapes and dtypes)."""
        if not self._specs:
            staged = {k: np.asarray(v) for k, v in arrays.items()}
            workers = {v.shape[0] if v.ndim else None for v in staged.values()}
            if len(workers) != 1 or None in workers:
                raise ValueError(
                    "TransitionReplay.store: every array must be [workers, ...] with the same "
                    f"number of workers, got shapes { {k: v.shape for k, v in staged.items()} }"
                )
            self.workers = workers.pop()
            self.capacity = max(self.size // self.workers, self.return_steps)
            self._specs = {k: (v.shape[1:], v.dtype) for k, v in staged.items()}
        elif arrays.keys() != self._specs.keys():
            raise ValueError(
                f"TransitionReplay.store: got {sorted(arrays)}, expected {sorted(self._specs)}"
            )
        if self._count == len(next(iter(self._staging.values()), ())):
            self._grow_staging()
        row = self._count
        for key, value in arrays.items():
            shape = self._specs[key][0]
            value_shape = np.shape(value)
            if value_shape != (self.workers, *shape):
                raise ValueError(
                    f"TransitionReplay.store: {key} has shape {value_shape}, expected "
                    f"{(self.workers, *shape)}"
                )
            self._staging[key][row] = value  # cast to the staged dtype in place
        self._count += 1

    def _grow_staging(self, room: int | None = None) -> None:
        """Room for twice as many staged steps (at least 64), keeping those staged."""
        room = room or max(64, 2 * self._count)
        for key, (shape, dtype) in self._specs.items():
            grown = np.zeros((room, self.workers, *shape), dtype)
            if key in self._staging:
                grown[: self._count] = self._staging[key][: self._count]
            self._staging[key] = grown

    @property
    def steps(self) -> int:
        """Steps of each worker available to batches (flushed and staged)."""
        return min(self.stored + self._count, self.capacity)

    def flush(
        self,
        xp: Any,
        *,
        device: Any = None,
        dtypes: dict[str, Any] | None = None,
        chunk_steps: int | None = None,
        compile: Callable | None = None,
    ) -> None:
        """Write the staged steps into the backend's arrays (created on the first flush, zeros
        of ``[capacity * workers, ...]`` on ``device``).

        Where the backend's arrays can be written in place (``xp.capabilities.mutable_arrays``:
        torch, numpy), the staged rows are assigned to their slices of the ring (two slices where
        it wraps around), which costs what the new rows cost, whatever the replay's size.
        Elsewhere (jax, tensorflow: immutable arrays) the steps go in pieces of ``chunk_steps``
        steps (padded; default: all staged steps), each written by one pure function of the
        arrays, the piece and the ring position (:func:`put_ring_rows`), so that a compiled
        writer (``compile``, e.g. ``ivy.compile_fn``) compiles once, whatever the position. It
        replaces only the piece's rows (``ivy.put_rows``; the padding rows keep their values),
        work of the piece's size; its result is new arrays, which a compiler that reuses the
        donated old ones (``compile=lambda fn: ivy.compile_fn(fn, donate_argnums=0)``, on jax)
        writes in place, and which tensorflow (no donation) makes by copying the old ones: a
        copy, which costs less than a pass that computes every row anew
        (``benchmarks/replay_flush.py`` measures both).

        With donation the arrays that :attr:`arrays` held before the flush are deleted by it:
        read ``replay.arrays`` anew after each flush, and keep no reference to its arrays across
        one (:meth:`state_dict` copies them to numpy).

        Args:
            xp: the backend namespace.
            device: where the arrays live.
            dtypes: numpy dtypes to store each array in, e.g. the agent's float dtype and
                int32 indices (default: the staged dtypes, 64-bit ones as 32-bit where the
                backend holds no 64-bit types: jax as it starts, :func:`held_dtype`).
            chunk_steps: steps per written piece (immutable arrays).
            compile: compiles the writer (immutable arrays; default: run as it is), e.g.
                ``lambda fn: ivy.compile_fn(fn, donate_argnums=0)`` (its first argument is the
                dict of arrays).
        """
        if not self._count:
            return
        given = dtypes or {}
        dtypes = {
            k: np.dtype(given[k]) if k in given else held_dtype(xp, spec[1])
            for k, spec in self._specs.items()
        }
        if self.arrays is None:
            self.arrays = {}
            for key, (shape, _) in self._specs.items():
                zeros = np.zeros((self.capacity * self.workers, *shape), dtypes[key])
                self.arrays[key] = xp.asarray(zeros, device=device)
        count, self._count = self._count, 0
        begin = 0
        if count > self.capacity:  # only the last capacity steps survive
            begin = count - self.capacity
            self.position = (self.position + begin) % self.capacity
        staged = {k: a[begin:count] for k, a in self._staging.items()}
        count -= begin
        mutable = getattr(getattr(xp, "capabilities", None), "mutable_arrays", False)
        if mutable:
            self._write_in_place(xp, staged, count, dtypes, device)
        else:
            self._write_pieces(xp, staged, count, dtypes, device, chunk_steps, compile)

    def _write_in_place(self, xp, staged, count, dtypes, device) -> None:
        w, first = self.workers, self.position
        head = min(count, self.capacity - first)  # the rows before the ring wraps
        for key, rows in staged.items():
            flat = rows.reshape((count * w, *rows.shape[2:])).astype(dtypes[key], copy=False)
            buffer = self.arrays[key]
            buffer[first * w : (first + head) * w] = xp.asarray(flat[: head * w], device=device)
            if head < count:
                buffer[: (count - head) * w] = xp.asarray(flat[head * w :], device=device)
        self.position = (first + count) % self.capacity
        self.stored = min(self.stored + count, self.capacity)

    def _write_pieces(self, xp, staged, count, dtypes, device, chunk_steps, compile) -> None:
        if self._writer is None:
            self._writer = put_ring_rows if compile is None else compile(put_ring_rows)
        size = min(chunk_steps or count, self.capacity)
        for begin in range(0, count, size):
            piece = min(size, count - begin)
            chunk = {}
            for key, rows in staged.items():
                padded = np.zeros((size, *rows.shape[1:]), dtypes[key])
                padded[:piece] = rows[begin : begin + piece]
                chunk[key] = padded.reshape((size * self.workers, *rows.shape[2:]))
            start = np.asarray(self.position * self.workers, np.int32)
            length = np.asarray(piece * self.workers, np.int32)
            self.arrays = self._writer(
                self.arrays,
                {k: xp.asarray(a, device=device) for k, a in chunk.items()},
                xp.asarray(start, device=device),
                xp.asarray(length, device=device),
            )
            self.position = (self.position + piece) % self.capacity
            self.stored = min(self.stored + piece, self.capacity)

    # ------------------------------------------------------------------------------------------
    # Reading
    # ------------------------------------------------------------------------------------------

    def ready(self) -> bool:
        """Whether a window of ``return_steps`` steps exists (after the next flush)."""
        return self.steps >= self.return_steps

    def windows(self, rng: np.random.Generator, batches: int, batch_size: int) -> np.ndarray:
        """Indices of ``batches`` batches of n-step windows, drawn uniformly (with replacement)
        among the complete windows of the flushed steps: int32 ``[batches, return_steps,
        batch_size]``, ``indices[b, j, i]`` the row of the ``j``-th step of window ``i``.

        Example:
            >>> import numpy as np, ivy
            >>> replay = TransitionReplay(100, return_steps=3)
            >>> for t in range(5):                      # 5 steps of 2 workers
            ...     replay.store(observations=np.zeros((2, 1)), actions=np.zeros((2, 1)),
            ...                  rewards=np.zeros(2), next_observations=np.zeros((2, 1)),
            ...                  resets=np.zeros(2), terminations=np.zeros(2))
            >>> replay.flush(ivy.numpy)
            >>> replay.windows(np.random.default_rng(0), 2, 4).shape
            (2, 3, 4)
        """
        complete = self.stored - self.return_steps + 1
        if complete < 1 or self.arrays is None:
            raise RuntimeError(
                f"TransitionReplay.windows: {self.stored} flushed steps per worker hold no "
                f"window of {self.return_steps} steps: store and flush more first"
            )
        oldest = (self.position - self.stored) % self.capacity
        offsets = rng.integers(0, complete, size=(batches, batch_size))
        workers = rng.integers(0, self.workers, size=(batches, batch_size))
        steps = np.arange(self.return_steps)[None, :, None]
        rows = (oldest + offsets[:, None, :] + steps) % self.capacity
        return (rows * self.workers + workers[:, None, :]).astype(np.int32)

    # ------------------------------------------------------------------------------------------
    # Checkpoints
    # ------------------------------------------------------------------------------------------

    def state_dict(self) -> dict[str, np.ndarray]:
        """The filled rows of the arrays (as numpy), the staged steps and the ring's counters.

        Until the ring is full its filled rows are the first ``stored * workers`` (it fills
        from row 0), and only those are kept: a replay of a million rows that holds twenty
        thousand steps saves twenty thousand rows. :meth:`load_state_dict` puts them back into
        arrays of the whole ring.
        """
        state = {
            "position": np.asarray(self.position, np.int64),
            "stored": np.asarray(self.stored, np.int64),
            "workers": np.asarray(self.workers, np.int64),
        }
        filled = self.stored * self.workers
        for key, value in (self.arrays or {}).items():
            # a copy: the arrays may be written in place by later flushes
            state[f"arrays.{key}"] = np.array(ivy.to_numpy(value[:filled]), copy=True)
        for key in self._specs:
            if self._count:
                state[f"staged.{key}"] = self._staging[key][: self._count].copy()
            state[f"specs.{key}"] = np.zeros((0, *self._specs[key][0]), self._specs[key][1])
        return state

    def load_state_dict(self, state: dict[str, Any], xp: Any, *, device: Any = None) -> None:
        """Restore :meth:`state_dict` into the backend ``xp`` on ``device``."""
        self.position, self.stored = int(state["position"]), int(state["stored"])
        self.workers = int(state["workers"])
        self._specs = {
            k.split(".", 1)[1]: (tuple(v.shape[1:]), v.dtype)
            for k, v in state.items()
            if k.startswith("specs.")
        }
        self.capacity = max(self.size // max(self.workers, 1), self.return_steps)
        arrays = {k.split(".", 1)[1]: v for k, v in state.items() if k.startswith("arrays.")}
        rows = self.capacity * self.workers
        if any(len(v) > rows for v in arrays.values()):
            raise ValueError(
                f"TransitionReplay.load_state_dict: the state holds more than the {rows} rows "
                f"of this replay (size {self.size}, {self.workers} workers)"
            )
        # the ring's arrays, with the saved rows first (the filled rows, or the whole ring as
        # earlier checkpoints held it); copies: they may be written in place
        self.arrays = {}
        for key, value in arrays.items():
            ring = np.zeros((rows, *value.shape[1:]), held_dtype(xp, value.dtype))
            ring[: len(value)] = value
            self.arrays[key] = xp.asarray(ring, device=device)
        self.arrays = self.arrays or None
        staged = {k.split(".", 1)[1]: v for k, v in state.items() if k.startswith("staged.")}
        self._count = len(next(iter(staged.values()))) if staged else 0
        self._staging = {}
        if self._specs:
            self._grow_staging(max(64, self._count))
            for key, value in staged.items():
                self._staging[key][: self._count] = value


_NARROWER = {"float64": "float32", "int64": "int32", "uint64": "uint32", "complex128": "complex64"}


def held_dtype(xp: Any, dtype: Any) -> np.dtype:
    """``dtype``, or its 32-bit kind where the backend ``xp`` holds no 64-bit types (jax with
    its 64-bit types off, as it starts: Gymnasium's float64 observations are then stored in
    float32, as jax itself would store them).

    Example:
        >>> held_dtype(ivy.get_framework(f="numpy"), "float64")
        dtype('float64')
        >>> # on jax with its 64-bit types off (as it starts): dtype('float32')
    """
    dtype = np.dtype(dtype)
    narrower = _NARROWER.get(dtype.name)
    if narrower is None:
        return dtype
    info = getattr(xp, "__array_namespace_info__", None)
    if info is None or dtype.name in info().dtypes():
        return dtype
    return np.dtype(narrower)


def put_ring_rows(
    arrays: dict[str, Array], chunk: dict[str, Array], start: Array, length: Array
) -> dict[str, Array]:
    """``arrays`` with the rows ``start, start + 1, ..., start + length - 1`` (wrapping around
    the end) replaced by the first ``length`` rows of ``chunk``, by work of ``chunk``'s size
    (pure; it compiles once for a chunk's shape: the position and the length are arrays).

    The chunk's ``size`` rows go to rows ``(start + arange(size)) % total`` with
    ``ivy.put_rows``; those beyond ``length`` (padding) write back the values the arrays hold
    there. Compiled with the arrays donated
    (``ivy.compile_fn(put_ring_rows, donate_argnums=0)``), jax writes the rows in place.

    Args:
        arrays: arrays of ``total`` rows each, by name.
        chunk: arrays of ``size <= total`` rows each, by the same names.
        start: integer 0-d array, the first row written (taken modulo ``total``).
        length: integer 0-d array, ``0 <= length <= size``: the rows of ``chunk`` written.

    Returns:
        New arrays by name, of the same shapes and dtypes.

    Example:
        >>> put_ring_rows({"r": jnp.zeros(4)}, {"r": jnp.ones(2)}, jnp.int32(3), jnp.int32(2))
        {'r': Array([1., 0., 0., 1.], dtype=float32)}
    """
    first = next(iter(arrays.values()))
    xp = ivy.get_framework(first)
    total = int(first.shape[0])
    size = int(next(iter(chunk.values())).shape[0])
    if size > total:
        raise ValueError(
            f"put_ring_rows: a chunk of {size} rows does not fit in arrays of {total} rows"
        )
    steps = xp.arange(size, dtype=start.dtype, device=xp.dev(first))
    rows = xp.remainder(start + steps, total)  # distinct: size <= total
    inside = steps < length
    out = {}
    for key, buffer in arrays.items():
        mask = xp.reshape(inside, (size,) + (1,) * (len(buffer.shape) - 1))
        rows_now = xp.take(buffer, rows, axis=0)
        out[key] = xp.put_rows(buffer, rows, xp.where(mask, chunk[key], rows_now))
    return out


def n_step_batch(
    xp: Any, arrays: dict[str, Array], indices: Array, *, discount: float, f: Framework = None
) -> dict[str, Array]:
    """n-step transitions of a batch of windows (pure; it compiles).

    For a window of rows ``t, t+1, ..., t+n-1`` of one worker, with ``k`` the last row used
    (the window's last, or the first that ends an episode):
    ``returns = Σ_{j<=k-t} γ^j r_{t+j}``, ``next_observations = s'_k`` and
    ``discounts = γ^(k-t+1) (1 - termination_k)``, so that the n-step target is
    ``returns + discounts * V(next_observations)``: bootstrapped after a time limit, not after a
    termination.

    Args:
        xp: backend namespace (or None to infer it from ``arrays``).
        arrays: the replay's arrays (:attr:`TransitionReplay.arrays`).
        indices: int ``[n, batch]`` rows of the windows (one batch of
            :meth:`TransitionReplay.windows`).
        discount: γ.
        f: framework (used when ``xp`` is None).

    Returns:
        ``{'observations', 'actions', 'returns', 'next_observations', 'discounts'}`` with a
        leading ``[batch]`` axis.

    Example:
        One worker whose episode terminates after its second step: the window of its first
        three steps sums two rewards and does not bootstrap.

        >>> import numpy as np, torch, ivy
        >>> replay = TransitionReplay(10, return_steps=3)
        >>> for t, end in enumerate([0.0, 1.0, 0.0]):
        ...     replay.store(observations=np.full((1, 1), float(t)), actions=np.zeros((1, 1)),
        ...                  rewards=np.ones(1), next_observations=np.full((1, 1), t + 1.0),
        ...                  resets=np.full(1, end), terminations=np.full(1, end))
        >>> replay.flush(ivy.torch)
        >>> batch = n_step_batch(ivy.torch, replay.arrays, torch.tensor([[0], [1], [2]]),
        ...                      discount=0.5)
        >>> batch["returns"].tolist(), batch["discounts"].tolist(), batch["next_observations"]
        ([1.5], [0.0], tensor([[2.]], dtype=torch.float64))

        The targets of a critic are then ``returns + discounts * V(next_observations)``.
    """
    xp = xp or ivy.get_framework(arrays["rewards"], f=f)
    first = indices[0]
    rewards = arrays["rewards"]
    dtype = rewards.dtype
    returns = xp.take(rewards, first, axis=0)
    ones = xp.ones_like(returns)
    alive = 1.0 - xp.astype(xp.take(arrays["resets"], first, axis=0), dtype)
    ends = xp.astype(xp.take(arrays["terminations"], first, axis=0), dtype)
    last = first
    scale = discount * ones  # γ^(j) for the next step j
    discounts = scale * (1.0 - ends)
    for j in range(1, int(indices.shape[0])):
        rows = indices[j]
        returns = returns + alive * scale * xp.take(rewards, rows, axis=0)
        ends = xp.astype(xp.take(arrays["terminations"], rows, axis=0), dtype)
        step_discount = scale * discount * (1.0 - ends)
        discounts = alive * step_discount + (1.0 - alive) * discounts
        last = xp.where(alive > 0.5, rows, last)
        alive = alive * (1.0 - xp.astype(xp.take(arrays["resets"], rows, axis=0), dtype))
        scale = scale * discount
    return {
        "observations": xp.take(arrays["observations"], first, axis=0),
        "actions": xp.take(arrays["actions"], first, axis=0),
        "returns": returns,
        "next_observations": xp.take(arrays["next_observations"], last, axis=0),
        "discounts": discounts,
    }
