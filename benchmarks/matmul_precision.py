"""The cost of full float32 matrix products against TF32 / bf16 passes, on one device.

``ivy.set_matmul_precision("highest")`` (ivy's default: full float32 on every backend) against
``"high"`` (TF32 tensor cores on torch, bf16 passes on jax): ``ivy.matmul`` of two N x N float32
matrices created on ``--device``, each precision's calls taking turns (benchmarks/_timing.py),
the median reported in ms and TFLOP/s with the ratio highest / high, and each precision's largest
error relative to numpy's float64 product (on a 512 x 512 corner). On a CPU both precisions are
full float32, so the ratio is about 1.

Usage: python benchmarks/matmul_precision.py [--device gpu:0] [--size 8192] [--backends torch,jax]
       [--repeats 7]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
import timeit

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples, median  # noqa: E402

import ivy  # noqa: E402

PRECISIONS = ("highest", "high")


def _sync(x):
    if hasattr(x, "block_until_ready"):
        x.block_until_ready()
    elif getattr(x, "is_cuda", False):
        import torch

        torch.cuda.synchronize()
    return x


def _with_precision(precision, fn):
    def run():
        ivy.set_matmul_precision(precision)
        try:
            return _sync(fn())
        finally:
            ivy.set_matmul_precision("highest")

    return run


def measure(backend, size, device, repeats):
    """name -> (median seconds, max relative error) of each precision on ``backend``."""
    rng = np.random.default_rng(0)
    a, b = (rng.standard_normal((size, size)).astype(np.float32) for _ in range(2))
    want = a[:512].astype(np.float64) @ b[:, :512].astype(np.float64)
    x, y = (ivy.asarray(m, f=backend, device=device) for m in (a, b))
    fn = ivy.compile_fn(ivy.matmul, f=backend) if backend == "jax" else ivy.matmul
    runs, errors = {}, {}
    for precision in PRECISIONS:
        run = _with_precision(precision, lambda: fn(x, y))
        got = ivy.to_numpy(run())[:512, :512]  # jax: compiles under this precision
        errors[precision] = float(np.max(np.abs(got - want)) / np.max(np.abs(want)))
        run()
        runs[precision] = timeit.Timer(run)
    samples = interleaved_samples(runs, 1, repeats)
    return {p: (median(samples[p]), errors[p]) for p in PRECISIONS}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--device", default="cpu", help="'cpu' or 'gpu:0' (CUDA)")
    parser.add_argument("--size", type=int, default=8192)
    parser.add_argument("--backends", default="torch,jax")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args(argv)
    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b)]
    flops = 2 * args.size**3
    print(f"float32 matmul {args.size} x {args.size} on {args.device}, median of {args.repeats}")
    print(f"{'backend':8} {'precision':9} {'ms':>9} {'TFLOP/s':>8} {'max rel err':>11}")
    for backend in backends:
        result = measure(backend, args.size, args.device, args.repeats)
        for precision, (seconds, error) in result.items():
            print(
                f"{backend:8} {precision:9} {seconds * 1e3:9.2f} {flops / seconds / 1e12:8.2f}"
                f" {error:11.1e}"
            )
        ratio = result["highest"][0] / result["high"][0]
        print(f"{backend:8} highest / high time: {ratio:.2f}")


if __name__ == "__main__":
    main()
