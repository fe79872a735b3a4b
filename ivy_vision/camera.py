"""A small camera object: intrinsics and extrinsics with their inverses, computed once.

Every function of ivy_vision takes plain arrays; :class:`Camera` only keeps the matrices of one
camera (or a batch of cameras) together, so that they are not recomputed.

Example:
    >>> cam = Camera.from_focal_lengths(np.array([100., 100.]), np.array([32., 24.]),
    ...                                 np.eye(3), np.array([0., 0., -5.]))
    >>> cam.project(np.array([0., 0., 0.]))   # the origin: 5 ahead, at the principal point
    array([160., 120.,   5.])
"""

from __future__ import annotations

from dataclasses import dataclass

import ivy
from ivy.typing import Array, Framework, Shape
from ivy_vision import _common as C
from ivy_vision import single_view_geometry as svg
from ivy_vision._checks import checked
from ivy_vision.projective_geometry import check_invertible

__all__ = ["Camera"]


@dataclass(frozen=True)
class Camera:
    """Matrices of a pinhole camera (or of a batch of them, with leading batch dimensions).

    Attributes:
        calib_mat: ``K`` *[batch_shape, 3, 3]*.
        inv_calib_mat: ``K^-1`` *[batch_shape, 3, 3]*.
        ext_mat: ``E = [R | -R C]`` (world to camera) *[batch_shape, 3, 4]*.
        inv_ext_mat: ``E^-1 = [R^T | C]`` (camera to world) *[batch_shape, 3, 4]*.
        full_mat: ``P = K E`` *[batch_shape, 3, 4]*.
        inv_full_mat: ``P^-1 = [R^T K^-1 | C]`` *[batch_shape, 3, 4]*.
    """

    calib_mat: Array
    inv_calib_mat: Array
    ext_mat: Array
    inv_ext_mat: Array
    full_mat: Array
    inv_full_mat: Array

    @classmethod
    @checked
    def from_calib_and_ext_mats(cls, calib_mat: Array, ext_mat: Array, *, f: Framework = None):
        """A camera from its calibration and extrinsic matrices.

        Args:
            calib_mat: ``K`` *[batch_shape, 3, 3]* (upper triangular, non-zero focal lengths:
                a singular one raises a ValueError in eager mode).
            ext_mat: ``E = [R | t]`` with a rotation ``R`` *[batch_shape, 3, 4]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            A :class:`Camera`.

        Example:
            >>> Camera.from_calib_and_ext_mats(np.eye(3), np.eye(3, 4)).inv_full_mat[:, 3]
            array([-0., -0., -0.])
        """
        xp = ivy.get_framework(calib_mat, ext_mat, f=f)
        C.check_matrix(xp, ext_mat, 3, 4, "ext_mat")
        check_invertible(
            xp, ext_mat[..., 0:3], "the rotation of ext_mat", "it must be a rotation matrix."
        )
        inv_calib = svg.invert_calib_mat(calib_mat, f=xp)
        rot, center = svg.ext_mat_to_rot_mat_and_cam_center(ext_mat, f=xp)
        rot_t = xp.swapaxes(rot, -1, -2)
        inv_ext = xp.concat([rot_t, center[..., None]], axis=-1)
        full = svg.calib_and_ext_to_full_mat(calib_mat, ext_mat, f=xp)
        batch = C.shape_of(xp, full)[:-2]
        inv_full = xp.concat(
            [xp.matmul(rot_t, inv_calib), xp.broadcast_to(center[..., None], (*batch, 3, 1))],
            axis=-1,
        )
        return cls(calib_mat, inv_calib, ext_mat, inv_ext, full, inv_full)

    @classmethod
    @checked
    def from_focal_lengths(
        cls,
        focal_lengths: Array,
        pp_offsets: Array,
        rotation_mat: Array,
        camera_center: Array,
        *,
        f: Framework = None,
    ):
        """A camera from focal lengths, principal point, world-to-camera rotation and centre.

        Args:
            focal_lengths: ``[fx, fy]`` in pixels *[batch_shape, 2]*.
            pp_offsets: principal point ``[px, py]`` *[batch_shape, 2]*.
            rotation_mat: world-to-camera rotation ``R`` *[batch_shape, 3, 3]*.
            camera_center: camera centre in the world *[batch_shape, 3]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            A :class:`Camera`.

        Example:
            >>> cam = Camera.from_focal_lengths(np.ones(2), np.zeros(2), np.eye(3), np.ones(3))
            >>> cam.camera_center
            array([1., 1., 1.])
        """
        xp = ivy.get_framework(focal_lengths, pp_offsets, rotation_mat, camera_center, f=f)
        calib = svg.focal_lengths_and_pp_offsets_to_calib_mat(focal_lengths, pp_offsets, f=xp)
        ext = svg.rot_mat_and_cam_center_to_ext_mat(rotation_mat, camera_center, f=xp)
        return cls.from_calib_and_ext_mats(calib, ext, f=xp)

    @classmethod
    @checked
    def from_persp_angles(
        cls,
        persp_angles: Array,
        pp_offsets: Array,
        image_dims: Shape,
        rotation_mat: Array,
        camera_center: Array,
        *,
        f: Framework = None,
    ):
        """A camera from its fields of view (see :func:`persp_angles_to_focal_lengths`).

        Args:
            persp_angles: ``[theta_x, theta_y]`` in radians *[batch_shape, 2]*.
            pp_offsets: principal point ``[px, py]`` *[batch_shape, 2]*.
            image_dims: ``(height, width)``.
            rotation_mat: world-to-camera rotation ``R`` *[batch_shape, 3, 3]*.
            camera_center: camera centre in the world *[batch_shape, 3]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            A :class:`Camera`.

        Example:
            >>> cam = Camera.from_persp_angles(np.full(2, np.pi / 2), np.array([1.5, 1.5]), (4, 4),
            ...                                np.eye(3), np.zeros(3))
            >>> float(cam.calib_mat[0, 0].round(12))
            2.0
        """
        xp = ivy.get_framework(persp_angles, pp_offsets, rotation_mat, camera_center, f=f)
        focal = svg.persp_angles_to_focal_lengths(persp_angles, image_dims, f=xp)
        return cls.from_focal_lengths(focal, pp_offsets, rotation_mat, camera_center, f=xp)

    @property
    def camera_center(self) -> Array:
        """The camera centre in the world frame *[batch_shape, 3]*."""
        return self.inv_ext_mat[..., 3]

    @property
    def rotation_mat(self) -> Array:
        """The world-to-camera rotation ``R`` *[batch_shape, 3, 3]*."""
        return self.ext_mat[..., 0:3]

    @checked
    def project(self, coords_wrt_world: Array, *, f: Framework = None) -> Array:
        """Depth-scaled pixel coordinates of world points (:func:`world_to_ds_pixel_coords`).

        Args:
            coords_wrt_world: world points *[batch_shape, image_shape, 3 or 4]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            ``[u*d, v*d, d]`` *[batch_shape, image_shape, 3]*.

        Example:
            >>> Camera.from_calib_and_ext_mats(np.eye(3), np.eye(3, 4)).project(np.ones(3))
            array([1., 1., 1.])
        """
        return svg.world_to_ds_pixel_coords(coords_wrt_world, self.full_mat, f=f)

    @checked
    def unproject(self, depth: Array, *, f: Framework = None) -> Array:
        """Homogeneous world points of every pixel of a depth image
        (:func:`depth_to_world_coords`).

        Args:
            depth: planar depth images *[batch_shape, h, w, 1]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            World points *[batch_shape, h, w, 4]*.

        Example:
            >>> Camera.from_calib_and_ext_mats(np.eye(3), np.eye(3, 4)).unproject(np.ones((1, 1, 1)))
            array([[[0., 0., 1., 1.]]])
        """
        return svg.depth_to_world_coords(depth, self.inv_full_mat, f=f)

    @checked
    def full_mat_to(self, other: Camera, *, f: Framework = None) -> Array:
        """The matrix ``P_other P_self^-1`` taking depth-scaled pixel coordinates of this camera
        to those of ``other`` (``cam1to2_full_mat``).

        Args:
            other: the target camera.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, 3, 4]*.

        Example:
            >>> cam = Camera.from_calib_and_ext_mats(np.eye(3), np.eye(3, 4))
            >>> cam.full_mat_to(cam)
            array([[1., 0., 0., 0.],
                   [0., 1., 0., 0.],
                   [0., 0., 1., 0.]])
        """
        xp = ivy.get_framework(self.full_mat, other.full_mat, f=f)
        m = xp.matmul(other.full_mat[..., 0:3], self.inv_full_mat)
        return xp.concat([m[..., 0:3], m[..., 3:4] + other.full_mat[..., 3:4]], axis=-1)
