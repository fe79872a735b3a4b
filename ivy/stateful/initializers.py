"""Variable initializers, seeded by ``ivy.seed``.

Every initializer is called as ``init(shape, *, fan_in, fan_out, dtype, device, f)`` and draws
with the backend's own random functions, so ``ivy.seed(n)`` makes a module's variables
reproducible on each backend. ``Module.add_variable`` supplies the fans (see
:func:`ivy.stateful.module.default_fans`); called directly, the fans default the same way.

Example:
    >>> ivy.seed(0)
    >>> w = glorot_uniform((64, 32), f="torch")  # a weight [out, in] for ivy.linear
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ivy import framework_handler as _fh
from ivy.stateful.module import default_fans
from ivy.typing import Array, Device, Dtype, Framework, Shape

__all__ = [
    "zeros",
    "ones",
    "constant",
    "glorot_uniform",
    "glorot_normal",
    "he_uniform",
    "he_normal",
    "orthogonal",
]


def _fans(shape, fan_in, fan_out) -> tuple[int, int]:
    default_in, default_out = default_fans(shape)
    return (default_in if fan_in is None else fan_in, default_out if fan_out is None else fan_out)


def _dtype(dtype):
    return "float32" if dtype is None else dtype


def zeros(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Zeros of ``shape`` (the usual bias initializer).

    Returns:
        An array of the framework ``f``. Example: ``zeros((4,), f='jax')``.
    """
    return _fh.get_framework(f=f).zeros(tuple(shape), dtype=_dtype(dtype), device=device)


def ones(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Ones of ``shape``. Example: ``ones((4,), f='jax')``."""
    return _fh.get_framework(f=f).ones(tuple(shape), dtype=_dtype(dtype), device=device)


def constant(value: float) -> Callable[..., Array]:
    """An initializer that fills with ``value``.

    Example:
        >>> init = constant(0.1); b = init((4,), f="numpy")
    """

    def init(shape, *, fan_in=None, fan_out=None, dtype=None, device=None, f=None):
        xp = _fh.get_framework(f=f)
        return xp.full(tuple(shape), value, dtype=_dtype(dtype), device=device)

    init.__name__ = init.__qualname__ = f"constant({value!r})"
    return init


def _uniform(limit, shape, dtype, device, f):
    xp = _fh.get_framework(f=f)
    return xp.random_uniform(-limit, limit, tuple(shape), dtype=_dtype(dtype), device=device)


def _normal(std, shape, dtype, device, f):
    xp = _fh.get_framework(f=f)
    return xp.random_normal(0.0, std, tuple(shape), dtype=_dtype(dtype), device=device)


def glorot_uniform(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Glorot (Xavier) uniform: U(-a, a) with ``a = sqrt(6 / (fan_in + fan_out))``.

    Args:
        shape: shape of the variable.
        fan_in, fan_out: units in and out; default from the shape (:func:`default_fans`).
        dtype, device, f: dtype (float32 if None), device and framework of the result.

    Returns:
        An array of ``shape``. Example: ``glorot_uniform((32, 16), f='tensorflow')``.
    """
    fan_in, fan_out = _fans(shape, fan_in, fan_out)
    return _uniform(math.sqrt(6.0 / (fan_in + fan_out)), shape, dtype, device, f)


def glorot_normal(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Glorot (Xavier) normal: N(0, 2 / (fan_in + fan_out)). Arguments as :func:`glorot_uniform`."""
    fan_in, fan_out = _fans(shape, fan_in, fan_out)
    return _normal(math.sqrt(2.0 / (fan_in + fan_out)), shape, dtype, device, f)


def he_uniform(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """He (Kaiming) uniform for ReLU layers: U(-a, a) with ``a = sqrt(6 / fan_in)``.

    Arguments as :func:`glorot_uniform`. Example: ``he_uniform((256, 128), f='jax')``.
    """
    fan_in, _ = _fans(shape, fan_in, fan_out)
    return _uniform(math.sqrt(6.0 / fan_in), shape, dtype, device, f)


def he_normal(
    shape: Shape,
    *,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """He (Kaiming) normal for ReLU layers: N(0, 2 / fan_in). Arguments as :func:`glorot_uniform`."""
    fan_in, _ = _fans(shape, fan_in, fan_out)
    return _normal(math.sqrt(2.0 / fan_in), shape, dtype, device, f)


def orthogonal(
    shape: Shape,
    *,
    gain: float = 1.0,
    fan_in: int | None = None,
    fan_out: int | None = None,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """A random orthogonal matrix (Haar distributed), times ``gain``.

    The shape is read as a matrix ``[prod(shape[:-1]), shape[-1]]``; its rows (if fewer) or its
    columns are orthonormal. Drawn as the polar factor ``U @ Vh`` of a Gaussian matrix.

    Args:
        shape: shape of the variable, at least 2-D.
        gain: scale of the result (``functools.partial(orthogonal, gain=2.0)`` to change it).
        fan_in, fan_out: ignored.
        dtype, device, f: dtype (float32 if None), device and framework of the result.

    Returns:
        An array of ``shape``. Example: ``orthogonal((64, 256), f='torch')`` (orthonormal rows).
    """
    shape = tuple(shape)
    if len(shape) < 2:
        raise ValueError(f"orthogonal needs a shape of at least 2 dimensions, got {shape}")
    xp = _fh.get_framework(f=f)
    rows, cols = math.prod(shape[:-1]), shape[-1]
    tall = (max(rows, cols), min(rows, cols))
    a = xp.random_normal(0.0, 1.0, tall, dtype=_dtype(dtype), device=device)
    u, _, vh = xp.svd(a, full_matrices=False)
    q = xp.matmul(u, vh)
    if rows < cols:
        q = xp.permute_dims(q, (1, 0))
    q = xp.reshape(q, shape)
    return q if gain == 1.0 else xp.multiply(q, gain)
