"""Triangle meshes: rasterizing projected triangles with a depth buffer, and meshes of
coordinate images.

Example:
    >>> triangle = np.array([[[0., 0., 1.], [3., 0., 1.], [0., 3., 1.]]])
    >>> depth, ids, bary = rasterize_triangles(triangle, (3, 3))
    >>> ids[..., 0]
    array([[ 0,  0,  0],
           [ 0,  0,  0],
           [ 0,  0, -1]])
"""

from __future__ import annotations

import math

import ivy
from ivy.typing import Array, Device, Framework, Shape
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = [
    "rasterize_triangles",
    "create_trimesh_indices_for_image",
    "coord_image_to_trimesh",
]


def _chunk(xp, tri, px, py):
    """Depths and perspective-correct barycentrics of the pixels ``(px, py)`` ``[P]`` in the
    triangles ``tri`` ``[b, T, 3, 3]``: ``z [b, T, P]`` (inf outside) and ``bary [b, T, P, 3]``."""
    x = [tri[..., i, 0][..., None] for i in range(3)]
    y = [tri[..., i, 1][..., None] for i in range(3)]
    z = [tri[..., i, 2][..., None] for i in range(3)]
    area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])
    # edge functions: twice the signed area of the sub-triangle opposite each vertex
    e = [
        (x[(i + 2) % 3] - x[(i + 1) % 3]) * (py - y[(i + 1) % 3])
        - (y[(i + 2) % 3] - y[(i + 1) % 3]) * (px - x[(i + 1) % 3])
        for i in range(3)
    ]
    lam = [xp.safe_divide(ei, area) for ei in e]
    front = xp.logical_and(xp.logical_and(z[0] > 0, z[1] > 0), z[2] > 0)
    inside = xp.logical_and(area != 0, front)
    for li in lam:
        inside = xp.logical_and(inside, li >= 0)
    weights = [xp.safe_divide(li, zi) for li, zi in zip(lam, z)]
    inverse_depth = weights[0] + weights[1] + weights[2]
    depth = xp.safe_divide(xp.ones_like(inverse_depth), inverse_depth)
    bary = xp.stack([wi * depth for wi in weights], axis=-1)
    depth = xp.where(inside, depth, xp.full_like(depth, math.inf))
    return depth, bary


@checked
def rasterize_triangles(
    pixel_coords_triangles: Array,
    image_dims: Shape,
    *,
    chunk_size: int = 64,
    f: Framework = None,
) -> tuple:
    """Rasterize projected triangles with a depth buffer.

    A pixel centre belongs to a triangle when its barycentric coordinates are all ``>= 0``
    (pixels on a shared edge belong to both; the nearer wins, the first on a tie). Depth and
    barycentric coordinates are interpolated perspective-correctly (linear in ``1 / z``), so the
    depth of a planar polygon is exact. Triangles with a vertex at depth ``<= 0`` or with no
    area are skipped. The work is ``O(num_triangles * h * w)``, in chunks of ``chunk_size``
    triangles: meant for small meshes and images.

    Args:
        pixel_coords_triangles: triangles as three vertices ``(x, y, depth)`` in pixels
            *[batch_shape, num_triangles, 3, 3]*.
        image_dims: ``(height, width)``.
        chunk_size: triangles tested at once (memory ``chunk_size * h * w``).
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(depth [batch_shape, h, w, 1], triangle_ids [batch_shape, h, w, 1],
        barycentric_coords [batch_shape, h, w, 3])``: the nearest triangle's depth (0 where
        none), its index (the default integer dtype, -1 where none) and the barycentric coordinates of the pixel
        centre in it (0 where none).

    Example:
        >>> triangle = np.array([[[0., 0., 2.], [2., 0., 2.], [0., 2., 2.]]])
        >>> rasterize_triangles(triangle, (2, 2))[0][..., 0]
        array([[2., 2.],
               [2., 2.]])
    """
    xp = ivy.get_framework(pixel_coords_triangles, f=f)
    shape = C.shape_of(xp, pixel_coords_triangles)
    if len(shape) < 3 or shape[-2:] != (3, 3):
        raise InputError(
            f"pixel_coords_triangles must be [..., num_triangles, 3, 3] (three vertices "
            f"(x, y, depth)); got shape {shape}."
        )
    h, w = C.image_dims_of(image_dims)
    batch, n = shape[:-3], shape[-3]
    b = math.prod(batch)
    tri = xp.reshape(pixel_coords_triangles, (b, n, 3, 3))
    grid = C.pixel_grid(xp, (h, w), xp.dtype(tri), xp.dev(tri), False)
    px, py = xp.reshape(grid[..., 0], (h * w,)), xp.reshape(grid[..., 1], (h * w,))
    best = xp.full((b, h * w), math.inf, dtype=xp.dtype(tri), device=xp.dev(tri))
    index_type = C.index_dtype(xp)
    best_id = xp.full((b, h * w), -1, dtype=index_type, device=xp.dev(tri))
    best_bary = xp.zeros((b, h * w, 3), dtype=xp.dtype(tri), device=xp.dev(tri))
    step = max(int(chunk_size), 1)
    for start in range(0, n, step):
        depth, bary = _chunk(xp, tri[:, start : start + step], px, py)
        nearest = xp.argmin(depth, axis=1)  # [b, P]: first index on ties
        chunk_depth = xp.take_along_axis(depth, nearest[:, None, :], axis=1)[:, 0]
        chunk_bary = xp.take_along_axis(bary, nearest[:, None, :, None], axis=1)[:, 0]
        closer = chunk_depth < best
        best = xp.where(closer, chunk_depth, best)
        best_id = xp.where(closer, xp.astype(nearest, index_type) + start, best_id)
        best_bary = xp.where(closer[..., None], chunk_bary, best_bary)
    covered = best_id >= 0
    depth = xp.where(covered, best, xp.zeros_like(best))
    best_bary = xp.where(covered[..., None], best_bary, xp.zeros_like(best_bary))
    return (
        xp.reshape(depth, (*batch, h, w, 1)),
        xp.reshape(best_id, (*batch, h, w, 1)),
        xp.reshape(best_bary, (*batch, h, w, 3)),
    )


@checked
def create_trimesh_indices_for_image(
    image_dims: Shape,
    batch_shape: Shape | None = None,
    *,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Vertex indices of the triangles of a regular mesh over an image's pixels (two per
    square of four neighbouring pixels, vertices numbered row by row).

    Args:
        image_dims: ``(height, width)``.
        batch_shape: leading batch dimensions to broadcast to (none by default).
        device: device of the result (the backend's default if None).
        f: framework name or namespace; the global framework if None.

    Returns:
        Indices of the default integer dtype *[batch_shape, 2 (h - 1) (w - 1), 3]*.

    Example:
        >>> create_trimesh_indices_for_image((2, 2), f='numpy')
        array([[0, 1, 2],
               [3, 1, 2]])
    """
    xp = ivy.get_framework(f=f)
    h, w = C.image_dims_of(image_dims)
    top_left = xp.reshape(
        xp.arange(w - 1, device=device)[None, :] + w * xp.arange(h - 1, device=device)[:, None],
        (-1,),
    )
    first = xp.stack([top_left, top_left + 1, top_left + w], axis=-1)
    second = xp.stack([top_left + w + 1, top_left + 1, top_left + w], axis=-1)
    indices = xp.concat([first, second], axis=0)
    if batch_shape:
        indices = xp.broadcast_to(indices, (*tuple(batch_shape), *C.shape_of(xp, indices)))
    return indices


@checked(exact=("validity_mask",))
def coord_image_to_trimesh(
    coord_img: Array, validity_mask: Array | None = None, *, f: Framework = None
) -> tuple:
    """A triangle mesh of a coordinate image: its pixels are the vertices, neighbours are
    joined as in :func:`create_trimesh_indices_for_image`.

    Args:
        coord_img: coordinates of every pixel *[batch_shape, h, w, 3]*.
        validity_mask: where the coordinates are valid *[h, w, 1]*; triangles with an invalid
            vertex are dropped (the number kept depends on the data: eager only, no batch).
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(vertices [batch_shape, h * w, 3], triangle_indices [batch_shape, num_triangles, 3])``.

    Example:
        >>> vertices, triangles = coord_image_to_trimesh(np.zeros((2, 3, 3)))
        >>> vertices.shape, triangles.shape
        ((6, 3), (4, 3))
    """
    xp = ivy.get_framework(coord_img, validity_mask, f=f)
    h, w = C.check_image(xp, coord_img, "coord_img", channels=3)
    batch = C.shape_of(xp, coord_img)[:-3]
    vertices = xp.reshape(coord_img, (*batch, h * w, 3))
    indices = create_trimesh_indices_for_image((h, w), batch, f=xp)
    if validity_mask is None:
        return vertices, indices
    if batch or C.shape_of(xp, validity_mask) != (h, w, 1):
        raise InputError(
            f"validity_mask must be [h, w, 1] = {(h, w, 1)} for an unbatched coord_img "
            f"(the number of triangles kept differs between images); got coord_img "
            f"{C.shape_of(xp, coord_img)} and validity_mask {C.shape_of(xp, validity_mask)}."
        )
    valid = xp.reshape(validity_mask, (h * w,))
    corner_valid = xp.take(valid, xp.reshape(indices, (-1,)), axis=0)
    keep = xp.all(xp.reshape(corner_valid, (-1, 3)), axis=-1)
    return vertices, xp.take(indices, xp.indices_where(keep)[:, 0], axis=0)
