"""``__array_namespace_info__()`` on every backend namespace, and dtypes that a backend cannot hold
(jax's 64-bit types while x64 is off) absent from the namespace."""

from __future__ import annotations

import subprocess
import sys

import pytest

import ivy
from ivy.dtypes import DTYPE_NAMES

KIND_MEMBERS = {
    "bool": {"bool"},
    "signed integer": {"int8", "int16", "int32", "int64"},
    "unsigned integer": {"uint8", "uint16", "uint32", "uint64"},
    "real floating": {"float16", "float32", "float64"},
    "complex floating": {"complex64", "complex128"},
}


def test_capabilities(xp):
    caps = xp.__array_namespace_info__().capabilities()
    assert isinstance(caps["boolean indexing"], bool)
    assert isinstance(caps["data-dependent shapes"], bool)
    assert caps["max dimensions"] is None or caps["max dimensions"] > 0


def test_devices_are_what_arrays_report(xp):
    info = xp.__array_namespace_info__()
    assert info.default_device() == xp.zeros(3).device
    assert info.default_device() in info.devices()
    assert xp.dev(xp.zeros(3, device=info.default_device())) == "cpu"  # the tests run on the CPU
    for device in info.devices():
        x = xp.ones(2, device=device)
        assert x.device == device
        assert ivy.to_numpy(x).tolist() == [1.0, 1.0]


def test_default_dtypes_are_ivys(xp):
    defaults = xp.__array_namespace_info__().default_dtypes(device="cpu")
    assert defaults["real floating"] == xp.float32
    assert defaults["complex floating"] == xp.complex64
    assert defaults["integral"] == xp.int64  # jax runs the tests with x64 on
    assert defaults["indexing"] == xp.argmax(xp.asarray([1.0, 2.0])).dtype


@pytest.mark.parametrize(
    "kind",
    [None, "bool", "signed integer", "integral", "numeric", ("bool", "complex floating")],
)
def test_dtypes_by_kind(xp, kind):
    found = xp.__array_namespace_info__().dtypes(kind=kind)
    kinds = (kind,) if isinstance(kind, str) else kind or tuple(KIND_MEMBERS)
    expected = set()
    for k in kinds:
        if k == "integral":
            expected |= KIND_MEMBERS["signed integer"] | KIND_MEMBERS["unsigned integer"]
        elif k == "numeric":
            expected |= set(DTYPE_NAMES) - {"bool"}
        else:
            expected |= KIND_MEMBERS[k]
    expected = {n for n in expected if n != "float16"}  # not an Array API dtype
    assert set(found) == expected
    for name, dtype in found.items():
        assert dtype == getattr(xp, name)
        assert xp.empty(1, dtype=dtype).dtype == dtype


def test_unknown_kind_raises(xp):
    with pytest.raises(ValueError, match="kind"):
        xp.__array_namespace_info__().dtypes(kind="floating")


def test_a_dtype_the_library_lacks_is_no_attribute():
    if "array_api_strict" not in ivy.available_frameworks():
        pytest.skip("array_api_strict is not registered")
    ns = ivy.array_api_strict
    assert not hasattr(ns, "float16")
    with pytest.raises(ivy.errors.UnavailableDtypeError, match="float16"):
        ns.float16  # noqa: B018
    assert "float16" not in ns.__array_namespace_info__().dtypes()


JAX_X64_SWITCH = """
import jax, ivy
ns = ivy.jax
off = (hasattr(ns, "float64"), sorted(ns.__array_namespace_info__().dtypes(kind="real floating")),
       ns.__array_namespace_info__().default_dtypes()["integral"].__name__)
try:
    ns.float64
except ivy.errors.UnavailableDtypeError as err:
    message = str(err)
with ivy.set_framework("jax"):
    bound = ivy.float64            # the namespace has none: ivy keeps its name
jax.config.update("jax_enable_x64", True)
on = (hasattr(ns, "float64"), sorted(ns.__array_namespace_info__().dtypes(kind="real floating")),
      ns.__array_namespace_info__().default_dtypes()["integral"].__name__)
print(off); print(on); print(bound); print("jax_enable_x64" in message)
print(ns.zeros(2, dtype=ns.float64).dtype)
"""


@pytest.mark.skipif("jax" not in ivy.installed_frameworks(), reason="jax is not installed")
def test_jax_dtypes_follow_x64_switched_on_after_import():
    out = subprocess.run(
        [sys.executable, "-c", JAX_X64_SWITCH],
        capture_output=True,
        text=True,
        check=True,
        env={**__import__("os").environ, "JAX_ENABLE_X64": "0"},
    ).stdout.splitlines()
    assert out[0] == "(False, ['float32'], 'int32')"
    assert out[1] == "(True, ['float32', 'float64'], 'int64')"
    assert out[2] == "float64"
    assert out[3] == "True"
    assert out[4] == "float64"
