"""Dtypes, devices, conversion and type promotion shared by the tensorflow backend's modules.

tensorflow never promotes dtypes and converts Python ints to int32. The backend keeps tf's own
functions on the fast path (same-dtype tensors, small Python scalars) and falls back to
:func:`promote` only when they refuse the inputs.
"""

from __future__ import annotations

import contextlib

import numpy as np
import tensorflow as tf

from ivy.backends._creation_args import check_python_data
from ivy.core import _dtype_rules as rules
from ivy.dtypes import DTYPE_NAMES

NATIVE_DTYPES = {name: tf.as_dtype(name) for name in DTYPE_NAMES}

TENSOR_TYPES = (tf.Tensor, tf.Variable)

# Types that tf's own binary functions convert correctly next to a tensor (see :func:`fast` for
# Python ints and floats, which are safe only for some values); numpy objects are not safe (tf
# casts them to the tensor's dtype silently: int64 * np.float64(2.5)). Tensor types are added as
# they are met.
with tf.init_scope():  # eager even when the backend is first loaded inside a tf.function
    EAGER_TENSOR = type(tf.constant(0.0))
FAST_TYPES = {EAGER_TENSOR, bool}
ARRAY_TYPES = (EAGER_TENSOR,)  # registered for inference when the backend loads

# Errors by which tf's functions refuse inputs (other dtypes, or a dtype without a kernel), eager
# and inside tf.function.
REFUSED = (
    TypeError,
    ValueError,
    tf.errors.InvalidArgumentError,
    tf.errors.NotFoundError,
)

_DEFAULT_OF_KIND = {0: tf.bool, 1: tf.int64, 2: tf.float32, 3: tf.complex64}
_DOWNCAST = {np.dtype(np.float64): np.float32, np.dtype(np.complex128): np.complex64}
_NULL_SCOPE = contextlib.nullcontext()
# Scalars, numpy's included, are weak: they take the dtype of the arrays beside them.
_SCALARS = (bool, int, float, complex, np.bool_, np.number)
_INTEGERS = (int, np.integer)


# ----------------------------------------------------------------------------------------------
# Dtypes
# ----------------------------------------------------------------------------------------------


def native_dtype(dtype) -> tf.DType | None:
    """tf dtype for a dtype name, tf dtype or numpy dtype; None stays None."""
    if dtype is None or isinstance(dtype, tf.DType):
        return dtype
    if isinstance(dtype, str):
        try:
            return NATIVE_DTYPES[dtype]
        except KeyError:
            raise TypeError(
                f"Unknown dtype {dtype!r}; use one of {', '.join(DTYPE_NAMES)}."
            ) from None
    try:
        return tf.as_dtype(np.dtype(dtype))
    except TypeError:
        raise TypeError(
            f"Unknown dtype {dtype!r}; use a name ({', '.join(DTYPE_NAMES)}), "
            f"a tf dtype or a numpy dtype."
        ) from None


def kind(dtype: tf.DType) -> int:
    """0 bool, 1 integer, 2 real floating, 3 complex."""
    if dtype == tf.bool:
        return 0
    if dtype.is_integer:
        return 1
    return 3 if dtype.is_complex else 2


def default_dtype_of_value(value) -> tf.DType:
    """The dtype a value gets by default: bool, int64, float32 or complex64 for a scalar, else
    its own."""
    if isinstance(value, _SCALARS):
        return _DEFAULT_OF_KIND[_scalar_kind(value)]
    if hasattr(value, "dtype"):
        return native_dtype(value.dtype)
    return to_tensor(value).dtype


def _scalar_kind(value) -> int:
    if isinstance(value, (bool, np.bool_)):
        return 0
    if isinstance(value, _INTEGERS):
        return 1
    return 2 if isinstance(value, (float, np.floating)) else 3


def promote_types(a: tf.DType, b: tf.DType) -> tf.DType:
    """Array API promotion of two dtypes, by ivy's one table (``ivy/core/_dtype_rules.py``); an
    integer or bool with a floating dtype gives the floating one."""
    if a == b:
        return a
    return NATIVE_DTYPES[rules.promote(a.name, b.name)]


def result_type(*values) -> tf.DType:
    """Result dtype of ``values`` (tensors, arrays, scalars) by ivy's rules
    (``ivy/core/_dtype_rules.py``): scalars take the dtype of the arrays unless they are of a
    higher kind (then the default dtype of their kind, complex keeping float64's precision)."""
    scalars = [
        v.item() if isinstance(v, np.generic) else v for v in values if isinstance(v, _SCALARS)
    ]
    arrays = [default_dtype_of_value(v).name for v in values if not isinstance(v, _SCALARS)]
    if not arrays:
        arrays = [_DEFAULT_OF_KIND[max(_scalar_kind(s) for s in scalars)].name]
    return NATIVE_DTYPES[rules.result_type(arrays, scalars)]


def fast(value) -> bool:
    """True when tf's own functions convert ``value`` correctly next to a tensor: tensors, bools,
    ints while small (tf wraps an out-of-range int silently: int8 * 300) and floats but zeros.
    tf caches the tensors it makes of Python scalars by value, and -0.0 == 0.0: whichever zero
    was made first comes back for both (``x * -0.0`` was ``x * 0.0`` once tf had made a 0.0)."""
    t = type(value)
    return t in FAST_TYPES or (t is int and 0 <= value < 128) or (t is float and value != 0.0)


def promote(*values) -> list:
    """``values`` as tensors of their common dtype (see :func:`result_type`)."""
    dtype = result_type(*values)
    out = []
    for v in values:
        if isinstance(v, TENSOR_TYPES):
            FAST_TYPES.add(type(v))
        out.append(tensor_of(v, dtype))
    return out


# ----------------------------------------------------------------------------------------------
# Conversion
# ----------------------------------------------------------------------------------------------


def has_own_dtype(obj) -> bool:
    """True when ``obj`` carries a dtype (an array, or a list of arrays), so it must be kept."""
    while isinstance(obj, (list, tuple)) and obj:
        obj = obj[0]
    return hasattr(obj, "dtype")


def to_tensor(obj, dtype: tf.DType | None = None):
    """``obj`` as a tensor: tensors keep their dtype, variables are read, Python floats become
    float32 and Python ints int64 (not tf's int32), numpy arrays keep their dtype."""
    if isinstance(obj, TENSOR_TYPES):
        if dtype is not None and obj.dtype is not dtype:
            return tf.cast(obj, dtype)
        return tf.convert_to_tensor(obj) if isinstance(obj, tf.Variable) else obj
    if not isinstance(obj, (np.ndarray, np.generic)) and hasattr(obj, "__dlpack__"):
        obj = _from_other_framework(obj)
    if has_own_dtype(obj):
        if isinstance(obj, np.generic):  # (as an array: tf caches scalars by value, -0.0 as 0.0)
            obj = np.asarray(obj)
        x = tf.convert_to_tensor(obj)  # numpy data, or a list of tensors (packed)
        return x if dtype is None or x.dtype is dtype else tf.cast(x, dtype)
    if dtype is not None:
        return tf.constant(np.asarray(obj, dtype=dtype.as_numpy_dtype))
    data = np.asarray(obj)
    check_python_data(data, "tensorflow")
    if data.dtype in _DOWNCAST:
        data = data.astype(_DOWNCAST[data.dtype])
    return tf.constant(data)


def tensor(x):
    """``x`` itself when it is a tensor or variable, else ``x`` converted by :func:`to_tensor`."""
    return x if isinstance(x, TENSOR_TYPES) else to_tensor(x)


def tensor_of(value, dtype: tf.DType):
    """``value`` (tensor, array, Python scalar) as a tensor of ``dtype``, converted exactly (a
    Python float goes to float64 without a float32 detour) and never wrapped around."""
    if isinstance(value, TENSOR_TYPES):
        return value if value.dtype is dtype else tf.cast(value, dtype)
    if (
        isinstance(value, _INTEGERS)
        and not isinstance(value, bool)
        and dtype.is_integer
        and not dtype.min <= value <= dtype.max
    ):
        raise OverflowError(
            f"Python integer {value} is out of bounds for {dtype.name}; use a wider dtype."
        )
    return to_tensor(value, dtype)


def _from_other_framework(obj):
    """A tensor of another framework as numpy data (detached first where it can be)."""
    detach = getattr(obj, "detach", None)
    if detach is not None:
        obj = detach().cpu()
    return np.asarray(obj)


def floating(x):
    """``x`` as a tensor, cast to the default float dtype (float32) unless it is floating."""
    x = tensor(x)
    dt = x.dtype
    if dt is tf.float32 or dt is tf.float64 or dt.is_floating or dt.is_complex:
        return x
    return tf.cast(x, tf.float32)


def normalize_axis(axis: int, ndim: int) -> int:
    if not -ndim <= axis < ndim:
        raise ValueError(f"axis {axis} is out of bounds for an array of {ndim} dimensions.")
    return axis % ndim


def static_rank(x, name: str) -> int:
    rank = x.shape.rank
    if rank is None:
        raise ValueError(
            f"{name} needs the number of dimensions of its input, which is unknown here (inside "
            f"tf.function); give the tf.function an input_signature with a known rank."
        )
    return rank


# ----------------------------------------------------------------------------------------------
# Devices
# ----------------------------------------------------------------------------------------------

_TF_DEVICES: dict[str, str] = {}
_IVY_DEVICES: dict[str, str] = {}


def tf_device(device: str) -> str:
    """tf device string ('/CPU:0', '/GPU:1') for an ivy device ('cpu', 'gpu:1')."""
    name = _TF_DEVICES.get(device)
    if name is not None:
        return name
    if not isinstance(device, str):
        raise _unavailable(device)
    if device.startswith("/"):  # tensorflow's own name ('/job:localhost/.../device:CPU:0')
        spec = tf.DeviceSpec.from_string(device)
        if spec.device_type is not None:
            device = f"{spec.device_type.lower()}:{spec.device_index or 0}"
    kind_, _, index = device.lower().lstrip("/").partition(":")
    if kind_ not in ("cpu", "gpu") or not (index or "0").isdigit():
        raise _unavailable(device)
    index = int(index or 0)
    if index >= len(tf.config.list_logical_devices(kind_.upper())):
        raise _unavailable(device)
    name = f"/{kind_.upper()}:{index}"
    _TF_DEVICES[device] = name
    return name


def _unavailable(device):
    from ivy import framework_handler as _fh
    from ivy.errors import unavailable_device

    return unavailable_device(device, _fh.load_backend("tensorflow"))


def devices() -> list[str]:
    """The devices tensorflow sees, by the names its tensors report as ``x.device``."""
    return [
        f"/job:localhost/replica:0/task:0/device:{d.device_type}:{d.name.rpartition(':')[2]}"
        for d in tf.config.list_logical_devices()
        if d.device_type in ("CPU", "GPU")
    ]


def placed(device):
    """Context manager placing new tensors on ``device`` (does nothing for None)."""
    return _NULL_SCOPE if device is None else tf.device(tf_device(device))


def ivy_device(tf_name: str) -> str:
    """'cpu' or 'gpu:N' for a tf device name such as '/job:localhost/.../device:GPU:0'."""
    dev = _IVY_DEVICES.get(tf_name)
    if dev is None:
        spec = tf.DeviceSpec.from_string(tf_name)
        if spec.device_type is None:  # a graph tensor not yet placed: tf's default choice
            gpu = bool(tf.config.list_logical_devices("GPU"))
            dev = "gpu:0" if gpu else "cpu"
        elif spec.device_type.upper() == "GPU":
            dev = f"gpu:{spec.device_index or 0}"
        else:
            dev = "cpu"
        _IVY_DEVICES[tf_name] = dev
    return dev


def as_inexact(x):
    """``x``, with an integer or boolean array converted to float32: how functions of real
    numbers treat such inputs on every backend (see ``ivy/backends/_reals.py``)."""
    x = tensor(x)
    return x if x.dtype.is_floating or x.dtype.is_complex else tf.cast(x, tf.float32)


def _of_reals(native, name: str):
    """tf's function of real numbers ``native``, which refuses integers and bools: those are
    computed in float32 (ivy's rule for every backend, ``ivy/backends/_reals.py``)."""

    def fn(x, /):
        try:
            return native(x)
        except REFUSED:
            x = tensor(x)
            if x.dtype.is_floating or x.dtype.is_complex:
                raise
            return native(tf.cast(x, tf.float32))

    fn.__name__ = fn.__qualname__ = name
    fn.__ivy_reals__ = True
    return fn


def _as_is(native, name: str):
    return native  # the shims of these convert integer inputs themselves


# ivy's rule for the functions of real numbers that the core declares (@dispatch(reals=True)),
# applied by the assembly.
REALS = {"unary": _of_reals, "binary": _as_is, "options": _as_is}


def set_precision(precision: str):
    """tensorflow's TF32 switch for float32 matrix products and convolutions (on by default
    in tf): off for ``'highest'``, on for ``'high'``; returns what restores the value found."""
    experimental = tf.config.experimental
    saved = experimental.tensor_float_32_execution_enabled()
    experimental.enable_tensor_float_32_execution(precision != "highest")
    return lambda: experimental.enable_tensor_float_32_execution(saved)
