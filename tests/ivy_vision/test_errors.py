"""Bad input gets a clear ValueError naming the problem: wrong channel counts, singular
calibration matrices, mismatched batch dimensions, bad options."""

from __future__ import annotations

import re

import numpy as np
import pytest

import ivy_vision as vis
from tests.helpers import native

K = np.array([[2.0, 0, 1], [0, 2, 1], [0, 0, 1]])
SINGULAR_K = np.array([[0.0, 0, 1], [0, 2, 1], [0, 0, 1]])
DEPTH = np.ones((2, 3, 4, 1))
IMAGE = np.ones((2, 3, 4, 3))
P = np.eye(3, 4)

S = np.stack

CASES = [
    # wrong channel counts
    (
        "depth with 3 channels",
        lambda a: vis.depth_to_ds_pixel_coords(a(IMAGE)),
        r"depth must be \[\.\.\., H, W, 1\]; got shape \(2, 3, 4, 3\)",
    ),
    (
        "depth with 3 channels (radial)",
        lambda a: vis.depth_to_radial_depth(a(IMAGE), a(K)),
        r"must be \[\.\.\., H, W, 1\]",
    ),
    (
        "ds pixel coords with 2 channels",
        lambda a: vis.ds_pixel_to_cam_coords(a(np.ones((3, 2))), a(K)),
        r"ds_pixel_coords must have 3 channels",
    ),
    (
        "flow with 3 channels",
        lambda a: vis.depth_from_flow_and_cam_mats(a(IMAGE), a(S([P, P]))),
        r"flow must be \[\.\.\., H, W, 2\]",
    ),
    (
        "sampling coords with 3 channels",
        lambda a: vis.sample_image(a(IMAGE), a(np.ones((2, 5, 3)))),
        r"sampling coordinates must have 2 channels",
    ),
    (
        "image without channels",
        lambda a: vis.sample_image(a(np.ones(4)), a(np.ones((5, 2)))),
        r"image must be \[\.\.\., H, W, C\]",
    ),
    (
        "inverse warp depth with 2 channels",
        lambda a: vis.inverse_warp(a(IMAGE), a(np.ones((2, 3, 4, 2))), a(P)),
        r"depth_tgt must be \[\.\.\., H, W, 1\]",
    ),
    (
        "points with 5 components",
        lambda a: vis.world_to_cam_coords(a(np.ones((4, 5))), a(P)),
        r"must have 3 or 4 channels",
    ),
    (
        "calibration matrix 3x4",
        lambda a: vis.cam_to_ds_pixel_coords(a(np.ones(3)), a(P)),
        r"calib_mat must be \[\.\.\., 3, 3\]",
    ),
    (
        "quantize without depth channel",
        lambda a: vis.quantize_to_image(a(np.ones((3, 2))), (2, 2), with_db=True),
        r"with_db needs features",
    ),
    # singular matrices
    (
        "singular calibration",
        lambda a: vis.invert_calib_mat(a(SINGULAR_K)),
        r"calibration matrix is singular",
    ),
    (
        "singular projection",
        lambda a: vis.projection_matrix_inverse(a(SINGULAR_K @ P)),
        r"is singular",
    ),
    (
        "singular full matrix",
        lambda a: vis.full_mats_to_cam1to2_full_mat(a(SINGULAR_K @ P), a(P)),
        r"singular",
    ),
    (
        "singular camera",
        lambda a: vis.Camera.from_calib_and_ext_mats(a(SINGULAR_K), a(P)),
        r"singular",
    ),
    (
        "singular triangulation",
        lambda a: vis.triangulate_depth(a(np.ones((2, 3, 3))), a(S([SINGULAR_K @ P, P]))),
        r"singular",
    ),
    # mismatched batch dimensions
    (
        "batch 2 vs 3",
        lambda a: vis.ds_pixel_to_cam_coords(a(np.ones((2, 5, 3))), a(S([K] * 3))),
        r"batch dimensions.*\(2,\).*\(3,\)",
    ),
    (
        "depth batch 2 vs matrix batch 3",
        lambda a: vis.depth_to_cam_coords(a(DEPTH), a(S([K] * 3))),
        r"do not match",
    ),
    (
        "warp batch 2 vs 3",
        lambda a: vis.inverse_warp(a(IMAGE), a(DEPTH), a(S([P] * 3))),
        r"do not match",
    ),
    (
        "sample batch 2 vs 3",
        lambda a: vis.sample_image(a(IMAGE), a(np.ones((3, 5, 2)))),
        r"do not match",
    ),
    (
        "calib and ext batch",
        lambda a: vis.calib_and_ext_to_full_mat(a(S([K] * 2)), a(S([P] * 3))),
        r"do not match",
    ),
    (
        "focal lengths and pp",
        lambda a: vis.focal_lengths_and_pp_offsets_to_calib_mat(
            a(np.ones((2, 2))), a(np.ones((3, 2)))
        ),
        r"do not match",
    ),
    (
        "features and coords",
        lambda a: vis.coords_to_voxel_grid(
            a(np.ones((2, 5, 3))), (2, 2, 2), features=a(np.ones((2, 4, 1)))
        ),
        r"features .* leading shape",
    ),
    (
        "triangulation pixels",
        lambda a: vis.triangulate_depth(a(np.ones((3, 2, 5, 3))), a(S([S([P, P])] * 2))),
        r"do not match",
    ),
    # options
    (
        "sampling method",
        lambda a: vis.sample_image(a(IMAGE), a(np.ones((2, 5, 2))), method="cubic"),
        r"method must be one of",
    ),
    (
        "padding",
        lambda a: vis.inverse_warp(a(IMAGE), a(DEPTH), a(P), padding="reflect"),
        r"padding must be one of",
    ),
    (
        "triangulation method",
        lambda a: vis.triangulate_depth(a(np.ones((2, 3, 3))), a(S([P, P])), method="svd"),
        r"'cmp' or 'dlt'",
    ),
    (
        "voxel mode",
        lambda a: vis.coords_to_voxel_grid(a(np.ones((5, 3))), (2, 2, 2), mode="SIZE"),
        r"'DIMS' or 'RES'",
    ),
    (
        "image dims",
        lambda a: vis.create_uniform_pixel_coords_image((0, 3), f="numpy"),
        r"image_dims must be positive",
    ),
    ("omni padding", lambda a: vis.pad_omni_image(a(IMAGE), 5), r"pad_size must be in"),
    (
        "smoothing kernel",
        lambda a: vis.weighted_image_smooth(a(IMAGE), a(IMAGE), 4),
        r"kernel_dim must be in",
    ),
]


@pytest.mark.parametrize("name", [c[0] for c in CASES])
def test_bad_input_gets_a_clear_error(name, backend):
    _, call, pattern = next(c for c in CASES if c[0] == name)
    with pytest.raises(ValueError, match=pattern):
        call(lambda x: native(x, backend))


def test_errors_say_what_to_do():
    """A sample of the messages, whole: what is wrong, the shape received, and the expectation."""
    with pytest.raises(ValueError) as info:
        vis.depth_to_ds_pixel_coords(IMAGE)
    message = str(info.value)
    assert message.startswith("depth_to_ds_pixel_coords: depth must be [..., H, W, 1]")
    assert "channel-last" in message
    with pytest.raises(ValueError) as info:
        vis.invert_calib_mat(SINGULAR_K)
    assert re.search(r"focal lengths must be non-zero", str(info.value))


def test_shape_errors_name_the_argument_the_shape_and_the_fix(backend):
    """Checked before anything is unpacked: a depth without its channel axis, and channel-first
    images that would otherwise be read as a wrong size."""
    image, depth, full = np.ones((5, 6, 3)), np.ones((5, 6, 1)), np.eye(3, 4)

    def a(x):
        return native(x, backend)

    with pytest.raises(ValueError) as info:
        vis.inverse_warp(a(image), a(depth[..., 0]), a(full))
    assert str(info.value) == (
        "inverse_warp: depth_tgt must be [..., H, W, 1]; got shape (5, 6). Give the channel "
        "axis: depth_tgt[..., None] has shape (5, 6, 1)."
    )
    channel_first = np.ones((3, 5, 6))
    with pytest.raises(ValueError, match=r"inverse_warp: image_src of shape \(3, 5, 6\) looks "):
        vis.inverse_warp(a(channel_first), a(depth), a(full))
    with pytest.raises(ValueError, match=r"channel-last \[\.\.\., H, W, C\]: move the channel"):
        vis.forward_warp(a(channel_first), a(depth), a(full))
    with pytest.raises(ValueError, match=r"depth looks channel-first|It looks channel-first"):
        vis.depth_to_ds_pixel_coords(a(np.ones((2, 1, 5, 6))))
    with pytest.raises(ValueError, match=r"sample_image: image must be \[\.\.\., H, W, C\]"):
        vis.sample_image(a(np.ones((5,))), a(np.ones((4, 2))))


def test_errors_name_the_function_the_user_called():
    """The checks do not know their function: the ``checked`` decorator names the public
    function the user called, the outermost one when public functions call each other."""
    with pytest.raises(ValueError) as info:
        vis.Camera.from_focal_lengths(np.ones(3), np.zeros(2), np.eye(3), np.zeros(3))
    assert str(info.value).startswith("Camera.from_focal_lengths: focal_lengths must have 2")
    with pytest.raises(ValueError) as info:
        vis.focal_lengths_and_pp_offsets_to_calib_mat(np.ones(3), np.zeros(2))
    assert str(info.value).startswith("focal_lengths_and_pp_offsets_to_calib_mat: focal_lengths")


def test_no_function_repeats_its_own_name_for_errors():
    import pathlib
    import re

    names = set(vis.__all__) | {"Camera.from_calib_and_ext_mats"}
    for path in pathlib.Path(vis.__file__).parent.glob("*.py"):
        body = re.sub(r"__all__ = \[.*?\]", "", path.read_text(), flags=re.S)
        body = "\n".join(line for line in body.splitlines() if ">>>" not in line)
        repeated = {n for n in re.findall(r"\"([\w.]+)(?::|\")", body) if n in names}
        assert not repeated, f"{path.name} names {sorted(repeated)} in strings"
        assert not re.search(r"\bfn = \"", body), path.name
