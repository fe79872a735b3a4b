"""Shared fixtures: a ``backend`` fixture over the frameworks that import here, and fixtures
over subsets of them that have a property a test needs:

- ``diff_backend``: automatic differentiation (every backend but numpy; also the backends that
  are compared with numpy as the reference);
- ``graph_backend``: graph compilers that start quickly (``jax.jit``, ``tf.function``);
  ``torch.compile`` takes about 17 s to start, so a few tests compile with it on purpose;
- ``mutable_backend``: arrays written in place (numpy, torch), where shared memory shows.

The backends and what each can do are listed once, in :data:`BACKENDS`; tests ask for a
capability (``capable(backend, "autodiff")``, the subset fixtures), never for a backend's name.

Narrow it with ``--backends numpy,torch`` or the environment variable ``IVY_BACKENDS``.
jax runs with 64-bit types enabled so that float64 works on every backend; ``--jax-x64 off`` (or
``IVY_JAX_X64=0``) runs it as users get it by default, 64-bit types off: a test that needs
float64 asks ``require(backend, "float64")`` and is skipped on jax then (a property of that
configuration), and everything else must pass.

Order. Every test draws from its own generator (the ``rng`` fixture, seeded by the test's name),
never from one shared by a module, so what it gets does not depend on the tests before it.
``--shuffle SEED`` (or ``IVY_TEST_SHUFFLE=SEED``; ``random`` picks and prints a seed) runs the
tests in an order shuffled by that seed, the check that the suite does not depend on its order:

    python -m pytest tests/ivy tests/ivy_mechanics tests/ivy_vision tests/ivy_rl tests/scripts \
        -n 2 --shuffle random

Opt-in backends. ``array_api_strict`` (a library registered with ``ivy.register_framework``, the
reference implementation of the Array API standard) joins the matrix only in the test
directories that opt in: the core's (``tests/ivy``) and ``ivy_mechanics``' (``tests/ivy_mechanics``).
A package opts in with one line in its directory's ``conftest.py``::

    IVY_OPT_IN_BACKENDS = ("array_api_strict",)

(a test module may set the same name for itself). Everywhere else ``backend`` stays the four
frameworks, so an applied library's tests do not meet a fifth backend before they opt in.

XLA compiles a little faster here. The suite's time is mostly jax compiling programs that each
run a few times, so the tests switch off LLVM's expensive passes in XLA's CPU backend
(``--xla_llvm_disable_expensive_passes=true``, added to ``XLA_FLAGS`` before jax starts): the
same operations, compiled about a tenth faster (a constrained double pendulum's step and
gradient: 7.1 s to 6.4 s). (``--xla_backend_optimization_level=0`` would save a third, but in
jax 0.10.2 it computes a wrong value, off by 23%, for the gradient program of
``ivy_vision.forward_warp``, which ``tests/ivy_vision/test_gradients.py`` caught.)
``IVY_TEST_XLA_DEFAULTS=1`` keeps XLA's own settings.
"""

from __future__ import annotations

import importlib.util
import os
import random
import sys
import zlib

import numpy as np
import pytest

import ivy

_XLA_QUICK = "--xla_llvm_disable_expensive_passes=true"
if os.environ.get("IVY_TEST_XLA_DEFAULTS", "0") in ("0", "") and "jax" not in sys.modules:
    os.environ["XLA_FLAGS"] = f"{os.environ.get('XLA_FLAGS', '')} {_XLA_QUICK}".strip()

# One table: every backend the tests know, and what it can do (ivy's own Capabilities, plus
# what the tests need to know of it). ``opt_in``: only where a test directory asks for it.
BACKENDS = {
    "numpy": dict(
        autodiff=False,
        compilation=False,
        fast_graph=False,
        mutable=True,
        float16=True,
        forward_vmap=False,
        opt_in=False,
    ),
    "torch": dict(
        autodiff=True,
        compilation=True,
        fast_graph=False,
        mutable=True,
        float16=True,
        forward_vmap=True,
        opt_in=False,
    ),
    "jax": dict(
        autodiff=True,
        compilation=True,
        fast_graph=True,
        mutable=False,
        float16=True,
        forward_vmap=True,
        opt_in=False,
    ),
    # no vmap of forward-mode transformations (ForwardAccumulator is not vectorised)
    "tensorflow": dict(
        autodiff=True,
        compilation=True,
        fast_graph=True,
        mutable=False,
        float16=True,
        forward_vmap=False,
        opt_in=False,
    ),
    # the standard has no float16: array_api_strict refuses it
    "array_api_strict": dict(
        autodiff=False,
        compilation=False,
        fast_graph=False,
        mutable=False,
        float16=False,
        forward_vmap=False,
        opt_in=True,
    ),
}
ALL_BACKENDS = tuple(n for n, c in BACKENDS.items() if not c["opt_in"])  # the four frameworks
OPT_IN_BACKENDS = tuple(n for n, c in BACKENDS.items() if c["opt_in"])
DIFFERENTIABLE = tuple(n for n, c in BACKENDS.items() if c["autodiff"])
SUBSETS = {
    "diff_backend": lambda c: c["autodiff"],
    "graph_backend": lambda c: c["fast_graph"],
    "mutable_backend": lambda c: c["mutable"],
}


def capable(backend: str, capability: str) -> bool:
    """Whether ``backend`` has ``capability`` (a key of :data:`BACKENDS`' rows; ``'float64'``:
    whether it holds float64 arrays in this run, which jax does only with ``--jax-x64 on``)."""
    if capability == "float64":
        return backend != "jax" or JAX_X64[0]
    return BACKENDS[backend][capability]


def require(backend: str, capability: str) -> None:
    """Skip the running test where ``backend`` lacks ``capability`` (a property of the library,
    such as float16 on array_api_strict, never a missing ivy feature)."""
    if not capable(backend, capability):
        pytest.skip(f"{backend} has no {capability}")


if importlib.util.find_spec("array_api_strict") is not None:
    ivy.register_framework("array_api_strict", "array_api_strict", mutable_arrays=True)


def pytest_addoption(parser):
    parser.addoption(
        "--backends",
        default=None,
        help="comma-separated backends to test (default: every installed one; or set IVY_BACKENDS)",
    )
    parser.addoption(
        "--shuffle",
        default=os.environ.get("IVY_TEST_SHUFFLE"),
        help="run the tests in an order shuffled by this seed ('random': a new seed, printed); "
        "or set IVY_TEST_SHUFFLE",
    )
    parser.addoption(
        "--jax-x64",
        choices=("on", "off"),
        default="off" if os.environ.get("IVY_JAX_X64", "1") in ("0", "off") else "on",
        help="jax's 64-bit types during the run (default on; off is jax's own default; or set "
        "IVY_JAX_X64=0)",
    )


def _selected(config) -> tuple[str, ...]:
    chosen = config.getoption("--backends") or os.environ.get("IVY_BACKENDS")
    names = tuple(BACKENDS) if not chosen else tuple(n.strip() for n in chosen.split(","))
    unknown = set(names) - set(BACKENDS)
    if unknown:
        raise pytest.UsageError(f"unknown backends {sorted(unknown)}; choose from {BACKENDS}")
    return tuple(n for n in names if importlib.util.find_spec(n) is not None)


def pytest_configure(config):
    config.ivy_backends = _selected(config)
    JAX_X64[0] = config.getoption("--jax-x64") == "on"
    if "jax" in config.ivy_backends:
        import jax

        jax.config.update("jax_enable_x64", JAX_X64[0])
    _target_the_device(config.ivy_backends)
    config.ivy_shuffle = _shuffle_seed(config)


#: Whether jax runs with 64-bit types (``--jax-x64``), set when the run is configured.
JAX_X64 = [True]


def _shuffle_seed(config) -> int | None:
    """The seed of ``--shuffle`` (a new one for ``random``; the same one on every xdist worker,
    which must collect the tests in one order: the controller passes it on)."""
    value = config.getoption("--shuffle")
    if value in (None, "", "off", "0"):
        return None
    workerinput = getattr(config, "workerinput", None)
    if workerinput is not None and "ivy_shuffle" in workerinput:
        return workerinput["ivy_shuffle"]
    if value == "random":
        return random.SystemRandom().randrange(1, 2**31)
    try:
        return int(value)
    except ValueError:
        raise pytest.UsageError(
            f"--shuffle takes an integer seed or 'random'; got {value!r}."
        ) from None


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node):
    """(xdist) every worker shuffles with the controller's seed."""
    node.workerinput["ivy_shuffle"] = node.config.ivy_shuffle


def pytest_report_header(config):
    seed = getattr(config, "ivy_shuffle", None)
    if seed is not None:
        return f"tests shuffled with seed {seed} (rerun this order: --shuffle {seed})"
    return None


def pytest_terminal_summary(terminalreporter, config):
    """The shuffle's seed also at the end (``-q`` hides the header)."""
    seed = getattr(config, "ivy_shuffle", None)
    if seed is not None and getattr(config, "workerinput", None) is None:
        terminalreporter.write_line(f"tests shuffled with seed {seed} (repeat: --shuffle {seed})")


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config, items):
    seed = getattr(config, "ivy_shuffle", None)
    if seed is not None:
        random.Random(seed).shuffle(items)


@pytest.fixture
def rng(request) -> np.random.Generator:
    """A random generator of this test's own, seeded by the test's module and name (not its
    parameters, so every backend gets the same draws): what a test draws never depends on the
    tests that ran before it in the same worker."""
    name = f"{request.node.module.__name__}::{request.node.originalname}"
    return np.random.default_rng(zlib.crc32(name.encode()))


def device_for(backend: str) -> str:
    """The device a test of ``backend`` creates its arrays on: the run's target device where the
    backend has that kind of device (``Capabilities.devices``), else the CPU (numpy)."""
    kind = TARGET_DEVICE.partition(":")[0]
    return TARGET_DEVICE if kind in ivy.framework_handler.capabilities(backend).devices else "cpu"


def _torch_target(kind: str, index: int) -> None:
    import torch

    if kind != "gpu" or index >= torch.cuda.device_count():
        raise pytest.UsageError(
            f"IVY_TEST_DEVICE={TARGET_DEVICE}: torch sees {torch.cuda.device_count()} CUDA "
            f"devices. Choose one it has, or leave torch out (IVY_BACKENDS=numpy,jax)."
        )
    torch.set_default_device(f"cuda:{index}")  # torch.zeros, torch.tensor... (tests' natives too)


def _jax_target(kind: str, index: int) -> None:
    import jax

    try:
        device = jax.devices(kind)[index]
    except (RuntimeError, IndexError):
        raise pytest.UsageError(
            f"IVY_TEST_DEVICE={TARGET_DEVICE}: jax has no such device ({jax.devices()}). "
            f"Choose one it has, or leave jax out (IVY_BACKENDS=numpy,torch)."
        ) from None
    jax.config.update("jax_default_device", device)


# What makes a framework create its arrays on the target device by default (tensorflow places
# them on its first GPU by itself; numpy has only the CPU).
_TARGETERS = {"torch": _torch_target, "jax": _jax_target}


def _target_the_device(backends) -> None:
    """``IVY_TEST_DEVICE=gpu:0``: the frameworks' default device, so that the arrays the tests
    make (``tests.helpers.native``, ``ivy.zeros(...)`` without ``device=``) live there."""
    if TARGET_DEVICE == "cpu":
        return
    kind, _, index = TARGET_DEVICE.partition(":")
    for backend in backends:
        if backend in _TARGETERS:
            _TARGETERS[backend](kind, int(index or 0))


def _opted_in(metafunc) -> tuple[str, ...]:
    """The opt-in backends that the test's module or one of its directories' conftest asks for."""
    module = metafunc.module
    found = getattr(module, "IVY_OPT_IN_BACKENDS", None)
    package = module.__name__.rpartition(".")[0]
    while found is None and package:
        conftest = sys.modules.get(f"{package}.conftest")
        found = getattr(conftest, "IVY_OPT_IN_BACKENDS", None)
        package = package.rpartition(".")[0]
    return tuple(found or ())


def backends_for(metafunc) -> list[str]:
    """The backends a test runs on: the selected ones, opt-in ones only where opted in."""
    opted = _opted_in(metafunc)
    return [b for b in metafunc.config.ivy_backends if not BACKENDS[b]["opt_in"] or b in opted]


def pytest_generate_tests(metafunc):
    backends = backends_for(metafunc)
    if "backend" in metafunc.fixturenames:
        metafunc.parametrize("backend", backends)
    for fixture, has in SUBSETS.items():
        if fixture in metafunc.fixturenames:
            metafunc.parametrize(fixture, [b for b in backends if has(BACKENDS[b])])


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


#: The device the test run targets: ``IVY_TEST_DEVICE`` (``'cpu'``, ``'gpu:0'``), default ``'cpu'``.
TARGET_DEVICE = os.environ.get("IVY_TEST_DEVICE", "cpu")


@pytest.fixture
def target_device() -> str:
    """The device the test run targets (``IVY_TEST_DEVICE``, default ``'cpu'``): tests that
    check where arrays are placed ask for this device, never for ``'cpu'`` by name."""
    return TARGET_DEVICE
