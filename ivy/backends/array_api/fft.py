"""The Array API ``fft`` extension, written once: ``xp.fft`` with ivy's rules on top.

Bool and integer inputs compute in float32 (numpy and jax with 64-bit types would use float64),
``s`` and ``axes`` of the n-dimensional transforms resolve by the Array API's rules
(``ivy/backends/_fft_args.py``), and ``fftfreq`` and ``rfftfreq`` take a dtype (float32 by
default).
"""

from __future__ import annotations

from ivy.backends._fft_args import sizes_and_axes
from ivy.backends.array_api._unbound import as_inexact, native_device, native_dtype, xp


def _complex(x):
    """``x`` as a complex array: the standard's ``fft``, ``ifft``, ``fftn``, ``ifftn`` and ``hfft``
    take complex input (numpy and jax convert real input themselves, to the same values)."""
    x = as_inexact(x)
    if xp.isdtype(x.dtype, "complex floating"):
        return x
    return xp.astype(x, xp.complex128 if x.dtype == xp.float64 else xp.complex64)


def _shifted_axes(x, axes):
    if axes is None:
        return tuple(range(x.ndim))
    return (axes,) if isinstance(axes, int) else tuple(axes)


def fftshift(x, /, *, axes=None):
    axes = _shifted_axes(x, axes)
    return xp.roll(x, tuple(x.shape[a] // 2 for a in axes), axis=axes) if axes else x


def ifftshift(x, /, *, axes=None):
    axes = _shifted_axes(x, axes)
    return xp.roll(x, tuple(-(x.shape[a] // 2) for a in axes), axis=axes) if axes else x


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.fft(_complex(x), n=n, axis=axis, norm=norm)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.ifft(_complex(x), n=n, axis=axis, norm=norm)


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    x = _complex(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "fftn")
    return xp.fft.fftn(x, s=s, axes=axes, norm=norm)


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    x = _complex(x)
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
    return xp.fft.hfft(_complex(x), n=n, axis=axis, norm=norm)


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    return xp.fft.ihfft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    out = xp.fft.fftfreq(n, d=d, device=native_device(device))
    return xp.astype(out, native_dtype(dtype) or xp.float32)


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    out = xp.fft.rfftfreq(n, d=d, device=native_device(device))
    return xp.astype(out, native_dtype(dtype) or xp.float32)
