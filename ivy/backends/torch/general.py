"""torch backend: utilities."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import device_name, dtype_name

__all__ = ["to_numpy", "to_list", "shape", "dtype", "dev"]

to_list = torch.Tensor.tolist


def to_numpy(x, /):
    return x.numpy(force=True)  # detached, on the CPU, conjugation resolved


def shape(x, /):
    return tuple(x.shape)


def dtype(x, /, *, as_str=False):
    return dtype_name(x.dtype) if as_str else x.dtype


def dev(x, /):
    return device_name(x.device)
