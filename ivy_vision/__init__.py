"""ivy_vision: cameras, projection, warping, optical flow, voxel grids and rendering, written
once for every ivy backend.

Every function is framework-agnostic: it takes a keyword-only ``f=None`` (a framework name or
namespace; inferred from the inputs when None), resolves the backend once, accepts leading
batch dimensions and keeps the float dtype of its inputs. It builds on :mod:`ivy_mechanics`.

Conventions (those of the original ivy_vision): images channel-last ``[..., H, W, C]``; pixel
coordinates with the origin at the top-left pixel's centre, ``x`` rightwards and ``y``
downwards; depth-scaled homogeneous pixel coordinates ``[u*d, v*d, d]`` (planar depth ``d``);
camera frame ``x`` right, ``y`` down, ``z`` forward; calibration ``K``, extrinsic
``E = R [I | -C]``, full ``P = K E`` and their inverses (``[..., 3, 4]``).

Modules: :mod:`~ivy_vision.single_view_geometry`, :mod:`~ivy_vision.omnidirectional`,
:mod:`~ivy_vision.projective_geometry`, :mod:`~ivy_vision.two_view_geometry`,
:mod:`~ivy_vision.sampling` (sampling and warping), :mod:`~ivy_vision.optical_flow`,
:mod:`~ivy_vision.voxel_grids`, :mod:`~ivy_vision.quantization`, :mod:`~ivy_vision.mesh`,
:mod:`~ivy_vision.smoothing`, :mod:`~ivy_vision.sdf`, :mod:`~ivy_vision.implicit` and
:mod:`~ivy_vision.camera`.

Example:
    >>> import numpy as np, ivy_vision as vis
    >>> K = vis.focal_lengths_and_pp_offsets_to_calib_mat(np.array([2., 2.]), np.array([1., 1.]))
    >>> vis.cam_to_ds_pixel_coords(np.array([0., 0., 3.]), K)     # the principal point, depth 3
    array([3., 3., 3.])
"""

from ivy_vision import (
    camera,
    implicit,
    mesh,
    omnidirectional,
    optical_flow,
    projective_geometry,
    quantization,
    sampling,
    sdf,
    single_view_geometry,
    smoothing,
    two_view_geometry,
    voxel_grids,
)
from ivy_vision.camera import *  # noqa: F403
from ivy_vision.implicit import *  # noqa: F403
from ivy_vision.mesh import *  # noqa: F403
from ivy_vision.omnidirectional import *  # noqa: F403
from ivy_vision.optical_flow import *  # noqa: F403
from ivy_vision.projective_geometry import *  # noqa: F403
from ivy_vision.quantization import *  # noqa: F403
from ivy_vision.sampling import *  # noqa: F403
from ivy_vision.sdf import *  # noqa: F403
from ivy_vision.single_view_geometry import *  # noqa: F403
from ivy_vision.smoothing import *  # noqa: F403
from ivy_vision.two_view_geometry import *  # noqa: F403
from ivy_vision.voxel_grids import *  # noqa: F403

MODULES = (
    single_view_geometry,
    omnidirectional,
    projective_geometry,
    two_view_geometry,
    sampling,
    optical_flow,
    voxel_grids,
    quantization,
    mesh,
    smoothing,
    sdf,
    implicit,
    camera,
)

__all__ = [name for module in MODULES for name in module.__all__]
