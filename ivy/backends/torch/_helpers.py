"""Dtype, device and argument conversion shared by the torch backend's modules."""

from __future__ import annotations

import numpy as np
import torch

from ivy.dtypes import DTYPE_NAMES

NATIVE_DTYPES = {name: getattr(torch, name) for name in DTYPE_NAMES}
_NAMES = {t: name for name, t in NATIVE_DTYPES.items()}


def native_dtype(dtype):
    """torch dtype for a dtype name, a torch dtype or anything numpy reads as a dtype (``float``,
    ``np.float64``); None stays None."""
    if dtype is None or isinstance(dtype, torch.dtype):
        return dtype
    try:
        return NATIVE_DTYPES[dtype if isinstance(dtype, str) else np.dtype(dtype).name]
    except (KeyError, TypeError):
        raise TypeError(f"Unknown dtype {dtype!r}; use one of {', '.join(DTYPE_NAMES)}.") from None


def dtype_name(dtype) -> str:
    try:
        return _NAMES[dtype]
    except KeyError:
        raise TypeError(f"torch dtype {dtype} has no ivy name; ivy knows {DTYPE_NAMES}.") from None


_CUDA: dict = {}  # ivy device name or torch device -> the torch device, once found to exist


def native_device(device):
    """torch device for an ivy device string ('cpu', 'gpu:N') or a torch device; None stays
    None. A device torch does not have here raises ivy's UnavailableDeviceError (torch's own
    error on a machine without CUDA is a long assertion from its CUDA initialisation)."""
    if device is None or device == "cpu":
        return device
    try:
        return _CUDA[device]
    except (KeyError, TypeError):
        pass
    found = _find_device(device)
    if found is None:
        from ivy import framework_handler as _fh
        from ivy.errors import unavailable_device

        raise unavailable_device(device, _fh.load_backend("torch"))
    _CUDA[device] = found
    return found


def _find_device(device):
    """The torch device named by ``device`` if torch has it here, else None."""
    if isinstance(device, torch.device):
        if device.type != "cuda":
            return device
        index = 0 if device.index is None else device.index
        return device if index < torch.cuda.device_count() else None
    if not isinstance(device, str):
        return None
    kind, _, index = device.partition(":")
    if kind not in ("cpu", "gpu") or not (index or "0").isdigit():
        return None
    index = int(index or 0)
    if kind == "cpu":
        return "cpu" if index == 0 else None
    return f"cuda:{index}" if index < torch.cuda.device_count() else None


def device_name(device: torch.device) -> str:
    if device.type == "cpu":
        return "cpu"
    if device.type == "cuda":
        return f"gpu:{device.index or 0}"
    return str(device)


def device_of(*values):
    """Device of the first tensor among ``values``, or None."""
    for v in values:
        if isinstance(v, torch.Tensor):
            return v.device
    return None


def has_own_dtype(obj) -> bool:
    """True when ``obj`` carries a dtype (an array, or a list of arrays), so it must be kept."""
    while isinstance(obj, (list, tuple)) and obj:
        obj = obj[0]
    return hasattr(obj, "dtype")


def default_dtype_of_value(value):
    """The dtype a Python value gets by default: bool, int64, float32 or complex64."""
    if isinstance(value, (bool, np.bool_)):
        return torch.bool
    if isinstance(value, (int, np.integer)):
        return torch.int64
    if isinstance(value, (float, np.floating)):
        return torch.float32
    if isinstance(value, (complex, np.complexfloating)):
        return torch.complex64
    return None


def with_tensor_operands(x1, x2):
    """Both operands as tensors: a Python scalar becomes a 0-d tensor, which (as a scalar would)
    takes the other operand's dtype when of the same kind (float16 tensor and 2.0 -> float16)."""
    if isinstance(x1, torch.Tensor):
        if isinstance(x2, torch.Tensor):
            return x1, x2
        return x1, _scalar_tensor(x2, x1)
    return _scalar_tensor(x1, x2), x2


def _scalar_tensor(value, other):
    """A Python scalar as a 0-d tensor next to ``other``: a float or complex next to a floating
    tensor is made in that precision (a float32 0-d tensor would round 1e-6 before torch
    promotes it to float64)."""
    dtype = None
    if isinstance(value, float) and (other.is_floating_point() or other.is_complex()):
        dtype = other.dtype
    elif isinstance(value, complex) and other.dtype in (torch.float64, torch.complex128):
        dtype = torch.complex128
    return torch.full((), value, dtype=dtype, device=other.device)


def reduction_args(x, axis, keepdims):
    """``(x, dim, keepdim)`` for a torch reduction. torch reads an empty ``dim`` as every axis, the
    Array API as none: for ``axis=()`` reduce over a new size-1 axis instead, keeping every value."""
    if isinstance(axis, (tuple, list)) and not axis:
        return x.unsqueeze(-1), -1, False
    return x, axis, keepdims


def as_inexact(x):
    """``x``, with an integer or boolean array converted to float32: how functions of real
    numbers treat such inputs on every backend (see ``ivy/backends/_reals.py``)."""
    if not isinstance(x, torch.Tensor):
        x = torch.as_tensor(x)
    return x if x.is_floating_point() or x.is_complex() else x.to(torch.float32)


def _as_is(native, name: str):
    return native


# ivy's rule for the functions of real numbers that the core declares (@dispatch(reals=True)),
# applied by the assembly: torch computes integer inputs of its unary and binary functions of
# real numbers in its default float dtype, float32, by itself; the shims of the others
# (reductions, activations) convert them.
REALS = {"unary": _as_is, "binary": _as_is, "options": _as_is}


def devices() -> list[torch.device]:
    """The devices torch sees: the CPU and each CUDA device."""
    return [torch.device("cpu")] + [
        torch.device("cuda", i) for i in range(torch.cuda.device_count())
    ]


def set_precision(precision: str):
    """torch's float32 precision switches for matrix products and cuDNN (convolutions, RNNs):
    IEEE float32 for ``'highest'``, TF32 for ``'high'``; returns what restores the values found.
    (torch's newer ``fp32_precision`` switches: mixing them with the legacy ``allow_tf32`` ones
    is an error in torch, so ivy uses only these.)"""
    value = "ieee" if precision == "highest" else "tf32"
    switches = (
        torch.backends.cuda.matmul,
        torch.backends.cudnn.conv,
        torch.backends.cudnn.rnn,
    )
    saved = [s.fp32_precision for s in switches]
    for s in switches:
        s.fp32_precision = value

    def restore() -> None:
        for s, old in zip(switches, saved):
            s.fp32_precision = old

    return restore


def values_known(x) -> bool:
    """Whether ``x``'s values can be read (a Python scalar's always): not while torch.compile or
    torch.func traces it."""
    if not isinstance(x, torch.Tensor):
        return True
    if torch.compiler.is_compiling():
        return False
    try:
        return not torch._C._functorch.is_functorch_wrapped_tensor(x)
    except AttributeError:  # (a torch without that query)
        return True
