"""tensorflow backend: the Array API ``fft`` extension, over ``tf.signal``.

``tf.signal`` transforms only the innermost axis, takes no ``norm`` and only complex (or, for the
real transforms, real floating) inputs. The shims move the axis innermost and back, pad or crop to
``n``, scale by ``norm``, compute bool and integer inputs in float32, and build the n-dimensional
transforms from one-dimensional ones (``hfft`` is ``irfft`` of the conjugate, ``ihfft`` the
conjugate of ``rfft``). Axis sizes must be known (static shapes inside ``tf.function``).
"""

from __future__ import annotations

import math

import numpy as np
import tensorflow as tf

from ivy.backends._fft_args import SWAPPED_NORM, axis_of, check_norm, size_of, sizes_and_axes
from ivy.backends.tensorflow._helpers import native_dtype, placed, static_rank, tensor


def fftshift(x, /, *, axes=None):
    x = tensor(x)
    return tf.identity(x) if x.shape.rank == 0 else tf.signal.fftshift(x, axes=axes)


def ifftshift(x, /, *, axes=None):
    x = tensor(x)
    return tf.identity(x) if x.shape.rank == 0 else tf.signal.ifftshift(x, axes=axes)


def _complex(x):
    """``x`` as a complex tensor: float64 becomes complex128, other real dtypes complex64."""
    x = tensor(x)
    if x.dtype.is_complex:
        return x
    return tf.cast(x, tf.complex128 if x.dtype == tf.float64 else tf.complex64)


def _real(x, fn):
    """``x`` as a real floating tensor: bool and integers become float32."""
    x = tensor(x)
    if x.dtype.is_complex:
        raise TypeError(f"{fn} takes a real-valued input; got {x.dtype.name}.")
    if x.dtype in (tf.float32, tf.float64):
        return x
    return tf.cast(x, tf.float32)


def _innermost(fn, x, axis):
    """``fn`` applied with ``axis`` moved innermost, then moved back."""
    rank = static_rank(x, "fft")
    if axis == rank - 1:
        return fn(x)
    perm = list(range(rank))
    perm[axis], perm[-1] = perm[-1], perm[axis]  # a swap is its own inverse
    return tf.transpose(fn(tf.transpose(x, perm)), perm)


def _fit(x, n):
    """Crop or zero-pad the innermost axis of ``x`` to length ``n``."""
    size = x.shape[-1]
    if n < size:
        return x[..., :n]
    if n > size:
        return tf.pad(x, [[0, 0]] * (x.shape.rank - 1) + [[0, n - size]])
    return x


def _scale(y, n, norm, inverse):
    """Scale an unnormalized forward transform, or tf's inverse (which divides by ``n``)."""
    if inverse:
        factor = {"backward": 1.0, "ortho": math.sqrt(n), "forward": float(n)}[norm]
    else:
        factor = {"backward": 1.0, "ortho": 1 / math.sqrt(n), "forward": 1.0 / n}[norm]
    return y if factor == 1.0 else y * tf.constant(factor, y.dtype)


def _one(x, n, axis, norm, name, inverse, real_input=False, real_output=False):
    """One 1-D transform ``name`` along ``axis`` with tf's innermost transform of that name."""
    fn = getattr(tf.signal, name)
    check_norm(norm, name)
    x = _real(x, name) if real_input else _complex(x)
    axis = axis_of(axis, static_rank(x, name), name)
    m = x.shape[axis]
    n = size_of(n, 2 * (m - 1) if real_output else m, name)
    if real_input or real_output:  # tf's real transforms crop and pad themselves
        y = _innermost(lambda t: fn(t, fft_length=[n]), x, axis)
    else:
        y = _innermost(lambda t: fn(_fit(t, n)), x, axis)
    return _scale(y, n, norm, inverse)


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return _one(x, n, axis, norm, "fft", inverse=False)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return _one(x, n, axis, norm, "ifft", inverse=True)


def rfft(x, /, *, n=None, axis=-1, norm="backward"):
    return _one(x, n, axis, norm, "rfft", inverse=False, real_input=True)


def irfft(x, /, *, n=None, axis=-1, norm="backward"):
    return _one(x, n, axis, norm, "irfft", inverse=True, real_output=True)


def hfft(x, /, *, n=None, axis=-1, norm="backward"):
    check_norm(norm, "hfft")
    return irfft(tf.math.conj(_complex(x)), n=n, axis=axis, norm=SWAPPED_NORM[norm])


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    check_norm(norm, "ihfft")
    return tf.math.conj(rfft(x, n=n, axis=axis, norm=SWAPPED_NORM[norm]))


def _nd(x, s, axes, norm, one, name):
    x = tensor(x)
    sizes, axes = sizes_and_axes(x.shape.as_list(), s, axes, name)
    for n, axis in zip(sizes, axes):
        x = one(x, n=n, axis=axis, norm=norm)
    return _complex(x)  # no axes: the input as complex


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    return _nd(x, s, axes, norm, fft, "fftn")


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    return _nd(x, s, axes, norm, ifft, "ifftn")


def rfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = tensor(x)
    sizes, axes = sizes_and_axes(x.shape.as_list(), s, axes, "rfftn")
    if not axes:
        raise ValueError("rfftn: needs at least one axis to transform.")
    x = rfft(x, n=sizes[-1], axis=axes[-1], norm=norm)
    for n, axis in zip(sizes[:-1], axes[:-1]):
        x = fft(x, n=n, axis=axis, norm=norm)
    return x


def irfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = tensor(x)
    sizes, axes = sizes_and_axes(x.shape.as_list(), s, axes, "irfftn", real_inverse=True)
    if not axes:
        raise ValueError("irfftn: needs at least one axis to transform.")
    for n, axis in zip(sizes[:-1], axes[:-1]):
        x = ifft(x, n=n, axis=axis, norm=norm)
    return irfft(x, n=sizes[-1], axis=axes[-1], norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    with placed(device):
        return tf.constant(np.fft.fftfreq(n, d), native_dtype(dtype) or tf.float32)


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    with placed(device):
        return tf.constant(np.fft.rfftfreq(n, d), native_dtype(dtype) or tf.float32)
