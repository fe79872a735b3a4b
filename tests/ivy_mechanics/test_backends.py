"""The whole API on every backend, from one table (tests/ivy_mechanics/_cases.py): the same
numbers as the numpy backend (float64 1e-12, float32 1e-5), the dtype of the input, arbitrary
batch shapes, and compiled (jax.jit, tf.function with unknown batch size) equal to eager."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import ivy_mechanics as mech
from tests.compilers import native_compile
from tests.helpers import dtype_name, native, numpy_of
from tests.ivy_mechanics._cases import BATCH_SHAPE, CASES, make_inputs
from tests.ivy_mechanics._utils import call

pytestmark = pytest.mark.filterwarnings("ignore:Gimbal lock")

NAMES = sorted(CASES)


def _inputs(name, seed, singular=False, dtype="float64"):
    kinds, kwargs = CASES[name]
    rng = np.random.default_rng(seed)
    arrays = make_inputs(kinds, rng, kwargs.get("convention", "zyx"), singular)
    return [a.astype(dtype) for a in arrays], kwargs


def test_every_backend_gives_the_same_numbers(diff_backend):  # numpy is the reference
    for name in NAMES:
        for dtype, singular, tol in (
            ("float64", False, 1e-12),
            ("float64", True, 1e-12),
            ("float32", False, 1e-5),
        ):
            args, kwargs = _inputs(name, 50, singular=singular, dtype=dtype)
            expected = call("numpy", name, args, kwargs)
            got = call(diff_backend, name, args, kwargs)
            assert got.dtype == dtype, f"{name}: {dtype} in, {got.dtype} out"
            np.testing.assert_allclose(
                got, expected, rtol=tol, atol=tol, err_msg=f"{name} {dtype} singular={singular}"
            )


def test_batch_shapes(backend):
    """No batch dimension, and two batch dimensions, give the per-item results."""
    for name in NAMES:
        args, kwargs = _inputs(name, 51)
        flat = call(backend, name, args, kwargs)
        shape = BATCH_SHAPE
        got = call(backend, name, [a.reshape(*shape, *a.shape[1:]) for a in args], kwargs)
        np.testing.assert_allclose(
            got, flat.reshape(*shape, *flat.shape[1:]), rtol=1e-14, atol=1e-14, err_msg=name
        )
        got = call(backend, name, [a[0] for a in args], kwargs)
        np.testing.assert_allclose(got, flat[0], rtol=1e-14, atol=1e-14, err_msg=name)


def test_framework_inferred_or_chosen(backend):
    """``f`` chosen explicitly (a name or a namespace) gives native arrays of that backend."""
    import ivy

    q = np.array([0.1, 0.2, 0.3, 0.9])
    for f in (backend, getattr(ivy, backend)):
        out = mech.quaternion_to_rot_mat(native(q, backend), f=f)
        assert dtype_name(out) == "float64"
        np.testing.assert_allclose(numpy_of(out), mech.quaternion_to_rot_mat(q), atol=1e-15)


def _compiled(backend, fn, args):
    """``fn`` compiled by the framework itself, with the batch size unknown where the compiler
    has that notion (tf.function's input_signature)."""
    compiled = native_compile(backend, fn, unknown_batch_of=args)
    return numpy_of(compiled(*[native(a, backend) for a in args]))


def test_compiled_equals_eager(graph_backend):
    for name in NAMES:
        args, kwargs = _inputs(name, 52)
        fn = functools.partial(getattr(mech, name), **kwargs)
        np.testing.assert_allclose(
            _compiled(graph_backend, fn, args),
            call(graph_backend, name, args, kwargs),
            rtol=1e-13,
            atol=1e-13,
            err_msg=name,
        )
