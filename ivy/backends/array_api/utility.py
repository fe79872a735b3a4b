"""Utilities, written once: truth tests and differences (``xp.all``, ``xp.any``, ``xp.diff``),
conversion to numpy and lists, shape, dtype and device."""

from __future__ import annotations

import numpy as np

from ivy.backends.array_api._unbound import device_name, dtype_name, xp

NATIVE = {"all": "all", "any": "any"}


def diff(x, /, *, axis=-1, n=1, prepend=None, append=None):
    extra = {}
    for key, value in (("prepend", prepend), ("append", append)):
        if value is not None:  # a Python scalar takes x's dtype (numpy's would be float64)
            scalar = type(value) in (bool, int, float, complex)
            extra[key] = xp.asarray(value, dtype=x.dtype) if scalar else value
    return xp.diff(x, axis=axis, n=n, **extra)


def to_numpy(x, /):
    return np.from_dlpack(x) if not isinstance(x, np.ndarray) else x


def to_list(x, /):
    return to_numpy(x).tolist()


def shape(x, /):
    return tuple(x.shape)


def dtype(x, /, *, as_str=False):
    return dtype_name(x.dtype) if as_str else x.dtype


def dev(x, /):
    return device_name(x.device)
