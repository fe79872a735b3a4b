"""Arrays stay on the device of the inputs (or the ``device=`` asked): the cameras' matrices,
projection, warping, splatting and the creation functions, on the device the test run targets
(``IVY_TEST_DEVICE``)."""

from __future__ import annotations

import numpy as np

import ivy_vision as vis
from tests.conftest import capable


def _device(xp, target_device):
    """The test run's device where the backend has that kind of device, else the CPU."""
    return target_device if target_device.split(":")[0] in xp.capabilities.devices else "cpu"


def test_results_stay_on_the_inputs_device(backend, xp, target_device):
    device = _device(xp, target_device)
    dtype = np.float64 if capable(backend, "float64") else np.float32

    def on(x):
        return xp.asarray(np.asarray(x, dtype=dtype), device=device)

    camera = vis.Camera.from_focal_lengths(
        on([4.0, 4.0]), on([2.0, 1.5]), on(np.eye(3)), on([0.0, 0.0, -3.0])
    )
    depth = on(np.full((4, 5, 1), 3.0))
    image = on(np.random.default_rng(0).uniform(size=(4, 5, 3)))
    points = camera.unproject(depth)
    outputs = {
        "camera matrices": camera.inv_full_mat,
        "project": camera.project(points),
        "unproject": points,
        "inverse_warp": vis.inverse_warp(image, depth, on(np.eye(3, 4)), with_validity=True)[1],
        "forward_warp": vis.forward_warp(image, depth, on(np.eye(3, 4)))[2],
        "pixel grid": vis.create_uniform_pixel_coords_image((4, 5), device=device, f=xp),
        "trimesh": vis.create_trimesh_indices_for_image((4, 5), device=device, f=xp),
    }
    for name, out in outputs.items():
        assert xp.dev(out) == device, f"{name} is on {xp.dev(out)}, not {device}"
