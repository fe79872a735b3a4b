"""torch backend: the Array API ``fft`` extension (``torch.fft``).

The shims rename ``axis``/``axes`` to ``dim``, compute bool and integer inputs in float32, resolve
``s`` and ``axes`` of the n-dimensional transforms by the Array API's rules, and give
``fftfreq`` and ``rfftfreq`` float32 by default.
"""

from __future__ import annotations

import torch

from ivy.backends._fft_args import sizes_and_axes
from ivy.backends.torch._helpers import as_inexact, native_device, native_dtype


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.fft(as_inexact(x), n=n, dim=axis, norm=norm)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.ifft(as_inexact(x), n=n, dim=axis, norm=norm)


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "fftn")
    return torch.fft.fftn(x, s=s, dim=axes, norm=norm)


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "ifftn")
    return torch.fft.ifftn(x, s=s, dim=axes, norm=norm)


def rfft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.rfft(as_inexact(x), n=n, dim=axis, norm=norm)


def irfft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.irfft(as_inexact(x), n=n, dim=axis, norm=norm)


def rfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "rfftn")
    return torch.fft.rfftn(x, s=s, dim=axes, norm=norm)


def irfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "irfftn", real_inverse=True)
    return torch.fft.irfftn(x, s=s, dim=axes, norm=norm)


def hfft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.hfft(as_inexact(x), n=n, dim=axis, norm=norm)


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    return torch.fft.ihfft(as_inexact(x), n=n, dim=axis, norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    dtype = native_dtype(dtype) or torch.float32
    return torch.fft.fftfreq(n, d=d, dtype=dtype, device=native_device(device))


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    dtype = native_dtype(dtype) or torch.float32
    return torch.fft.rfftfreq(n, d=d, dtype=dtype, device=native_device(device))


def fftshift(x, /, *, axes=None):
    if x.ndim == 0:  # (torch's needs an axis to shift; a 0-d array has none)
        return x.clone()
    return torch.fft.fftshift(x, dim=axes)


def ifftshift(x, /, *, axes=None):
    if x.ndim == 0:
        return x.clone()
    return torch.fft.ifftshift(x, dim=axes)
