"""The Array API ``fft`` extension, written once: ``xp.fft`` with ivy's rules on top.

Bool and integer inputs compute in float32 (numpy and jax with 64-bit types would use float64),
``s`` and ``axes`` of the n-dimensional transforms resolve by the Array API's rules
(``ivy/backends/_fft_args.py``), and ``fftfreq`` and ``rfftfreq`` take a dtype (float32 by
default).
"""

from __future__ import annotations

from ivy.backends._fft_args import sizes_and_axes
from ivy.backends.array_api._unbound import as_inexact, native_device, native_dtype, xp

NATIVE = {"fftshift": "fft.fftshift", "ifftshift": "fft.ifftshift"}


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.fft(as_inexact(x), n=n, axis=axis, norm=norm)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.ifft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "fftn")
    return xp.fft.fftn(x, s=s, axes=axes, norm=norm)


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "ifftn")
    return xp.fft.ifftn(x, s=s, axes=axes, norm=norm)


def rfft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.rfft(as_inexact(x), n=n, axis=axis, norm=norm)


def irfft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.irfft(as_inexact(x), n=n, axis=axis, norm=norm)


def rfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "rfftn")
    return xp.fft.rfftn(x, s=s, axes=axes, norm=norm)


def irfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "irfftn", real_inverse=True)
    return xp.fft.irfftn(x, s=s, axes=axes, norm=norm)


def hfft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.hfft(as_inexact(x), n=n, axis=axis, norm=norm)


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.ihfft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    out = xp.fft.fftfreq(n, d=d, device=native_device(device))
    return xp.astype(out, native_dtype(dtype) or xp.float32)


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    out = xp.fft.rfftfreq(n, d=d, device=native_device(device))
    return xp.astype(out, native_dtype(dtype) or xp.float32)
