"""Data types. Dtypes may be given as strings ('float32') or as the framework's objects.

``can_cast``, ``finfo``, ``iinfo``, ``isdtype`` and ``result_type`` take dtypes rather than
arrays. The framework comes from ``f``, else the global framework, else the arrays and native
dtype objects among the arguments (``torch.float32`` picks torch, ``np.float32`` numpy); with none
of these (dtype names, Python scalars) they answer without any framework, by ivy's own rules
(``ivy.core._dtype_rules``): ``ivy.finfo('float32').eps`` needs no framework installed.

Type promotion follows the Array API's table within a kind. Across kinds, which the standard
leaves open, each backend answers as its own functions compute (numpy: int64 with float32 gives
float64; torch, jax and tensorflow: float32), and the framework-independent rules as torch does.
"""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core import _dtype_rules as _rules
from ivy.core._by_hand import by_hand, framework_or_none
from ivy.core._dispatch import alias, dispatch
from ivy.core._dtype_rules import FInfo, IInfo
from ivy.typing import Array, Device, Dtype, Framework, Scalar

__all__ = [
    "astype",
    "can_cast",
    "cast",
    "dtype_name",
    "enable_float64",
    "finfo",
    "iinfo",
    "isdtype",
    "result_type",
]

_SCALARS = (bool, int, float, complex)


@dispatch
def astype(
    x: Array,
    dtype: Dtype,
    /,
    *,
    copy: bool = True,
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """``x`` converted to ``dtype`` (and moved to ``device`` if given). Example:
    ``ivy.astype(x, 'float64')``.

    Floats that an integer dtype cannot hold (NaN, infinities, values beyond its range) have
    no integer value: the Array API leaves the result undefined, and the backends differ (numpy,
    torch and tensorflow give the dtype's minimum, jax saturates). ivy does not check (that would
    cost a pass over every cast, and compiled code has no values to check): clean such values
    first (``ivy.nan_to_num``, ``ivy.clip``) where they can occur."""


cast = alias("cast", astype)


@by_hand
def can_cast(from_: Dtype | Array, to: Dtype, /, *, f: Framework = None) -> bool:
    """Whether ``from_`` (a dtype or an array) promotes with dtype ``to`` to ``to``, i.e. casts
    to it by the type promotion rules.

    Example: ``ivy.can_cast('int8', 'int16')`` -> True; ``ivy.can_cast('float64', 'float32')``
    -> False.
    """
    ns = framework_or_none(from_, to, f=f)
    if ns is None:
        return _rules.can_cast(_rules.name_of(from_), _rules.name_of(to))
    return ns.can_cast(from_, to)


@by_hand
def finfo(type: Dtype | Array, /, *, f: Framework = None) -> FInfo:  # noqa: A002 - the Array API name
    """Machine limits of a floating dtype (or of an array's dtype; complex: of its real part).

    Returns:
        An object with ``bits``, ``eps``, ``max``, ``min``, ``smallest_normal`` (Python numbers)
        and ``dtype``: the framework's dtype, or the dtype's name when no framework is involved.

    Example: ``ivy.finfo('float32').eps`` -> 1.1920928955078125e-07.
    """
    ns = framework_or_none(type, f=f)
    if ns is None:
        return _rules.finfo(_rules.name_of(type))
    return ns.finfo(type)


@by_hand
def iinfo(type: Dtype | Array, /, *, f: Framework = None) -> IInfo:  # noqa: A002 - the Array API name
    """Machine limits of an integer dtype (or of an array's dtype).

    Returns:
        An object with ``bits``, ``max``, ``min`` (Python ints) and ``dtype``: the framework's
        dtype, or the dtype's name when no framework is involved.

    Example: ``ivy.iinfo('int8').min`` -> -128.
    """
    ns = framework_or_none(type, f=f)
    if ns is None:
        return _rules.iinfo(_rules.name_of(type))
    return ns.iinfo(type)


@by_hand
def isdtype(
    dtype: Dtype, kind: Dtype | str | tuple[Dtype | str, ...], *, f: Framework = None
) -> bool:
    """Whether ``dtype`` is of ``kind``: a dtype, one of ``'bool'``, ``'signed integer'``,
    ``'unsigned integer'``, ``'integral'``, ``'real floating'``, ``'complex floating'``,
    ``'numeric'``, or a tuple of these (any of them).

    Example: ``ivy.isdtype('float32', ('integral', 'real floating'))`` -> True.
    """
    ns = framework_or_none(dtype, kind, f=f)
    if ns is None:
        return _rules.isdtype(_rules.name_of(dtype), kind)
    return ns.isdtype(dtype, kind)


@by_hand
def result_type(*arrays_and_dtypes: Array | Dtype | Scalar, f: Framework = None) -> Dtype:
    """The dtype that an operation on ``arrays_and_dtypes`` (arrays, dtypes and Python scalars;
    at least one array or dtype) gives by the type promotion rules.

    Example: ``ivy.result_type('int8', 'uint8')`` -> ``'int16'``; with a framework, its dtype.
    """
    ns = framework_or_none(*arrays_and_dtypes, f=f)
    if ns is None:
        names = [_rules.name_of(a) for a in arrays_and_dtypes if not isinstance(a, _SCALARS)]
        scalars = [a for a in arrays_and_dtypes if isinstance(a, _SCALARS)]
        return _rules.result_type(names, scalars)
    if f is not None:  # arrays of another framework: converted, as every function does
        arrays_and_dtypes = [
            _fh.to_namespace(ns, a) if hasattr(a, "shape") else a for a in arrays_and_dtypes
        ]
    return ns.result_type(*arrays_and_dtypes)


@by_hand
def dtype_name(dtype: Dtype | Array, /, *, f: Framework = None) -> str:
    """The ivy name (``'float32'``) of a dtype: a framework's dtype object (``torch.float32``,
    ``tf.int8``, ``np.dtype('uint8')``, ``np.float64``), a name, or an array's dtype.

    Applied code compares dtypes by this name rather than by a framework's objects.

    Args:
        dtype: the dtype, its name, or an array.
        f: framework name or namespace; by default the dtype's own framework.

    Returns:
        One of ``ivy.dtypes.DTYPE_NAMES``; a TypeError for anything else.

    Example:
        >>> ivy.dtype_name(torch.float64), ivy.dtype_name(np.ones(2, np.int8))
        ('float64', 'int8')
    """
    ns = framework_or_none(dtype, f=f)
    if ns is None:
        return _rules.name_of(dtype)
    return ns.dtype_name(dtype)


@dispatch()
def enable_float64(*, f: Framework = None) -> None:
    """Make 64-bit dtypes (float64, int64, complex128) work on the framework, process-wide.

    jax: switches ``jax_enable_x64`` on (do it before making arrays: arrays made before keep
    their 32-bit dtypes); numpy, torch and tensorflow hold 64-bit types anyway (nothing to do).
    A backend registered with ``float64=False`` raises :class:`ivy.errors.UnsupportedError`.
    Whether a backend can do it is its capability ``float64``.

    Args:
        f: framework name or namespace (or the global framework).

    Example:
        >>> ivy.enable_float64(f="jax")
        >>> ivy.asarray([1.0], dtype="float64", f="jax").dtype
        dtype('float64')
    """
