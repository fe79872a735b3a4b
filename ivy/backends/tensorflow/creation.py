"""tensorflow backend: array creation (float32 and int64 by default, as on every backend)."""

from __future__ import annotations

import numpy as np
import tensorflow as tf

from ivy.backends._constants import ConstantCache
from ivy.backends._creation_args import check_step, linspace_dtype
from ivy.backends.tensorflow._helpers import (
    TENSOR_TYPES,
    default_dtype_of_value,
    native_dtype,
    placed,
    tensor,
    tensor_of,
    to_tensor,
)


def asarray(obj, /, *, dtype=None, device=None, copy=None):
    """tf tensors are immutable, so ``copy`` changes nothing; a variable is read into a tensor."""
    if device is None:
        return to_tensor(obj, native_dtype(dtype))
    with placed(device):
        return tf.identity(to_tensor(obj, native_dtype(dtype)))


def zeros(shape, *, dtype=None, device=None):
    with placed(device):
        return tf.zeros(shape, native_dtype(dtype) or tf.float32)


def ones(shape, *, dtype=None, device=None):
    with placed(device):
        return tf.ones(shape, native_dtype(dtype) or tf.float32)


def empty(shape, *, dtype=None, device=None):
    """tf has no uninitialised memory: zeros."""
    return zeros(shape, dtype=dtype, device=device)


def full(shape, fill_value, *, dtype=None, device=None):
    dt = native_dtype(dtype) or default_dtype_of_value(fill_value)
    shape = (shape,) if isinstance(shape, int) else shape
    with placed(device):
        return tf.broadcast_to(tensor_of(fill_value, dt), shape)


def _is_int(value) -> bool:
    dt = getattr(value, "dtype", None)
    if dt is None:
        return isinstance(value, int)
    return native_dtype(dt).is_integer


def arange(start, /, stop=None, step=1, *, dtype=None, device=None):
    check_step(step, "tensorflow")
    ints = all(_is_int(v) for v in (start, stop, step) if v is not None)
    dt = native_dtype(dtype) or (tf.int64 if ints else tf.float32)
    work = dt if ints and dt.is_integer else tf.float64  # the length as numpy counts it
    if stop is None:
        start, stop = 0, start
    with placed(device):
        if (
            all(isinstance(v, (int, float)) for v in (start, stop, step))
            and (stop - start) * step <= 0
        ):
            return tf.zeros([0], dt)  # an empty range, which tf refuses
        if dt.is_integer and dt not in (tf.int32, tf.int64):  # tf.range has no uint8 kernel
            work = tf.int64 if dt.size < 8 or not dt.is_unsigned else tf.float64
        out = tf.range(tensor_of(start, work), tensor_of(stop, work), tensor_of(step, work))
        return out if work is dt else tf.cast(out, dt)


def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True):
    dt = native_dtype(linspace_dtype(start, stop, dtype, "tensorflow") or dtype)
    if dt.is_complex:  # the real and imaginary parts, each spaced evenly
        parts = [
            linspace(
                complex(v).real if i == 0 else complex(v).imag,
                complex(w).real if i == 0 else complex(w).imag,
                num,
                dtype=dt.real_dtype,
                device=device,
                endpoint=endpoint,
            )
            for i, (v, w) in enumerate(((start, stop), (start, stop)))
        ]
        return tf.complex(*parts)
    work = dt if dt.is_floating else tf.float64
    with placed(device):
        out = tf.linspace(tensor_of(start, work), tensor_of(stop, work), num + (not endpoint))
        if not endpoint:
            out = out[:-1]
        if dt.is_integer:
            out = tf.math.floor(out)
        return out if work is dt else tf.cast(out, dt)


def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None):
    dt = native_dtype(dtype) or tf.float32
    n_cols = n_rows if n_cols is None else n_cols
    with placed(device):
        if k == 0:
            return tf.eye(n_rows, n_cols, dtype=dt)
        k = max(-n_rows, min(k, n_cols))  # (beyond the matrix every diagonal is empty)
        rows = tf.range(n_rows, dtype=tf.int64)[:, None]
        return tf.cast(tf.equal(rows + k, tf.range(n_cols, dtype=tf.int64)), dt)


def zeros_like(x, /, *, dtype=None, device=None):
    with placed(device):
        return tf.zeros_like(tensor(x), dtype=native_dtype(dtype))


def ones_like(x, /, *, dtype=None, device=None):
    with placed(device):
        return tf.ones_like(tensor(x), dtype=native_dtype(dtype))


def empty_like(x, /, *, dtype=None, device=None):
    """tf has no uninitialised memory: zeros."""
    return zeros_like(x, dtype=dtype, device=device)


def full_like(x, /, fill_value, *, dtype=None, device=None):
    x = tensor(x)
    with placed(device):
        return tf.fill(tf.shape(x), tensor_of(fill_value, native_dtype(dtype) or x.dtype))


def meshgrid(*arrays, indexing="xy"):
    """A list, as the Array API (2023.12) says; arrays of several dtypes (which tf refuses)
    each keep their dtype."""
    arrays = [tensor(a) for a in arrays]
    if len({a.dtype for a in arrays}) <= 1:
        return tf.meshgrid(*arrays, indexing=indexing)
    n = len(arrays)
    sizes = [tf.size(a) for a in arrays]
    order = list(range(n))
    if indexing == "xy" and n > 1:
        order[0], order[1] = 1, 0
    shape = [sizes[order[k]] for k in range(n)]
    out = []
    for i, a in enumerate(arrays):
        view = [1] * n
        view[order.index(i)] = -1
        out.append(tf.broadcast_to(tf.reshape(a, view), shape))
    return out


def from_dlpack(x, /, *, device=None, copy=None):
    """tf tensors are immutable. ``copy=None`` shares the producer's memory where tf can (then a
    later in-place change of, say, a torch tensor shows through); ``copy=True`` never shares.
    CPU memory that is not 64-byte aligned is copied (tf's kernels abort the process on it), and
    so refused with ``copy=False``."""
    if isinstance(x, TENSOR_TYPES):
        out = tf.identity(x) if copy else tf.convert_to_tensor(x)
    elif x.__dlpack_device__()[0] == _DLPACK_CPU:
        view = np.from_dlpack(x)
        if copy:
            out = tf.constant(np.array(view))
        elif view.ctypes.data % 64:
            if copy is False:
                raise BufferError(
                    "from_dlpack: copy=False, but tensorflow needs 64-byte aligned memory and "
                    "this buffer is not: pass copy=None to allow a copy."
                )
            out = tf.constant(view)  # tf copies unaligned data into a buffer of its own
        else:
            out = tf.experimental.dlpack.from_dlpack(x.__dlpack__())
    else:
        out = tf.experimental.dlpack.from_dlpack(x.__dlpack__())
        if copy:
            out = tf.raw_ops.DeepCopy(x=out)
    if device is None:
        return out
    with placed(device):
        return tf.identity(out)


_DLPACK_CPU = 1  # DLDeviceType kDLCPU


def _triangle_mask(x, k, lower: bool):
    """True on and below (``lower``) or above diagonal ``k`` of the last two axes of ``x``."""
    shape = tf.shape(x, out_type=tf.int64)
    rows = tf.range(shape[-2])[:, None]
    cols = tf.range(shape[-1])[None, :]
    return cols - rows <= k if lower else cols - rows >= k


def tril(x, /, *, k=0):
    x = tensor(x)
    return tf.where(_triangle_mask(x, k, True), x, tf.zeros((), x.dtype))


def triu(x, /, *, k=0):
    x = tensor(x)
    return tf.where(_triangle_mask(x, k, False), x, tf.zeros((), x.dtype))


_CONSTANTS = ConstantCache()


def constant(value, /, *, dtype=None, device=None):
    """Inside a ``tf.function`` the value is a constant of the graph; eagerly, the tensor is
    made once per dtype and device and kept."""
    if not isinstance(value, np.ndarray) or not tf.executing_eagerly():
        return asarray(value, dtype=dtype, device=device)
    key = (native_dtype(dtype), device)
    return _CONSTANTS.get(value, key, lambda v: asarray(v, dtype=dtype, device=device))
