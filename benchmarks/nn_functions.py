"""Speed of ivy's nn functions as ratios to each framework's own function, in one run.

For each backend it times ``ivy.<fn>`` (the framework inferred from the input) against the
native call on the same data, with interleaved repeats, and prints the minimum over repeats
(interference on a shared machine only adds time) and the ratio ivy / native. Channel-last ivy
calls are compared with the native call in the framework's preferred layout (torch: ``NCHW``
tensors, so the ratio includes ivy's layout permutation), and compositions (softmax,
layer_norm, attention, lstm_update) with the fused native kernels where one exists. Backends
and functions without a native peer are left out (numpy has no convolution of its own).

Usage: python benchmarks/nn_functions.py [--backends torch,jax] [--functions conv2d,softmax]
       [--repeats 15]
"""

from __future__ import annotations

import argparse
import timeit

import numpy as np
from _timing import calls_per_sample, interleaved_samples

import ivy

RNG = np.random.default_rng(0)


def _data(shape):
    return RNG.standard_normal(shape).astype(np.float32)


def _cases_torch():
    import torch
    import torch.nn.functional as F

    t = torch.from_numpy
    x = t(_data((8, 32, 32, 16)))
    x_nchw = x.permute(0, 3, 1, 2).contiguous()
    w = t(_data((3, 3, 16, 32)))
    w_oihw = w.permute(3, 2, 0, 1).contiguous()
    z = t(_data((64, 1000)))
    h = t(_data((64, 512)))
    q = t(_data((4, 8, 64, 32)))
    seq = t(_data((16, 20, 32)))
    h0 = torch.zeros(16, 64)
    lstm = torch.nn.LSTM(32, 64, batch_first=True)
    kernel = lstm.weight_ih_l0.detach().T.contiguous()
    recurrent = lstm.weight_hh_l0.detach().T.contiguous()
    b1, b2 = lstm.bias_ih_l0.detach(), lstm.bias_hh_l0.detach()
    with torch.no_grad():
        yield (
            "conv2d",
            lambda: ivy.conv2d(x, w, 1, "SAME"),
            lambda: F.conv2d(x_nchw, w_oihw, padding=1),
        )
        yield (
            "max_pool2d",
            lambda: ivy.max_pool2d(x, 2, 2, "VALID"),
            lambda: F.max_pool2d(x_nchw, 2, 2),
        )
        yield (
            "avg_pool2d",
            lambda: ivy.avg_pool2d(x, 3, 1, "SAME"),
            lambda: F.avg_pool2d(x_nchw, 3, 1, 1, count_include_pad=False),
        )
        yield "softmax", lambda: ivy.softmax(z), lambda: torch.softmax(z, -1)
        yield "log_softmax", lambda: ivy.log_softmax(z), lambda: torch.log_softmax(z, -1)
        yield "sigmoid", lambda: ivy.sigmoid(z), lambda: torch.sigmoid(z)
        yield "gelu", lambda: ivy.gelu(z), lambda: F.gelu(z)
        yield "layer_norm", lambda: ivy.layer_norm(h), lambda: F.layer_norm(h, (512,))
        yield (
            "scaled_dot_product_attention",
            lambda: ivy.scaled_dot_product_attention(q, q, q),
            lambda: F.scaled_dot_product_attention(q, q, q),
        )
        yield (
            "lstm_update",
            lambda: ivy.lstm_update(seq, h0, h0, kernel, recurrent, b1, b2),
            lambda: lstm(seq, (h0[None], h0[None])),
        )


def _cases_jax():
    import jax
    import jax.numpy as jnp
    from jax import lax

    x, w = jnp.asarray(_data((8, 32, 32, 16))), jnp.asarray(_data((3, 3, 16, 32)))
    z, q = jnp.asarray(_data((64, 1000))), jnp.asarray(_data((4, 64, 8, 32)))
    dn = ("NHWC", "HWIO", "NHWC")

    def ready(fn):
        return lambda: jax.block_until_ready(fn())

    yield (
        "conv2d",
        ready(lambda: ivy.conv2d(x, w, 1, "SAME")),
        ready(lambda: lax.conv_general_dilated(x, w, (1, 1), "SAME", dimension_numbers=dn)),
    )
    yield (
        "max_pool2d",
        ready(lambda: ivy.max_pool2d(x, 2, 2, "VALID")),
        ready(lambda: lax.reduce_window(x, -jnp.inf, lax.max, (1, 2, 2, 1), (1, 2, 2, 1), "VALID")),
    )
    yield "softmax", ready(lambda: ivy.softmax(z)), ready(lambda: jax.nn.softmax(z))
    yield "log_softmax", ready(lambda: ivy.log_softmax(z)), ready(lambda: jax.nn.log_softmax(z))
    yield "sigmoid", ready(lambda: ivy.sigmoid(z)), ready(lambda: jax.nn.sigmoid(z))
    yield "gelu", ready(lambda: ivy.gelu(z)), ready(lambda: jax.nn.gelu(z, approximate=False))
    # jax's layout is [batch, length, heads, d]; ivy's [batch, heads, length, d]
    qh = jnp.swapaxes(q, 1, 2)
    yield (
        "scaled_dot_product_attention",
        ready(lambda: ivy.scaled_dot_product_attention(qh, qh, qh)),
        ready(lambda: jax.nn.dot_product_attention(q, q, q)),
    )


def _cases_tensorflow():
    import tensorflow as tf

    x, w = tf.constant(_data((8, 32, 32, 16))), tf.constant(_data((3, 3, 16, 32)))
    z = tf.constant(_data((64, 1000)))
    yield "conv2d", lambda: ivy.conv2d(x, w, 1, "SAME"), lambda: tf.nn.conv2d(x, w, 1, "SAME")
    yield (
        "max_pool2d",
        lambda: ivy.max_pool2d(x, 2, 2, "VALID"),
        lambda: tf.nn.max_pool2d(x, 2, 2, "VALID"),
    )
    yield (
        "avg_pool2d",
        lambda: ivy.avg_pool2d(x, 3, 1, "SAME"),
        lambda: tf.nn.avg_pool2d(x, 3, 1, "SAME"),
    )
    yield "softmax", lambda: ivy.softmax(z), lambda: tf.nn.softmax(z)
    yield "log_softmax", lambda: ivy.log_softmax(z), lambda: tf.nn.log_softmax(z)
    yield "sigmoid", lambda: ivy.sigmoid(z), lambda: tf.sigmoid(z)
    yield "gelu", lambda: ivy.gelu(z), lambda: tf.nn.gelu(z)


def _cases_numpy():
    from scipy import special

    z = _data((64, 1000))
    yield "softmax", lambda: ivy.softmax(z), lambda: special.softmax(z, -1)
    yield "log_softmax", lambda: ivy.log_softmax(z), lambda: special.log_softmax(z, -1)
    yield "sigmoid", lambda: ivy.sigmoid(z), lambda: special.expit(z)


CASES = {
    "numpy": _cases_numpy,
    "torch": _cases_torch,
    "jax": _cases_jax,
    "tensorflow": _cases_tensorflow,
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default=",".join(ivy.installed_frameworks()))
    parser.add_argument("--functions", default=None)
    parser.add_argument("--repeats", type=int, default=15)
    args = parser.parse_args()
    wanted = None if args.functions is None else set(args.functions.split(","))
    print(f"{'backend':<11} {'function':<30} {'native':>11} {'ivy':>11} {'ratio':>7}")
    for backend in args.backends.split(","):
        for name, ours, native in CASES[backend]():
            if wanted is not None and name not in wanted:
                continue
            ours(), native()  # warm up (jax compiles on the first call)
            timers = {"ivy": timeit.Timer(ours), "native": timeit.Timer(native)}
            number = calls_per_sample(timers["native"], target_s=0.02)
            samples = interleaved_samples(timers, number, args.repeats)
            best = {k: min(v) for k, v in samples.items()}
            print(
                f"{backend:<11} {name:<30} {best['native'] * 1e6:9.1f}us "
                f"{best['ivy'] * 1e6:9.1f}us {best['ivy'] / best['native']:7.2f}"
            )


if __name__ == "__main__":
    main()
