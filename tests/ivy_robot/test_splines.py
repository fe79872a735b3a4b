"""Spline paths against scipy: RBFInterpolator(kernel, degree=1) for the polyharmonic splines
and make_interp_spline(k=3) for the cubic B-spline, to 1e-10; gradients with respect to the
anchor values against finite differences; compiled equals eager; bad input raises."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.helpers import assert_close, check_gradients, native, numpy_of

interpolate = pytest.importorskip("scipy.interpolate")

KERNELS = {1: "linear", 2: "thin_plate_spline", 3: "cubic"}
TOL = dict(rtol=1e-10, atol=1e-10)


def _anchors(rng, n, dim):
    """Anchors in [0, 1]^dim no closer than 0.05 to each other (a well-posed problem)."""
    points = []
    while len(points) < n:
        p = rng.uniform(size=dim)
        if all(np.linalg.norm(p - q) > 0.05 for q in points):
            points.append(p)
    return np.asarray(points)


@pytest.mark.parametrize("dim", [1, 2, 3])
@pytest.mark.parametrize("order", [1, 2, 3])
def test_polyharmonic_matches_scipy(order, dim, backend):
    rng = np.random.default_rng(10 * order + dim)
    points, values = _anchors(rng, 8, dim), rng.normal(size=(8, 3))
    samples = rng.uniform(-0.1, 1.1, size=(25, dim))
    want = interpolate.RBFInterpolator(points, values, kernel=KERNELS[order], degree=1)(samples)
    got = ivy_robot.sample_spline_path(
        native(points, backend), native(values, backend), native(samples, backend), order
    )
    assert_close(numpy_of(got), want, **TOL)
    at_anchors = ivy_robot.sample_spline_path(
        native(points, backend), native(values, backend), native(points, backend), order
    )
    assert_close(numpy_of(at_anchors), values, **TOL)


def test_bspline_matches_scipy(backend):
    rng = np.random.default_rng(3)
    times = np.concatenate([[0.0], np.sort(rng.uniform(0.1, 0.9, 5)), [1.0]])
    values = rng.normal(size=(7, 4))
    samples = np.linspace(0.0, 1.0, 33)
    want = interpolate.make_interp_spline(times, values, k=3)(samples)
    got = ivy_robot.sample_spline_path(
        native(times[:, None], backend),
        native(values, backend),
        native(samples[:, None], backend),
        method="bspline",
    )
    assert_close(numpy_of(got), want, **TOL)


def test_bspline_extrapolates_as_scipy(backend):
    # past the anchors (even by a rounding error) the first and last cubic pieces continue,
    # as make_interp_spline's BSpline does; before the fix the path dropped to 0 there. The
    # shapes are those of test_bspline_matches_scipy (jax compiles them once).
    rng = np.random.default_rng(3)
    times = np.concatenate([[0.0], np.sort(rng.uniform(0.1, 0.9, 5)), [1.0]])
    values = rng.normal(size=(7, 4)) + 3.0
    outside = [-0.5, -1e-4, -1e-12, 1.0 + 1e-12, 1.0 + 1e-4, 1.7, np.nan]
    samples = np.concatenate([outside, np.linspace(0.0, 1.0, 26)])
    got = numpy_of(
        ivy_robot.sample_spline_path(
            native(times[:, None], backend),
            native(values, backend),
            native(samples[:, None], backend),
            method="bspline",
        )
    )
    known = ~np.isnan(samples)
    want = interpolate.make_interp_spline(times, values, k=3)(samples[known])
    assert_close(got[known], want, **TOL)
    assert np.all(np.isnan(got[~known]))  # a NaN time stays NaN, never 0


def test_batches_and_weights(backend):
    rng = np.random.default_rng(4)
    times = np.linspace(0.0, 1.0, 6)[:, None]
    values = rng.normal(size=(2, 3, 6, 5))
    samples = np.linspace(0.0, 1.0, 20)[:, None]
    got = numpy_of(
        ivy_robot.sample_spline_path(
            native(times, backend), native(values, backend), native(samples, backend)
        )
    )
    want = interpolate.RBFInterpolator(times, values.transpose(2, 0, 1, 3).reshape(6, -1),
                                       kernel="cubic", degree=1)(samples)  # fmt: skip
    assert_close(got, want.reshape(20, 2, 3, 5).transpose(1, 2, 0, 3), **TOL)
    for method in ("polyharmonic", "bspline"):
        weights = numpy_of(
            ivy_robot.spline_weights(
                native(times, backend), native(samples, backend), method=method
            )
        )
        direct = ivy_robot.sample_spline_path(times, values[0, 0], samples, method=method)
        assert_close(weights @ values[0, 0], direct, **TOL)


@pytest.mark.parametrize("order", [1, 2, 3])
def test_gradients_with_respect_to_anchor_values(order, diff_backend):
    rng = np.random.default_rng(5)
    times = np.linspace(0.0, 1.0, 5)[:, None]
    samples = rng.uniform(size=(12, 1))
    values = rng.normal(size=(5, 2))
    t, s = native(times, diff_backend), native(samples, diff_backend)
    check_gradients(diff_backend, lambda v: ivy_robot.sample_spline_path(t, v, s, order), [values])


def test_gradients_with_respect_to_sample_points(diff_backend):
    rng = np.random.default_rng(6)
    times = np.linspace(0.0, 1.0, 6)[:, None]
    values = native(rng.normal(size=(6, 2)), diff_backend)
    t = native(times, diff_backend)
    samples = rng.uniform(0.05, 0.95, size=(9, 1))
    # the weighted directional derivative is a small sum of large terms (the path's slopes are
    # ~30): finite differences carry ~1e-8 of absolute error, hence the relative tolerance
    for method in ("polyharmonic", "bspline"):
        check_gradients(
            diff_backend,
            lambda s, m=method: ivy_robot.sample_spline_path(t, values, s, method=m),
            [samples],
            rtol=1e-4,
        )


def test_kernel_values_and_gradients(diff_backend):
    for order in (1, 2, 3):
        check_gradients(
            diff_backend,
            lambda r, k=order: ivy_robot.polyharmonic_kernel(r, k),
            [np.array([0.3, 2.0])],
        )
    from tests.ivy_robot._utils import autodiff_jacobian

    for order in (1, 2, 3):  # finite (zero) gradients where the distance is zero
        jac = autodiff_jacobian(
            diff_backend, lambda r, k=order: ivy_robot.polyharmonic_kernel(r, k), np.zeros(2)
        )
        assert np.all(np.isfinite(jac))
    r = native(np.array([0.0, 4.0]), diff_backend)
    assert_close(numpy_of(ivy_robot.polyharmonic_kernel(r, 1)), [0.0, 2.0])
    assert_close(numpy_of(ivy_robot.polyharmonic_kernel(r, 2)), [0.0, 4.0 * np.log(2.0)])


def test_compiled_equals_eager(graph_backend):
    rng = np.random.default_rng(7)
    t = native(np.linspace(0.0, 1.0, 5)[:, None], graph_backend)
    s = native(np.linspace(0.0, 1.0, 17)[:, None], graph_backend)
    v = native(rng.normal(size=(5, 3)), graph_backend)

    def path(values):
        return ivy_robot.sample_spline_path(t, values, s, 2)

    assert_close(numpy_of(ivy.compile_fn(path)(v)), numpy_of(path(v)))


def test_bad_input(backend):
    t = native(np.linspace(0.0, 1.0, 4)[:, None], backend)
    v = native(np.zeros((4, 2)), backend)
    s = native(np.linspace(0.0, 1.0, 5)[:, None], backend)
    with pytest.raises(ValueError, match="order must be 1, 2 or 3"):
        ivy_robot.sample_spline_path(t, v, s, 4)
    with pytest.raises(ValueError, match="method must be one of"):
        ivy_robot.sample_spline_path(t, v, s, method="akima")
    with pytest.raises(ValueError, match="4 anchor_points but 3 anchor_values"):
        ivy_robot.sample_spline_path(t, v[:3], s)
    with pytest.raises(ValueError, match="dimension 1 but sample_points 2"):
        ivy_robot.sample_spline_path(t, v, native(np.zeros((5, 2)), backend))
    with pytest.raises(ValueError, match=r"\[..., N, 1\]"):
        ivy_robot.sample_spline_path(t[:, 0], v, s)
    with pytest.raises(ValueError, match="at least 4 anchors"):
        ivy_robot.sample_spline_path(t[:3], v[:3], s, method="bspline")
    with pytest.raises(ValueError, match="strictly increasing"):
        ivy_robot.sample_spline_path(native(np.array([[0.0], [0.5], [0.2], [1.0]]), backend),
                                     v, s, method="bspline")  # fmt: skip
    with pytest.raises(ValueError, match="bspline method is cubic"):
        ivy_robot.sample_spline_path(t, v, s, 2, method="bspline")
    with pytest.raises(TypeError, match="floating"):
        ivy_robot.sample_spline_path(t, native(np.zeros((4, 2), dtype=np.int64), backend), s)
