"""Random numbers. ``ivy.seed(n)`` seeds every backend; draws need ``f=`` or a global framework
unless an array argument decides it."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import dispatch

__all__ = ["seed", "random_uniform", "random_normal", "randint", "shuffle"]

_seed_value: list[int | None] = [None]


def seed(seed_value: int = 0, *, f=None) -> None:
    """Seed the random generators so that re-runs draw the same numbers.

    With ``f`` only that backend is seeded; otherwise every loaded backend, and backends loaded
    later are seeded with the same value on load.
    """
    if f is not None:
        _fh.get_framework(f=f).seed(seed_value)
        return
    _seed_value[0] = seed_value
    for ns in _fh._loaded.values():
        ns.seed(seed_value)


def _seed_on_load(ns) -> None:
    if _seed_value[0] is not None:
        ns.seed(_seed_value[0])


_fh.on_backend_load(_seed_on_load)


@dispatch("low", "high")
def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None, f=None):
    """Samples from U[low, high) of ``shape`` (default: the broadcast shape of the bounds)."""


@dispatch("mean", "std")
def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None, f=None):
    """Samples from N(mean, std**2) of ``shape`` (default: the broadcast shape of the bounds)."""


@dispatch("low", "high")
def randint(low, high, shape=None, *, dtype=None, device=None, f=None):
    """Integers from [low, high) of ``shape``; int64 by default."""


@dispatch
def shuffle(x, /, *, f=None):
    """``x`` with its first axis randomly permuted."""
