"""Tests of the core group ``fft`` (``ivy/core/fft.py``), on every backend.

The Array API ``fft`` extension on every backend, against a discrete Fourier transform written
here as a float64 matrix product (independent of every FFT library), and the ``ivy.fft`` and
``ivy.<backend>.fft`` namespaces.
"""

from __future__ import annotations

import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, api_f, check, native, numpy_of, tolerance

NAMES = [
    "fft", "ifft", "fftn", "ifftn", "rfft", "irfft", "rfftn", "irfftn", "hfft", "ihfft",
    "fftfreq", "rfftfreq", "fftshift", "ifftshift",
]  # fmt: skip


COMPLEX_OF = {"float32": "complex64", "float64": "complex128"}


REAL_OF = {"complex64": "float32", "complex128": "float64", "float32": "float32"}
REAL_OF["float64"] = "float64"


NORMS = ["backward", "ortho", "forward"]


SWAPPED = {"backward": "forward", "forward": "backward", "ortho": "ortho"}


def _fit(x, n, axis):
    """Crop or zero-pad ``x`` to ``n`` along ``axis``."""
    x = np.moveaxis(x, axis, -1)
    if n <= x.shape[-1]:
        x = x[..., :n]
    else:
        x = np.concatenate([x, np.zeros((*x.shape[:-1], n - x.shape[-1]), x.dtype)], -1)
    return np.moveaxis(x, -1, axis)


def dft(x, n, axis, norm, inverse=False):
    x = np.moveaxis(_fit(np.asarray(x, np.complex128), n, axis), axis, -1)
    k = np.arange(n)
    w = np.exp((2j if inverse else -2j) * np.pi * np.outer(k, k) / n)
    scale = {
        "backward": 1 / n if inverse else 1,
        "ortho": n**-0.5,
        "forward": 1 if inverse else 1 / n,
    }
    return np.moveaxis(x @ w * scale[norm], -1, axis)


def rdft(x, n, axis, norm):
    return np.moveaxis(np.moveaxis(dft(x, n, axis, norm), axis, -1)[..., : n // 2 + 1], -1, axis)


def irdft(x, n, axis, norm):
    """Real signal of length ``n`` from its ``n // 2 + 1`` non-negative frequency terms."""
    half = np.moveaxis(_fit(np.asarray(x, np.complex128), n // 2 + 1, axis), axis, -1)
    k = np.arange(n)
    mirrored = np.where(k < n // 2 + 1, k, n - k)
    full = np.where(k < n // 2 + 1, half[..., np.minimum(k, n // 2)], np.conj(half[..., mirrored]))
    return np.moveaxis(dft(full, n, -1, norm, inverse=True).real, -1, axis)


REFERENCE = {
    "fft": lambda x, n, axis, norm: dft(x, n, axis, norm),
    "ifft": lambda x, n, axis, norm: dft(x, n, axis, norm, inverse=True),
    "rfft": rdft,
    "irfft": irdft,
    "hfft": lambda x, n, axis, norm: irdft(np.conj(x), n, axis, SWAPPED[norm]),
    "ihfft": lambda x, n, axis, norm: np.conj(rdft(x, n, axis, SWAPPED[norm])),
}


REAL_INPUT = {"rfft", "ihfft"}


REAL_OUTPUT = {"irfft", "hfft"}


def _signal(shape, dtype, seed):
    rng = np.random.default_rng(seed)
    x = rng.standard_normal(shape)
    if dtype.startswith("complex"):
        x = x + 1j * rng.standard_normal(shape)
    return x.astype(dtype)


def _result_dtype(name, dtype):
    if name in REAL_OUTPUT:
        return REAL_OF[dtype]
    return COMPLEX_OF.get(dtype, dtype)


def test_the_fft_namespace_is_callable_and_holds_the_agnostic_functions():
    assert sorted(NAMES) == sorted(ivy.fft.__all__)
    assert set(dir(ivy.fft)) == set(NAMES) and "fft" in ivy.__all__
    for name in NAMES:
        if name != "fft":
            assert getattr(ivy.fft, name) is getattr(ivy, name), name
    assert ivy.fft.fft is sys.modules["ivy.core.fft"].fft and ivy.core.fft is ivy.fft
    x = np.array([1.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(ivy.fft(x), np.ones(4))  # ivy.fft(x) is ivy.fft.fft(x)
    np.testing.assert_allclose(ivy.fft.fft(x), np.ones(4))


def test_each_backend_has_an_fft_namespace_of_its_own_functions(backend, xp):
    assert "fft" in xp.__all__ and xp.fft.__name__ == f"ivy.{backend}.fft"
    for name in NAMES:
        if name != "fft":
            assert getattr(xp.fft, name) is getattr(xp, name), name
    x = native(np.array([0.0, 1.0, 0.0, 0.0]), backend)
    expected = np.exp(-2j * np.pi * np.arange(4) / 4)
    check(xp.fft(x), expected, backend, **tolerance("complex128"))
    check(xp.fft.fft(x), expected, backend, **tolerance("complex128"))


def test_set_framework_binds_the_backend_fft_namespace(backend, xp):
    with ivy.set_framework(backend):
        assert ivy.fft is xp.fft
        assert ivy.fft.rfft is xp.rfft
    assert ivy.fft.rfft is ivy.core.rfft


SHAPES = [(8,), (5,), (2, 6), (3, 4, 5)]


@pytest.mark.parametrize("name", list(REFERENCE))
@settings(HYPOTHESIS, max_examples=15)  # six functions: 90 examples per backend
@given(data=st.data())
def test_one_dimensional_transforms(backend, name, data):
    real = st.sampled_from(["float32", "float64"])
    any_float = st.sampled_from(["float32", "float64", "complex64", "complex128"])
    dtype = data.draw(real if name in REAL_INPUT else any_float, label="dtype")
    shape = data.draw(st.sampled_from(SHAPES), label="shape")
    axis = data.draw(st.integers(-len(shape), len(shape) - 1), label="axis")
    m = shape[axis]
    default = 2 * (m - 1) if name in REAL_OUTPUT else m
    n = data.draw(st.sampled_from([None, 1, 3, default + 3, max(m - 1, 1)]), label="n")
    norm = data.draw(st.sampled_from(NORMS), label="norm")
    x = _signal(shape, dtype, 7)
    expected = REFERENCE[name](x, default if n is None else n, axis, norm)
    want = _result_dtype(name, dtype)
    tol = tolerance(want, 4 * (n or default))
    for fn in api(backend, name):
        out = fn(native(x, backend), n=n, axis=axis, norm=norm)
        check(out, expected.astype(want), backend, **tol)


@pytest.mark.parametrize("name", list(REFERENCE))
def test_defaults_are_the_last_axis_and_backward_norm(backend, name):
    dtype = "float64" if name in REAL_INPUT else "complex128"
    x = _signal((3, 6), dtype, 8)
    m = 6
    n = 2 * (m - 1) if name in REAL_OUTPUT else m
    expected = REFERENCE[name](x, n, -1, "backward")
    for fn in api(backend, name):
        check(fn(native(x, backend)), expected.astype(_result_dtype(name, dtype)), backend)


@pytest.mark.parametrize("name", ["fft", "rfft", "ihfft", "fftn"])
def test_integer_inputs_are_computed_in_float32(backend, name):
    x = np.arange(6, dtype=np.int64).reshape(2, 3)
    ref = {"fft": "fft", "rfft": "rfft", "ihfft": "ihfft", "fftn": "fft"}[name]
    expected = REFERENCE[ref](x.astype(np.float64), 3, -1, "backward")
    if name == "fftn":
        expected = dft(expected, 2, 0, "backward")
    for fn in api(backend, name):
        check(
            fn(native(x, backend)),
            expected.astype("complex64"),
            backend,
            **tolerance("complex64", 20),
        )


def _sizes_and_axes(shape, s, axes, real_inverse=False):
    if axes is None:
        axes = (
            list(range(len(shape))) if s is None else list(range(len(shape) - len(s), len(shape)))
        )
    axes = [a % len(shape) for a in axes]
    s = [-1] * len(axes) if s is None else list(s)
    sizes = [
        (2 * (shape[a] - 1) if real_inverse and i == len(axes) - 1 else shape[a]) if n == -1 else n
        for i, (n, a) in enumerate(zip(s, axes))
    ]
    return sizes, axes


def _fftn_reference(name, x, s, axes, norm):
    inverse = name in ("ifftn", "irfftn")
    sizes, axes = _sizes_and_axes(x.shape, s, axes, real_inverse=name == "irfftn")
    if name == "rfftn":
        x = rdft(x, sizes[-1], axes[-1], norm)
        sizes, axes = sizes[:-1], axes[:-1]
    if name == "irfftn":
        for n, a in zip(sizes[:-1], axes[:-1]):
            x = dft(x, n, a, norm, inverse=True)
        return irdft(x, sizes[-1], axes[-1], norm)
    for n, a in zip(sizes, axes):
        x = dft(x, n, a, norm, inverse=inverse)
    return x


# (shape, s, axes): defaults, s alone (its last axes), axes alone, both, -1 entries, negative axes
FFTN_CASES = [
    ((4, 6), None, None),
    ((2, 3, 4), None, None),
    ((2, 3, 4), (5, 2), None),
    ((2, 3, 4), None, (0, 2)),
    ((2, 3, 4), (3, -1), (-1, 0)),
    ((3, 4, 5), (-1, 6, 4), None),
    ((4, 6), (3,), (0,)),
]


@pytest.mark.parametrize("name", ["fftn", "ifftn", "rfftn", "irfftn"])
@pytest.mark.parametrize("case", FFTN_CASES, ids=str)
def test_n_dimensional_transforms(backend, name, case):
    shape, s, axes = case
    dtype = "float64" if name == "rfftn" else "complex128"
    x = _signal(shape, dtype, 9)
    for norm in NORMS if case is FFTN_CASES[2] else ["backward"]:
        expected = _fftn_reference(name, x, s, axes, norm)
        want = "float64" if name == "irfftn" else "complex128"
        for fn in api(backend, name):
            check(fn(native(x, backend), s=s, axes=axes, norm=norm), expected, backend, dtype=want)


@pytest.mark.parametrize("name", ["fftn", "rfftn", "irfftn"])
def test_n_dimensional_transforms_in_single_precision(backend, name):
    dtype = "float32" if name == "rfftn" else "complex64"
    x = _signal((3, 4, 6), dtype, 10)
    expected = _fftn_reference(name, x, None, None, "ortho")
    want = "float32" if name == "irfftn" else "complex64"
    for fn in api(backend, name):
        out = fn(native(x, backend), norm="ortho")
        check(out, expected.astype(want), backend, **tolerance(want, 20))


def test_round_trips(backend):
    x = _signal((4, 6), "float64", 11)
    xp = getattr(ivy, backend)
    nx = native(x, backend)
    check(xp.irfftn(xp.rfftn(nx), s=x.shape), x, backend)
    check(xp.ifftn(xp.fftn(nx)), x.astype("complex128"), backend)
    check(xp.irfft(xp.rfft(nx, n=7), n=7)[..., :6], x, backend)
    spectrum = xp.ihfft(nx)  # the half spectrum of a real signal is Hermitian: hfft inverts it
    check(xp.ihfft(xp.hfft(spectrum, n=6)), numpy_of(spectrum), backend)


@pytest.mark.parametrize("n", [1, 4, 7])
@pytest.mark.parametrize("d", [1.0, 0.1])
def test_fftfreq_and_rfftfreq(backend, n, d):
    k = np.arange(n)
    expected = np.where(k < (n + 1) // 2, k, k - n) / (d * n)
    expected_r = np.arange(n // 2 + 1) / (d * n)
    for fn in api_f(backend, "fftfreq"):
        check(fn(n, d=d), expected.astype("float32"), backend)  # float32 by default
        check(fn(n, d=d, dtype="float64"), expected, backend)
    for fn in api_f(backend, "rfftfreq"):
        check(fn(n, d=d), expected_r.astype("float32"), backend)
        check(fn(n, d=d, dtype="float64", device="cpu"), expected_r, backend)


def _roll_reference(x, axes, inverse):
    axes = range(x.ndim) if axes is None else [axes] if isinstance(axes, int) else axes
    for a in axes:
        shift = x.shape[a] // 2
        x = np.roll(x, -shift if inverse else shift, axis=a)
    return x


@pytest.mark.parametrize("name", ["fftshift", "ifftshift"])
@pytest.mark.parametrize("axes", [None, 0, -1, (0, 1)], ids=str)
def test_shifts(backend, name, axes):
    x = np.arange(35, dtype=np.int64).reshape(5, 7)
    expected = _roll_reference(x, axes, inverse=name == "ifftshift")
    for fn in api(backend, name):
        check(fn(native(x, backend), axes=axes), expected, backend)
    if axes is None:
        check(api(backend, name)[0](native(x, backend)), expected, backend)
