"""Array creation. Floating results default to float32 on every backend, numpy included."""

from __future__ import annotations

from typing import Literal

from ivy import framework_handler as _fh
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import alias, composition, dispatch
from ivy.typing import Array, ArrayLike, Device, Dtype, Framework, Scalar, Shape

__all__ = [
    "asarray",
    "array",
    "constant",
    "zeros",
    "ones",
    "empty",
    "full",
    "arange",
    "linspace",
    "logspace",
    "eye",
    "zeros_like",
    "ones_like",
    "empty_like",
    "full_like",
    "from_dlpack",
    "meshgrid",
    "tril",
    "triu",
]


@dispatch
def asarray(
    obj: ArrayLike,
    /,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    copy: bool | None = None,
    f: Framework = None,
) -> Array:
    """Convert ``obj`` (array, scalar, nested list) to an array of the chosen framework.

    Python floats become float32 and Python ints int64 unless ``dtype`` says otherwise; arrays
    keep their dtype. Example: ``ivy.asarray([1., 2.], f='torch')`` -> float32 tensor.
    """


array = alias("array", asarray)


@dispatch
def constant(
    value: ArrayLike,
    /,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """A model constant (a numpy array, a Python scalar or a nested list) as an array of the
    chosen framework, in a way that every compiler traces.

    Keep one numpy copy of each constant and call ``xp.constant(value, dtype=..., device=...)``
    where it is needed, also inside functions that ``jax.jit``, ``tf.function`` or
    ``torch.compile`` trace: it breaks no graph and recompiles nothing there (jax and tensorflow
    embed the value in the program; torch.compile takes a numpy array as an input of the graph).
    Outside a trace, the conversion of a numpy array is made once per dtype and device and kept
    while the array lives, so an eager loop pays no conversion (and no host-to-device copy) per
    step. A constant is never written after its first use: later writes into the numpy array
    may not be seen.

    Args:
        value: a numpy array, numpy or Python scalar, or nested list of numbers.
        dtype: the dtype wanted; None: as :func:`asarray` (numpy arrays keep theirs, Python
            floats give float32).
        device: the device wanted (``'cpu'``, ``'gpu:0'`` or the framework's device); None:
            the framework's default.
        f: framework name or namespace; without it, a numpy ``value`` gives a numpy array.

    Returns:
        The array. Do not write into it: it may be shared by every caller.

    Example:
        >>> K = np.array([[500.0, 0.0, 320.0], [0.0, 500.0, 240.0], [0.0, 0.0, 1.0]])
        >>> ivy.constant(K, dtype="float32", f="torch").dtype
        torch.float32
    """


@dispatch()
def zeros(
    shape: int | Shape,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Array of zeros of ``shape`` (int or tuple); float32 by default."""


@dispatch()
def ones(
    shape: int | Shape,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Array of ones of ``shape``; float32 by default."""


@dispatch()
def empty(
    shape: int | Shape,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Uninitialised array of ``shape``; float32 by default."""


@dispatch()
def full(
    shape: int | Shape,
    fill_value: Scalar,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Array of ``shape`` filled with ``fill_value``; the dtype follows the value (bool, int64,
    float32, complex64) unless given."""


@dispatch()
def arange(
    start: int | float,
    /,
    stop: int | float | None = None,
    step: int | float = 1,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Values from ``start`` (or 0) to ``stop`` (excluded) by ``step``: int64 if every bound is
    an int, else float32."""


@dispatch()
def linspace(
    start: float,
    stop: float,
    /,
    num: int,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    endpoint: bool = True,
    f: Framework = None,
) -> Array:
    """``num`` evenly spaced values from ``start`` to ``stop``; float32 by default."""


@composition
def logspace(
    start: float,
    stop: float,
    /,
    num: int,
    *,
    base: float = 10.0,
    dtype: Dtype | None = None,
    device: Device | None = None,
    endpoint: bool = True,
    f: Framework = None,
) -> Array:
    """``num`` values spaced evenly on a log scale: ``base ** linspace(start, stop, num)``, as
    ``numpy.logspace``.

    Args:
        start: exponent of the first value.
        stop: exponent of the last value (excluded with ``endpoint=False``).
        num: how many values.
        base: the base of the powers.
        dtype: float32 by default; the values are computed in ``dtype`` when it is floating, else
            in float64 and then cast (truncated, as numpy does).
        device: where to put the array.
        endpoint: whether ``stop`` is included.
        f: framework (name or namespace); by default the global framework.

    Returns:
        A 1-D array of ``num`` values.

    Example: ``ivy.logspace(0, 3, 4, f='numpy')`` -> ``[1., 10., 100., 1000.]``.
    """
    xp = _fh.get_framework(f=f)
    work = "float32" if dtype is None else dtype
    floating = xp.isdtype(work, "real floating")
    if not floating:
        work = "float64"
    exponents = xp.linspace(start, stop, num, dtype=work, device=device, endpoint=endpoint)
    out = xp.pow(xp.asarray(base, dtype=work, device=device), exponents)
    return out if floating else xp.astype(out, dtype)


@dispatch()
def eye(
    n_rows: int,
    n_cols: int | None = None,
    /,
    *,
    k: int = 0,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Identity-like matrix with ones on diagonal ``k``; float32 by default."""


@dispatch
def zeros_like(
    x: Array, /, *, dtype: Dtype | None = None, device: Device | None = None, f: Framework = None
) -> Array:
    """Zeros with the shape (and by default dtype and device) of ``x``."""


@dispatch
def ones_like(
    x: Array, /, *, dtype: Dtype | None = None, device: Device | None = None, f: Framework = None
) -> Array:
    """Ones with the shape (and by default dtype and device) of ``x``."""


@dispatch
def empty_like(
    x: Array, /, *, dtype: Dtype | None = None, device: Device | None = None, f: Framework = None
) -> Array:
    """Uninitialised array with the shape (and by default dtype and device) of ``x``."""


@dispatch
def full_like(
    x: Array,
    /,
    fill_value: Scalar,
    *,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Array shaped like ``x`` filled with ``fill_value``, with the dtype of ``x`` by default."""


@dispatch
def from_dlpack(
    x: Array, /, *, device: Device | None = None, copy: bool | None = None, f: Framework = None
) -> Array:
    """An array of the chosen framework sharing the memory of ``x``, any object with
    ``__dlpack__`` (torch, jax, numpy, tensorflow arrays...): choose the framework with ``f``.

    ``copy=True`` always copies, ``copy=False`` never does (raising if it would have to), ``None``
    copies only if needed. Example: ``ivy.from_dlpack(torch_tensor, f='jax')``.
    """


@by_hand
def meshgrid(
    *arrays: Array, indexing: Literal["xy", "ij"] = "xy", f: Framework = None
) -> list[Array]:
    """List of coordinate arrays from 1-D ``arrays``: with ``indexing='xy'`` (Cartesian) the first
    two output axes are swapped, with ``'ij'`` (matrix) output axis i follows ``arrays[i]``.

    Example: ``[a.shape for a in ivy.meshgrid(np.ones(3), np.ones(2))]`` -> ``[(2, 3), (2, 3)]``.
    """
    ns = _fh.get_framework(*arrays, f=f)
    if f is not None:
        arrays = _fh.to_namespace(ns, arrays)
    return ns.meshgrid(*arrays, indexing=indexing)


@dispatch
def tril(x: Array, /, *, k: int = 0, f: Framework = None) -> Array:
    """``x`` (a matrix or a stack of them) with the elements above diagonal ``k`` zeroed."""


@dispatch
def triu(x: Array, /, *, k: int = 0, f: Framework = None) -> Array:
    """``x`` (a matrix or a stack of them) with the elements below diagonal ``k`` zeroed."""
