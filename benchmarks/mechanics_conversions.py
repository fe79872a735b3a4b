"""Batched rotation conversions: ivy_mechanics on every installed backend, against scipy's
Rotation (numpy) and roma (torch), measured in the same run.

Three conversions of N rotations (default 1e5): Euler angles ('xyz') -> matrix, matrix ->
quaternion, rotation vector -> matrix. Every result is checked against scipy before it is
timed. After a warm-up (which also compiles jax.jit / tf.function), the implementations of one
conversion take turns call by call (benchmarks/_timing.py: interleaved, shuffled repeats), so
that drift in the machine's load is shared. The minimum over the repeats (the least disturbed
call on a shared machine) is reported in nanoseconds per rotation, with the median beside it,
and the ratios of the minima to scipy and to roma (> 1 means slower than the peer).

roma is a benchmark-only dependency: ``.venv/bin/pip install roma``. Without it the roma rows
and ratios are left out and the run says so.

Usage:
    .venv/bin/python benchmarks/mechanics_conversions.py [--n 100000] [--repeats 7]
        [--backends numpy,torch,jax,tensorflow] [--dtype float64] [--torch-threads 1]
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import sys
import timeit
import warnings

import numpy as np

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [_HERE, os.path.join(_HERE, "..")]

from _timing import interleaved_samples, median  # noqa: E402

import ivy_mechanics as mech  # noqa: E402

CONVENTION = "xyz"
OPS = ("euler -> matrix", "matrix -> quaternion", "rotvec -> matrix")
MECH_FUNCTIONS = {
    "euler -> matrix": lambda x: mech.euler_to_rot_mat(x, CONVENTION),
    "matrix -> quaternion": mech.rot_mat_to_quaternion,
    "rotvec -> matrix": mech.rot_vec_to_rot_mat,
}


def _inputs(n, seed=0):
    from scipy.spatial.transform import Rotation

    rot = Rotation.random(n, random_state=seed)
    return {
        "euler -> matrix": rot.as_euler(CONVENTION),
        "matrix -> quaternion": rot.as_matrix(),
        "rotvec -> matrix": rot.as_rotvec(),
    }


def _scipy_functions():
    from scipy.spatial.transform import Rotation

    return {
        "euler -> matrix": lambda x: Rotation.from_euler(CONVENTION, x).as_matrix(),
        # ivy_mechanics takes the matrix to be orthonormal, so scipy is told so too
        "matrix -> quaternion": lambda x: Rotation.from_matrix(x, assume_valid=True).as_quat(),
        "rotvec -> matrix": lambda x: Rotation.from_rotvec(x).as_matrix(),
    }


def _roma_functions():
    import roma

    return {
        "euler -> matrix": lambda x: roma.euler_to_rotmat(CONVENTION, x),
        "matrix -> quaternion": roma.rotmat_to_unitquat,
        "rotvec -> matrix": roma.rotvec_to_rotmat,
    }


def _native(a, backend):
    if backend == "numpy":
        return a
    if backend == "torch":
        import torch

        return torch.from_numpy(a)
    if backend == "jax":
        import jax.numpy as jnp

        return jnp.asarray(a)
    import tensorflow as tf

    return tf.constant(a)


def _to_numpy(x):
    if isinstance(x, np.ndarray):
        return x
    if hasattr(x, "detach"):
        return x.detach().numpy()
    if hasattr(x, "numpy"):
        return x.numpy()
    return np.asarray(x)


def _sync(x):
    """Wait for asynchronous backends (jax) to finish."""
    if hasattr(x, "block_until_ready"):
        x.block_until_ready()
    return x


def _implementations(backends):
    """(name, backend of its inputs, {op: fn}) for every implementation to time."""
    from scipy.spatial.transform import Rotation

    impls = [
        ("scipy Rotation", "numpy", _scipy_functions()),
        # scipy's default from_matrix also checks the determinant and orthogonality
        (
            "scipy (from_matrix checked)",
            "numpy",
            {"matrix -> quaternion": lambda x: Rotation.from_matrix(x).as_quat()},
        ),
    ]
    if importlib.util.find_spec("roma") is not None:
        impls.append(("roma (torch)", "torch", _roma_functions()))
    for backend in backends:
        impls.append((f"ivy_mechanics {backend}", backend, MECH_FUNCTIONS))
        if backend == "jax":
            import jax

            impls.append(
                (
                    "ivy_mechanics jax.jit",
                    "jax",
                    {op: jax.jit(f) for op, f in MECH_FUNCTIONS.items()},
                )
            )
        if backend == "tensorflow":
            import tensorflow as tf

            for label, xla in (("tf.function", False), ("tf.function(XLA)", True)):
                compiled = {
                    op: tf.function(f, autograph=False, jit_compile=xla)
                    for op, f in MECH_FUNCTIONS.items()
                }
                impls.append((f"ivy_mechanics {label}", "tensorflow", compiled))
    return impls


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="rotations per call")
    parser.add_argument("--repeats", type=int, default=15, help="timed calls per implementation")
    parser.add_argument("--backends", default="numpy,torch,jax,tensorflow")
    parser.add_argument("--dtype", default="float64", choices=["float64", "float32"])
    parser.add_argument(
        "--torch-threads", type=int, default=1, help="torch intra-op threads (scipy uses one)"
    )
    args = parser.parse_args(argv)

    backends = [b for b in args.backends.split(",") if importlib.util.find_spec(b) is not None]
    if "jax" in backends:
        import jax

        jax.config.update("jax_enable_x64", True)
    have_roma = importlib.util.find_spec("roma") is not None
    if not have_roma:
        print(
            "NOTE: roma is not installed, so the roma rows and ratios are left out. "
            "It is a benchmark-only dependency: .venv/bin/pip install roma\n"
        )
    if "torch" in backends or have_roma:
        import torch

        torch.set_num_threads(args.torch_threads)
        print(f"torch threads: {torch.get_num_threads()}")
    print(f"N = {args.n} rotations per call, {args.dtype}, {args.repeats} interleaved repeats\n")

    inputs = _inputs(args.n)
    reference = {op: _scipy_functions()[op](x) for op, x in inputs.items()}
    impls = _implementations(backends)
    results = {}
    for op in OPS:
        timers = {}
        for name, backend, functions in impls:
            if op not in functions:
                continue
            dtype = "float64" if name.startswith("scipy") else args.dtype
            x = _native(inputs[op].astype(dtype), backend)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                out = _to_numpy(functions[op](x))
            expected = reference[op]
            if op == "matrix -> quaternion":  # q and -q are the same rotation
                sign = np.sign(np.sum(out * expected, axis=-1, keepdims=True))
                out = out * np.where(sign == 0, 1, sign)
            err = float(np.max(np.abs(out - expected)))
            tol = 1e-10 if dtype == "float64" else 1e-5
            if err > tol:
                raise AssertionError(f"{name} {op}: max error {err:.2e} against scipy")
            fn = functions[op]
            _sync(fn(x))  # warm-up
            timers[name] = timeit.Timer(lambda fn=fn, x=x: _sync(fn(x)))
            results[name, op] = [err]
        samples = interleaved_samples(timers, number=1, repeats=args.repeats)
        for name, seconds in samples.items():
            per_rotation = [t / args.n * 1e9 for t in seconds]
            results[name, op] = [min(per_rotation), median(per_rotation), *results[name, op]]

    names = [name for name, _, _ in impls]
    header = f"{'conversion':22} {'implementation':31} {'ns/rot':>8} {'median':>8} {'vs scipy':>9}"
    header += f" {'vs roma':>8}" if have_roma else ""
    print(header + f" {'max err':>9}")
    print("-" * len(header + " max err  "))
    for op in OPS:
        scipy_ns = results["scipy Rotation", op][0]
        roma_ns = results["roma (torch)", op][0] if have_roma else None
        for name in names:
            if (name, op) not in results:
                continue
            ns, med, err = results[name, op]
            row = f"{op:22} {name:31} {ns:8.1f} {med:8.1f} {ns / scipy_ns:9.2f}"
            row += f" {ns / roma_ns:8.2f}" if have_roma else ""
            print(row + f" {err:9.1e}")
        print()


if __name__ == "__main__":
    main()
