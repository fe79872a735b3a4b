"""torch backend: utilities (truth tests, differences, conversion to numpy and lists, shape,
dtype, device)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import device_name, dtype_name, reduction_args


def all(x, /, *, axis=None, keepdims=False):  # noqa: A001 - the Array API name
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.all(x, dim=dim, keepdim=keepdim)


def any(x, /, *, axis=None, keepdims=False):  # noqa: A001
    x, dim, keepdim = reduction_args(x, axis, keepdims)
    return torch.any(x, dim=dim, keepdim=keepdim)


def diff(x, /, *, axis=-1, n=1, prepend=None, append=None):
    prepend, append = (_edge(v, x, axis) for v in (prepend, append))
    return torch.diff(x, n=n, dim=axis, prepend=prepend, append=append)


def _edge(value, x, axis):
    """``prepend`` or ``append`` as a tensor with the axes of ``x`` (a scalar fills one slice)."""
    if value is None:
        return None
    value = torch.as_tensor(value, device=x.device)
    if value.ndim == 0:
        shape = list(x.shape)
        shape[axis] = 1
        value = value.expand(shape)
    return value


to_list = torch.Tensor.tolist


def to_numpy(x, /):
    return x.numpy(force=True)  # detached, on the CPU, conjugation resolved


def shape(x, /):
    return tuple(x.shape)


def dtype(x, /, *, as_str=False):
    return dtype_name(x.dtype) if as_str else x.dtype


def dev(x, /):
    return device_name(x.device)
