"""``ivy.set_matmul_precision``: full float32 matrix products and convolutions by default on
every backend (no TF32 or bf16 passes that break the same answer on GPUs), set in the
frameworks' own switches when ivy loads or binds a backend, restored when it unbinds. The
switches are read on the CPU here; a GPU would use them."""

from __future__ import annotations

import pytest

import ivy


def _torch_switches():
    import torch

    return (torch.backends.cuda.matmul.fp32_precision, torch.backends.cudnn.conv.fp32_precision)


def _jax_switches():
    import jax

    return jax.config.jax_default_matmul_precision


def _tf_switches():
    import tensorflow as tf

    return tf.config.experimental.tensor_float_32_execution_enabled()


# Each framework's own precision switches, read with its own API (a backend with no such switch,
# numpy or array_api_strict, has no row).
SWITCHES = {"torch": _torch_switches, "jax": _jax_switches, "tensorflow": _tf_switches}


def _switches(backend: str):
    return SWITCHES[backend]() if backend in SWITCHES else None


# What each framework's switches read under ivy's precisions, and a user's own other setting.
EXPECTED = {
    "torch": {"highest": ("ieee", "ieee"), "high": ("tf32", "tf32")},
    "jax": {"highest": "highest", "high": "high"},
    "tensorflow": {"highest": False, "high": True},
}


def _torch_user_value():
    import torch

    torch.backends.cuda.matmul.fp32_precision = "tf32"
    torch.backends.cudnn.conv.fp32_precision = "tf32"


def _jax_user_value():
    import jax

    jax.config.update("jax_default_matmul_precision", "bfloat16")


def _tf_user_value():
    import tensorflow as tf

    tf.config.experimental.enable_tensor_float_32_execution(True)


# A setting of the user's own (TF32 or bf16 on), made as a user's code would.
USER_VALUES = {"torch": _torch_user_value, "jax": _jax_user_value, "tensorflow": _tf_user_value}


@pytest.fixture
def restored_precision():
    yield
    ivy.set_matmul_precision("highest")


def test_loaded_backends_run_at_full_float32_precision(backend, xp, restored_precision):
    if backend not in EXPECTED:
        assert _switches(backend) is None  # nothing to switch (numpy, array_api_strict)
        return
    ivy.set_matmul_precision("highest")
    assert ivy.matmul_precision() == "highest"
    assert _switches(backend) == EXPECTED[backend]["highest"]
    ivy.set_matmul_precision("high")
    assert ivy.matmul_precision() == "high"
    assert _switches(backend) == EXPECTED[backend]["high"]


def test_binding_sets_the_switches_and_unbinding_restores_them(backend, xp, restored_precision):
    if backend not in EXPECTED:
        return
    USER_VALUES[backend]()
    users = _switches(backend)
    assert users != EXPECTED[backend]["highest"]
    with ivy.set_framework(backend):
        assert _switches(backend) == EXPECTED[backend]["highest"]
        with ivy.set_framework("numpy"):  # nested: the outer binding's values stay
            assert _switches(backend) == EXPECTED[backend]["highest"]
    assert _switches(backend) == users
    ivy.set_framework(backend)
    assert _switches(backend) == EXPECTED[backend]["highest"]
    ivy.unset_framework()
    assert _switches(backend) == users
    with pytest.raises(RuntimeError):  # an exception in the block still restores
        with ivy.set_framework(backend):
            raise RuntimeError
    assert _switches(backend) == users


def test_unknown_precision_says_what_to_choose():
    with pytest.raises(ValueError, match="'highest', 'high'"):
        ivy.set_matmul_precision("medium")
