"""Every public function of ivy_mechanics and ivy_vision, on every backend, with the same odd
inputs: the same behaviour everywhere (the same result, or an error of the same class).

A table gives each function valid inputs (numpy float64, small); each variant below changes them
the way a user might, and every backend gets its own copy of the changed inputs:

- ``as given``, ``integers`` (every floating array rounded to int64) and ``float32 and
  float64`` (the first floating array in float32, the rest float64) must work everywhere, with
  one result dtype (integers compute in float32, float32 with float64 is float64) and the same
  values;
- ``wrong shape`` (the first array's last axis one longer), ``NaN`` (a NaN in the first array)
  and ``empty batch`` (a leading batch axis of size 0) may work or raise, but alike.

This is the tool that found the classes of issue 40 (tensorflow refusing what the others promote,
shapes accepted silently, raw framework errors); the tests of each fix are next to the library's
own tests. Functions with no array input (``create_*``, ``get_random_*``,
``downsampled_image_dims_from_desired_num_pixels``), ``sample_images`` (a list of images),
``render_implicit_features_and_depth`` (a network function) and the ``Camera`` class are
covered by their own tests.
"""

from __future__ import annotations

import inspect

import numpy as np
import pytest

import ivy_mechanics as mech
import ivy_vision as vis
from tests.helpers import native, numpy_of
from tests.ivy_vision import _cases as V

FRAMEWORKS = ("numpy", "torch", "jax", "tensorflow")


# ----------------------------------------------------------------------------------------------
# The table: name -> (function, positional args, keyword args, random result)
# ----------------------------------------------------------------------------------------------


def _mechanics_table() -> dict:
    """Inputs from the shapes each function declares (``ivy_mechanics._checks``): a batch of
    2, every named size 3."""
    gen = np.random.default_rng(4040)
    table = {}
    for name in mech.__all__:
        fn = getattr(mech, name)
        shapes = getattr(fn, "__checked_shapes__", None)
        if not callable(fn) or not shapes:
            continue  # constants, and the get_random_* functions (no array input)
        args = []
        for p in inspect.signature(fn).parameters.values():
            if p.kind is p.KEYWORD_ONLY or p.default is not p.empty and p.name not in shapes:
                break
            spec = shapes.get(p.name)
            if spec is None:  # t, scale, delta_t: an array or a float
                args.append(np.full((2, 1), 0.5))
                continue
            dims = [
                v[0] if isinstance(v, tuple) else (3 if isinstance(v, str) else v) for v in spec
            ]
            args.append(gen.normal(size=(2, *dims[1:])))
        table[f"mech.{name}"] = (fn, tuple(args), {}, False)
    return table


def _vision_table() -> dict:
    gen = np.random.default_rng(4041)
    b, h, w = V.B, V.H, V.W
    image = gen.normal(size=(b, h, w, 3))
    flow = gen.normal(size=(b, h, w, 2))
    cam = np.concatenate([gen.normal(size=(b, h, w, 2)), gen.uniform(1, 3, (b, h, w, 1))], -1)
    cam4 = np.concatenate([cam, np.ones((b, h, w, 1))], -1)
    ids = np.zeros((b, h, w, 1), np.int64)
    ids[:, :2] = 1
    obj_ids, obj_trans = np.ones((b, 1, 1), np.int64), np.tile(np.eye(3, 4), (b, 1, 1, 1))
    delta_t = np.full((b, 1), 0.1)
    two = np.stack([V.FULL, V.FULL2], 1)
    pixels = np.stack([V.DS / V.DS[..., 2:3], V.DS / V.DS[..., 2:3]], 1)
    density, spacing = gen.uniform(0, 3, (3, 8)), gen.uniform(0.01, 0.5, (3, 8))
    tris = np.concatenate([gen.uniform(0, 6, (b, 4, 3, 2)), gen.uniform(1, 3, (b, 4, 3, 1))], -1)
    rays = np.stack([gen.normal(size=(b, 6, 3)), gen.normal(size=(b, 6, 3))], 1)
    table = {f"vis.{n}": (getattr(vis, n), a, k, False) for n, (a, k, _) in V.CASES.items()}
    rows = {
        "solve_homogeneous_dlt": ((gen.normal(size=(b, 6, 4)),), {}),
        "get_fundamental_matrix": ((V.FULL, V.FULL2), {}),
        "closest_mutual_points_along_two_skew_rays": ((gen.normal(size=(b, 2, 3)), rays), {}),
        "triangulate_depth": ((pixels, two), {}),
        "sample_image": ((image, gen.uniform(-1, 5, (b, 6, 2))), {}),
        "bilinearly_interpolate_image": ((image, gen.uniform(-1, 5, (b, 6, 2))), {}),
        "inverse_warp": ((image, V.DEPTH, V.FULL12), {"with_validity": True}),
        "forward_warp": ((image, V.DEPTH, V.FULL12, (3, 4)), {}),
        "flow_from_depth_and_cam_mats": ((V.DS, V.FULL12), {}),
        "depth_from_flow_and_cam_mats": ((flow, two), {}),
        "project_flow_to_epipolar_line": ((flow, gen.normal(size=(b, 3, 3))), {}),
        "pixel_cost_volume": ((image, image[:, ::-1], 1), {}),
        "velocity_from_flow_cam_coords_and_cam_mats": ((flow, cam4, cam4, V.EXT12, delta_t), {}),
        "project_cam_coords_with_object_transformations": (
            (cam, ids, obj_ids, obj_trans, V.EXT12),
            {},
        ),
        "velocity_from_cam_coords_id_image_and_object_trans": (
            (cam4, ids, obj_ids, obj_trans, delta_t),
            {},
        ),
        "flow_from_cam_coords_id_image_and_object_trans": (
            (cam, ids, obj_ids, obj_trans, V.K, V.EXT12),
            {},
        ),
        "coords_to_voxel_grid": (
            (gen.uniform(0, 1, (b, 20, 3)), (2, 3, 2), "DIMS", (0, 0, 0, 1, 1, 1)),
            {"features": gen.normal(size=(b, 20, 1))},
        ),
        "quantize_to_image": ((gen.uniform(-1, 5, (b, 20, 2)), (4, 5), gen.normal(size=(b, 20, 2))), {}),
        "rasterize_triangles": ((tris, (5, 6)), {"chunk_size": 2}),
        "coord_image_to_trimesh": ((cam,), {}),
        "weighted_image_smooth": ((image, gen.uniform(0.1, 2, image.shape), 3), {}),
        "smooth_image_from_var_image": ((image, gen.uniform(0.1, 2, image.shape), 3, 1.0), {}),
        "smooth_image_fom_var_image": ((image, gen.uniform(0.1, 2, image.shape), 3, 1.0), {}),
        "sphere_signed_distances": (
            (gen.normal(size=(b, 3, 3)), gen.uniform(0.2, 1, (b, 3, 1)), gen.normal(size=(b, 5, 3))),
            {},
        ),
        "cuboid_signed_distances": (
            (np.tile(np.eye(3, 4), (b, 2, 1, 1)), gen.uniform(0.5, 2, (b, 2, 3)), gen.normal(size=(b, 5, 3))),
            {},
        ),
        "sampled_volume_density_to_occupancy_probability": ((density, spacing), {}),
        "ray_termination_probabilities": ((density, spacing), {}),
        "render_rays_via_termination_probabilities": (
            (density / 10, gen.normal(size=(3, 8, 2))),
            {"render_variance": True},
        ),
    }  # fmt: skip
    table.update({f"vis.{n}": (getattr(vis, n), a, k, False) for n, (a, k) in rows.items()})
    table["vis.stratified_sample"] = (vis.stratified_sample, (np.zeros(3), np.ones(3), 4), {}, True)
    return table


TABLE = {**_mechanics_table(), **_vision_table()}
NOT_IN_THE_TABLE = {
    "vis.create_uniform_pixel_coords_image", "vis.create_trimesh_indices_for_image",
    "vis.create_sampled_pixel_coords_image", "vis.downsampled_image_dims_from_desired_num_pixels",
    "vis.sample_images", "vis.render_implicit_features_and_depth", "vis.Camera",
    *(f"mech.{n}" for n in mech.__all__ if n.startswith("get_random_")), "mech.EULER_CONVENTIONS",
}  # fmt: skip


def test_the_table_has_every_public_function():
    public = {f"mech.{n}" for n in mech.__all__} | {f"vis.{n}" for n in vis.__all__}
    assert sorted(public - set(TABLE) - NOT_IN_THE_TABLE) == []


# ----------------------------------------------------------------------------------------------
# The variants
# ----------------------------------------------------------------------------------------------


def _floating(a) -> bool:
    return isinstance(a, np.ndarray) and a.dtype.kind == "f"


def _first(args, test) -> int | None:
    return next((i for i, a in enumerate(args) if test(a)), None)


def _integers(args):
    return tuple(np.round(a).astype(np.int64) if _floating(a) else a for a in args)


def _float32_and_float64(args):
    i = _first(args, _floating)
    return tuple(a.astype(np.float32) if j == i else a for j, a in enumerate(args))


def _wrong_shape(args):
    i = _first(args, lambda a: isinstance(a, np.ndarray) and a.ndim)
    out = list(args)
    a = out[i]
    out[i] = np.concatenate([a, a[..., :1]], axis=-1)
    return tuple(out)


def _nan(args):
    i = _first(args, _floating)
    out = list(args)
    out[i] = out[i].copy()
    out[i].reshape(-1)[0] = np.nan
    return tuple(out)


def _empty_batch(args):
    return tuple(a[:0] if isinstance(a, np.ndarray) and a.ndim >= 2 else a for a in args)


VARIANTS = {
    "as given": (lambda args: args, True),
    "integers": (_integers, True),
    "float32 and float64": (_float32_and_float64, True),
    "wrong shape": (_wrong_shape, False),
    "NaN": (_nan, False),
    "empty batch": (_empty_batch, False),
}


# ----------------------------------------------------------------------------------------------
# Calling every backend and comparing
# ----------------------------------------------------------------------------------------------


def _leaves(out) -> list[np.ndarray]:
    if isinstance(out, (tuple, list)):
        return [leaf for o in out for leaf in _leaves(o)]
    return [np.asarray(numpy_of(out))]


def _answer(backend, fn, args, kwargs):
    """The leaves of ``fn``'s result on ``backend`` (numpy), or the class of its error."""
    native_args = [native(a, backend) if isinstance(a, np.ndarray) else a for a in args]
    native_kwargs = {
        k: native(v, backend) if isinstance(v, np.ndarray) else v for k, v in kwargs.items()
    }
    try:
        with np.errstate(all="ignore"):  # (NaN and integer inputs divide by zero on purpose)
            return _leaves(fn(*native_args, **native_kwargs))
    except Exception as error:  # the class is what is compared
        return error


def _tolerance(dtype) -> dict:
    return dict(rtol=1e-9, atol=1e-9) if dtype == np.float64 else dict(rtol=2e-4, atol=2e-4)


def _differences(answers: dict, random: bool, must_work: bool) -> list[str]:
    found = []
    errors = {b: type(a).__name__ for b, a in answers.items() if isinstance(a, Exception)}
    if errors and must_work:
        return [f"{b} raised {type(answers[b]).__name__}: {answers[b]}" for b in errors]
    if errors:
        if len(errors) != len(answers) or len(set(errors.values())) > 1:
            found.append(f"errors differ: {errors}; " + ", ".join(
                f"{b} answered" for b in answers if b not in errors))  # fmt: skip
        return found
    (first, reference), *others = answers.items()
    for backend, leaves in others:
        if len(leaves) != len(reference):
            found.append(f"{backend}: {len(leaves)} results, {first}: {len(reference)}")
            continue
        for k, (got, want) in enumerate(zip(leaves, reference)):
            if got.shape != want.shape or got.dtype != want.dtype:
                found.append(
                    f"result {k}: {backend} {got.dtype}{got.shape}, {first} {want.dtype}{want.shape}"
                )
            elif not random and got.dtype.kind in "fc":
                finite = np.abs(want[np.isfinite(want)])
                scale = max(1.0, float(finite.max(initial=0.0)))
                tol = _tolerance(want.dtype)
                if not np.allclose(got, want, rtol=tol["rtol"], atol=tol["atol"] * scale,
                                   equal_nan=True):  # fmt: skip
                    found.append(f"result {k}: {backend} differs from {first}")
            elif not random and not np.array_equal(got, want):
                found.append(f"result {k}: {backend} differs from {first}")
    return found


@pytest.fixture
def frameworks(request) -> tuple[str, ...]:
    chosen = tuple(b for b in FRAMEWORKS if b in request.config.ivy_backends)
    if len(chosen) < 2:
        pytest.skip("comparing backends needs two or more of them")
    return chosen


@pytest.mark.parametrize("library", ["mech", "vis"])
def test_odd_inputs_behave_alike_on_every_backend(library, frameworks):
    """Every variant in one test per library: jax compiles each operation once per shape and
    dtype, and the variants share most of them (a test per variant on another worker would
    compile them again)."""
    report = []
    for variant, (change, must_work) in VARIANTS.items():
        for name, (fn, args, kwargs, random) in sorted(TABLE.items()):
            if not name.startswith(library + "."):
                continue
            changed = change(args)
            answers = {b: _answer(b, fn, changed, kwargs) for b in frameworks}
            found = _differences(answers, random, must_work)
            if found:
                report.append(f"{variant}: {name}: " + "; ".join(found))
    assert not report, f"{len(report)} calls behave differently:\n" + "\n".join(report)


@pytest.mark.parametrize("variant", ["integers", "float32 and float64"])
def test_promotion_gives_one_dtype(variant, frameworks):
    """Integers compute in float32; float32 with float64 is float64 (checked on one function
    per library: the comparison above checks that every backend agrees)."""
    change = VARIANTS[variant][0]
    want = np.float32 if variant == "integers" else np.float64
    for name in ("mech.hamilton_product", "vis.cam_to_ds_pixel_coords"):
        fn, args, kwargs, _ = TABLE[name]
        for backend in frameworks:
            (out,) = _answer(backend, fn, change(args), kwargs)
            assert out.dtype == want, (name, backend, out.dtype)
