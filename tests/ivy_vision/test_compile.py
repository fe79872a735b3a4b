"""Compiled (``ivy.compile_fn``: jax.jit, tf.function; torch.compile once) equals eager for the
main pipelines; randomness in compiled code is fresh on every call."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_vision as vis
from tests.helpers import native, numpy_of
from tests.ivy_vision import _cases as K

# torch.compile's internals still call the deprecated torch.jit.script_method
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning:torch.*")

_data = np.random.default_rng(41)  # constants only; tests: the rng fixture
IMAGE = _data.standard_normal((2, 4, 5, 3))


def _inverse_warp(image, depth, mat):
    return vis.inverse_warp(image, depth, mat, with_validity=True)


def _forward_warp(image, depth, mat):
    return vis.forward_warp(image, depth, mat, (3, 4))


def _quantize(coords, feat):
    return vis.quantize_to_image(coords, (4, 5), feat, with_db=True)


def _voxels(points, feats):
    return vis.coords_to_voxel_grid(points, (2, 3, 2), "DIMS", (0, 0, 0, 1, 1, 1), feats)[0]


def _rasterize(tris):
    return vis.rasterize_triangles(tris, (5, 6), chunk_size=2)


def _geometry(depth, inv_full, full2):
    world = vis.depth_to_world_coords(depth, inv_full)
    flow = vis.flow_from_depth_and_cam_mats(
        vis.depth_to_ds_pixel_coords(depth),
        vis.full_mats_to_cam1to2_full_mat(vis.projection_matrix_inverse(inv_full), full2),
    )
    return (
        world,
        flow,
        vis.ds_pixel_to_sphere_coords(vis.depth_to_ds_pixel_coords(depth), inv_full[..., 0:3]),
    )


def _triangulate(pixels, full_mats):
    return vis.triangulate_depth(pixels, full_mats), vis.triangulate_depth(
        pixels, full_mats, method="dlt"
    )


DS2 = K.R.apply(K.FULL12, K.DS)
PIXELS = np.stack([K.DS / K.DS[..., 2:3], DS2 / DS2[..., 2:3]], 1)
TRIS = np.concatenate([_data.uniform(0, 6, (2, 4, 3, 2)), _data.uniform(1, 3, (2, 4, 3, 1))], -1)

CASES = {
    "inverse_warp": (_inverse_warp, (IMAGE, K.DEPTH, K.FULL12)),
    "forward_warp": (_forward_warp, (IMAGE, K.DEPTH, K.FULL12)),
    "quantize_to_image": (
        _quantize,
        (_data.uniform(-1, 5, (2, 20, 2)), _data.uniform(1, 2, (2, 20, 2))),
    ),
    "coords_to_voxel_grid": (
        _voxels,
        (_data.uniform(0, 1, (2, 40, 3)), _data.normal(size=(2, 40, 1))),
    ),
    "rasterize_triangles": (_rasterize, (TRIS,)),
    "geometry": (_geometry, (K.DEPTH, K.FULL_INV, K.FULL2)),
    "triangulate_depth": (_triangulate, (PIXELS, np.stack([K.FULL, K.FULL2], 1))),
}


def _flat(out):
    return [numpy_of(o) for o in (out if isinstance(out, tuple) else (out,))]


@pytest.mark.parametrize("name", sorted(CASES))
def test_compiled_equals_eager(name, graph_backend):
    fn, arrays = CASES[name]
    inputs = [native(a, graph_backend) for a in arrays]
    eager = _flat(fn(*inputs))
    compiled = _flat(ivy.compile_fn(fn)(*inputs))
    for c, e in zip(compiled, eager):
        np.testing.assert_allclose(c, e, rtol=1e-10, atol=1e-10)


def test_torch_compile_inverse_warp():
    torch = pytest.importorskip("torch")
    args = [torch.from_numpy(a) for a in (IMAGE, K.DEPTH, K.FULL12)]
    eager = vis.inverse_warp(*args)
    compiled = ivy.compile_fn(lambda *a: vis.inverse_warp(*a))(*args)
    np.testing.assert_allclose(compiled.numpy(), eager.numpy(), rtol=1e-12, atol=1e-12)


def test_randomness_is_fresh_in_compiled_code(graph_backend):
    fn = ivy.compile_fn(lambda s, e: vis.stratified_sample(s, e, 4))
    starts, ends = native(np.zeros(3), graph_backend), native(np.ones(3), graph_backend)
    a, b = numpy_of(fn(starts, ends)), numpy_of(fn(starts, ends))
    assert not np.array_equal(a, b)
    assert np.all((a >= np.arange(4) / 4) & (a < np.arange(1, 5) / 4))


del _data  # no test draws from a generator shared by the module
