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


# ----------------------------------------------------------------------------------------------
# Native conversion, independent of ivy: inputs are built and outputs are read with each
# framework's own functions, so that a bug in ivy.asarray or ivy.to_numpy cannot hide another.
# ----------------------------------------------------------------------------------------------

_TYPE_ROOTS = {
    "numpy": ("numpy",),
    "torch": ("torch",),
    "jax": ("jax", "jaxlib"),
    "tensorflow": ("tensorflow",),
    "array_api_strict": ("array_api_strict",),
}


def _torch_native(a):
    import torch

    t = torch.from_numpy(a)  # (on the CPU whatever torch's default device: moved to that one)
    return t.to(torch.get_default_device())


def _jax_native(a):
    import jax
    import jax.numpy as jnp

    if a.dtype in (np.float64, np.complex128) and not jax.config.jax_enable_x64:
        import pytest  # (a test asking for float64 on jax without 64-bit types: the run's choice)

        pytest.skip("jax runs without 64-bit types (--jax-x64 off): it holds no float64")
    return jnp.asarray(a)


def _tf_native(a):
    import tensorflow as tf

    return tf.convert_to_tensor(a)


def _strict_native(a):
    import array_api_strict

    return array_api_strict.asarray(a)


# backend -> (numpy array -> native array of the same dtype), with each framework's own API
_NATIVE = {
    "numpy": lambda a: a,
    "torch": _torch_native,
    "jax": _jax_native,
    "tensorflow": _tf_native,
    "array_api_strict": _strict_native,
}
# root module of an array's type -> (native array -> numpy array), likewise
_TO_NUMPY = {
    "torch": lambda x: x.detach().cpu().resolve_conj().numpy(),
    "tensorflow": lambda x: x.numpy(),
    "jax": np.asarray,
    "jaxlib": np.asarray,
    "array_api_strict": lambda x: np.asarray(x),
}


def native(a, backend: str):
    """A numpy array (or nested list / scalar) as a native array of ``backend``, same dtype."""
    try:
        make = _NATIVE[backend]
    except KeyError:
        raise ValueError(f"unknown backend {backend!r}") from None
    return make(np.array(a))


def is_native(x, backend: str) -> bool:
    """True when ``x`` is an array of ``backend`` (numpy scalars count as numpy arrays)."""
    roots = _TYPE_ROOTS[backend]
    return any(k.__module__.partition(".")[0] in roots for k in type(x).__mro__[:-1])


def numpy_of(x) -> np.ndarray:
    """A native array of any backend as a numpy array, read with the framework's own API."""
    if isinstance(x, (np.ndarray, np.generic)):
        return np.asarray(x)
    root = type(x).__module__.partition(".")[0]
    try:
        return _TO_NUMPY[root](x)
    except KeyError:
        raise TypeError(f"not an array of a known framework: {type(x)!r}") from None


def dtype_name(x) -> str:
    """Name ('float32', 'int64', 'bool', ...) of the dtype of a native array of any backend."""
    name = str(x.dtype)
    for prefix in ("torch.", "array_api_strict."):
        if name.startswith(prefix):
            name = name[len(prefix) :]
    if name.startswith("<dtype: "):  # tf.DType repr
        name = x.dtype.name
    return np.dtype(name).name if name != "bool" else "bool"


def check(actual, expected, backend: str, *, dtype=None, signed_zeros=False, **overrides):
    """Assert that ``actual`` is a ``backend`` array with the dtype, shape and values of the
    numpy reference ``expected``.

    Args:
        actual: the result under test.
        expected: numpy reference; its dtype is the expected dtype unless ``dtype`` is given.
        backend: the backend ``actual`` must belong to.
        dtype: expected dtype name, when it differs from ``expected.dtype``.
        signed_zeros: also require the sign of zero results to match the reference.
        **overrides: tolerance overrides (``rtol``, ``atol``).
    """
    expected = np.asarray(expected)
    want = dtype or expected.dtype.name
    assert is_native(actual, backend), f"expected a {backend} array, got {type(actual)!r}"
    assert dtype_name(actual) == want, f"dtype {dtype_name(actual)} != expected {want}"
    got = numpy_of(actual)
    assert got.shape == expected.shape, f"shape {got.shape} != expected {expected.shape}"
    if want in TOLERANCES:
        tol = {**TOLERANCES[want], **overrides}
        np.testing.assert_allclose(got, expected.astype(want), equal_nan=True, **tol)
        if signed_zeros:
            zeros = expected == 0
            np.testing.assert_array_equal(
                np.signbit(got[zeros]), np.signbit(expected[zeros]), err_msg="sign of zero"
            )
    else:
        np.testing.assert_array_equal(got, expected)


# ----------------------------------------------------------------------------------------------
# Gradients against finite differences, in float64, on the differentiable backends
# ----------------------------------------------------------------------------------------------

FD_STEP = 1e-5  # central differences of float64 functions


def native_value_and_grads(backend, fn, arrays, weights, jit=True):
    """``sum(fn(*arrays) * weights)`` and its gradients, by the framework's own autodiff.

    On jax the gradient is jitted by default: one compilation instead of one dispatch per
    primitive, the faster for large programs (dynamics). ``jit=False`` runs it eagerly, the
    faster for many small functions called once each (jax caches each primitive's compilation
    across them, where a jitted program is compiled per function and input shape)."""
    if backend == "torch":
        import torch

        inputs = [torch.tensor(a, requires_grad=True) for a in arrays]
        loss = (fn(*inputs) * torch.as_tensor(np.asarray(weights))).sum()
        return loss.item(), [g.numpy() for g in torch.autograd.grad(loss, inputs)]
    if backend == "jax":
        import jax
        import jax.numpy as jnp

        def loss(*inputs):
            return jnp.sum(fn(*inputs) * weights)

        value_and_grad = jax.value_and_grad(loss, argnums=tuple(range(len(arrays))))
        if jit:
            value_and_grad = jax.jit(value_and_grad)
        value, grads = value_and_grad(*[_jax_native(np.asarray(a)) for a in arrays])
        return float(value), [np.asarray(g) for g in grads]
    if backend == "tensorflow":
        import tensorflow as tf

        inputs = [tf.convert_to_tensor(a) for a in arrays]
        with tf.GradientTape() as tape:
            for t in inputs:
                tape.watch(t)
            loss = tf.reduce_sum(fn(*inputs) * weights)
        return float(loss), [g.numpy() for g in tape.gradient(loss, inputs)]
    raise ValueError(backend)


def check_gradients(backend, fn, arrays, n_directions=1, rtol=1e-6, step=FD_STEP):
    """Check the gradients of ``fn`` (native arrays in, one native array out) at the float64
    ``arrays`` on the differentiable ``backend``: the framework's own gradients of
    ``sum(fn(*arrays) * weights)`` (random weights) along random directions, against central
    finite differences of ``fn`` run on the same backend, with the given ``step`` (stiff
    functions, such as dynamics with contacts, need a smaller one)."""
    arrays = [np.asarray(a, np.float64) for a in arrays]
    out = numpy_of(fn(*[native(a, backend) for a in arrays]))
    weights = np.random.default_rng(159).standard_normal(out.shape)
    value, grads = native_value_and_grads(backend, fn, arrays, weights)
    assert np.isclose(value, np.sum(out * weights), rtol=1e-12)

    def loss(inputs):
        return np.sum(numpy_of(fn(*[native(a, backend) for a in inputs])) * weights)

    rng = np.random.default_rng(7)
    for _ in range(n_directions):
        v = [rng.standard_normal(a.shape) for a in arrays]
        plus = loss([a + step * d for a, d in zip(arrays, v)])
        minus = loss([a - step * d for a, d in zip(arrays, v)])
        numeric = (plus - minus) / (2 * step)
        analytic = sum(np.sum(g * d) for g, d in zip(grads, v))
        np.testing.assert_allclose(analytic, numeric, rtol=rtol, atol=1e-8)


def tolerance(dtype: str, scale: float = 1.0) -> dict:
    """The tolerance of ``dtype`` with ``atol`` scaled to the magnitude of the problem."""
    tol = TOLERANCES[dtype]
    return dict(rtol=tol["rtol"], atol=tol["atol"] * max(scale, 1.0))


def api(backend: str, name: str):
    """The two ways to call function ``name`` on ``backend``: the framework-agnostic
    ``ivy.<name>`` (the framework inferred from the arrays) and the namespace's ``xp.<name>``."""
    return [getattr(ivy, name), getattr(getattr(ivy, backend), name)]


def api_f(backend: str, name: str):
    """Like :func:`api` for functions with no array argument: ``ivy.<name>(..., f=backend)``
    and ``xp.<name>(...)``."""
    agnostic = getattr(ivy, name)

    def with_f(*args, **kwargs):
        return agnostic(*args, f=backend, **kwargs)

    return [with_f, getattr(getattr(ivy, backend), name)]


try:
    from hypothesis import HealthCheck, settings

    # Modest and derandomized: the suite runs in minutes on two cores and does not flake.
    HYPOTHESIS = settings(
        max_examples=25,
        deadline=None,
        derandomize=True,
        suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
    )
except ImportError:  # hypothesis is a test extra; helpers stay importable without it
    HYPOTHESIS = None


def reference(fn, *args, **kwargs):
    """Call a numpy/scipy reference with floating-point warnings silenced (inf, nan, empty
    slices are expected inputs here)."""
    import warnings

    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore", RuntimeWarning)
        return fn(*args, **kwargs)


def cast(a, dtype: str) -> np.ndarray:
    """A numpy reference in float64 rounded to ``dtype`` (overflow to inf is expected)."""
    with np.errstate(all="ignore"):
        return np.asarray(a).astype(dtype)


def check_meta(actual, backend: str, dtype: str, shape: tuple):
    """Assert that ``actual`` is a ``backend`` array of ``dtype`` and ``shape`` (values free)."""
    assert is_native(actual, backend), f"expected a {backend} array, got {type(actual)!r}"
    assert dtype_name(actual) == dtype, f"dtype {dtype_name(actual)} != expected {dtype}"
    got = tuple(numpy_of(actual).shape)
    assert got == tuple(shape), f"shape {got} != expected {tuple(shape)}"


def run_notebook(path, monkeypatch, settings: dict, timeout: int = 600) -> tuple[list, str]:
    """Execute the notebook at ``path`` headless (nbclient) with the environment variables
    ``settings`` and this checkout on ``PYTHONPATH``; assert that no cell raised. Returns the
    PNG outputs and the text that the cells printed. Skips without nbformat and nbclient."""
    import os
    import pathlib

    import pytest

    nbformat = pytest.importorskip("nbformat", reason="notebook tests need the [test] extra")
    nbclient = pytest.importorskip("nbclient", reason="notebook tests need the [test] extra")
    root = pathlib.Path(__file__).resolve().parents[1]
    for key, value in settings.items():
        monkeypatch.setenv(key, value)
    path_var = os.pathsep.join(filter(None, [str(root), os.environ.get("PYTHONPATH")]))
    monkeypatch.setenv("PYTHONPATH", path_var)
    book = nbformat.read(path, as_version=4)
    nbclient.NotebookClient(
        book, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(root)}}
    ).execute()
    outputs = [o for cell in book.cells if cell.cell_type == "code" for o in cell.outputs]
    errors = [o for o in outputs if o.get("output_type") == "error"]
    assert not errors, errors
    images = [o for o in outputs if "image/png" in o.get("data", {})]
    return images, "".join(o.get("text", "") for o in outputs)
