"""ivy's main demo: one framework-agnostic function, run on every installed backend.

The function below is written once against ivy's API. It is run on numpy, torch, jax and
tensorflow (whichever are installed), compared with a float64 numpy reference written here
independently, and timed.

Usage: python scripts/demo.py
"""

from __future__ import annotations

import time

import numpy as np

import ivy


def attention(q, k, v, f=None):
    """Softmax attention of queries ``q`` over keys ``k`` and values ``v``, written once.

    Args:
        q: queries ``[..., n, d]``; k: keys ``[..., m, d]``; v: values ``[..., m, e]``.
        f: the framework (inferred from ``q`` when None).

    Returns:
        ``[..., n, e]``: each query's softmax-weighted average of the values.
    """
    xp = ivy.get_framework(q, f=f)
    scores = xp.divide(xp.matmul(q, xp.swapaxes(k, -1, -2)), float(xp.shape(q)[-1]) ** 0.5)
    scores = xp.exp(xp.subtract(scores, xp.max(scores, axis=-1, keepdims=True)))
    weights = xp.divide(scores, xp.sum(scores, axis=-1, keepdims=True))
    return xp.matmul(weights, v)


def reference(q, k, v):
    """The same computation in numpy float64, written independently of ivy."""
    s = q @ np.swapaxes(k, -1, -2) / np.sqrt(q.shape[-1])
    w = np.exp(s - s.max(-1, keepdims=True))
    return (w / w.sum(-1, keepdims=True)) @ v


def main() -> None:
    rng = np.random.default_rng(0)
    q, k, v = (rng.standard_normal((8, 64, 32)).astype(np.float32) for _ in range(3))
    expected = reference(q.astype(np.float64), k.astype(np.float64), v.astype(np.float64))
    print(f"ivy {ivy.__version__}: attention over {q.shape} float32 inputs\n")
    print(f"{'backend':<12}{'output type':<28}{'max |err|':>12}{'time / call':>14}")
    results = {}
    for name in ivy.installed_frameworks():
        t0 = time.perf_counter()
        xp = getattr(ivy, name)  # imports the framework on first access
        import_s = time.perf_counter() - t0
        args = [ivy.asarray(a, f=name) for a in (q, k, v)]
        attention(*args)  # warm-up
        calls = 20
        t0 = time.perf_counter()
        for _ in range(calls):
            out = attention(*args)
        per_call = (time.perf_counter() - t0) / calls
        results[name] = ivy.to_numpy(out)
        err = np.abs(results[name] - expected).max()
        kind = type(out).__module__.split(".")[0] + "." + type(out).__name__
        note = f"   (first use imported {name} in {import_s:.1f} s)" if import_s > 0.05 else ""
        print(f"{name:<12}{kind:<28}{err:>12.2e}{per_call * 1e3:>11.3f} ms{note}")
        assert xp.backend == name
    names = list(results)
    agree = all(
        np.allclose(results[a], results[b], rtol=1e-4, atol=1e-5) for a in names for b in names
    )
    close = all(np.allclose(r, expected, rtol=1e-4, atol=1e-5) for r in results.values())
    print(f"\nall {len(names)} backends agree with each other: {agree}")
    print(f"all agree with the float64 reference:          {close}")
    if not (agree and close):
        raise SystemExit("backends disagree")


if __name__ == "__main__":
    main()
