"""torch backend: array creation (float32 by default, as on every backend)."""

from __future__ import annotations

import numpy as np
import torch

from ivy.backends._constants import ConstantCache
from ivy.backends._creation_args import beyond_int64, check_fill_value, check_step
from ivy.backends._dlpack import exportable, on_host, refuse_copy_between_devices
from ivy.backends.torch._helpers import (
    default_dtype_of_value,
    has_own_dtype,
    native_device,
    native_dtype,
)
from ivy.backends.torch._unsigned import WIDE_UNSIGNED, unsigned_safe, work_dtype
from ivy.errors import DtypeError

# torch's default dtypes can be changed by the user; ivy's cannot.
_DOWNCAST = {torch.float64: torch.float32, torch.complex128: torch.complex64}


def asarray(obj, /, *, dtype=None, device=None, copy=None):
    dtype, device = native_dtype(dtype), native_device(device)
    if isinstance(obj, torch.Tensor):
        return _from_tensor(obj, dtype, device, copy)
    if isinstance(obj, (list, tuple)) and obj and has_own_dtype(obj):
        obj = _stack(obj)
    elif (
        isinstance(obj, np.ndarray)
        and not torch.compiler.is_compiling()  # (torch.compile cannot read numpy's flags)
        and not obj.flags.writeable
    ):
        obj = obj.copy()  # torch would alias a read-only buffer as writable (and warn)
    elif not isinstance(obj, (torch.Tensor, np.ndarray, np.generic)) and (
        hasattr(obj, "__dlpack__") or hasattr(obj, "__array__")
    ):
        obj = _from_other_framework(obj)
    try:
        x = torch.asarray(obj, dtype=dtype, device=device, copy=copy)
    except (ValueError, RuntimeError) as err:  # ("Overflow when unpacking long long")
        if dtype is None and "Overflow" in str(err) and not has_own_dtype(obj):
            raise beyond_int64("torch") from None
        raise
    if dtype is None and x.dtype in _DOWNCAST and not has_own_dtype(obj):
        return x.to(_DOWNCAST[x.dtype])
    return x


def _from_tensor(x, dtype, device, copy):
    """A tensor as it is, or converted (``Tensor.to``, which keeps ``requires_grad`` without
    torch.asarray's warning about it)."""
    same = (dtype is None or dtype is x.dtype) and (
        device is None or torch.device(device) == x.device
    )
    if same and not copy:
        return x
    if not same and copy is False:
        raise ValueError(
            "asarray: copy=False, but the dtype or device asked for needs a copy. Pass copy=None "
            "to allow it."
        )
    return x.to(dtype=dtype or x.dtype, device=device or x.device, copy=bool(copy))


def _stack(seq):
    """A (nested) list of arrays as one tensor, keeping their dtype."""
    return torch.stack([_stack(o) if isinstance(o, (list, tuple)) else asarray(o) for o in seq])


def _from_other_framework(obj):
    """A jax or tensorflow array, copied: their buffers are immutable, a torch tensor is not."""
    if hasattr(obj, "__dlpack__"):
        return torch.from_dlpack(obj).clone()  # keeps the device
    return torch.from_numpy(np.array(obj))


def zeros(shape, *, dtype=None, device=None):
    return torch.zeros(
        shape, dtype=native_dtype(dtype) or torch.float32, device=native_device(device)
    )


def ones(shape, *, dtype=None, device=None):
    return torch.ones(
        shape, dtype=native_dtype(dtype) or torch.float32, device=native_device(device)
    )


def empty(shape, *, dtype=None, device=None):
    return torch.empty(
        shape, dtype=native_dtype(dtype) or torch.float32, device=native_device(device)
    )


def full(shape, fill_value, *, dtype=None, device=None):
    shape = (shape,) if isinstance(shape, int) else shape
    dtype = native_dtype(dtype) or default_dtype_of_value(fill_value)
    check_fill_value(fill_value, str(dtype).rsplit(".", 1)[-1], "torch")
    return torch.full(shape, fill_value, dtype=dtype, device=native_device(device))


def arange(start, /, stop=None, step=1, *, dtype=None, device=None):
    check_step(step, "torch")
    if dtype is None:
        ints = all(isinstance(v, (int, np.integer)) for v in (start, stop, step) if v is not None)
        dtype = torch.int64 if ints else torch.float32
    if stop is None:
        start, stop = 0, start
    dtype, device = native_dtype(dtype), native_device(device)
    if (stop - start) * step <= 0:  # an empty range, which torch refuses
        return torch.empty(0, dtype=dtype, device=device)
    out = torch.arange(start, stop, step, dtype=work_dtype(dtype), device=device)
    return out if out.dtype is dtype or dtype is None else out.to(dtype)


def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True):
    dtype, device = native_dtype(dtype), native_device(device)
    if dtype is None:  # complex bounds (the Array API allows them) give complex64
        dtype = (
            torch.complex64
            if isinstance(start, complex) or isinstance(stop, complex)
            else torch.float32
        )
    work = work_dtype(dtype)
    if dtype.is_complex and not (isinstance(start, complex) or isinstance(stop, complex)):
        start, stop = complex(start), complex(stop)
    if not dtype.is_complex and (isinstance(start, complex) or isinstance(stop, complex)):
        raise DtypeError(
            f"complex bounds {start!r}, {stop!r} need a complex dtype, not {dtype}.",
            function="linspace",
            argument="dtype",
            backend="torch",
        )
    if endpoint:
        out = torch.linspace(start, stop, num, dtype=work, device=device)
    else:
        out = torch.linspace(start, stop, num + 1, dtype=work, device=device)[:-1]
    return out if out.dtype is dtype else out.to(dtype)


def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None):
    dtype, device = native_dtype(dtype) or torch.float32, native_device(device)
    n_cols = n_rows if n_cols is None else n_cols
    if k == 0 and dtype not in WIDE_UNSIGNED:
        return torch.eye(n_rows, n_cols, dtype=dtype, device=device)
    k = max(-n_rows, min(k, n_cols))  # (beyond the matrix every diagonal is empty)
    rows = torch.arange(n_rows, device=device)[:, None]
    return (torch.arange(n_cols, device=device) - rows == k).to(dtype)


def zeros_like(x, /, *, dtype=None, device=None):
    return torch.zeros_like(x, dtype=native_dtype(dtype), device=native_device(device))


def ones_like(x, /, *, dtype=None, device=None):
    return torch.ones_like(x, dtype=native_dtype(dtype), device=native_device(device))


def empty_like(x, /, *, dtype=None, device=None):
    return torch.empty_like(x, dtype=native_dtype(dtype), device=native_device(device))


def full_like(x, /, fill_value, *, dtype=None, device=None):
    return torch.full_like(x, fill_value, dtype=native_dtype(dtype), device=native_device(device))


def from_dlpack(x, /, *, device=None, copy=None):
    """Between the host and an accelerator the array is imported where it is and then moved
    (``Tensor.to``: a copy); without ``device`` it stays where ``x`` is."""
    x, copy_after = exportable(x)
    target = native_device(device)
    if target is not None and on_host(x) != (torch.device(target).type == "cpu"):
        refuse_copy_between_devices(copy, f"to {target}")
        return from_dlpack(x).to(target)
    if copy_after:
        out = torch.from_dlpack(x, device=native_device(device))
        return out.clone() if copy else out
    return torch.from_dlpack(x, device=native_device(device), copy=copy)


def meshgrid(*arrays, indexing="xy"):
    if not arrays:
        return []  # torch refuses no arrays
    arrays = [a if isinstance(a, torch.Tensor) else asarray(a) for a in arrays]
    if len({a.dtype for a in arrays}) == 1:
        return list(torch.meshgrid(*arrays, indexing=indexing))
    # arrays of several dtypes (torch refuses them): each result keeps its array's dtype
    shape = [a.numel() for a in arrays]
    if indexing == "xy" and len(arrays) > 1:
        shape[0], shape[1] = shape[1], shape[0]
    out = []
    for i, a in enumerate(arrays):
        axis = {0: 1, 1: 0}.get(i, i) if indexing == "xy" and len(arrays) > 1 else i
        view = [1] * len(arrays)
        view[axis] = -1
        out.append(a.reshape(view).expand(shape))
    return out


_tril = unsigned_safe(torch.tril, "tril", "move", (0,))
_triu = unsigned_safe(torch.triu, "triu", "move", (0,))


def tril(x, /, *, k=0):
    return _tril(x, k)


def triu(x, /, *, k=0):
    return _triu(x, k)


_CONSTANTS = ConstantCache()


def constant(value, /, *, dtype=None, device=None):
    """Inside ``torch.compile`` a numpy array becomes an input of the graph (dynamo converts it
    without a copy at each call and guards on its shape and dtype only, so a constant of another
    object recompiles nothing); eagerly, the tensor is made once and kept (a copy: it never
    shares memory with the numpy array)."""
    if torch.compiler.is_compiling() or not isinstance(value, np.ndarray):
        return asarray(value, dtype=dtype, device=device)
    dtype, device = native_dtype(dtype), native_device(device)
    return _CONSTANTS.get(
        value, (dtype, device), lambda v: asarray(v, dtype=dtype, device=device, copy=True)
    )
