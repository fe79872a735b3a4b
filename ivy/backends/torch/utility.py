"""torch backend: utilities (truth tests, differences, conversion to numpy and lists, shape,
dtype, device)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import device_name, dtype_name, reduction_args
from ivy.backends.torch._unsigned import promoted, work_dtype


def _truth(x):
    """``x`` as torch's all and any take it: bools as they are; the others compared with zero
    where torch would answer in uint8 or has no kernel (NaN is true)."""
    if x.dtype is torch.bool or x.dtype.is_floating_point or x.dtype.is_complex:
        return x
    return x != 0


def all(x, /, *, axis=None, keepdims=False):  # noqa: A001 - the Array API name
    x, dim, keepdim = reduction_args(_truth(x), axis, keepdims)
    return torch.all(x, dim=dim, keepdim=keepdim)


def any(x, /, *, axis=None, keepdims=False):  # noqa: A001
    x, dim, keepdim = reduction_args(_truth(x), axis, keepdims)
    return torch.any(x, dim=dim, keepdim=keepdim)


def diff(x, /, *, axis=-1, n=1, prepend=None, append=None):
    prepend, append = (_edge(v, x, axis) for v in (prepend, append))
    parts = [v for v in (prepend, x, append) if v is not None]
    dtype = promoted(parts)
    work = work_dtype(dtype)  # uint16+ (no torch kernels): through int64, the same bits
    x, prepend, append = (None if v is None else v.to(work) for v in (x, prepend, append))
    out = torch.diff(x, n=n, dim=axis, prepend=prepend, append=append)
    return out if work is dtype else out.to(dtype)


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
