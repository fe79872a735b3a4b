"""Cost of ivy's dispatch per call, as ratios to the native framework call, in one run.

For each backend and input size (10 and 10,000 float32 elements) it times, with ``timeit``
statement strings and many interleaved repeats. The minimum over repeats is reported: on a
shared machine, interference only ever adds time, so the minimum is the least noisy estimate
(as the timeit documentation advises); the median is printed beside it for the noise:

    native        the framework's own function (np.add, torch.add, jnp.add, tf.math.add)
    ivy.<b>.fn    the backend namespace function
    inferred      ivy.fn(x, y), the framework inferred from the input types
    f=            ivy.fn(x, y, f='<b>')
    set           ivy.fn(x, y) after ivy.set_framework('<b>') (ivy.fn is then ivy.<b>.fn)

Usage: python benchmarks/dispatch_overhead.py [--backends numpy,torch] [--functions add,sin]
       [--repeats 31] [--sizes 10,10000]
"""

from __future__ import annotations

import argparse
import statistics
import timeit

import numpy as np
from _timing import calls_per_sample, interleaved_samples

import ivy

NATIVE = {
    "numpy": ("import numpy as nat", "nat.{fn}"),
    "torch": ("import torch as nat", "nat.{fn}"),
    "jax": ("import jax.numpy as nat", "nat.{fn}"),
    "tensorflow": ("import tensorflow as tf; nat = tf.math", "nat.{fn}"),
}
ARITY = {"add": 2, "multiply": 2, "divide": 2, "sin": 1, "exp": 1, "maximum": 2}
VARIANTS = ("native", "ivy.<b>.fn", "inferred", "f=", "set")


def _statements(backend: str, fn: str) -> dict[str, str]:
    args = "x, y" if ARITY[fn] == 2 else "x"
    native_fn = NATIVE[backend][1].format(fn=fn)
    return {
        "native": f"{native_fn}({args})",
        "ivy.<b>.fn": f"ns.{fn}({args})",
        "inferred": f"ivy.{fn}({args})",
        "f=": f"ivy.{fn}({args}, f='{backend}')",
        "set": f"ivy.{fn}({args})",
    }


def measure(backend: str, fn: str, size: int, repeats: int) -> dict[str, float]:
    """(min, median) seconds per call of each variant, repeats interleaved to share drift."""
    ns = getattr(ivy, backend)
    env: dict = {"ivy": ivy, "ns": ns}
    exec(NATIVE[backend][0], env)
    env["x"] = ns.asarray(np.linspace(-1, 1, size, dtype=np.float32))
    env["y"] = ns.asarray(np.linspace(1, 2, size, dtype=np.float32))
    stmts = _statements(backend, fn)
    timers = {v: timeit.Timer(stmt, globals=env) for v, stmt in stmts.items()}
    number = calls_per_sample(timers["native"], target_s=0.02)
    samples = interleaved_samples(
        timers, number, repeats, around={"set": lambda: ivy.set_framework(backend)}
    )
    return {v: (min(s), statistics.median(s)) for v, s in samples.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default=",".join(ivy.installed_frameworks()))
    parser.add_argument("--functions", default="add,sin")
    parser.add_argument("--sizes", default="10,10000")
    parser.add_argument("--repeats", type=int, default=31)
    args = parser.parse_args()
    header = "| backend | fn | n | native (min / median) | " + " | ".join(VARIANTS[1:]) + " |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for backend in args.backends.split(","):
        for fn in args.functions.split(","):
            for size in (int(s) for s in args.sizes.split(",")):
                t = measure(backend, fn, size, args.repeats)
                (lo, med) = t["native"]
                ratios = " | ".join(
                    f"{t[v][0] / lo:.3f}x ({t[v][1] / med:.2f}x)" for v in VARIANTS[1:]
                )
                print(
                    f"| {backend} | {fn} | {size} | {lo * 1e9:,.0f} / {med * 1e9:,.0f} ns | {ratios} |"
                )


if __name__ == "__main__":
    main()
