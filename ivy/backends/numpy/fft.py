"""numpy backend: the Array API ``fft`` extension (``np.fft``, which keeps float32 precision).

The shims compute bool and integer inputs in float32 (numpy would use float64), resolve ``s`` and
``axes`` of the n-dimensional transforms by the Array API's rules, and give ``fftfreq`` and
``rfftfreq`` a dtype (float32 by default).
"""

from __future__ import annotations

import numpy as np

from ivy.backends._fft_args import sizes_and_axes
from ivy.backends.numpy._helpers import as_inexact, check_device, native_dtype

__all__ = [
    "fft",
    "ifft",
    "fftn",
    "ifftn",
    "rfft",
    "irfft",
    "rfftn",
    "irfftn",
    "hfft",
    "ihfft",
    "fftfreq",
    "rfftfreq",
    "fftshift",
    "ifftshift",
]

fftshift = np.fft.fftshift
ifftshift = np.fft.ifftshift


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.fft(as_inexact(x), n=n, axis=axis, norm=norm)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.ifft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "fftn")
    return np.fft.fftn(x, s=s, axes=axes, norm=norm)


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "ifftn")
    return np.fft.ifftn(x, s=s, axes=axes, norm=norm)


def rfft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.rfft(as_inexact(x), n=n, axis=axis, norm=norm)


def irfft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.irfft(as_inexact(x), n=n, axis=axis, norm=norm)


def rfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "rfftn")
    return np.fft.rfftn(x, s=s, axes=axes, norm=norm)


def irfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "irfftn", real_inverse=True)
    return np.fft.irfftn(x, s=s, axes=axes, norm=norm)


def hfft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.hfft(as_inexact(x), n=n, axis=axis, norm=norm)


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    return np.fft.ihfft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    check_device(device)
    return np.fft.fftfreq(n, d).astype(native_dtype(dtype) or np.float32)


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    check_device(device)
    return np.fft.rfftfreq(n, d).astype(native_dtype(dtype) or np.float32)
