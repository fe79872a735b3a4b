"""The functions added for the Array API (and other recent additions) run inside jax.jit and
tf.function and give the eager results there (functions with data-dependent shapes raise inside
jax.jit: see their tests)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.compilers import native_compile
from tests.helpers import check, native, numpy_of

X = np.array([[3.0, -0.0, np.nan, 1.5], [2.0, 2.0, -np.inf, 0.25]], np.float32)
INTS = np.array([[5, -3, 12, 0], [7, 7, 1, -8]], np.int32)

# name, function of (xp, x, i), to be compiled
CALLS = {
    "elementwise": lambda xp, x, i: [
        xp.hypot(x, 2.0),
        xp.copysign(x, -1.0),
        xp.logaddexp(x, x),
        xp.nextafter(x, 0.0),
        xp.signbit(x),
        xp.reciprocal(x),
        xp.bitwise_and(i, 6),
        xp.bitwise_left_shift(i, 2),
        xp.bitwise_invert(i),
    ],
    "creation and manipulation": lambda xp, x, i: [
        xp.tril(x, k=1),
        xp.triu(x),
        *xp.meshgrid(x[0], x[1, :3], indexing="ij"),
        xp.moveaxis(x, 0, -1),
        *xp.broadcast_arrays(x, x[:1]),
    ],
    "sorting and statistics": lambda xp, x, i: [
        xp.sort(x, descending=True),
        xp.argsort(x, axis=0),
        xp.cumulative_sum(i, axis=1, include_initial=True),
        xp.cumulative_prod(x, axis=0),
        xp.searchsorted(xp.sort(x[0]), x[1]),
        xp.count_nonzero(x, axis=1),
        xp.all(x, axis=0),
        xp.any(i, keepdims=True),
        xp.diff(i, n=2),
    ],
    "selection, statistics and clipping": lambda xp, x, i: [
        xp.take_along_axis(x, xp.remainder(i, 4) - 2, axis=1),
        xp.put_rows(x, xp.asarray([-1]), x[:1] * 2.0),
        xp.put_rows(i, xp.asarray([1, 0]), i[::-1] + 1),
        *xp.top_k(x, 3, axis=1),
        *xp.top_k(i, 1, axis=0, largest=False),
        xp.logsumexp(x, axis=1),
        xp.median(x, axis=0),
        xp.quantile(x, [0.2, 0.5], axis=1, method="midpoint"),
        xp.nan_to_num(x, posinf=9.0),
        xp.isclose(x, x[:, ::-1], equal_nan=True),
        xp.allclose(x, x),
        xp.cosine_similarity(x, x[:, ::-1]),
        xp.clip_vector_norm(i, 10.0, axis=1),
        xp.clip_by_global_norm({"a": i[:, :2], "b": i[0]}, 5.0)[0]["a"],
        xp.interp(x, xp.asarray([-1.0, 0.0, 2.0]), xp.asarray([0.0, 1.0, 5.0])),
        xp.logspace(0.0, 2.0, 3),
    ],
}


def _run_both(backend, name):
    import ivy

    xp = getattr(ivy, backend)
    x, i = native(X, backend), native(INTS, backend)
    eager = CALLS[name](xp, x, i)
    compiled = native_compile(backend, lambda x, i: CALLS[name](xp, x, i))(x, i)
    return eager, compiled


@pytest.mark.parametrize("name", sorted(CALLS))
def test_compiled_equals_eager(graph_backend, name):
    eager, compiled = _run_both(graph_backend, name)
    assert len(eager) == len(compiled)
    for e, c in zip(eager, compiled):
        expected = numpy_of(e)
        check(c, expected, graph_backend, rtol=0, atol=0)


def test_tf_function_with_unknown_shapes():
    tf = pytest.importorskip("tensorflow")
    import ivy

    xp = ivy.tensorflow
    spec = tf.TensorSpec([None, None], tf.float32)

    @tf.function(input_signature=[spec])
    def fn(x):
        return [
            xp.sort(x, axis=0),
            xp.unique_values(x),
            xp.cumulative_sum(x, axis=1),
            *xp.broadcast_arrays(x, x[:1]),
            xp.tril(x),
            *xp.nonzero(x),
        ]

    x = tf.constant(X)
    for got, want in zip(
        fn(x),
        [
            xp.sort(x, axis=0),
            xp.unique_values(x),
            xp.cumulative_sum(x, axis=1),
            *xp.broadcast_arrays(x, x[:1]),
            xp.tril(x),
            *xp.nonzero(x),
        ],
    ):
        check(got, numpy_of(want), "tensorflow", rtol=0, atol=0)
