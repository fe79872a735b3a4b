"""Hypothesis strategies shared by the core tests.

Arrays are drawn with ``hypothesis.extra.array_api`` strategies built from ``ivy.numpy`` (an
Array API namespace), so the draws carry numpy arrays the tests use directly as float64
references and convert to each backend with the framework's own functions. Strategies built from
every other backend namespace are exercised in ``test_array_api_strategies.py``.
"""

from __future__ import annotations

import math
import warnings
from functools import cache

from hypothesis import strategies as st
from hypothesis.extra.array_api import make_strategies_namespace

import ivy

FLOAT_DTYPES = ("float32", "float64")
INT_DTYPES = ("int32", "int64")

# Edge values every elementwise function is tried on (halves exercise round-half-to-even).
SPECIALS = (0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1.5, 2.5, -2.5, math.inf, -math.inf, math.nan)

# Shapes from 0-d to 3-d, empty ones included. A short fixed menu rather than arbitrary shapes:
# jax compiles every operation once per shape and dtype, and few shapes keep the suite fast.
SHAPE_LIST = [(), (0,), (5,), (2, 3), (2, 1, 3), (3, 0)]
NONEMPTY_SHAPE_LIST = [(), (1,), (5,), (2, 3), (2, 1, 3)]
SHAPES = st.sampled_from(SHAPE_LIST)
NONEMPTY_SHAPES = st.sampled_from(NONEMPTY_SHAPE_LIST)
# Pairs of shapes that broadcast together.
BROADCAST_PAIRS = st.sampled_from(
    [
        ((), ()),
        ((2, 3), ()),
        ((), (5,)),
        ((2, 3), (2, 3)),
        ((2, 1), (1, 3)),
        ((0,), (1,)),
        ((2, 1, 3), (3,)),
    ]
)


def reals(dtype: str, lo: float, hi: float, specials: bool = True) -> st.SearchStrategy:
    """Floats of ``dtype`` in ``[lo, hi]`` (no subnormals, which some CPUs flush to zero),
    mixed with :data:`SPECIALS` when ``specials``."""
    width = 32 if dtype == "float32" else 64
    elements = st.floats(lo, hi, width=width, allow_subnormal=False)
    return elements | st.sampled_from(SPECIALS) if specials else elements


def quarters(lo: int, hi: int) -> st.SearchStrategy:
    """Multiples of 1/4 in ``[lo, hi]``: exact in every float dtype, with many ties."""
    return st.integers(4 * lo, 4 * hi).map(lambda i: i / 4)


@cache
def array_api_strategies():
    """``hypothesis.extra.array_api`` strategies over the ``ivy.numpy`` namespace."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # hypothesis notes the namespace is not one it knows
        return make_strategies_namespace(ivy.numpy, api_version="2023.12")


def arrays(dtype: str, elements: st.SearchStrategy, shape=SHAPES) -> st.SearchStrategy:
    """numpy arrays of ``dtype`` with ``elements``, of a shape drawn from ``shape`` (a shape or a
    strategy of shapes), drawn by the Array API ``arrays`` strategy."""
    return array_api_strategies().arrays(dtype, shape, elements=elements)


def axis_arguments(ndim: int, tuples: bool = True) -> st.SearchStrategy:
    """Valid ``axis`` arguments for an array of ``ndim`` axes: None, an int (possibly
    negative) or, with ``tuples``, a tuple of distinct axes."""
    if ndim == 0:
        return st.none()
    one = st.integers(-ndim, ndim - 1)
    options = [st.none(), one]
    if tuples:
        distinct = st.lists(st.integers(0, ndim - 1), min_size=1, max_size=ndim, unique=True)
        options.append(
            distinct.flatmap(lambda ax: st.tuples(*[st.sampled_from((a, a - ndim)) for a in ax]))
        )
    return st.one_of(*options)


def normalize_axis(axis, ndim: int):
    """``axis`` (None, int or tuple) as a tuple of non-negative axes."""
    if axis is None:
        return tuple(range(ndim))
    if isinstance(axis, int):
        axis = (axis,)
    return tuple(a % ndim for a in axis)
