"""Random numbers. ``ivy.seed(n)`` seeds every backend; draws need ``f=`` or a global framework
unless an array argument decides it.

Design (the same on every backend): user code never handles keys or generators. Each backend
keeps its generator state in one place, which every draw reads and advances:

- numpy: one module-level ``numpy.random.Generator``;
- torch: torch's global generator (``torch.manual_seed``); inside ``torch.compile`` inductor
  takes a fresh seed from it on every call;
- tensorflow: one ``tf.random.Generator``, whose state is a ``tf.Variable``: a ``tf.function``
  reads and advances that variable on every call;
- jax: one PRNG key in a small state object (``ivy.backends.jax.random._state``). Each draw
  splits it. ``ivy.compile_fn`` threads the key through ``jax.jit`` as an extra input and output
  (while tracing, the state holds the traced key; after the call the advanced key is written
  back).

Hence random calls inside functions compiled with ``ivy.compile_fn`` draw new numbers on every
call, and after ``ivy.seed(n)`` a re-run draws the same numbers again, eager and compiled alike
(compiled torch draws differ from eager torch draws for the same seed, but repeat themselves).
Under a plain ``jax.jit`` (not ``ivy.compile_fn``) the jax key cannot be threaded: the numbers
are drawn once, when the function is traced, with a warning; use ``ivy.compile_fn``, or
``jax.random`` with explicit keys.

Example:
    >>> ivy.seed(0)
    >>> noisy = ivy.compile_fn(lambda x: x + ivy.random_normal(shape=x.shape, f="jax"))
    >>> x = jnp.zeros(3)
    >>> a, b = noisy(x), noisy(x)  # different draws; ivy.seed(0) then repeats a, b
"""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import by_hand, dispatch
from ivy.typing import Array, Device, Dtype, Framework, Shape

__all__ = ["seed", "random_uniform", "random_normal", "randint", "shuffle", "random_categorical"]

_seed_value: list[int | None] = [None]


@by_hand
def seed(seed_value: int = 0, *, f: Framework = None) -> None:
    """Seed the random generators so that re-runs draw the same numbers, eager and compiled.

    With ``f`` only that backend is seeded; otherwise every loaded backend, and backends loaded
    later are seeded with the same value on load.

    Args:
        seed_value: a non-negative integer.
        f: a framework name or namespace to seed only that backend.

    Example:
        >>> ivy.seed(42); a = ivy.random_uniform(shape=(2,), f="torch")
        >>> ivy.seed(42); bool((a == ivy.random_uniform(shape=(2,), f="torch")).all())
        True
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
def random_uniform(
    low: float | Array = 0.0,
    high: float | Array = 1.0,
    shape: int | Shape | None = None,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Samples from U[low, high) of ``shape`` (default: the broadcast shape of the bounds)."""


@dispatch("mean", "std")
def random_normal(
    mean: float | Array = 0.0,
    std: float | Array = 1.0,
    shape: int | Shape | None = None,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Samples from N(mean, std**2) of ``shape`` (default: the broadcast shape of the bounds)."""


@dispatch("low", "high")
def randint(
    low: int | Array,
    high: int | Array,
    shape: int | Shape | None = None,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Integers from [low, high) of ``shape``; int64 by default."""


@dispatch
def shuffle(x: Array, /, *, f: Framework = None) -> Array:
    """``x`` with its first axis randomly permuted."""


@dispatch
def random_categorical(
    logits: Array, /, *, num_samples: int = 1, dtype: Dtype | None = None, f: Framework = None
) -> Array:
    """Class indices drawn from the categorical distributions ``softmax(logits)`` along the last
    axis, with replacement; batched over the leading axes.

    Draws come from the backend's generator, as every random function's (reproducible after
    :func:`seed`, fresh on every call of a function compiled with ``ivy.compile_fn``). The
    numbers drawn differ between backends; their distribution does not.

    Args:
        logits: ``[..., num_classes]`` unnormalised log-probabilities (``-inf`` for a class that
            must never be drawn; each distribution needs at least one finite logit).
        num_samples: how many indices to draw from each distribution.
        dtype: integer dtype of the result; int64 by default.

    Returns:
        ``[..., num_samples]`` indices in ``[0, num_classes)``.

    Example:
        >>> logits = np.array([[0.0, 0.0, 0.0], [5.0, -np.inf, 0.0]])  # class 1 of row 1: never
        >>> ivy.random_categorical(logits, num_samples=4).shape
        (2, 4)
    """
