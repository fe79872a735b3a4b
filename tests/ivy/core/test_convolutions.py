"""Tests of the core group ``convolutions`` (``ivy/core/convolutions.py``), on every backend.

Gradients of the nn functions against central finite differences in float64, and compiled runs
against eager ones, on the differentiable backends.

Gradients are taken with each framework's own autodiff (``torch.autograd.grad``, ``jax.grad``,
``tf.GradientTape``) of ``sum(fn(*inputs) * weights)``, and compared along random directions
``v`` with ``(L(inputs + h v) - L(inputs - h v)) / 2h``.

Convolutions (channel-last) against naive numpy float64 loops (``_nn_reference.py``), on every
backend.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from tests.helpers import check, check_gradients, native, numpy_of, tolerance
from tests.ivy.core._nn_reference import (
    FLOATS,
    GEOMETRY,
    PADDINGS,
    random_array,
    ref_conv,
    ref_conv_transpose,
    ref_pads,
)


def _random(shape, seed, scale=1.0):
    return scale * np.random.default_rng(60 + seed).standard_normal(shape)


CONV_CASES = {
    "conv2d-same-stride": (
        lambda x, w: ivy.conv2d(x, w, 2, "SAME"),
        [(2, 5, 6, 3), (3, 3, 3, 2)],
    ),
    "conv2d-dilated-explicit": (
        lambda x, w: ivy.conv2d(x, w, 1, [(1, 0), (2, 1)], dilations=2),
        [(1, 5, 6, 2), (2, 3, 2, 3)],
    ),
    "conv1d-stride-dilation": (
        lambda x, w: ivy.conv1d(x, w, 2, "SAME", dilations=2),
        [(2, 9, 2), (3, 2, 3)],
    ),
    "conv3d-dilated": (
        lambda x, w: ivy.conv3d(x, w, 1, "VALID", dilations=(2, 1, 1)),
        [(1, 4, 3, 3, 2), (2, 2, 2, 2, 2)],
    ),
    "conv2d_transpose": (
        lambda x, w: ivy.conv2d_transpose(x, w, 2, "SAME", dilations=(1, 2)),
        [(1, 3, 3, 2), (3, 2, 3, 2)],
    ),
    "conv3d_transpose": (
        lambda x, w: ivy.conv3d_transpose(x, w, (1, 2, 1), "SAME"),
        [(1, 2, 2, 3, 2), (2, 2, 2, 3, 2)],
    ),
    "conv1d_transpose-output_shape": (
        lambda x, w: ivy.conv1d_transpose(x, w, 2, "VALID", output_shape=(10,)),
        [(2, 4, 3), (3, 2, 3)],
    ),
    "depthwise_conv2d": (
        lambda x, w: ivy.depthwise_conv2d(x, w, (1, 2), "SAME"),
        [(2, 5, 5, 3), (3, 3, 3)],
    ),
    "max_pool2d": (lambda x: ivy.max_pool2d(x, 2, 2, "SAME"), [(2, 5, 5, 3)]),
    "avg_pool2d-explicit": (lambda x: ivy.avg_pool2d(x, 3, 2, [(1, 2), 1]), [(2, 5, 5, 3)]),
    "avg_pool3d": (lambda x: ivy.avg_pool3d(x, 2, 2, "SAME"), [(1, 3, 4, 3, 2)]),
    "max_pool3d": (lambda x: ivy.max_pool3d(x, 2, 1, "VALID"), [(1, 3, 3, 3, 2)]),
}


@pytest.mark.parametrize("case", sorted(CONV_CASES))
def test_conv_and_pool_gradients(diff_backend, case):
    fn, shapes = CONV_CASES[case]
    check_gradients(diff_backend, fn, [_random(s, i) for i, s in enumerate(shapes)])


# (x shape, filter shape, strides, padding, dilations)
CONV_CASES_nn_conv = {
    "conv1d": [
        ((2, 7, 3), (3, 3, 4), 1, "SAME", 1),
        ((2, 7, 3), (3, 3, 4), 2, "VALID", 1),
        ((2, 8, 3), (3, 3, 4), 2, "SAME", 2),
        ((2, 7, 3), (2, 3, 4), 3, "same", 1),
        ((2, 7, 3), (3, 3, 4), 1, [(1, 2)], 1),
    ],
    "conv2d": [
        ((2, 6, 5, 3), (3, 2, 3, 4), 1, "SAME", 1),
        ((2, 6, 5, 3), (3, 2, 3, 4), (2, 1), "VALID", 1),
        ((2, 7, 6, 3), (3, 3, 3, 4), 2, "SAME", (2, 1)),
        ((2, 6, 5, 3), (3, 2, 3, 4), 1, [(0, 1), (2, 0)], 1),
        ((2, 6, 5, 3), (3, 3, 3, 4), 2, 1, 1),
        ((2, 2, 5, 4, 3), (3, 3, 3, 4), 1, "SAME", 1),  # extra leading batch axis
    ],
    "conv3d": [
        ((1, 4, 5, 4, 2), (2, 3, 2, 2, 3), 1, "SAME", 1),
        ((2, 5, 4, 4, 2), (2, 2, 2, 2, 3), 2, "VALID", 1),
        ((1, 5, 5, 4, 2), (2, 2, 2, 2, 3), (1, 2, 1), [(1, 0), 1, (0, 2)], (2, 1, 1)),
    ],
}


def _conv_case_ids():
    return [
        pytest.param(name, case, id=f"{name}-{i}")
        for name, cases in CONV_CASES_nn_conv.items()
        for i, case in enumerate(cases)
    ]


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize(("name", "case"), _conv_case_ids())
def test_conv(backend, dtype, name, case):
    x_shape, w_shape, strides, padding, dilations = case
    x, w = random_array(x_shape, dtype, 1), random_array(w_shape, dtype, 2)
    nd = len(w_shape) - 2
    flat = x.reshape(-1, *x_shape[-nd - 1 :])
    expected = ref_conv(
        flat, w, strides, padding.upper() if isinstance(padding, str) else padding, dilations
    )
    expected = expected.reshape(x_shape[: -nd - 1] + expected.shape[1:])
    fn = getattr(ivy, name)
    out = fn(native(x, backend), native(w, backend), strides, padding, dilations=dilations)
    check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_conv_namespace_function_and_f(backend):
    """``ivy.<backend>.conv2d`` and ``ivy.conv2d(..., f=backend)`` on numpy input."""
    x, w = random_array((1, 4, 4, 2), "float64", 3), random_array((2, 2, 2, 3), "float64", 4)
    expected = ref_conv(x, w, 1, "SAME", 1)
    xp = getattr(ivy, backend)
    check(xp.conv2d(native(x, backend), native(w, backend), 1, "SAME"), expected, backend)
    check(ivy.conv2d(x, w, 1, "SAME", f=backend), expected, backend)


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize(
    "case",
    [
        ((2, 6, 5, 3), (3, 3, 3), 1, "SAME", 1),
        ((2, 7, 6, 3), (3, 2, 3), 2, "VALID", 1),
        ((2, 7, 6, 3), (3, 3, 3), 2, "SAME", 2),
        ((2, 6, 5, 3), (2, 3, 3), (1, 2), [(1, 0), (0, 2)], (2, 1)),
    ],
    ids=str,
)
def test_depthwise_conv2d(backend, dtype, case):
    x_shape, w_shape, strides, padding, dilations = case
    x, w = random_array(x_shape, dtype, 5), random_array(w_shape, dtype, 6)
    expected = ref_conv(x, w, strides, padding, dilations, depthwise=True)
    out = ivy.depthwise_conv2d(
        native(x, backend), native(w, backend), strides, padding, dilations=dilations
    )
    check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


# (x shape, filter shape [*K, out, in], strides, padding, dilations, output_shape, out sizes)
TRANSPOSE_CASES = {
    "conv1d_transpose": [
        ((2, 4, 3), (3, 2, 3), 2, "SAME", 1, None, (8,)),
        ((2, 4, 3), (3, 2, 3), 2, "VALID", 1, None, (9,)),
        ((2, 4, 3), (3, 2, 3), 2, "SAME", 1, (7,), (7,)),  # odd output size
        ((2, 4, 3), (3, 2, 3), 2, "VALID", 1, [2, 10, 2], (10,)),  # extended with zeros
        ((2, 4, 3), (3, 2, 3), 1, "SAME", 2, None, (4,)),
        ((2, 4, 3), (3, 2, 3), 3, [(1, 2)], 1, None, (9,)),
    ],
    "conv2d_transpose": [
        ((2, 3, 4, 3), (3, 2, 2, 3), 2, "SAME", 1, None, (6, 8)),
        ((2, 3, 4, 3), (3, 2, 2, 3), (2, 1), "VALID", (1, 2), None, (7, 6)),
        ((2, 3, 3, 3), (3, 3, 2, 3), 2, [(1, 1), (0, 2)], 1, None, (5, 5)),
        ((2, 3, 3, 3), (3, 3, 2, 3), 2, "SAME", 2, (5, 6), (5, 6)),
    ],
    "conv3d_transpose": [
        ((1, 2, 3, 2, 2), (2, 2, 3, 3, 2), 2, "SAME", 1, None, (4, 6, 4)),
        ((1, 2, 2, 2, 2), (2, 2, 2, 3, 2), (1, 2, 1), "VALID", 1, None, (3, 4, 3)),
    ],
}


def _transpose_case_ids():
    return [
        pytest.param(name, case, id=f"{name}-{i}")
        for name, cases in TRANSPOSE_CASES.items()
        for i, case in enumerate(cases)
    ]


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize(("name", "case"), _transpose_case_ids())
def test_conv_transpose(backend, dtype, name, case):
    x_shape, w_shape, strides, padding, dilations, output_shape, out_sizes = case
    x, w = random_array(x_shape, dtype, 7), random_array(w_shape, dtype, 8)
    expected = ref_conv_transpose(x, w, strides, padding, dilations, out_sizes)
    fn = getattr(ivy, name)
    out = fn(
        native(x, backend),
        native(w, backend),
        strides,
        padding,
        output_shape=output_shape,
        dilations=dilations,
    )
    check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_conv_transpose_is_the_adjoint_of_conv(backend):
    """<conv(y, w), x> == <y, conv_transpose(x, w)>: the transpose is the input gradient."""
    w = random_array(
        (3, 2, 3, 4), "float64", 9
    )  # conv: [fh, fw, in=3, out=4]; transpose: out=3, in=4
    y = random_array((2, 7, 6, 3), "float64", 10)
    for strides, padding, dilations in [
        (2, "SAME", 1),
        ((1, 2), "VALID", (2, 1)),
        (2, [(1, 2), 0], 1),
    ]:
        conv = numpy_of(
            ivy.conv2d(
                native(y, backend), native(w, backend), strides, padding, dilations=dilations
            )
        )
        x = random_array(conv.shape, "float64", 11)
        back = ivy.conv2d_transpose(
            native(x, backend),
            native(w, backend),
            strides,
            padding,
            output_shape=y.shape[1:3],
            dilations=dilations,
        )
        np.testing.assert_allclose(np.sum(conv * x), np.sum(y * numpy_of(back)), rtol=1e-12)


@GEOMETRY
@given(
    n=st.integers(1, 7),
    k=st.integers(1, 3),
    s=st.integers(1, 3),
    d=st.integers(1, 2),
    padding=PADDINGS,
)
def test_conv1d_geometry(backend, n, k, s, d, padding):
    x, w = random_array((1, n, 2), "float64", 13), random_array((k, 2, 2), "float64", 14)
    pads = ref_pads(padding, (n,), (d * (k - 1) + 1,), (s,))
    if n + sum(pads[0]) < d * (k - 1) + 1:
        with pytest.raises(ValueError, match="larger than the padded input"):
            ivy.conv1d(native(x, backend), native(w, backend), s, padding, dilations=d)
        return
    out = ivy.conv1d(native(x, backend), native(w, backend), s, padding, dilations=d)
    check(out, ref_conv(x, w, s, padding, d), backend)
    # the transposed convolution maps the output back to n entries
    y = numpy_of(out)
    back = ivy.conv1d_transpose(
        native(y, backend), native(w, backend), s, padding, output_shape=(n,), dilations=d
    )
    check(back, ref_conv_transpose(y, w, s, padding, d, (n,)), backend)


def test_conv_errors(backend):
    x = native(np.ones((1, 5, 5, 2)), backend)
    w = native(np.ones((3, 3, 2, 4)), backend)
    with pytest.raises(ValueError, match=r"rank >= 4, channel-last \[N, H, W, C\]"):
        ivy.conv2d(native(np.ones((5, 5, 2)), backend), w, 1, "SAME")
    with pytest.raises(ValueError, match=r"filters of rank 4, \[fh, fw, in, out\]"):
        ivy.conv2d(x, native(np.ones((3, 3, 2)), backend), 1, "SAME")
    with pytest.raises(ValueError, match="x has 2 channels"):
        ivy.conv2d(x, native(np.ones((3, 3, 3, 4)), backend), 1, "SAME")
    with pytest.raises(ValueError, match="unknown padding 'FULL'"):
        ivy.conv2d(x, w, 1, "FULL")
    with pytest.raises(ValueError, match="unknown padding"):
        ivy.conv2d(x, w, 1, [(1, 1)])  # one pair for two spatial axes
    with pytest.raises(ValueError, match="unknown padding"):
        ivy.conv2d(x, w, 1, -1)
    with pytest.raises(ValueError, match="strides must be a positive int or 2 positive ints"):
        ivy.conv2d(x, w, 0, "SAME")
    with pytest.raises(ValueError, match="dilations must be"):
        ivy.conv2d(x, w, 1, "SAME", dilations=(1, 1, 1))
    with pytest.raises(ValueError, match="larger than the padded input"):
        ivy.conv2d(x, native(np.ones((7, 7, 2, 4)), backend), 1, "VALID")
    with pytest.raises(ValueError, match=r"filters of rank 3, \[fh, fw, C\]"):
        ivy.depthwise_conv2d(x, w, 1, "SAME")
    with pytest.raises(ValueError, match=r"\[fh, fw, out, in\]"):
        ivy.conv2d_transpose(x, native(np.ones((3, 3, 4, 3)), backend), 1, "SAME")
    with pytest.raises(ValueError, match="does not fit"):
        ivy.conv2d_transpose(
            x, native(np.ones((3, 3, 4, 2)), backend), 2, "SAME", output_shape=(12, 10)
        )
    with pytest.raises(ValueError, match="has 5 channels but the filters give 4"):
        ivy.conv2d_transpose(
            x, native(np.ones((3, 3, 4, 2)), backend), 2, "SAME", output_shape=(1, 10, 10, 5)
        )
    with pytest.raises(ValueError, match="output_shape must give the 2 spatial sizes"):
        ivy.conv2d_transpose(
            x, native(np.ones((3, 3, 4, 2)), backend), 2, "SAME", output_shape=(10,)
        )


@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize("groups", [2, 3])
def test_conv_general_with_feature_groups(backend, dtype, groups):
    """The backends' one convolution, called with resolved arguments: grouped channels (the
    public functions use one group, or one per channel)."""
    x = random_array((2, 6, 5, 6), dtype, 15)
    w = random_array((3, 2, 6 // groups, 3 * groups), dtype, 16)
    pads = ((1, 1), (0, 1))
    expected = ref_conv(x, w, (2, 1), pads, (1, 2), groups=groups)
    out = ivy.conv_general(
        native(x, backend), native(w, backend), (2, 1), pads, (1, 2), groups=groups
    )
    check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


@pytest.mark.parametrize(
    "name, x_shape, w_shape, args",
    [
        ("conv1d", (5, 3), (2, 3, 4), (1, "VALID")),
        ("conv2d", (5, 5, 2), (3, 3, 2, 4), (2, "SAME")),
        ("conv2d_transpose", (5, 5, 2), (3, 3, 4, 2), (2, "VALID")),
        ("depthwise_conv2d", (5, 5, 2), (3, 3, 2), (1, "VALID")),
    ],
)
def test_an_empty_batch_gives_an_empty_batch_of_the_output_shape(
    backend, name, x_shape, w_shape, args
):
    """(tensorflow's convolutions gave back their input for an empty batch)"""
    rng = np.random.default_rng(3)
    w = native(rng.standard_normal(w_shape).astype("float32"), backend)
    fn = getattr(ivy, name)
    one = fn(native(np.ones((1, *x_shape), "float32"), backend), w, *args)
    out = fn(native(np.ones((0, *x_shape), "float32"), backend), w, *args)
    assert tuple(out.shape) == (0, *tuple(one.shape)[1:])
