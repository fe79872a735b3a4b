"""Implicit (volumetric) rendering, as in NeRF: stratified samples along rays, termination
probabilities from densities, and rendering of features and depth.

Along a ray with samples at depths ``z_i``, densities ``sigma_i`` and spacings
``delta_i = z_{i+1} - z_i`` (the last spacing effectively infinite), the occupancy of a segment
is ``alpha_i = 1 - exp(-sigma_i delta_i)`` and the probability that the ray terminates in it is
``w_i = alpha_i exp(-sum_{j<i} sigma_j delta_j)``; renderings are ``sum_i w_i f_i``.

Example:
    >>> ray_termination_probabilities(np.array([0., 1e9, 1e9]), np.ones(3))
    array([0., 1., 0.])
"""

from __future__ import annotations

import math

import ivy
from ivy.checks import check_floating_dtype
from ivy.typing import Array, Device, Dtype, Framework, Shape
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = [
    "downsampled_image_dims_from_desired_num_pixels",
    "create_sampled_pixel_coords_image",
    "sample_images",
    "sampled_volume_density_to_occupancy_probability",
    "ray_termination_probabilities",
    "stratified_sample",
    "render_rays_via_termination_probabilities",
    "render_implicit_features_and_depth",
]

#: The spacing after the last sample of a ray (the ray runs on to infinity).
FAR_SPACING = 1e10


@checked
def downsampled_image_dims_from_desired_num_pixels(
    image_dims: Shape, num_pixels: int, maximum: bool = False, *, f: Framework = None
) -> tuple:
    """Image dimensions with about ``num_pixels`` pixels and the aspect ratio of ``image_dims``.

    Args:
        image_dims: ``(height, width)`` of the original image.
        num_pixels: the desired number of pixels.
        maximum: never exceed ``num_pixels`` (round down) instead of rounding to nearest.
        f: accepted for uniformity with the other functions; the result is plain Python.

    Returns:
        ``([height, width], height * width)``.

    Example:
        >>> downsampled_image_dims_from_desired_num_pixels((480, 640), 12)
        ([3, 4], 12)
    """
    h, w = C.image_dims_of(image_dims)
    to_int = math.floor if maximum else round
    ratio = w / h
    height = (num_pixels / ratio) ** 0.5
    new_h, new_w = max(int(to_int(height)), 1), max(int(to_int(height * ratio)), 1)
    return [new_h, new_w], new_h * new_w


@checked
def create_sampled_pixel_coords_image(
    image_dims: Shape,
    samples_per_dim: Shape,
    batch_shape: Shape | None = None,
    *,
    normalized: bool = False,
    randomize: bool = True,
    homogeneous: bool = False,
    dtype: Dtype = "float32",
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Pixel coordinates of one sample per cell of a regular grid over an image: the cell's
    centre, or (``randomize``) a random pixel of the cell, rounded to integers (halves up).

    Args:
        image_dims: ``(height, width)`` of the image.
        samples_per_dim: ``(rows, columns)`` of samples.
        batch_shape: leading batch dimensions (none by default).
        normalized: divide ``x`` by the width and ``y`` by the height.
        randomize: place each sample randomly in its cell (fresh draws on every call, also in
            compiled code; reproducible after ``ivy.seed``).
        homogeneous: append the homogeneous 1.
        dtype: floating dtype of the result.
        device: device of the result.
        f: framework name or namespace; the global framework if None.

    Returns:
        Pixel coordinates *[batch_shape, rows, columns, 2 or 3]*.

    Example:
        >>> create_sampled_pixel_coords_image((4, 4), (2, 2), randomize=False, f='numpy')[..., 0]
        array([[1., 3.],
               [1., 3.]], dtype=float32)
    """
    xp = ivy.get_framework(f=f)
    h, w = C.image_dims_of(image_dims)
    rows, cols = C.image_dims_of(samples_per_dim, "samples_per_dim")
    check_floating_dtype(dtype)  # (integer coordinates would round the samples)
    batch = tuple(batch_shape or ())
    cell = (w / cols, h / rows)
    grid = C.pixel_grid(xp, (rows, cols), dtype, device, False)
    scale = xp.asarray([cell[0], cell[1]], dtype=dtype, device=device)
    centres = grid * scale + (scale / 2.0 - 0.5)
    centres = xp.broadcast_to(centres, (*batch, rows, cols, 2))
    if randomize:
        offsets = xp.random_uniform(-0.5, 0.5, (*batch, rows, cols, 2), dtype=dtype, device=device)
        centres = centres + offsets * scale
    limits = xp.asarray([w - 1.0, h - 1.0], dtype=dtype, device=device)
    coords = xp.clip(xp.floor(centres + 0.5), xp.zeros_like(limits), limits)
    if normalized:
        coords = coords / xp.asarray([float(w), float(h)], dtype=dtype, device=device)
    if homogeneous:
        coords = C.homogeneous(xp, coords)
    return coords


@checked
def sample_images(
    list_of_images: list,
    num_pixels: int,
    *,
    randomize: bool = True,
    f: Framework = None,
) -> list:
    """Sample aligned images at the same pixels: about ``num_pixels`` of them, one per cell of a
    regular grid (see :func:`create_sampled_pixel_coords_image`).

    Args:
        list_of_images: images *[batch_shape, h, w, d_i]* with one batch shape and size.
        num_pixels: the desired number of samples.
        randomize: random pixels within the cells (else their centres).
        f: framework name or namespace; inferred from the images if None.

    Returns:
        A list of samples *[batch_shape, num_samples, d_i]*, one per image.

    Example:
        >>> image = np.arange(16.).reshape(4, 4, 1)
        >>> sample_images([image], 4, randomize=False)[0][..., 0]
        array([ 5.,  7., 13., 15.])
    """
    if not list_of_images:
        raise InputError("list_of_images is empty.")
    xp = ivy.get_framework(*list_of_images, f=f)
    h, w = C.check_image(xp, list_of_images[0], "list_of_images[0]")
    batch = C.shape_of(xp, list_of_images[0])[:-3]
    for image in list_of_images:
        if C.shape_of(xp, image)[:-1] != (*batch, h, w):
            raise InputError(
                f"the images must share their batch shape and size; got "
                f"{[C.shape_of(xp, i) for i in list_of_images]}."
            )
    dims, count = downsampled_image_dims_from_desired_num_pixels((h, w), num_pixels)
    coords = create_sampled_pixel_coords_image(
        (h, w), dims, batch, randomize=randomize, dtype="float32", f=xp
    )
    flat = xp.astype(coords[..., 1] * w + coords[..., 0], C.index_dtype(xp))
    flat = xp.reshape(flat, (*batch, count, 1))
    channels = [C.shape_of(xp, image)[-1] for image in list_of_images]
    combined = xp.concat(
        [xp.reshape(image, (*batch, h * w, -1)) for image in list_of_images], axis=-1
    )
    sampled = xp.take_along_axis(
        combined, xp.broadcast_to(flat, (*batch, count, sum(channels))), axis=-2
    )
    out, start = [], 0
    for c in channels:
        out.append(sampled[..., start : start + c])
        start += c
    return out


@checked(broadcast=True, density=("...",), inter_sample_distance=("...",))
def sampled_volume_density_to_occupancy_probability(
    density: Array, inter_sample_distance: Array, *, f: Framework = None
) -> Array:
    """Occupancy probability ``1 - exp(-density * distance)`` of ray segments.

    Args:
        density: volume densities *[batch_shape]*.
        inter_sample_distance: segment lengths *[batch_shape]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Occupancy probabilities *[batch_shape]*.

    Example:
        >>> sampled_volume_density_to_occupancy_probability(np.array([0., np.log(2)]), np.ones(2))
        array([0. , 0.5])
    """
    xp = ivy.get_framework(density, inter_sample_distance, f=f)
    return -xp.expm1(-density * inter_sample_distance)


@checked(broadcast=True, density=("...", "n"), inter_sample_distance=("...", "n"))
def ray_termination_probabilities(
    density: Array, inter_sample_distance: Array, *, f: Framework = None
) -> Array:
    """Probability that a ray terminates in each of its segments:
    ``alpha_i exp(-sum_{j<i} sigma_j delta_j)`` (computed in log space, exactly).

    Args:
        density: densities along rays *[batch_shape, num_samples_per_ray]*.
        inter_sample_distance: segment lengths *[batch_shape, num_samples_per_ray]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Termination probabilities *[batch_shape, num_samples_per_ray]* (they sum to at most 1).

    Example:
        >>> ray_termination_probabilities(np.array([np.log(2), np.log(2)]), np.ones(2))
        array([0.5 , 0.25])
    """
    xp = ivy.get_framework(density, inter_sample_distance, f=f)
    optical_depth = density * inter_sample_distance
    transmittance = xp.exp(-xp.cumsum(optical_depth, axis=-1, exclusive=True))
    return -xp.expm1(-optical_depth) * transmittance


@checked(broadcast=True, starts=("...",), ends=("...",))
def stratified_sample(
    starts: Array, ends: Array, num_samples: int, *, f: Framework = None
) -> Array:
    """Stratified samples between ``starts`` and ``ends``: the range is cut into
    ``num_samples`` equal bins and one uniform sample is drawn in each (fresh draws on every
    call, also in compiled code; reproducible after ``ivy.seed``).

    Args:
        starts: range starts *[batch_shape]*.
        ends: range ends *[batch_shape]*.
        num_samples: samples per range.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Increasing samples *[batch_shape, num_samples]*.

    Example:
        >>> s = stratified_sample(np.zeros(1), np.ones(1), 4)
        >>> bool(np.all((s >= [0, .25, .5, .75]) & (s < [.25, .5, .75, 1])))
        True
    """
    xp = ivy.get_framework(starts, ends, f=f)
    n = int(num_samples)
    bins = (ends - starts)[..., None] / float(n)
    left = starts[..., None] + bins * xp.arange(n, dtype=xp.dtype(starts), device=xp.dev(starts))
    shape = C.shape_of(xp, left)
    u = xp.random_uniform(0.0, 1.0, shape, dtype=xp.dtype(starts), device=xp.dev(starts))
    return left + u * bins


@checked(broadcast=True, ray_term_probs=("...", "n"), features=("...", "n", "c"))
def render_rays_via_termination_probabilities(
    ray_term_probs: Array, features: Array, render_variance: bool = False, *, f: Framework = None
) -> Array | tuple:
    """Render features along rays: their expectation under the termination probabilities.

    Args:
        ray_term_probs: termination probabilities *[batch_shape, num_samples_per_ray]*.
        features: features at the samples *[batch_shape, num_samples_per_ray, feat_dim]*.
        render_variance: also return ``sum_i w_i (f_i - rendering)^2``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Renderings *[batch_shape, feat_dim]*, and with ``render_variance`` their variances.

    Example:
        >>> render_rays_via_termination_probabilities(np.array([0.5, 0.5]), np.array([[1.], [3.]]), True)
        (array([2.]), array([1.]))
    """
    xp = ivy.get_framework(ray_term_probs, features, f=f)
    weights = ray_term_probs[..., None]
    rendering = xp.sum(weights * features, axis=-2)
    if not render_variance:
        return rendering
    return rendering, xp.sum(weights * (features - rendering[..., None, :]) ** 2, axis=-2)


@checked
def render_implicit_features_and_depth(
    network_fn,
    rays_o: Array,
    rays_d: Array,
    near: Array,
    far: Array,
    samples_per_ray: int,
    timestamps: Array | None = None,
    render_depth: bool = True,
    render_feats: bool = True,
    render_variance: bool = False,
    inter_feat_fn=None,
    v=None,
    *,
    f: Framework = None,
) -> tuple:
    """Render features and depth of an implicit function along rays: stratified samples between
    ``near`` and ``far``, densities and features from ``network_fn``, termination
    probabilities, expectations.

    Args:
        network_fn: ``network_fn(points [*B, num_rays, spr, 3], features, timestamps, v=v)
            -> (feat [..., spr, feat_dim] or flat, densities [..., spr] or flat)``.
        rays_o: ray origins (camera centres) *[batch_shape, 3]*.
        rays_d: ray directions *[batch_shape, ray_batch_shape, 3]*; with unit directions the
            rendered depth is radial.
        near: near distances *[batch_shape, ray_batch_shape]*.
        far: far distances *[batch_shape, ray_batch_shape]*.
        samples_per_ray: stratified samples per ray.
        timestamps: passed to ``network_fn``.
        render_depth: render the depth (distance along the rays, in units of ``rays_d``).
        render_feats: render the features.
        render_variance: also render their variances.
        inter_feat_fn: ``inter_feat_fn(points) -> features`` passed to ``network_fn``.
        v: the network's variables, passed to ``network_fn``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        A tuple of the requested renderings: features *[batch_shape, ray_batch_shape, feat]*
        (and variances), then depth *[batch_shape, ray_batch_shape, 1]* (and variance).

    Example:
        >>> def wall(points, features, timestamps, v=None):   # opaque beyond z = 2
        ...     z = points[..., 2]
        ...     return np.ones(z.shape + (1,)), np.where(z > 2, 1e9, 0.)
        >>> depth, = render_implicit_features_and_depth(
        ...     wall, np.zeros(3), np.array([[0., 0., 1.]]), np.ones(1), np.full(1, 3.), 64,
        ...     render_feats=False)
        >>> bool(abs(depth[0, 0] - 2) < 1 / 32)
        True
    """
    xp = ivy.get_framework(rays_o, rays_d, near, far, f=f)
    C.check_last_dim(xp, rays_o, 3, "rays_o")
    C.check_last_dim(xp, rays_d, 3, "rays_d")
    batch = C.shape_of(xp, rays_o)[:-1]
    ray_batch = C.shape_of(xp, rays_d)[len(batch) : -1]
    n = int(samples_per_ray)
    flat_rays = math.prod(ray_batch)
    depths = stratified_sample(near, far, n, f=xp)  # [*B, *R, S]
    origins = xp.reshape(rays_o, (*batch, *(1,) * len(ray_batch), 1, 3))
    points = origins + rays_d[..., None, :] * depths[..., None]
    features = None
    if inter_feat_fn is not None:
        features = xp.reshape(inter_feat_fn(points), (*batch, flat_rays, n, -1))
    feat, densities = network_fn(
        xp.reshape(points, (*batch, flat_rays, n, 3)), features, timestamps, v=v
    )
    densities = xp.reshape(densities, (*batch, *ray_batch, n))
    spacing = xp.concat(
        [depths[..., 1:] - depths[..., :-1], xp.full_like(depths[..., -1:], FAR_SPACING)], axis=-1
    )
    weights = ray_termination_probabilities(densities, spacing, f=xp)
    out = []
    if render_feats:
        feat = xp.reshape(feat, (*batch, *ray_batch, n, -1))
        rendered = render_rays_via_termination_probabilities(weights, feat, render_variance, f=xp)
        out += list(rendered) if render_variance else [rendered]
    if render_depth:
        rendered = render_rays_via_termination_probabilities(
            weights, depths[..., None], render_variance, f=xp
        )
        out += list(rendered) if render_variance else [rendered]
    return tuple(out)
