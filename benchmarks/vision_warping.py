"""Inverse warping of an image with depth: ivy_vision on every installed backend, eager and
compiled, against kornia's ``warp_frame_depth`` on torch, measured in the same run.

The task (kornia's): given a source image, the target camera's depth, the pose of the target
in the source camera and the calibration, sample the source image where every target pixel
lands. Both sides take the same inputs and compute the camera-to-camera matrix inside the timed
call (kornia inverts the calibration matrix, so ivy does too). Images are float32, channel-last
for ivy ``[B, H, W, 3]`` and channel-first for kornia ``[B, 3, H, W]`` (each library's own
layout). Every output is checked against kornia's (or, without kornia, against ivy on numpy in
float64) before it is timed. Each ivy_vision variant (backend, eager or compiled) runs in a
process of its own with kornia beside it (another framework's thread pools and allocations
would otherwise slow whatever runs after them), the two taking turns call by call (benchmarks/_timing.py); the minimum over the repeats (the least
disturbed call on a shared machine) is reported in milliseconds with the median beside it, and
the ratio of the minima to kornia's in the same process (> 1 means slower than kornia).

kornia is a benchmark-only dependency: ``.venv/bin/pip install kornia`` (check with
``--dry-run`` that it keeps torch at 2.13.0). Without it the kornia rows and ratios are left
out.

``--device gpu:0`` creates every input on that device (numpy stays on the CPU), kornia's too, and
synchronises the device after each timed call; the reference is computed on the CPU. The issue's
GPU size: ``--device gpu:0 --batch 4 --sizes 480x640 --backends torch,jax``.

Usage:
    .venv/bin/python benchmarks/vision_warping.py [--sizes 240x320,480x640] [--batch 1]
        [--repeats 15] [--backends numpy,torch,jax,tensorflow] [--threads 1] [--no-torch-compile]
        [--device cpu|gpu:0]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import subprocess
import sys
import time
import timeit
import warnings

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples, median  # noqa: E402

import ivy  # noqa: E402
import ivy_vision as vis  # noqa: E402


def _inputs(batch, h, w, seed=0):
    """A smooth random image, depth in [1, 3], a small camera motion, a pinhole calibration."""
    rng = np.random.default_rng(seed)
    ys, xs = np.mgrid[0:h, 0:w] / max(h, w)
    image = np.stack([np.sin(7 * xs + 3 * ys), np.cos(5 * ys - 2 * xs), xs * ys], -1)
    image = np.broadcast_to(image, (batch, h, w, 3)) + rng.normal(0, 0.01, (batch, h, w, 3))
    depth = 2 + np.sin(4 * xs)[None, ..., None] * 0.5 + rng.uniform(0, 0.1, (batch, h, w, 1))
    angle = 0.03
    rot = np.array(
        [[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]]
    )
    pose = np.eye(4)
    pose[:3, :3], pose[:3, 3] = rot, [0.05, -0.02, 0.03]
    f = 0.8 * w
    calib = np.array([[f, 0, (w - 1) / 2], [0, f, (h - 1) / 2], [0, 0, 1.0]])
    return {
        "image": image.astype(np.float32),
        "depth": depth.astype(np.float32),
        "pose": np.broadcast_to(pose, (batch, 4, 4)).astype(np.float32),
        "calib": np.broadcast_to(calib, (batch, 3, 3)).astype(np.float32),
    }


def ivy_warp(image, depth, pose, calib):
    """ivy_vision's inverse warp from kornia's inputs: ``P_src P_tgt^-1 = K [R | t] K^-1``."""
    xp = ivy.get_framework(image)
    rot_part = xp.matmul(xp.matmul(calib, pose[..., 0:3, 0:3]), xp.inv(calib))
    full = xp.concat([rot_part, xp.matmul(calib, pose[..., 0:3, 3:4])], axis=-1)
    return vis.inverse_warp(image, depth, full, padding="zeros")


def _kornia_warp():
    from kornia.geometry.depth import warp_frame_depth

    def warp(image, depth, pose, calib):
        return warp_frame_depth(image, depth, pose, calib)

    return warp


def _native(a, backend, device="cpu"):
    """``a`` as an array of ``backend`` on ``device`` (numpy: always the CPU)."""
    if backend == "numpy":
        return a
    return ivy.asarray(np.ascontiguousarray(a), f=backend, device=device)


def _to_numpy(x):
    if isinstance(x, np.ndarray):
        return x
    if hasattr(x, "detach"):
        return x.detach().cpu().numpy()
    if hasattr(x, "numpy"):
        return x.numpy()
    return np.asarray(x)


def _sync(x):
    if hasattr(x, "block_until_ready"):
        x.block_until_ready()
    elif getattr(x, "is_cuda", False):
        import torch

        torch.cuda.synchronize()
    return x


COMPILERS = {"torch": "torch.compile", "jax": "jax.jit", "tensorflow": "tf.function"}


def _variants(backends, torch_compile):
    """``(backend, compiled)`` of every ivy_vision variant to time."""
    out = []
    for backend in backends:
        out.append((backend, False))
        if backend in COMPILERS and (backend != "torch" or torch_compile):
            out.append((backend, True))
    return out


def _implementations(backend, compiled):
    """(name, backend, channel_first, fn): kornia, if installed, and one ivy_vision variant."""
    impls = []
    if importlib.util.find_spec("kornia") is not None:
        impls.append((KORNIA, "torch", True, _kornia_warp()))
    if compiled:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fn = ivy.compile_fn(ivy_warp)
        impls.append((f"ivy_vision {COMPILERS[backend]}", backend, False, fn))
    else:
        impls.append((f"ivy_vision {backend}", backend, False, ivy_warp))
    return impls


def _set_threads(threads, backends):
    """OpenMP's threads (before a library starts its pool) and the intra-op threads of each of
    ``backends`` (:func:`ivy.set_threads`), torch's too where kornia runs beside them."""
    os.environ.setdefault("OMP_NUM_THREADS", str(threads))
    names = set(backends)
    if importlib.util.find_spec("kornia") is not None:
        names.add("torch")
    for name in names:
        ivy.set_threads(name, threads)


def _reference(data):
    """kornia's warp (channel-last), or ivy on numpy in float64 without kornia."""
    keys = ("image", "depth", "pose", "calib")
    if importlib.util.find_spec("kornia") is None:
        return ivy_warp(*[data[k].astype(np.float64) for k in keys])
    import torch

    arrays = [np.moveaxis(data[k], -1, 1) if k in ("image", "depth") else data[k] for k in keys]
    out = _kornia_warp()(*[torch.from_numpy(np.ascontiguousarray(a)) for a in arrays])
    return out.permute(0, 2, 3, 1).numpy()


def _measure(variant, args):
    """Rows ``(size, name, min ms, median ms, kornia min ms, max err)`` of one ivy_vision
    variant (``backend`` or ``backend:compiled``), kornia timed in the same process, the two
    taking turns call by call."""
    backend, _, compiled = variant.partition(":")
    _set_threads(args.threads, [backend])
    clock = time.perf_counter if args.clock == "wall" else time.process_time
    rows = []
    for size in args.sizes.split(","):
        h, w = (int(v) for v in size.split("x"))
        data = _inputs(args.batch, h, w)
        if backend == "torch":  # compile each size afresh, with static shapes, as jax and tf do
            import torch

            torch._dynamo.reset()
        reference = _reference(data)
        timers, errors = {}, {}
        for name, impl_backend, channel_first, fn in _implementations(backend, bool(compiled)):
            arrays = [data[k] for k in ("image", "depth", "pose", "calib")]
            if channel_first:
                arrays[0], arrays[1] = (np.moveaxis(a, -1, 1) for a in arrays[:2])
            arrays = [_native(a, impl_backend, args.device) for a in arrays]
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                out = _to_numpy(_sync(fn(*arrays)))
            if channel_first:
                out = np.moveaxis(out, 1, -1)
            # kornia divides by z + 1e-8 (float32): a few 1e-4 of difference
            errors[name] = float(np.max(np.abs(out - reference)))
            if errors[name] > 2e-3:
                raise AssertionError(f"{name} {size}: max difference {errors[name]:.2e}")
            _sync(fn(*arrays))
            timers[name] = timeit.Timer(lambda fn=fn, a=arrays: _sync(fn(*a)), timer=clock)
        samples = interleaved_samples(timers, number=1, repeats=args.repeats)
        kornia = min(samples[KORNIA]) * 1e3 if KORNIA in samples else None
        for name, values in samples.items():
            if name != KORNIA:
                rows.append(
                    (size, name, min(values) * 1e3, median(values) * 1e3, kornia, errors[name])
                )
    return rows


KORNIA = "kornia warp_frame_depth (torch)"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="240x320,480x640", help="HxW image sizes")
    parser.add_argument("--batch", type=int, default=1)
    parser.add_argument("--repeats", type=int, default=15, help="timed calls per implementation")
    parser.add_argument("--backends", default="numpy,torch,jax,tensorflow")
    parser.add_argument("--threads", type=int, default=1, help="intra-op threads of every backend")
    parser.add_argument(
        "--no-torch-compile",
        action="store_true",
        help="skip torch.compile (its first compilation takes ~20 s)",
    )
    parser.add_argument(
        "--clock",
        default="wall",
        choices=["wall", "process"],
        help="wall time, or the process's CPU time (steadier on a machine shared with other "
        "work; with --threads 1 it is the compute time)",
    )
    parser.add_argument("--device", default="cpu", help="'cpu' or 'gpu:0' (CUDA)")
    parser.add_argument("--worker", help=argparse.SUPPRESS)  # one variant, rows as JSON
    args = parser.parse_args(argv)
    if args.worker:
        print(json.dumps(_measure(args.worker, args)))
        return

    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b) is not None]
    have_kornia = importlib.util.find_spec("kornia") is not None
    if not have_kornia:
        print(
            "NOTE: kornia is not installed, so its rows and ratios are left out. It is a "
            "benchmark-only dependency: .venv/bin/pip install kornia\n"
        )
    print(
        f"device {args.device}, batch {args.batch}, float32, 3 channels, {args.threads} thread(s), "
        f"{args.repeats} interleaved repeats, {args.clock} clock; each variant in its own "
        f"process, kornia timed beside it\n"
    )
    header = f"{'size':9} {'implementation':28} {'ms':>8} {'median':>8}"
    header += f" {'kornia ms':>9} {'vs kornia':>9}" if have_kornia else ""
    print(header + f" {'max err':>9}")
    print("-" * (len(header) + 10))
    rows = []
    # a process per variant: one framework's threads and allocations never slow another's
    for backend, compiled in _variants(backends, not args.no_torch_compile):
        forwarded = [
            "--sizes",
            args.sizes,
            "--batch",
            str(args.batch),
            "--repeats",
            str(args.repeats),
            "--threads",
            str(args.threads),
            "--clock",
            args.clock,
            "--device",
            args.device,
        ]
        forwarded += ["--no-torch-compile"] if args.no_torch_compile else []
        out = subprocess.run(
            [
                sys.executable,
                __file__,
                *forwarded,
                "--worker",
                backend + (":c" if compiled else ""),
            ],
            env={**os.environ, "OMP_WAIT_POLICY": "PASSIVE"},  # idle OpenMP threads sleep
            capture_output=True,
            text=True,
            check=True,
        )
        rows += json.loads(out.stdout.strip().splitlines()[-1])
    for size in args.sizes.split(","):
        for row_size, name, best, med, kornia, err in rows:
            if row_size != size:
                continue
            row = f"{size:9} {name:28} {best:8.2f} {med:8.2f}"
            row += f" {kornia:9.2f} {best / kornia:9.2f}" if kornia else ""
            print(row + f" {err:9.1e}")
        print()


if __name__ == "__main__":
    main()
