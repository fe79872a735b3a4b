"""Record the native operations that a call makes, with each framework's own interception
mechanism, so that they can be replayed (eagerly or compiled) without ivy around them.

No source is rewritten and nothing of ivy is patched: the call runs as it always does, and the
framework reports what it executes.

- torch: a ``TorchFunctionMode`` sees every torch function, Tensor method, operator and property
  read called from outside torch. The mode is switched off while its handler runs, so only the
  outermost calls are recorded (``torch.nn.functional.conv2d``, not what it calls).
- numpy: array inputs are passed as views of an ndarray subclass whose ``__array_function__`` and
  ``__array_ufunc__`` record numpy's public functions and ufuncs (operators included), and whose
  overrides of a few methods (``astype``, ``reshape``, ``__getitem__``, ...) record those. Calls on
  plain arrays (after ``np.asarray``, which drops the subclass) are not seen.
- jax: ``jax.make_jaxpr``; the top-level equations are primitives and the jitted ``jax.numpy``
  functions that are not inlined. Each equation is replayed as a ``jax.jit`` of that one equation,
  which is how ``jax.numpy`` functions run eagerly.
- tensorflow: an op callback (``tensorflow.python.framework.op_callbacks``, the hook of tf's
  debugger) sees every op executed eagerly with its inputs, attributes and outputs. Ops are
  replayed through ``tf.raw_ops`` (which also works inside ``tf.function``).

A :class:`Trace` holds the ops in order; array arguments are kept both as concrete values (for an
eager replay with the arguments bound in advance) and as references to the trace's inputs or to
earlier ops' outputs (for a replay as a function of the inputs, which a compiler can trace).
"""

from __future__ import annotations

import dataclasses
import inspect
from collections.abc import Callable
from typing import Any

__all__ = [
    "Op",
    "Trace",
    "Ref",
    "trace",
    "is_array",
    "flatten_arrays",
    "fill",
    "as_array_function",
    "leaf_paths",
    "program",
]


@dataclasses.dataclass(frozen=True)
class Ref:
    """An array argument: ``('in', i)`` the i-th array input, ``('op', j, k)`` the k-th array
    output of op j, ``('x', i)`` the i-th array that came from neither (a constant)."""

    key: tuple


@dataclasses.dataclass
class Op:
    name: str  # the native name: 'torch.sin', 'Tensor.__lt__', 'numpy.mean', 'jit:clip', 'Sin'
    match_name: str  # the bare name used to decide whether it implements a function
    call: Callable  # call(*args, **kwargs)
    args: tuple  # with array arguments as Ref
    kwargs: dict
    concrete_args: tuple
    concrete_kwargs: dict
    outputs: list  # the array outputs, flattened
    compute: bool  # False for metadata reads (shape, dtype, dim, ...): Python work
    graph_ok: bool = True  # call also works inside the framework's compiler
    out_paths: list | None = None  # index path of each array output in what ``call`` returns


@dataclasses.dataclass
class Trace:
    backend: str
    ops: list[Op]
    inputs: list  # concrete array inputs, flattened in the order of the call's arguments
    extras: list  # concrete arrays that came from neither the inputs nor a recorded op
    incomplete: bool = False  # an array of the result came from calls the recorder missed

    def names(self, ops: list[Op] | None = None) -> list[str]:
        return [op.name for op in (self.ops if ops is None else ops)]


# ----------------------------------------------------------------------------------------------
# Array leaves
# ----------------------------------------------------------------------------------------------

_ARRAY_TYPES: dict[str, tuple[type, ...]] = {}


def _array_types(backend: str) -> tuple[type, ...]:
    types_ = _ARRAY_TYPES.get(backend)
    if types_ is None:
        import numpy as np

        if backend == "numpy":
            types_ = (np.ndarray,)
        elif backend == "torch":
            import torch

            types_ = (torch.Tensor,)
        elif backend == "jax":
            import jax

            types_ = (jax.Array,)
        elif backend == "tensorflow":
            import tensorflow as tf

            types_ = (tf.Tensor, tf.Variable)
        else:
            raise ValueError(backend)
        _ARRAY_TYPES[backend] = types_
    return types_


def is_array(backend: str, obj: Any) -> bool:
    return isinstance(obj, _array_types(backend))


def flatten_arrays(backend: str, obj: Any) -> list:
    """Array leaves of ``obj``, searching lists, tuples (named ones too) and dicts, in order."""
    out: list = []
    types_ = _array_types(backend)

    def visit(o):
        if isinstance(o, types_):
            out.append(o)
        elif isinstance(o, (list, tuple)):
            for v in o:
                visit(v)
        elif isinstance(o, dict):
            for v in o.values():
                visit(v)

    visit(obj)
    return out


def leaf_paths(backend: str, obj: Any) -> list[tuple]:
    """Index paths of the array leaves of ``obj``, in the order of :func:`flatten_arrays`."""
    types_ = _array_types(backend)
    out: list[tuple] = []

    def visit(o, path):
        if isinstance(o, types_):
            out.append(path)
        elif isinstance(o, (list, tuple)):
            for i, v in enumerate(o):
                visit(v, (*path, i))
        elif isinstance(o, dict):
            for k, v in o.items():
                visit(v, (*path, k))

    visit(obj, ())
    return out


def _template(obj: Any, types_: tuple, lookup: Callable[[Any], Ref]) -> Any:
    """``obj`` with array leaves replaced by ``lookup(leaf)``."""
    if isinstance(obj, types_):
        return lookup(obj)
    if isinstance(obj, tuple) and not hasattr(obj, "_fields"):
        return tuple(_template(v, types_, lookup) for v in obj)
    if isinstance(obj, list):
        return [_template(v, types_, lookup) for v in obj]
    if isinstance(obj, dict):
        return {k: _template(v, types_, lookup) for k, v in obj.items()}
    return obj


def fill(template: Any, env: dict) -> Any:
    """The inverse of :func:`_template`: references replaced by ``env[ref.key]``."""
    if isinstance(template, Ref):
        return env[template.key]
    if isinstance(template, tuple):
        return tuple(fill(v, env) for v in template)
    if isinstance(template, list):
        return [fill(v, env) for v in template]
    if isinstance(template, dict):
        return {k: fill(v, env) for k, v in template.items()}
    return template


class _Registry:
    """Maps array objects (by identity, kept alive) to references."""

    def __init__(self, backend: str):
        self.types = _array_types(backend)
        self.refs: dict[int, Ref] = {}
        self.alive: list = []
        self.extras: list = []

    def add(self, obj: Any, key: tuple) -> None:
        self.refs[id(obj)] = Ref(key)
        self.alive.append(obj)

    def lookup(self, obj: Any, concrete: Any = None) -> Ref:
        ref = self.refs.get(id(obj))
        if ref is None:
            ref = Ref(("x", len(self.extras)))
            self.extras.append(obj if concrete is None else concrete)
            self.add(obj, ref.key)
        return ref

    def template(self, obj: Any) -> Any:
        return _template(obj, self.types, self.lookup)


# ----------------------------------------------------------------------------------------------
# torch
# ----------------------------------------------------------------------------------------------

_TORCH_METADATA = frozenset(
    "dim ndimension size numel nelement is_floating_point is_complex is_contiguous stride "
    "element_size get_device data_ptr storage_offset is_signed __len__ __bool__ __index__ "
    "__int__ __float__ __format__ __repr__ __hash__".split()
)


def _torch_names(func: Any) -> tuple[str, str]:
    name = getattr(func, "__name__", None) or type(func).__name__
    if name in ("__get__", "__set__"):  # a property of Tensor, e.g. Tensor.shape.__get__
        owner = getattr(func, "__self__", None)
        prop = getattr(owner, "__name__", "property")
        return f"Tensor.{prop}", "__get__"
    qual = getattr(func, "__qualname__", name)
    module = getattr(func, "__module__", None) or ""
    if qual.startswith(("Tensor.", "TensorBase.")) or module == "torch._tensor":
        return f"Tensor.{name}", name
    if module.startswith("torch.") and module not in ("torch._C._VariableFunctions",):
        return f"{module}.{name}", name
    return f"torch.{name}", name


def _trace_torch(fn, args, kwargs):
    import torch
    from torch.overrides import TorchFunctionMode

    reg = _Registry("torch")
    inputs = flatten_arrays("torch", (args, kwargs))
    for i, x in enumerate(inputs):
        reg.add(x, ("in", i))
    ops: list[Op] = []

    class Recorder(TorchFunctionMode):
        def __torch_function__(self, func, types, a=(), kw=None):
            kw = kw or {}
            out = func(*a, **kw)
            name, bare = _torch_names(func)
            outs = flatten_arrays("torch", out)
            tmpl_a, tmpl_k = reg.template(tuple(a)), reg.template(dict(kw))
            j = len(ops)
            for k, o in enumerate(outs):
                if id(o) not in reg.refs:
                    reg.add(o, ("op", j, k))
            compute = bare != "__get__" and bare not in _TORCH_METADATA
            op = Op(name, bare, func, tmpl_a, tmpl_k, tuple(a), dict(kw), outs, compute)
            op.out_paths = leaf_paths("torch", out)
            ops.append(op)
            return out

    with Recorder():
        result = fn(*args, **kwargs)
    del torch
    return Trace("torch", ops, inputs, reg.extras), result


# ----------------------------------------------------------------------------------------------
# numpy
# ----------------------------------------------------------------------------------------------

_NP_METHODS = (
    "astype reshape transpose copy ravel flatten squeeze swapaxes __getitem__ take repeat "
    "clip tolist item dot nonzero argsort sort cumsum any all"
).split()
_np_state: dict[str, Any] = {}


def _numpy_traced_class():
    cls = _np_state.get("cls")
    if cls is not None:
        return cls
    import numpy as np

    def unwrap(obj):
        if isinstance(obj, Traced):
            return obj.view(np.ndarray)
        if isinstance(obj, tuple) and not hasattr(obj, "_fields"):
            return tuple(unwrap(v) for v in obj)
        if isinstance(obj, list):
            return [unwrap(v) for v in obj]
        if isinstance(obj, dict):
            return {k: unwrap(v) for k, v in obj.items()}
        return obj

    def record(name, bare, call, a, kw, raw_out):
        rec = _np_state.get("recorder")
        if rec is None:
            return raw_out
        return rec(name, bare, call, a, kw, raw_out)

    class Traced(np.ndarray):
        def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
            call = ufunc if method == "__call__" else getattr(ufunc, method)
            raw = call(*unwrap(inputs), **unwrap(kwargs))
            name = ufunc.__name__ if method == "__call__" else f"{ufunc.__name__}.{method}"
            return record(f"numpy.{name}", name, call, inputs, kwargs, raw)

        def __array_function__(self, func, types, args, kwargs):
            raw = func(*unwrap(args), **unwrap(kwargs))
            return record(f"numpy.{func.__name__}", func.__name__, func, args, kwargs, raw)

    def method(name):
        base = getattr(np.ndarray, name)

        def traced(self, *a, **kw):
            raw = base(self.view(np.ndarray), *unwrap(a), **unwrap(kw))
            return record(f"ndarray.{name}", name, base, (self, *a), kw, raw)

        traced.__name__ = name
        return traced

    for name in _NP_METHODS:
        setattr(Traced, name, method(name))
    _np_state["cls"] = Traced
    _np_state["unwrap"] = unwrap
    return Traced


def _trace_numpy(fn, args, kwargs):
    import numpy as np

    traced_cls = _numpy_traced_class()
    unwrap = _np_state["unwrap"]
    reg = _Registry("numpy")
    inputs: list = []

    def wrap_inputs(obj):
        if isinstance(obj, np.ndarray):
            view = obj.view(traced_cls)
            reg.add(view, ("in", len(inputs)))
            inputs.append(obj)
            return view
        if isinstance(obj, tuple) and not hasattr(obj, "_fields"):
            return tuple(wrap_inputs(v) for v in obj)
        if isinstance(obj, list):
            return [wrap_inputs(v) for v in obj]
        if isinstance(obj, dict):
            return {k: wrap_inputs(v) for k, v in obj.items()}
        return obj

    wrapped_args, wrapped_kwargs = wrap_inputs(tuple(args)), wrap_inputs(dict(kwargs))
    ops: list[Op] = []

    def lookup(obj):
        return reg.lookup(obj, concrete=unwrap(obj))

    def recorder(name, bare, call, a, kw, raw_out):
        tmpl_a = _template(tuple(a), reg.types, lookup)
        tmpl_k = _template(dict(kw), reg.types, lookup)
        j = len(ops)
        raw_outs = flatten_arrays("numpy", raw_out)

        # Keys by position among the flattened outputs (identity, not equality).
        out = raw_out
        if isinstance(raw_out, np.ndarray):
            out = raw_out.view(traced_cls)
            reg.add(out, ("op", j, 0))
        elif isinstance(raw_out, (list, tuple)) and not hasattr(raw_out, "_fields"):
            pieces = []
            k = 0
            for o in raw_out:
                if isinstance(o, np.ndarray):
                    v = o.view(traced_cls)
                    reg.add(v, ("op", j, k))
                    k += 1
                    pieces.append(v)
                else:
                    pieces.append(o)
            out = type(raw_out)(pieces)
        concrete_a, concrete_k = unwrap(tuple(a)), unwrap(dict(kw))
        op = Op(name, bare, call, tmpl_a, tmpl_k, concrete_a, concrete_k, raw_outs, True)
        op.out_paths = leaf_paths("numpy", raw_out)
        ops.append(op)
        return out

    _np_state["recorder"] = recorder
    try:
        result = fn(*wrapped_args, **wrapped_kwargs)
    finally:
        _np_state["recorder"] = None
    # A plain ndarray in the result that no recorded op produced, or an op's argument that is
    # not a constant (0-d), was computed out of sight (after np.asarray dropped the subclass).
    missed = any(
        id(o) not in reg.refs and not isinstance(o, traced_cls) and o.size > 1
        for o in flatten_arrays("numpy", result)
    ) or any(np.ndim(x) > 0 for x in reg.extras)
    return Trace("numpy", ops, inputs, reg.extras, missed), unwrap(result)


# ----------------------------------------------------------------------------------------------
# jax
# ----------------------------------------------------------------------------------------------


def _jax_eqn_name(eqn) -> tuple[str, str]:
    prim = eqn.primitive.name
    if prim in ("pjit", "jit", "closed_call", "core_call", "custom_jvp_call", "custom_vjp_call"):
        name = eqn.params.get("name")
        if name is None:
            inner = eqn.params.get("call_jaxpr") or eqn.params.get("fun_jaxpr")
            name = getattr(getattr(inner, "jaxpr", inner), "debug_info", None)
            name = getattr(name, "func_name", None) or prim
        return f"{prim}:{name}", str(name)
    return prim, prim


_JAX_EQN_CACHE: dict = {}


def _jax_eqn_callable(eqn):
    """The equation alone, as a jitted function of its operands (as jax.numpy runs eagerly).
    Equations with the same primitive and parameters share one function (and so jax's cache of
    compiled executables)."""
    try:
        key = (eqn.primitive, tuple(sorted(eqn.params.items())))
        hash(key)
    except TypeError:
        key = None
    if key is not None and key in _JAX_EQN_CACHE:
        return _JAX_EQN_CACHE[key]
    fn = _jax_jit_eqn(eqn)
    if key is not None:
        _JAX_EQN_CACHE[key] = fn
    return fn


def _jax_jit_eqn(eqn):
    import jax

    prim = eqn.primitive

    def one(*invals):
        bind = prim.get_bind_params(eqn.params)  # jax < 0.5: (subfuns, params)
        subfuns, params = bind if isinstance(bind, tuple) else ((), bind)
        out = prim.bind(*subfuns, *invals, **params)
        return list(out) if prim.multiple_results else [out]

    one.__name__ = _jax_eqn_name(eqn)[1].replace(":", "_")
    return jax.jit(one)


def _trace_jax(fn, args, kwargs):
    import jax
    from jax.extend.core import Literal

    inputs = flatten_arrays("jax", (args, kwargs))
    types_ = _array_types("jax")
    counter = iter(range(len(inputs)))
    skeleton = _template((tuple(args), dict(kwargs)), types_, lambda _: Ref(("in", next(counter))))

    def as_function(*arrays):
        a, kw = fill(skeleton, {("in", i): v for i, v in enumerate(arrays)})
        return fn(*a, **kw)

    closed = jax.make_jaxpr(as_function)(*inputs)
    jaxpr = closed.jaxpr
    env: dict = {}
    refs: dict = {}
    extras: list = []
    for i, (v, x) in enumerate(zip(jaxpr.invars, inputs)):
        env[v], refs[v] = x, Ref(("in", i))
    for v, c in zip(jaxpr.constvars, closed.consts):
        env[v], refs[v] = c, Ref(("x", len(extras)))
        extras.append(c)
    ops: list[Op] = []
    for j, eqn in enumerate(jaxpr.eqns):
        call = _jax_eqn_callable(eqn)
        tmpl = tuple(v.val if isinstance(v, Literal) else refs[v] for v in eqn.invars)
        concrete = tuple(v.val if isinstance(v, Literal) else env[v] for v in eqn.invars)
        outs = call(*concrete)
        for k, (v, o) in enumerate(zip(eqn.outvars, outs)):
            env[v], refs[v] = o, Ref(("op", j, k))
        name, bare = _jax_eqn_name(eqn)
        op = Op(name, bare, call, tmpl, {}, concrete, {}, list(outs), True)
        op.out_paths = [(k,) for k in range(len(outs))]
        ops.append(op)
    result = fn(*args, **kwargs)
    return Trace("jax", ops, inputs, extras), result


# ----------------------------------------------------------------------------------------------
# tensorflow
# ----------------------------------------------------------------------------------------------


def _tf_attr_value(value):
    if isinstance(value, bytes):
        return value.decode()
    return value


def _tf_op_callable(op_type: str, n_inputs: int, attrs: tuple):
    """(call, graph_ok): ``call(*inputs)`` runs the op through ``tf.raw_ops`` (usable inside
    ``tf.function`` too), else through the eager executor only."""
    import tensorflow as tf
    from tensorflow.python.framework import op_def_registry

    attr_values = {_tf_attr_value(k): v for k, v in zip(attrs[::2], attrs[1::2])}
    raw = getattr(tf.raw_ops, op_type, None)
    op_def = op_def_registry.get(op_type)
    if raw is not None and op_def is not None:
        params = inspect.signature(raw).parameters
        groups: list[tuple[str, int | None]] = []
        for arg in op_def.input_arg:
            if arg.number_attr:
                groups.append((arg.name, int(attr_values[arg.number_attr])))
            elif arg.type_list_attr:
                groups.append((arg.name, len(attr_values[arg.type_list_attr])))
            else:
                groups.append((arg.name, None))
        inferred = {a.number_attr for a in op_def.input_arg} | {
            a.type_list_attr for a in op_def.input_arg
        }
        inferred |= {a.type_attr for a in op_def.input_arg}
        static = {
            k: _tf_attr_value(v)
            for k, v in attr_values.items()
            if k in params and k not in inferred
        }
        # Inputs by position: a raw op takes its inputs first, in the op definition's order
        # (its Python names may differ: Mean's reduction_indices is axis).
        names = list(params)[: len(groups)]

        def call(*inputs):
            kw = dict(static)
            i = 0
            for (_, count), pname in zip(groups, names):
                if count is None:
                    kw[pname] = inputs[i]
                    i += 1
                else:
                    kw[pname] = list(inputs[i : i + count])
                    i += count
            return raw(**kw)

        if sum(1 if c is None else c for _, c in groups) == n_inputs:
            call.__name__ = op_type
            return call, True

    return None, False


def _tf_eager_callable(op_type: str, attrs: tuple, n_outputs: int):
    """``call(*inputs)`` running the op through tf's eager executor (not usable in a graph)."""
    from tensorflow.python.eager import context, execute

    ctx = context.context()
    op_bytes = op_type.encode()

    def eager_call(*inputs):
        return execute.execute(op_bytes, n_outputs, list(inputs), attrs, ctx)

    eager_call.__name__ = op_type
    return eager_call


def _trace_tensorflow(fn, args, kwargs):
    from tensorflow.python.framework import op_callbacks

    reg = _Registry("tensorflow")
    inputs = flatten_arrays("tensorflow", (args, kwargs))
    for i, x in enumerate(inputs):
        reg.add(x, ("in", i))
    raw_log: list = []

    def callback(op_type, inputs_, attrs, outputs, op_name=None, graph=None):
        if graph is None:  # executed eagerly (not an op added to a graph being traced)
            raw_log.append((op_type, tuple(inputs_), tuple(attrs or ()), tuple(outputs or ())))
        return None

    op_callbacks.add_op_callback(callback)
    try:
        result = fn(*args, **kwargs)
    finally:
        op_callbacks.remove_op_callback(callback)
    ops: list[Op] = []
    for j, (op_type, ins, attrs, outs) in enumerate(raw_log):
        op_type = _tf_attr_value(op_type)
        call, graph_ok = _tf_op_callable(op_type, len(ins), attrs)
        if not graph_ok:
            call = _tf_eager_callable(op_type, attrs, len(outs))
        tmpl = reg.template(tuple(ins))
        for k, o in enumerate(outs):
            if id(o) not in reg.refs:
                reg.add(o, ("op", j, k))
        op = Op(op_type, op_type, call, tmpl, {}, tuple(ins), {}, list(outs), True, graph_ok)
        try:
            op.out_paths = leaf_paths("tensorflow", call(*ins))
        except Exception:
            call, graph_ok = _tf_eager_callable(op_type, attrs, len(outs)), False
            op.call, op.graph_ok = call, graph_ok
            op.out_paths = [(k,) for k in range(len(outs))]
        if len(op.out_paths) != len(outs):
            op.out_paths, op.graph_ok = [(k,) for k in range(len(outs))], False
            op.call = _tf_eager_callable(op_type, attrs, len(outs))
        ops.append(op)
    return Trace("tensorflow", ops, inputs, reg.extras), result


_TRACERS = {
    "torch": _trace_torch,
    "numpy": _trace_numpy,
    "jax": _trace_jax,
    "tensorflow": _trace_tensorflow,
}


def trace(backend: str, fn: Callable, args: tuple, kwargs: dict) -> tuple[Trace, Any]:
    """Run ``fn(*args, **kwargs)`` once, recording the native ops it executes on ``backend``.

    Returns:
        (the trace, the call's result).
    """
    return _TRACERS[backend](fn, tuple(args), dict(kwargs))


# ----------------------------------------------------------------------------------------------
# Replays
# ----------------------------------------------------------------------------------------------


def program(tr: Trace, ops: list[Op]) -> tuple[Callable, list]:
    """``(fn, arrays)``: ``fn(*arrays)`` runs ``ops`` (a subset of ``tr.ops``, in order) as
    straight-line Python generated for them, the same code as written by hand: each op reads the
    outputs of earlier ops of the subset as they are produced (so data stays as hot in the
    caches as in the original call). Everything the subset reads from outside it (the trace's
    inputs, constants, outputs of ops left out) is an argument, so that a compiler cannot fold
    it; non-array arguments are constants. ``fn`` returns the outputs that no later op of the
    subset reads."""
    index = {id(op): j for j, op in enumerate(tr.ops)}
    chosen = [index[id(op)] for op in ops]
    chosen_set = set(chosen)
    concrete: dict[tuple, Any] = {("in", i): x for i, x in enumerate(tr.inputs)}
    concrete.update({("x", i): x for i, x in enumerate(tr.extras)})
    for j, op in enumerate(tr.ops):
        concrete.update({("op", j, k): o for k, o in enumerate(op.outputs)})
    external: list[tuple] = []
    consumed: set[tuple] = set()
    consts: list = []
    names: dict[tuple, str] = {}

    def name_of(key: tuple) -> str:
        if key[0] == "op" and key[1] in chosen_set:
            consumed.add(key)
            return f"o{key[1]}_{key[2]}"
        if key not in names:
            names[key] = f"a{len(external)}"
            external.append(key)
        return names[key]

    def render(t: Any) -> str:
        if isinstance(t, Ref):
            return name_of(t.key)
        if isinstance(t, tuple):
            return "(" + "".join(render(v) + ", " for v in t) + ")"
        if isinstance(t, list):
            return "[" + ", ".join(render(v) for v in t) + "]"
        if isinstance(t, dict) and all(isinstance(k, str) for k in t):
            return "{" + ", ".join(f"{k!r}: {render(v)}" for k, v in t.items()) + "}"
        consts.append(t)
        return f"K[{len(consts) - 1}]"

    body: list[str] = []
    calls: dict[str, Callable] = {}
    for j in chosen:
        op = tr.ops[j]
        calls[f"C{j}"] = op.call
        parts = [render(v) for v in op.args]
        for k, v in op.kwargs.items():
            parts.append(f"{k}={render(v)}" if k.isidentifier() else f"**{{{k!r}: {render(v)}}}")
        body.append(f"t{j} = C{j}({', '.join(parts)})")
        for k, path in enumerate(op.out_paths or [()] * len(op.outputs)):
            body.append(f"o{j}_{k} = t{j}" + "".join(f"[{p!r}]" for p in path))
    sinks = [
        f"o{j}_{k}"
        for j in chosen
        for k in range(len(tr.ops[j].outputs))
        if ("op", j, k) not in consumed
    ]
    source = "def replay({}):\n    {}\n    return ({})\n".format(
        ", ".join(f"a{i}" for i in range(len(external))),
        "\n    ".join(body) or "pass",
        "".join(s + ", " for s in sinks),
    )
    scope: dict[str, Any] = {"K": consts, **calls}
    exec(compile(source, "<native replay>", "exec"), scope)
    fn = scope["replay"]
    fn.source = source
    return fn, [concrete[key] for key in external]


def as_array_function(backend: str, call: Callable, args: tuple, kwargs: dict) -> tuple:
    """``(g, arrays)`` with ``g(*arrays) == call(*args, **kwargs)``: the arrays become arguments
    (so that a compiler sees them as inputs) and everything else is closed over (static)."""
    arrays = flatten_arrays(backend, (args, kwargs))
    ids = {id(a): i for i, a in enumerate(arrays)}
    skeleton = _template((args, kwargs), _array_types(backend), lambda a: Ref(("in", ids[id(a)])))

    def g(*arrs):
        a, k = fill(skeleton, {("in", i): v for i, v in enumerate(arrs)})
        return call(*a, **k)

    return g, arrays


# ----------------------------------------------------------------------------------------------
# Public-API calls (jax and tensorflow), for a native call at the level a user writes
# ----------------------------------------------------------------------------------------------

_API_ROOTS = {
    "jax": ("jax.", "jaxlib."),
    "tensorflow": ("tensorflow.", "keras.", "tf_keras."),
    "numpy": ("numpy.",),
    "torch": ("torch.",),
}
_CODE_INDEX: dict | None = None


@dataclasses.dataclass
class ApiCall:
    name: str  # the function's __name__ (e.g. 'reduce_mean', 'zeros')
    qualname: str  # module and qualified name, for the report
    func: Callable
    args: tuple
    kwargs: dict
    output: Any = None


def _functions_of(code) -> list:
    """Function objects whose code is ``code`` (an index of every function, built once)."""
    global _CODE_INDEX
    import gc
    import types

    if _CODE_INDEX is None:
        _CODE_INDEX = {}
        for obj in gc.get_objects():
            if isinstance(obj, types.FunctionType):
                _CODE_INDEX.setdefault(obj.__code__, []).append(obj)
    funcs = _CODE_INDEX.get(code)
    if funcs is None:
        funcs = [
            o
            for o in gc.get_referrers(code)
            if isinstance(o, types.FunctionType) and o.__code__ is code
        ]
        _CODE_INDEX[code] = funcs
    return funcs


def _resolve(code, local: dict, globals_: dict):
    """The function that a 'call' event with this code and these locals was a call of. Copies of
    one function (the same code, globals and no closure, e.g. an op and its raw_ops entry) are
    interchangeable: every argument is passed explicitly."""
    funcs = [fn for fn in _functions_of(code) if fn.__globals__ is globals_]
    if len(funcs) > 1 and not code.co_freevars:
        return funcs[0]
    if len(funcs) > 1 and code.co_freevars:  # closures of one factory: match their cells
        same = []
        for fn in funcs:
            cells = fn.__closure__ or ()
            try:
                if all(
                    c.cell_contents is local.get(n)
                    for n, c in zip(code.co_freevars, cells)
                    if n in local
                ):
                    same.append(fn)
            except ValueError:  # an empty cell
                continue
        funcs = same
    return funcs[0] if len(funcs) == 1 else None


def _bound_arguments(code, local: dict) -> tuple[tuple, dict] | None:
    import inspect as _inspect

    names = code.co_varnames
    n_pos, n_kw = code.co_argcount, code.co_kwonlyargcount
    try:
        args = [local[n] for n in names[:n_pos]]
        kwargs = {n: local[n] for n in names[n_pos : n_pos + n_kw]}
        i = n_pos + n_kw
        if code.co_flags & _inspect.CO_VARARGS:
            args += list(local[names[i]])
            i += 1
        if code.co_flags & _inspect.CO_VARKEYWORDS:
            kwargs.update(local[names[i]])
    except KeyError:
        return None
    return tuple(args), kwargs


def api_calls(backend: str, fn: Callable, args: tuple, kwargs: dict) -> list[ApiCall] | None:
    """The framework's public Python functions that ivy code calls directly while running
    ``fn(*args, **kwargs)`` (``jnp.zeros``, ``tf.math.reduce_mean``), with their arguments and
    results, from ``sys.setprofile`` call events (nothing is patched). Functions implemented in C
    (jitted jax.numpy functions, tf ops' C wrappers) raise no Python call event and are not seen;
    None when a call could not be resolved to its function."""
    import sys

    roots = _API_ROOTS[backend]
    records: list[list] = []
    pending: dict[int, list] = {}

    def profile(frame, event, arg):
        if event == "call":
            back = frame.f_back
            if back is None or not back.f_globals.get("__name__", "").startswith("ivy"):
                return
            if not frame.f_globals.get("__name__", "").startswith(roots):
                return
            if frame.f_code.co_name.startswith("_"):  # dunders (hash, eq) and private helpers
                return
            record = [frame.f_code, dict(frame.f_locals), None, frame.f_globals]
            records.append(record)
            pending[id(frame)] = record
        elif event == "return" and id(frame) in pending:
            pending.pop(id(frame))[2] = arg  # the call's result

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        fn(*args, **kwargs)
    finally:
        sys.setprofile(previous)
    calls: list[ApiCall] = []
    for code, local, output, globals_ in records:
        func = _resolve(code, local, globals_)
        bound = _bound_arguments(code, local)
        if func is None or bound is None:
            return None
        module = getattr(func, "__module__", "") or ""
        calls.append(
            ApiCall(
                func.__name__,
                f"{module}.{func.__qualname__}",
                func,
                bound[0],
                bound[1],
                output,
            )
        )
    return calls
