"""Shared fixtures: a ``backend`` fixture over the frameworks that import here, and fixtures
over subsets of them that have a property a test needs:

- ``diff_backend``: automatic differentiation (every backend but numpy; also the backends that
  are compared with numpy as the reference);
- ``graph_backend``: graph compilers that start quickly (``jax.jit``, ``tf.function``);
  ``torch.compile`` takes about 17 s to start, so a few tests compile with it on purpose;
- ``mutable_backend``: arrays written in place (numpy, torch), where shared memory shows.

Narrow it with ``--backends numpy,torch`` or the environment variable ``IVY_BACKENDS``.
jax runs with 64-bit types enabled so that float64 works on every backend.
"""

from __future__ import annotations

import importlib.util
import os

import pytest

import ivy

ALL_BACKENDS = ("numpy", "torch", "jax", "tensorflow")
DIFFERENTIABLE = ("torch", "jax", "tensorflow")
SUBSETS = {
    "diff_backend": DIFFERENTIABLE,
    "graph_backend": ("jax", "tensorflow"),
    "mutable_backend": ("numpy", "torch"),
}


def pytest_addoption(parser):
    parser.addoption(
        "--backends",
        default=None,
        help="comma-separated backends to test (default: every installed one; or set IVY_BACKENDS)",
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
    for fixture, subset in SUBSETS.items():
        if fixture in metafunc.fixturenames:
            metafunc.parametrize(fixture, [b for b in backends if b in subset])


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
