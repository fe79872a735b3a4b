"""Framework selection: inference from every input type, f=, global setting, blocks, errors."""

from __future__ import annotations

import inspect
import types

import numpy as np
import pytest

import ivy
from ivy import framework_handler as fh
from tests.helpers import is_native, native, numpy_of


@pytest.fixture
def installed(request):
    """Skip a case whose framework is not among the backends under test."""

    def need(name):
        if name not in request.config.ivy_backends:
            pytest.skip(f"{name} is not among the tested backends")
        return __import__(name)

    return need


# ---------------------------------------------------------------------------------------------
# Inference from input types
# ---------------------------------------------------------------------------------------------


def _numpy_objects():
    return [np.ones(2), np.float32(1.0), np.int64(1)]


def _torch_objects():
    import torch

    return [torch.ones(2), torch.nn.Parameter(torch.ones(2))]


def _jax_objects():
    import jax.numpy as jnp

    return [jnp.ones(3)]


def _tensorflow_objects():
    import tensorflow as tf

    return [tf.constant([1.0]), tf.Variable([1.0])]


def _array_api_strict_objects():
    import array_api_strict

    return [array_api_strict.asarray([1.0])]


# Every kind of array object of each backend's library, which inference must recognise; the
# first is floating (a new backend adds its row).
ARRAY_OBJECTS = {
    "numpy": _numpy_objects,
    "torch": _torch_objects,
    "jax": _jax_objects,
    "tensorflow": _tensorflow_objects,
    "array_api_strict": _array_api_strict_objects,
}


def test_every_array_object_infers_its_backend(backend, xp):
    objects = ARRAY_OBJECTS[backend]()
    for obj in objects:
        assert ivy.get_framework(obj) is xp, type(obj)
    out = ivy.sin(objects[0])
    assert is_native(out, backend)
    np.testing.assert_allclose(numpy_of(out), np.sin(numpy_of(objects[0])), rtol=1e-6)


def _jax_transforms():
    import jax

    return [(jax.jit, np.sum), (jax.vmap, lambda s: np.sum(s, axis=-1)), (jax.grad, None)]


def _torch_transforms():
    import torch.func

    return [(torch.func.vmap, lambda s: np.sum(s, axis=-1)), (torch.func.grad, None)]


def _tensorflow_transforms():
    import tensorflow as tf

    return [(tf.function, np.sum)]


# The library's own transformations, under which its arrays are traced: inference must know the
# traced objects too. Each entry: (transformation, numpy reduction of sin(x) that the
# transformed ``sum(sin(x))`` gives; None: the gradient, cos(x)).
TRANSFORMS = {
    "torch": _torch_transforms,
    "jax": _jax_transforms,
    "tensorflow": _tensorflow_transforms,
}


def _recording(seen):
    """``sum(sin(y))``, recording the backend that ``y`` infers."""

    def fn(y):
        seen.append(ivy.get_framework(y).backend)
        return ivy.sum(ivy.sin(y))

    return fn


def test_inference_inside_the_librarys_transformations(backend, xp):
    if backend not in TRANSFORMS:
        pytest.skip(f"{backend}'s library has no transformations of functions")
    x = np.array([[0.5, 1.0, 1.5], [2.0, 2.5, 3.0]])
    for transform, reduction in TRANSFORMS[backend]():
        seen = []
        out = numpy_of(transform(_recording(seen))(native(x, backend)))
        expected = np.cos(x) if reduction is None else reduction(np.sin(x))
        np.testing.assert_allclose(out, expected, rtol=1e-6)
        assert seen and set(seen) == {backend}, (transform, seen)


def test_inference_searches_lists_tuples_and_dicts():
    x = np.ones(2)
    assert ivy.get_framework([1.0, (2, {"a": x})]) is ivy.numpy
    assert ivy.get_framework({"w": [x]}) is ivy.numpy
    out = ivy.concat([np.zeros(1), np.ones(1)])
    np.testing.assert_array_equal(out, [0.0, 1.0])


def test_python_scalars_beside_an_array_follow_the_array():
    out = ivy.add(1.0, np.array([1.0]))
    np.testing.assert_array_equal(out, [2.0])
    out = ivy.clip(np.array([-1.0, 2.0]), 0, 1)
    np.testing.assert_array_equal(out, [0.0, 1.0])


def test_numpy_scalar_yields_to_another_framework(diff_backend):
    out = ivy.multiply(getattr(ivy, diff_backend).ones(2), np.float32(3.0))
    assert is_native(out, diff_backend)


def test_type_cache_is_filled_once():
    ivy.sin(np.ones(1))
    assert fh._by_type[np.ndarray] is ivy.numpy
    assert fh._by_type_id[id(np.ndarray)] is ivy.numpy


def _torch_compile_counting(request, fn):
    """``fn`` under torch.compile (fullgraph), and the list of graphs it has compiled so far."""
    if "torch" not in request.config.ivy_backends:
        pytest.skip("torch is not among the tested backends")
    import torch

    graphs = []

    def counting_backend(graph_module, example_inputs):
        graphs.append(graph_module)
        return graph_module.forward

    return torch.compile(fn, backend=counting_backend, fullgraph=True), graphs


def test_types_seen_later_do_not_recompile_torch_compiled_inference(request):
    """torch.compile guards on what the traced Python read: inference (``get_framework``, as
    the applied libraries call it) reads its tables by a type's id, so a compiled function
    depends on its own input types only, not on every type that ivy meets later (it used to
    recompile on each new array type: a guard on the length of the type table)."""

    def fn(v, x):
        xp = ivy.get_framework(v, x)
        return xp.sum(xp.multiply(xp.sin(x), v["w"][0]), axis=0)

    compiled, graphs = _torch_compile_counting(request, fn)
    import torch

    x, w = torch.ones(3, 2, dtype=torch.float64), torch.full((2,), 0.5, dtype=torch.float64)
    ivy.get_framework(x), ivy.get_framework(np.ones(1))  # loaded outside the compiled function
    compiled({"w": [w]}, x)
    assert len(graphs) == 1

    class NewTensor(torch.Tensor):
        pass

    class NewNeutral:
        pass

    ivy.get_framework(torch.ones(2).as_subclass(NewTensor))  # a new array type
    ivy.get_framework(x, NewNeutral(), np.float16(1.0))  # a new neutral and a new weak type
    out = compiled({"w": [w]}, x)
    assert len(graphs) == 1  # not compiled again
    np.testing.assert_allclose(numpy_of(out), 0.5 * np.sin(1.0) * np.ones(2) * 3)


def test_dispatchers_under_torch_compile_do_not_recompile_for_numpy_or_parameters(request):
    """The generated dispatchers (``ivy.add(x, y)``) read the type table directly (an ``id()``
    would cost every inferred call), so torch.compile guards on its size. Each backend registers
    its array types, and numpy's, when it loads: a numpy array or a Parameter met after
    compiling adds nothing to the table and compiles nothing again."""

    def fn(x, y):
        return ivy.multiply(ivy.sin(ivy.add(x, y)), 2.0)

    compiled, graphs = _torch_compile_counting(request, fn)
    import torch

    x, y = torch.ones(3, dtype=torch.float64), torch.full((3,), 0.5, dtype=torch.float64)
    fn(x, y)  # the backend loaded outside the compiled function
    compiled(x, y)
    assert len(graphs) == 1
    size = len(fh._by_type)
    ivy.add(np.ones(2), np.ones(2))
    ivy.add(torch.nn.Parameter(torch.ones(3, dtype=torch.float64)), y)
    assert len(fh._by_type) == size
    out = compiled(x, y)
    assert len(graphs) == 1  # not compiled again
    np.testing.assert_allclose(numpy_of(out), 2 * np.sin(1.5) * np.ones(3))


# ---------------------------------------------------------------------------------------------
# Explicit f
# ---------------------------------------------------------------------------------------------


# The other names a backend answers to.
ALIASES = {"np": "numpy", "pytorch": "torch", "tf": "tensorflow"}


def test_f_as_name_namespace_and_alias(backend, xp):
    x = np.array([-1.0, 2.0])
    for f in (backend, xp):
        out = ivy.clip(x, 0, 1, f=f)
        assert ivy.get_framework(out) is xp
        np.testing.assert_allclose(ivy.to_numpy(out), [0.0, 1.0])
    assert ivy.get_framework(f=backend) is xp
    for alias in [a for a, name in ALIASES.items() if name == backend]:
        assert ivy.get_framework(f=alias) is xp


def test_f_wins_over_the_global_framework(backend, xp):
    with ivy.set_framework("numpy"):
        assert ivy.get_framework(f=backend) is xp
        out = ivy.core.zeros(2, f=backend)
        assert ivy.framework_of_type(type(out)) == backend


def test_compositions_take_f_while_a_framework_is_set(backend, xp):
    """Under a global framework ``ivy.compiled_scan`` is that backend's composition; an
    explicit ``f`` still chooses the backend (the same one, or another one)."""

    def step(c, x):
        return c + x, c

    xs = np.arange(3.0, dtype=np.float32)
    for outer in ("numpy", backend):
        with ivy.set_framework(outer):
            run = ivy.compiled_scan(step, f=backend)
            carry, ys = run(xp.asarray(np.float32(0.0)), xp.asarray(xs))
            assert ivy.framework_of_type(type(carry)) == backend
            np.testing.assert_allclose(ivy.to_numpy(ys), [0.0, 0.0, 1.0])
            assert "f" in inspect.signature(ivy.compiled_scan).parameters


# ---------------------------------------------------------------------------------------------
# Global setting and blocks
# ---------------------------------------------------------------------------------------------


def test_set_framework_binds_backend_functions_into_ivy(backend, xp):
    agnostic_sin = ivy.sin
    ivy.set_framework(backend)
    try:
        assert ivy.sin is xp.sin
        assert ivy.add is xp.add
        assert ivy.float32 is xp.float32
        assert ivy.current_framework() is xp
        assert ivy.get_framework() is xp
    finally:
        ivy.unset_framework()
    assert ivy.sin is agnostic_sin
    assert ivy.float32 == "float32"
    assert ivy.current_framework() is None


def test_global_framework_wins_over_inference_for_held_references(backend, xp):
    agnostic_zeros_like = ivy.zeros_like  # held before the framework is set
    with ivy.set_framework(backend):
        out = agnostic_zeros_like(xp.ones(2))
        assert ivy.get_framework(out) is xp
        assert ivy.get_framework(np.ones(2)) is xp


def test_blocks_nest_and_restore(request):
    if len(request.config.ivy_backends) < 3:
        pytest.skip("needs three backends under test")
    first, second, third = (getattr(ivy, b) for b in request.config.ivy_backends[-3:])
    with ivy.set_framework(first.backend) as outer:
        assert outer is first
        assert ivy.sin is first.sin
        with second.use as inner:
            assert inner is second
            assert ivy.sin is second.sin
            with third.use:
                assert ivy.sin is third.sin
            assert ivy.sin is second.sin
        assert ivy.sin is first.sin
    assert ivy.current_framework() is None
    assert ivy.sin is ivy.core.sin


def test_use_is_reusable_and_reentrant():
    use = ivy.numpy.use
    with use:
        with use:
            assert ivy.current_framework() is ivy.numpy
        assert ivy.current_framework() is ivy.numpy
    assert ivy.current_framework() is None


def test_exception_inside_a_block_restores():
    with pytest.raises(RuntimeError):
        with ivy.set_framework("numpy"):
            raise RuntimeError("boom")
    assert ivy.current_framework() is None
    assert ivy.sin is ivy.core.sin
    with pytest.raises(RuntimeError):
        with ivy.numpy.use:
            ivy.set_framework("numpy")  # left set inside the block: the block still restores
            raise RuntimeError("boom")
    assert ivy.current_framework() is None


def test_set_and_unset_as_statements_stack():
    ivy.set_framework("numpy")
    ivy.set_framework(ivy.numpy)
    ivy.unset_framework()
    assert ivy.current_framework() is ivy.numpy
    ivy.unset_framework()
    assert ivy.current_framework() is None
    ivy.unset_framework()  # a no-op when nothing is set
    assert ivy.current_framework() is None


# ---------------------------------------------------------------------------------------------
# Errors
# ---------------------------------------------------------------------------------------------


def test_unknown_framework_name():
    with pytest.raises(ivy.UnknownFrameworkError, match="Choose one of numpy, torch, jax"):
        ivy.zeros(2, f="mxnet")
    with pytest.raises(ivy.UnknownFrameworkError):
        ivy.set_framework("caffe")
    with pytest.raises(ivy.UnknownFrameworkError, match="not a framework"):
        ivy.zeros(2, f=types.ModuleType("numpy"))


def test_native_package_names_the_frameworks_own_module_and_imports_nothing():
    import sys

    before = set(sys.modules)
    assert fh.native_package("tf") == "tensorflow"
    assert fh.native_package("Torch") == "torch"
    assert fh.native_package("numpy") == "numpy"
    assert fh.native_package("jax") == "jax"
    assert set(sys.modules) == before
    with pytest.raises(ivy.UnknownFrameworkError, match="Choose one of"):
        fh.native_package("caffe")


def test_framework_not_installed_names_the_extra(monkeypatch):
    spec = fh._BackendSpec("ivy.backends.paddle", "paddle_is_not_installed_here", "paddle")
    monkeypatch.setitem(fh._BACKENDS, "paddle", spec)
    with pytest.raises(ivy.FrameworkNotInstalledError, match=r"pip install '\.\[paddle\]'"):
        ivy.zeros(2, f="paddle")
    assert issubclass(ivy.FrameworkNotInstalledError, ImportError)


def test_arrays_of_two_frameworks(diff_backend):
    xp = getattr(ivy, diff_backend)
    with pytest.raises(ivy.MixedFrameworksError, match="two frameworks"):
        ivy.add(np.ones(2), xp.ones(2))
    with pytest.raises(ivy.MixedFrameworksError):
        ivy.concat([xp.ones(2), np.ones(2)])
    with pytest.raises(ivy.MixedFrameworksError):
        ivy.get_framework({"a": np.ones(1), "b": [xp.ones(1)]})


def test_python_scalars_and_lists_need_a_framework():
    for call in (lambda: ivy.sin(1.0), lambda: ivy.array([1.0, 2.0]), lambda: ivy.zeros(3)):
        with pytest.raises(ivy.NoFrameworkError, match="set_framework"):
            call()
    with pytest.raises(ivy.NoFrameworkError, match="f='torch'"):
        ivy.get_framework(1.0, [2, 3])
    with ivy.set_framework("numpy"):
        assert ivy.array([1.0, 2.0]).dtype == np.float32


# ---------------------------------------------------------------------------------------------
# The paper's snippets, verbatim
# ---------------------------------------------------------------------------------------------


def test_paper_snippets(installed):
    tf = installed("tensorflow")
    torch = installed("torch")
    x = ivy.clip(np.array([-1.0, 2.0]), 0, 1, f="tensorflow")
    np.testing.assert_array_equal(x.numpy(), [0.0, 1.0])
    x = ivy.clip(np.array([-1.0, 2.0]), 0, 1, f=ivy.torch)
    assert isinstance(x, torch.Tensor)
    np.testing.assert_array_equal(x.numpy(), [0.0, 1.0])
    x = ivy.clip(tf.constant([-1, 2.0]), 0, 1)
    np.testing.assert_array_equal(x.numpy(), [0.0, 1.0])
    x = ivy.clip(torch.tensor([-1, 2.0]), 0, 1)
    np.testing.assert_array_equal(x.numpy(), [0.0, 1.0])
    ivy.set_framework("tensorflow")
    x = ivy.array([-1, 2.0])
    x = ivy.clip(x, 0, 1)
    ivy.unset_framework()
    assert isinstance(x, tf.Tensor)
    np.testing.assert_array_equal(x.numpy(), [0.0, 1.0])
