"""Helpers shared by the tests: one tolerance table by dtype, and comparison with references."""

from __future__ import annotations

import numpy as np

import ivy

TOLERANCES = {
    "float16": dict(rtol=1e-3, atol=1e-3),
    "float32": dict(rtol=1e-5, atol=1e-6),
    "float64": dict(rtol=1e-12, atol=1e-12),
    "complex64": dict(rtol=1e-5, atol=1e-6),
    "complex128": dict(rtol=1e-12, atol=1e-12),
}


def assert_close(actual, expected, dtype=None, **overrides):
    """Compare an array of any backend with a numpy reference, by the tolerance of ``dtype``."""
    actual = np.asarray(ivy.to_numpy(actual)) if not isinstance(actual, np.ndarray) else actual
    expected = np.asarray(expected)
    name = dtype or actual.dtype.name
    tol = {**TOLERANCES.get(name, dict(rtol=0, atol=0)), **overrides}
    assert actual.shape == expected.shape, f"shape {actual.shape} != expected {expected.shape}"
    np.testing.assert_allclose(actual, expected, equal_nan=True, **tol)
