"""torch backend: dtype conversion."""

from __future__ import annotations

from ivy.backends.torch._helpers import native_dtype

__all__ = ["astype"]


def astype(x, dtype, /, *, copy=True):
    return x.to(native_dtype(dtype), copy=copy)
