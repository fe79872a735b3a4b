"""What the complex special values (``ivy/backends/_complex_special.py``) cost real inputs.

For each function a backend wraps, it times a float32 array of 10 elements through:

    before   the function as ivy built it without the special values: jax's and numpy's
             ``_reals.unary(native)`` wrapper, torch's and tensorflow's native itself
    after    ``ivy.<backend>.<fn>`` now

with interleaved repeats (``benchmarks/_timing.py``), and prints the ratio after / before of the
minimum and of the median over repeats. ``sin`` on jax, which nothing changed, shows the noise.

Usage: python benchmarks/complex_special_overhead.py [--backends jax,numpy] [--repeats 41]
"""

from __future__ import annotations

import argparse
import statistics
import timeit

import numpy as np
from _timing import calls_per_sample, interleaved_samples

import ivy
from ivy.backends import _reals

CASES = {
    "jax": ["exp", "sin", "tanh", "sign"],
    "numpy": ["expm1", "tanh", "sin"],
    "torch": ["acos", "expm1", "log1p", "tanh"],
    "tensorflow": ["expm1", "log1p", "sqrt", "tanh"],
}


def _before(backend: str, name: str):
    """The function as it was built before the special values."""
    if backend in ("jax", "numpy"):
        module = __import__("jax.numpy").numpy if backend == "jax" else np
        native = getattr(module, name)
        return native if name == "sign" else _reals.unary(native, name)
    if backend == "torch":
        return getattr(__import__("torch"), name)
    return getattr(__import__("tensorflow").math, name)


def measure(backend: str, name: str, repeats: int) -> tuple[float, float, float]:
    ns = getattr(ivy, backend)
    x = ns.asarray(np.linspace(0.1, 0.9, 10, dtype=np.float32))
    env = {"before": _before(backend, name), "after": getattr(ns, name), "x": x}
    timers = {v: timeit.Timer(f"{v}(x)", globals=env) for v in ("before", "after")}
    number = calls_per_sample(timers["before"], target_s=0.01)
    samples = interleaved_samples(timers, number, repeats)
    ratio_min = min(samples["after"]) / min(samples["before"])
    ratio_median = statistics.median(samples["after"]) / statistics.median(samples["before"])
    return ratio_min, ratio_median, min(samples["before"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default=",".join(CASES))
    parser.add_argument("--repeats", type=int, default=41)
    args = parser.parse_args()
    print("| backend | function | before (us) | after/before (min) | after/before (median) |")
    print("| --- | --- | --- | --- | --- |")
    for backend in args.backends.split(","):
        for name in CASES[backend]:
            ratio_min, ratio_median, before = measure(backend, name, args.repeats)
            print(
                f"| {backend} | {name} | {before * 1e6:.2f} | {ratio_min:.3f} | "
                f"{ratio_median:.3f} |"
            )


if __name__ == "__main__":
    main()
