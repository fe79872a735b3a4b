"""numpy backend: utilities (truth tests, differences, conversion to numpy and lists, shape,
dtype, device)."""

from __future__ import annotations

import numpy as np

from ivy.backends.numpy._helpers import dtype_name


def to_numpy(x, /):
    return np.asarray(x)


def to_list(x, /):
    return np.asarray(x).tolist()


def shape(x, /):
    return tuple(np.shape(x))


def dtype(x, /, *, as_str=False):
    return dtype_name(x.dtype) if as_str else x.dtype


def dev(x, /):
    return "cpu"
