"""The backend namespaces: same public names, every core function implemented, native dtypes."""

from __future__ import annotations

import subprocess
import sys

import pytest

import ivy

NATIVE_MODULES = {
    "array_api_strict": "array_api_strict",
    "numpy": "numpy",
    "torch": "torch",
    "jax": "jax.numpy",
    "tensorflow": "tensorflow",
}


def test_all_namespaces_export_the_same_public_names(request):
    backends = request.config.ivy_backends
    names = {b: set(getattr(ivy, b).__all__) for b in backends}
    reference = names[backends[0]]
    for backend, exported in names.items():
        assert exported == reference, (
            f"{backend} differs from {backends[0]}: "
            f"missing {sorted(reference - exported)}, extra {sorted(exported - reference)}"
        )


def _public_attributes(ns) -> set[str]:
    """What a user sees in a namespace: every public attribute, listed or not."""
    return {n for n in vars(ns) if not n.startswith("_")}


def test_namespaces_have_no_public_names_beyond_their_list(request):
    """Exactly ``__all__`` and the namespace attributes (``backend``, ``capabilities``, ``use``):
    no group modules (``ivy.torch.compilation``), no framework module (``ivy.torch.torch``), no
    helpers (``NATIVE_DTYPES``, ``add_array_methods``); the same on every backend."""
    from ivy.backends._assemble import NAMESPACE_ATTRIBUTES

    seen = {}
    for backend in request.config.ivy_backends:
        ns = getattr(ivy, backend)
        extra = _public_attributes(ns) - set(ns.__all__) - set(NAMESPACE_ATTRIBUTES)
        assert not extra, f"ivy.{backend} also exports {sorted(extra)}"
        for attribute in NAMESPACE_ATTRIBUTES:
            assert hasattr(ns, attribute), f"ivy.{backend}.{attribute}"
        # dtypes that the library cannot hold (now) are listed but no attribute (see the docs)
        seen[backend] = _public_attributes(ns) | (set(ns.__all__) & set(ivy.dtypes.DTYPE_NAMES))
    reference = next(iter(seen.values()))
    assert all(names == reference for names in seen.values()), {
        b: sorted(names ^ reference) for b, names in seen.items()
    }


def test_every_core_function_is_in_every_namespace(xp):
    for info in ivy.list_functions():
        assert callable(getattr(xp, info.name)), info.name
        assert info.name in xp.__all__, info.name
    for info in ivy.list_functions(kind="alias"):
        assert getattr(xp, info.name) is getattr(xp, info.target)
        assert getattr(ivy, info.name) is getattr(ivy, info.target)


def test_agnostic_namespace_lists_every_core_function():
    for info in ivy.list_functions():
        assert info.name in ivy.__all__
        assert getattr(ivy, info.name) is getattr(ivy.core, info.name)


def test_dtypes_are_native_objects(backend, xp):
    native = __import__(NATIVE_MODULES[backend], fromlist=["_"])
    for name in ("float32", "float64", "int32", "int64", "uint8", "complex64"):
        assert getattr(xp, name) is getattr(native, name)
    assert ivy.float32 == "float32"


def test_backend_namespace_attributes(backend, xp):
    assert xp.backend == backend
    assert ivy.get_framework(f=xp) is xp


@pytest.mark.parametrize("statement", ["import ivy", "import ivy; ivy.sin; ivy.get_framework"])
def test_import_ivy_imports_no_framework(statement):
    code = (
        f"{statement}\nimport sys\n"
        "heavy = [m for m in ('torch', 'jax', 'tensorflow', 'jaxlib') if m in sys.modules]\n"
        "print(','.join(heavy))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_only_the_used_framework_is_imported():
    code = (
        "import numpy as np, ivy, sys\n"
        "ivy.sin(np.ones(2)); ivy.zeros(2, f='numpy')\n"
        "print(','.join(m for m in ('torch', 'jax', 'tensorflow') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""
