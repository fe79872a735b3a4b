"""Array creation. Floating results default to float32 on every backend, numpy included."""

from __future__ import annotations

from ivy.core._dispatch import alias, dispatch

__all__ = [
    "asarray", "array", "zeros", "ones", "empty", "full", "arange", "linspace", "eye",
    "zeros_like", "ones_like", "empty_like", "full_like",
]


@dispatch
def asarray(obj, /, *, dtype=None, device=None, copy=None, f=None):
    """Convert ``obj`` (array, scalar, nested list) to an array of the chosen framework.

    Python floats become float32 and Python ints int64 unless ``dtype`` says otherwise; arrays
    keep their dtype. Example: ``ivy.asarray([1., 2.], f='torch')`` -> float32 tensor.
    """


array = alias("array", asarray)


@dispatch()
def zeros(shape, *, dtype=None, device=None, f=None):
    """Array of zeros of ``shape`` (int or tuple); float32 by default."""


@dispatch()
def ones(shape, *, dtype=None, device=None, f=None):
    """Array of ones of ``shape``; float32 by default."""


@dispatch()
def empty(shape, *, dtype=None, device=None, f=None):
    """Uninitialised array of ``shape``; float32 by default."""


@dispatch()
def full(shape, fill_value, *, dtype=None, device=None, f=None):
    """Array of ``shape`` filled with ``fill_value``; the dtype follows the value (bool, int64,
    float32, complex64) unless given."""


@dispatch()
def arange(start, /, stop=None, step=1, *, dtype=None, device=None, f=None):
    """Values from ``start`` (or 0) to ``stop`` (excluded) by ``step``: int64 if every bound is
    an int, else float32."""


@dispatch()
def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True, f=None):
    """``num`` evenly spaced values from ``start`` to ``stop``; float32 by default."""


@dispatch()
def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None, f=None):
    """Identity-like matrix with ones on diagonal ``k``; float32 by default."""


@dispatch
def zeros_like(x, /, *, dtype=None, device=None, f=None):
    """Zeros with the shape (and by default dtype and device) of ``x``."""


@dispatch
def ones_like(x, /, *, dtype=None, device=None, f=None):
    """Ones with the shape (and by default dtype and device) of ``x``."""


@dispatch
def empty_like(x, /, *, dtype=None, device=None, f=None):
    """Uninitialised array with the shape (and by default dtype and device) of ``x``."""


@dispatch
def full_like(x, /, fill_value, *, dtype=None, device=None, f=None):
    """Array shaped like ``x`` filled with ``fill_value``, with the dtype of ``x`` by default."""
