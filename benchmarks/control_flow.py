"""What a 100-step ``ivy.scan`` costs on each backend, eager and compiled, against the native loop.

The loop is a small batched recurrence, the shape of an environment rollout: a carry of 64 x 4
float32, ``c = c + 0.01 * tanh(c @ W + x)``, 100 steps, the carries stacked as outputs. For each
backend, in one run:

    ivy eager           ivy.scan(step, c0, xs) called eagerly
    native eager        the framework's own loop: numpy/torch a Python loop and stack; jax
                        jax.lax.scan called eagerly; tensorflow a Python loop and tf.stack
    ivy compiled        ivy.compile_fn of the scan (jax.jit, tf.function, torch.compile)
    native compiled     jax.jit(lax.scan); tf.function(tf.scan); torch.compile of the loop
    ivy compiled grad   forward and backward (gradient of sum(ys**2) w.r.t. W), compiled

The first call of a compiled function (tracing and compiling) is reported separately as
"compile s". Times are the minimum over repeats (interference only adds time), in milliseconds
per 100-step scan.

Usage: python benchmarks/control_flow.py [--backends numpy,torch,jax,tensorflow] [--steps 100]
       [--repeats 7]
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

import ivy

BATCH, DIM = 64, 4


def _data(steps):
    rng = np.random.default_rng(0)
    c0 = rng.standard_normal((BATCH, DIM)).astype(np.float32)
    xs = rng.standard_normal((steps, BATCH, DIM)).astype(np.float32)
    w = (rng.standard_normal((DIM, DIM)) * 0.5).astype(np.float32)
    return c0, xs, w


def _ivy_step(w):
    def step(c, x):
        c = c + 0.01 * ivy.tanh(ivy.matmul(c, w) + x)
        return c, c

    return step


def _block(out):
    for leaf in ivy.nest.nest_leaves(out):
        if hasattr(leaf, "block_until_ready"):
            leaf.block_until_ready()
        elif hasattr(leaf, "numpy"):
            leaf.numpy() if not hasattr(leaf, "detach") else leaf.detach()
    return out


def _time(fn, repeats):
    first = time.perf_counter()
    _block(fn())
    first = time.perf_counter() - first
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        _block(fn())
        best = min(best, time.perf_counter() - start)
    return first, best


def _natives(backend, c0, xs, w):
    """(eager, compiled) native loops of the same recurrence; compiled is None for numpy."""
    if backend == "numpy":

        def eager():
            c, ys = c0, []
            for x in xs:
                c = c + np.float32(0.01) * np.tanh(c @ w + x)
                ys.append(c)
            return c, np.stack(ys)

        return eager, None
    if backend == "torch":
        import torch

        tc0, txs, tw = (torch.from_numpy(a) for a in (c0, xs, w))

        def loop(c0, xs, w):
            c, ys = c0, []
            for x in xs.unbind(0):
                c = c + 0.01 * torch.tanh(c @ w + x)
                ys.append(c)
            return c, torch.stack(ys)

        compiled = torch.compile(loop)
        return (lambda: loop(tc0, txs, tw)), (lambda: compiled(tc0, txs, tw))
    if backend == "jax":
        import jax
        import jax.numpy as jnp

        jc0, jxs, jw = (jnp.asarray(a) for a in (c0, xs, w))

        def scan(c0, xs, w):
            def step(c, x):
                c = c + 0.01 * jnp.tanh(c @ w + x)
                return c, c

            return jax.lax.scan(step, c0, xs)

        jitted = jax.jit(scan)
        return (lambda: scan(jc0, jxs, jw)), (lambda: jitted(jc0, jxs, jw))
    import tensorflow as tf

    tc0, txs, tw = (tf.constant(a) for a in (c0, xs, w))

    def eager():
        c, ys = tc0, []
        for x in tf.unstack(txs):
            c = c + 0.01 * tf.tanh(c @ tw + x)
            ys.append(c)
        return c, tf.stack(ys)

    @tf.function(autograph=False)
    def compiled(c0, xs, w):
        ys = tf.scan(lambda c, x: c + 0.01 * tf.tanh(c @ w + x), xs, initializer=c0)
        return ys[-1], ys

    return eager, (lambda: compiled(tc0, txs, tw))


def run(backend, steps, repeats):
    c0, xs, w = _data(steps)
    nc0, nxs, nw = (ivy.asarray(a, f=backend) for a in (c0, xs, w))
    step = _ivy_step(nw)
    rows = []
    _, t = _time(lambda: ivy.scan(step, nc0, nxs), repeats)
    rows.append(("ivy eager", None, t))
    native_eager, native_compiled = _natives(backend, c0, xs, w)
    _, t = _time(native_eager, repeats)
    rows.append(("native eager", None, t))
    if backend == "numpy":
        return rows
    compiled = ivy.compile_fn(lambda c, xs, w: ivy.scan(_ivy_step(w), c, xs))
    first, t = _time(lambda: compiled(nc0, nxs, nw), repeats)
    rows.append(("ivy compiled", first, t))
    first, t = _time(native_compiled, repeats)
    rows.append(("native compiled", first, t))

    def loss(v):
        _, ys = ivy.scan(_ivy_step(v["w"]), nc0, nxs)
        return ivy.sum(ys * ys)

    grad = ivy.compile_fn(lambda v: ivy.execute_with_gradients(loss, v))
    first, t = _time(lambda: grad({"w": nw}), repeats)
    rows.append(("ivy compiled grad", first, t))
    _, t = _time(lambda: ivy.execute_with_gradients(loss, {"w": nw}), repeats)
    rows.append(("ivy eager grad", None, t))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--backends", default="numpy,torch,jax,tensorflow")
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    warnings.filterwarnings("ignore")
    print(f"{args.steps}-step scan, carry {BATCH}x{DIM} float32; ms per scan (min of repeats)")
    print(f"{'backend':<11} {'variant':<18} {'ms':>9} {'compile s':>10}")
    for backend in args.backends.split(","):
        for name, first, t in run(backend, args.steps, args.repeats):
            compile_s = f"{first:10.2f}" if first is not None else " " * 10
            print(f"{backend:<11} {name:<18} {t * 1e3:9.3f} {compile_s}")


if __name__ == "__main__":
    main()
