"""Timing helpers shared by ``benchmarks/`` and ``scripts/profile_overhead.py``.

Every measurement is a set of variants of one computation (the native call, ``ivy.<b>.fn``,
``ivy.fn`` ...). Each sample times ``number`` consecutive calls of one variant with
:mod:`timeit` (garbage collection off), and the variants take turns sample by sample
(interleaved repeats, in a shuffled order each round), so that drift in the machine's load is
shared by all of them. The median of the samples is the estimate; the interquartile range
relative to the median says how noisy it was.
"""

from __future__ import annotations

import contextlib
import random
import statistics
import timeit
from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager as ContextManager

__all__ = ["calls_per_sample", "interleaved_samples", "median", "relative_spread"]


def calls_per_sample(timer: timeit.Timer, target_s: float = 0.02, max_calls: int = 10**6) -> int:
    """Number of calls that one sample of ``timer`` needs to last about ``target_s`` seconds.

    Starts from one call and grows geometrically until a batch takes a tenth of the target, so
    that calibrating a slow call costs little.
    """
    number = 1
    while True:
        elapsed = timer.timeit(number)
        if elapsed >= target_s / 10 or number >= max_calls:
            break
        number *= 10 if elapsed < target_s / 1000 else 2
    per_call = max(elapsed / number, 1e-9)
    return int(min(max_calls, max(1, round(target_s / per_call))))


def interleaved_samples(
    timers: Mapping[str, timeit.Timer],
    number: int,
    repeats: int,
    around: Mapping[str, Callable[[], ContextManager]] | None = None,
    seed: int | None = 0,
) -> dict[str, list[float]]:
    """Seconds per call of each timer, ``repeats`` samples each, the timers taking turns.

    Args:
        timers: name -> :class:`timeit.Timer`.
        number: calls per sample (the same for every timer, so samples are comparable).
        repeats: samples per timer.
        around: name -> factory of a context manager entered around that timer's samples
            (e.g. ``lambda: ivy.set_framework('torch')``).
        seed: seed of the shuffled order of the timers in each round (None: fixed order).

    Returns:
        name -> list of ``repeats`` seconds-per-call values.
    """
    around = around or {}
    names = list(timers)
    rng = random.Random(seed)
    samples: dict[str, list[float]] = {name: [] for name in names}
    for _ in range(repeats):
        if seed is not None:
            rng.shuffle(names)
        for name in names:
            ctx = around[name]() if name in around else contextlib.nullcontext()
            with ctx:
                elapsed = timers[name].timeit(number)
            samples[name].append(elapsed / number)
    return samples


def median(values: list[float]) -> float:
    return statistics.median(values) if values else float("nan")


def relative_spread(values: list[float]) -> float:
    """Interquartile range divided by the median (0.1 = the middle half of the samples lies
    within 10% of the median's size); nan for fewer than 4 samples."""
    if len(values) < 4:
        return float("nan")
    q1, _, q3 = statistics.quantiles(values, n=4)
    mid = statistics.median(values)
    return (q3 - q1) / mid if mid > 0 else float("nan")
