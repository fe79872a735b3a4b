"""jax backend: the Array API ``fft`` extension (``jax.numpy.fft``).

The shims compute bool and integer inputs in float32 (jax would use float64 with 64-bit types
enabled), resolve ``s`` and ``axes`` of the n-dimensional transforms by the Array API's rules, and
give ``fftfreq`` and ``rfftfreq`` float32 by default.
"""

from __future__ import annotations

import jax.numpy as jnp

from ivy.backends._fft_args import sizes_and_axes
from ivy.backends.jax._helpers import as_inexact, native_device, native_dtype

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

fftshift = jnp.fft.fftshift
ifftshift = jnp.fft.ifftshift


def fft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.fft(as_inexact(x), n=n, axis=axis, norm=norm)


def ifft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.ifft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "fftn")
    return jnp.fft.fftn(x, s=s, axes=axes, norm=norm)


def ifftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "ifftn")
    return jnp.fft.ifftn(x, s=s, axes=axes, norm=norm)


def rfft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.rfft(as_inexact(x), n=n, axis=axis, norm=norm)


def irfft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.irfft(as_inexact(x), n=n, axis=axis, norm=norm)


def rfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "rfftn")
    return jnp.fft.rfftn(x, s=s, axes=axes, norm=norm)


def irfftn(x, /, *, s=None, axes=None, norm="backward"):
    x = as_inexact(x)
    s, axes = sizes_and_axes(x.shape, s, axes, "irfftn", real_inverse=True)
    return jnp.fft.irfftn(x, s=s, axes=axes, norm=norm)


def hfft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.hfft(as_inexact(x), n=n, axis=axis, norm=norm)


def ihfft(x, /, *, n=None, axis=-1, norm="backward"):
    return jnp.fft.ihfft(as_inexact(x), n=n, axis=axis, norm=norm)


def fftfreq(n, /, *, d=1.0, dtype=None, device=None):
    dtype = native_dtype(dtype) or jnp.float32
    return jnp.fft.fftfreq(n, d, dtype=dtype, device=native_device(device))


def rfftfreq(n, /, *, d=1.0, dtype=None, device=None):
    dtype = native_dtype(dtype) or jnp.float32
    return jnp.fft.rfftfreq(n, d, dtype=dtype, device=native_device(device))
