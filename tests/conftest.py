"""Shared fixtures: a ``backend`` fixture over the frameworks that import here.

Narrow it with ``--backends numpy,torch`` or the environment variable ``IVY_BACKENDS``.
jax runs with 64-bit types enabled so that float64 works on every backend.
"""

from __future__ import annotations

import importlib.util
import os

import numpy as np
import pytest

import ivy

ALL_BACKENDS = ("numpy", "torch", "jax", "tensorflow")
DIFFERENTIABLE = ("torch", "jax", "tensorflow")

# Tolerances by dtype, used by every test that compares numbers.
TOLERANCES = {
    "float16": dict(rtol=1e-3, atol=1e-3),
    "float32": dict(rtol=1e-5, atol=1e-6),
    "float64": dict(rtol=1e-12, atol=1e-12),
    "complex64": dict(rtol=1e-5, atol=1e-6),
    "complex128": dict(rtol=1e-12, atol=1e-12),
}


def pytest_addoption(parser):
    parser.addoption(
        "--backends",
        default=None,
        help="comma-separated backends to test (default: every installed one; "
        "or set IVY_BACKENDS)",
    )


def _selected(config) -> tuple[str, ...]:
    chosen = config.getoption("--backends") or os.environ.get("IVY_BACKENDS")
    names = ALL_BACKENDS if not chosen else tuple(n.strip() for n in chosen.split(","))
    unknown = set(names) - set(ALL_BACKENDS)
    if unknown:
        raise pytest.UsageError(f"unknown backends {sorted(unknown)}; choose from {ALL_BACKENDS}")
    return tuple(n for n in names if importlib.util.find_spec(n) is not None)


def pytest_configure(config):
    config.ivy_backends = _selected(config)
    if "jax" in config.ivy_backends:
        import jax

        jax.config.update("jax_enable_x64", True)


def pytest_generate_tests(metafunc):
    backends = metafunc.config.ivy_backends
    if "backend" in metafunc.fixturenames:
        metafunc.parametrize("backend", backends)
    if "diff_backend" in metafunc.fixturenames:
        metafunc.parametrize("diff_backend", [b for b in backends if b in DIFFERENTIABLE])


@pytest.fixture
def xp(backend):
    """The ivy namespace of the backend under test (``ivy.torch`` ...)."""
    return getattr(ivy, backend)


@pytest.fixture(autouse=True)
def _no_global_framework():
    """Every test starts and ends with no framework set globally."""
    while ivy.current_framework() is not None:
        ivy.unset_framework()
    yield
    while ivy.current_framework() is not None:
        ivy.unset_framework()


def assert_close(actual, expected, dtype=None, **overrides):
    """Compare an array of any backend with a numpy reference, by the tolerance of ``dtype``."""
    actual = np.asarray(ivy.to_numpy(actual)) if not isinstance(actual, np.ndarray) else actual
    expected = np.asarray(expected)
    name = dtype or actual.dtype.name
    tol = {**TOLERANCES.get(name, dict(rtol=0, atol=0)), **overrides}
    assert actual.shape == expected.shape, f"shape {actual.shape} != expected {expected.shape}"
    np.testing.assert_allclose(actual, expected, equal_nan=True, **tol)
