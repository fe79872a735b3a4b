"""What a flush of the off-policy replay costs, old writer against new, on each backend.

The replay is Hopper-sized: 1,000,000 rows of observations (11), next observations (11),
actions (3), rewards, terminations and resets, float32, as :class:`ivy_rl.agents.OffPolicyAgent`
stores them. Each flush writes 56 steps of 1 worker (an update every 56 steps) through the
replay's own API, ``store`` then ``flush`` with ``chunk_steps=56``, as the agents do; the stores
are not timed, the flush is (until its arrays are ready). The writers, in one run per backend:

    old                 the writer before: ``write_rows`` (below) compiled (``ivy.compile_fn``), a
                        ``where`` over every row of the replay per flush
    new                 what ``flush`` does now: jax and tensorflow ``put_ring_rows`` compiled
                        with the arrays donated (as the agents compile it), which writes the
                        piece's rows with ``ivy.put_rows`` (jax: in place; tensorflow: into a
                        copy, tf.function having no donation); torch assigns the rows in place
                        (mutable arrays: no writer)
    new, not donated    jax only: ``put_ring_rows`` compiled without donation (a copy of the
                        replay per flush), to show what donation saves

torch's flush never calls a writer, so its "old" row is ``write_rows`` compiled with
``torch.compile`` called as the flush of immutable arrays would call it (its inputs, the padded
piece, converted from numpy in the timed part too). Times are the median over the flushes, in
milliseconds per flush, after a first flush that compiles (its time reported as "first s"); the
variants take turns in rounds (each a run of consecutive flushes). "old / this" is the speed-up.

Usage: python benchmarks/replay_flush.py [--backends jax,tensorflow,torch] [--rows 1000000]
       [--steps 56] [--flushes 30]
"""

from __future__ import annotations

import argparse
import statistics
import time
import warnings

import numpy as np

import ivy
from ivy_rl.buffers import TransitionReplay


def write_rows(arrays, chunk, start, length):
    """The replay's writer before ``put_ring_rows``: ``arrays`` with the entries ``start, ...,
    start + length - 1`` (wrapping around) replaced by the first ``length`` entries of ``chunk``,
    every row computed anew (a ``where`` over all rows), the pass per flush measured here."""
    first = next(iter(arrays.values()))
    xp = ivy.get_framework(first)
    total = int(first.shape[0])
    size = int(next(iter(chunk.values())).shape[0])
    offsets = xp.remainder(xp.arange(total, dtype=start.dtype, device=xp.dev(first)) - start, total)
    inside = offsets < length
    picks = xp.clip(offsets, 0, size - 1)
    out = {}
    for key, buffer in arrays.items():
        mask = xp.reshape(inside, (total,) + (1,) * (len(buffer.shape) - 1))
        out[key] = xp.where(mask, xp.take(chunk[key], picks, axis=0), buffer)
    return out


SHAPES = {
    "observations": (11,),
    "actions": (3,),
    "rewards": (),
    "next_observations": (11,),
    "resets": (),
    "terminations": (),
}


def _block(arrays):
    for leaf in arrays.values():
        if hasattr(leaf, "block_until_ready"):
            leaf.block_until_ready()
    return arrays


def _steps(rng, steps):
    """``steps`` steps of 1 worker, as the agents store them (float32)."""
    return [
        {k: rng.standard_normal((1, *s)).astype(np.float32) for k, s in SHAPES.items()}
        for _ in range(steps)
    ]


class _ViaFlush:
    """A replay flushed with ``compile`` (None: the backend's own path, in place on torch)."""

    def __init__(self, xp, rows, steps, compile):
        self.xp, self.steps, self.compile = xp, steps, compile
        self.replay = TransitionReplay(rows)

    def stage(self, data):
        for step in data:
            self.replay.store(**step)

    def flush(self):
        self.replay.flush(self.xp, chunk_steps=self.steps, compile=self.compile)
        return _block(self.replay.arrays)


class _ViaWriter:
    """The arrays of a replay written by calling a compiled writer as ``flush`` does for
    immutable arrays (for torch, whose flush writes in place and calls no writer)."""

    def __init__(self, xp, rows, steps, writer):
        self.xp, self.rows, self.writer = xp, rows, writer
        self.arrays = {
            k: xp.asarray(np.zeros((rows, *s), np.float32), device="cpu") for k, s in SHAPES.items()
        }
        self.position, self.data = 0, None

    def stage(self, data):
        self.data = data

    def flush(self):
        xp, data = self.xp, self.data
        chunk = {k: xp.asarray(np.concatenate([d[k] for d in data])) for k in SHAPES}
        start = xp.asarray(np.asarray(self.position, np.int32))
        length = xp.asarray(np.asarray(len(data), np.int32))
        self.arrays = self.writer(self.arrays, chunk, start, length)
        self.position = (self.position + len(data)) % self.rows
        return _block(self.arrays)


def _variants(backend, rows, steps):
    xp = getattr(ivy, backend)

    def compiled(fn, **options):
        return lambda _: ivy.compile_fn(fn, f=xp, **options)

    if xp.capabilities.mutable_arrays:
        return {
            "old": _ViaWriter(xp, rows, steps, ivy.compile_fn(write_rows, f=xp)),
            "new": _ViaFlush(xp, rows, steps, None),
        }
    variants = {
        "old": _ViaFlush(xp, rows, steps, compiled(write_rows)),
        "new": _ViaFlush(xp, rows, steps, lambda fn: ivy.compile_fn(fn, f=xp, donate_argnums=0)),
    }
    if backend == "jax":
        variants["new, not donated"] = _ViaFlush(
            xp, rows, steps, lambda fn: ivy.compile_fn(fn, f=xp)
        )
    return variants


def measure(backend, rows, steps, flushes, rounds=3):
    """{variant: (first flush s, median ms per flush)} for ``backend``: ``rounds`` rounds in
    which each variant makes ``flushes // rounds`` flushes in a row (in a row, so that none
    pays for another's freeing of its 100 MB arrays; in rounds, so that drift is shared)."""
    rng = np.random.default_rng(0)
    variants = _variants(backend, rows, steps)
    firsts, times = {}, {name: [] for name in variants}
    for name, variant in variants.items():
        variant.stage(_steps(rng, steps))
        start = time.perf_counter()
        variant.flush()
        firsts[name] = time.perf_counter() - start
    for _ in range(rounds):
        for name, variant in variants.items():
            variant.stage(_steps(rng, steps))
            variant.flush()  # untimed: the first after another variant's flushes
            for _ in range(max(flushes // rounds, 1)):
                variant.stage(_steps(rng, steps))
                start = time.perf_counter()
                variant.flush()
                times[name].append(time.perf_counter() - start)
    return {name: (firsts[name], statistics.median(times[name]) * 1e3) for name in variants}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default="jax,tensorflow,torch")
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--steps", type=int, default=56)
    parser.add_argument("--flushes", type=int, default=30)
    args = parser.parse_args()
    warnings.simplefilter("ignore", UserWarning)
    print(f"replay of {args.rows:,} rows (Hopper-sized), {args.steps} steps x 1 worker per flush")
    print(f"{'backend':<11} {'writer':<17} {'first s':>8} {'ms/flush':>9} {'old / this':>10}")
    for backend in args.backends.split(","):
        results = measure(backend, args.rows, args.steps, args.flushes)
        old = results["old"][1]
        for name, (first, ms) in results.items():
            print(f"{backend:<11} {name:<17} {first:8.2f} {ms:9.3f} {old / ms:10.1f}")


if __name__ == "__main__":
    main()
