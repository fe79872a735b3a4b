"""Discrete Fourier transforms: the Array API (2023.12) ``fft`` extension.

Every function here is reachable flat (``ivy.ifft``, ``ivy.torch.ifft``) and in the extension
namespace (``ivy.fft.ifft``, ``ivy.torch.fft.ifft``). ``ivy.fft`` is that namespace and, being
also the name of the transform, is callable: ``ivy.fft(x)`` is ``ivy.fft.fft(x)``.

Conventions (numpy's): ``norm='backward'`` leaves the forward transform unscaled and divides the
inverse by ``n``; ``'ortho'`` scales both by ``1/sqrt(n)``; ``'forward'`` divides the forward one
by ``n``. ``n`` (or ``s``) crops or zero-pads the input along the transformed axes. Real inputs of
the complex transforms become complex of the same precision (float32 -> complex64); bool and
integer inputs are computed in float32, on every backend.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Device, Dtype, Framework

__extension__ = "fft"

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


@dispatch
def fft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """One-dimensional discrete Fourier transform along ``axis``.

    Args:
        x: input array (complex, or real: computed as complex).
        n: length of the transform; the input is cropped or zero-padded to it (default: its
            size along ``axis``).
        axis: the transformed axis.
        norm: ``'backward'``, ``'ortho'`` or ``'forward'``.

    Returns:
        A complex array, of size ``n`` along ``axis``.

    Example: ``ivy.fft(np.array([1., 0., 0., 0.]))`` -> ``[1.+0.j, 1.+0.j, 1.+0.j, 1.+0.j]``.
    """


@dispatch
def ifft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Inverse of :func:`fft` (``norm='backward'`` divides by ``n``)."""


@dispatch
def fftn(
    x: Array,
    /,
    *,
    s: Sequence[int] | None = None,
    axes: Sequence[int] | None = None,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """N-dimensional discrete Fourier transform.

    Args:
        x: input array.
        s: length of the transform along each of ``axes``; ``-1`` (or ``s=None``) keeps the
            input's size there.
        axes: the transformed axes; None is every axis, or the last ``len(s)`` when ``s`` is
            given.
        norm: ``'backward'``, ``'ortho'`` or ``'forward'`` (the scaling is over all the axes).

    Returns:
        A complex array.
    """


@dispatch
def ifftn(
    x: Array,
    /,
    *,
    s: Sequence[int] | None = None,
    axes: Sequence[int] | None = None,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Inverse of :func:`fftn` (arguments as there)."""


@dispatch
def rfft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Fourier transform of a real signal: the ``n // 2 + 1`` non-negative frequency terms
    (float32 -> complex64, float64 -> complex128)."""


@dispatch
def irfft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Inverse of :func:`rfft`: a real signal of length ``n`` (default ``2 * (m - 1)``, ``m`` the
    input's size along ``axis``) from its non-negative frequency terms."""


@dispatch
def rfftn(
    x: Array,
    /,
    *,
    s: Sequence[int] | None = None,
    axes: Sequence[int] | None = None,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """N-dimensional :func:`rfft`: the real transform over the last of ``axes``, then complex
    transforms over the others (``s`` and ``axes`` as in :func:`fftn`)."""


@dispatch
def irfftn(
    x: Array,
    /,
    *,
    s: Sequence[int] | None = None,
    axes: Sequence[int] | None = None,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Inverse of :func:`rfftn`; the output length along the last of ``axes`` defaults to
    ``2 * (m - 1)`` (also for an entry ``-1`` of ``s`` there)."""


@dispatch
def hfft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Fourier transform of a signal with Hermitian symmetry, given by its non-negative frequency
    half: a real result of length ``n`` (default ``2 * (m - 1)``)."""


@dispatch
def ihfft(
    x: Array,
    /,
    *,
    n: int | None = None,
    axis: int = -1,
    norm: Literal["backward", "ortho", "forward"] = "backward",
    f: Framework = None,
) -> Array:
    """Inverse of :func:`hfft`: the ``n // 2 + 1`` terms of a real signal's Hermitian
    spectrum."""


@dispatch()
def fftfreq(
    n: int,
    /,
    *,
    d: float = 1.0,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Sample frequencies of :func:`fft` for a signal of ``n`` samples spaced by ``d``:
    ``[0, 1, ..., n//2 - 1 (or (n-1)//2), -n//2 (or -(n-1)//2), ..., -1] / (d * n)``.

    Args:
        n: number of samples.
        d: sample spacing.
        dtype: a real floating dtype, float32 by default.
        device: ``'cpu'``, ``'gpu:0'``, ...

    Example: ``ivy.fftfreq(4, f='numpy')`` -> ``[0., 0.25, -0.5, -0.25]``.
    """


@dispatch()
def rfftfreq(
    n: int,
    /,
    *,
    d: float = 1.0,
    dtype: Dtype | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Sample frequencies of :func:`rfft`: ``[0, 1, ..., n // 2] / (d * n)`` (float32 by
    default)."""


@dispatch
def fftshift(x: Array, /, *, axes: int | Sequence[int] | None = None, f: Framework = None) -> Array:
    """Move the zero-frequency term to the centre of ``axes`` (None: all), rolling each by
    ``size // 2``."""


@dispatch
def ifftshift(
    x: Array, /, *, axes: int | Sequence[int] | None = None, f: Framework = None
) -> Array:
    """Inverse of :func:`fftshift` (rolls each axis by ``-(size // 2)``)."""
