"""Nests: nested dicts, lists and tuples of arrays (variables, gradients, optimizer states).

Built on `optree <https://github.com/metaopt/optree>`_. What counts as a node and what as a leaf:

- **nodes**: ``dict`` (also ``OrderedDict``, ``defaultdict``), ``list``, ``tuple``, named tuples
  and ``deque``; anything registered with optree in its default namespace;
- **leaves**: everything else, so arrays of every framework (numpy arrays, torch tensors and
  parameters, jax arrays and tracers, tf tensors and variables) and Python scalars are leaves
  with no registration needed;
- **None is not a leaf**: it is an empty node, kept in place by the maps (``fn`` is never called
  on it) and absent from the leaves, as in jax's pytrees. Use it for "no value here".

Dict leaves are visited in sorted key order (as jax does), so two dicts with the same keys in a
different insertion order line up; :func:`unflatten_nest` restores each dict's own key order.

Example:
    >>> v = {"w": np.ones((2, 3)), "b": np.zeros(3)}
    >>> ivy.nest.map_nest(lambda x: x * 2, v)["w"].sum()
    np.float64(12.0)
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from ivy.typing import Nest

try:
    import optree
except ModuleNotFoundError:  # a declared dependency: ``import ivy`` works without it, nests don't

    class _MissingOptree:
        def __getattr__(self, name: str) -> Any:
            raise ModuleNotFoundError(
                "ivy's nests (gradients, compile_fn, scan, stateful modules) need optree, a "
                "dependency of ivy: install it with `pip install optree` (or reinstall ivy)."
            )

    optree = _MissingOptree()

__all__ = [
    "map_nest",
    "multi_map_nest",
    "map_nest_with_path",
    "flatten_nest",
    "unflatten_nest",
    "nest_leaves",
    "nest_structure",
    "reduce_nest",
    "is_leaf_nest",
]

# optree's defaults, spelled out: None is an empty node, and the default registry namespace.
_OPTS = dict(none_is_leaf=False, namespace="")
_NO_INITIAL = object()


def map_nest(fn: Callable[[Any], Any], nest: Nest, /) -> Nest:
    """Apply ``fn`` to every leaf of ``nest``; the result has the structure of ``nest``.

    Args:
        fn: called on each leaf (never on None).
        nest: nested dicts, lists and tuples of arrays (or a single array).

    Returns:
        A new nest of the same structure holding ``fn(leaf)``.

    Example:
        >>> ivy.nest.map_nest(lambda x: x + 1, {"a": [1, 2], "b": None})
        {'a': [2, 3], 'b': None}
    """
    return optree.tree_map(fn, nest, **_OPTS)


def multi_map_nest(fn: Callable[..., Any], nest: Nest, /, *nests: Nest) -> Nest:
    """Apply ``fn`` leafwise to several nests of the same structure.

    ``fn`` receives one leaf from each nest, in order. The first nest decides the structure; the
    others must have the same structure (a ValueError names the mismatch otherwise).

    Args:
        fn: called as ``fn(leaf, *other_leaves)``.
        nest: the first nest.
        *nests: further nests with the structure of ``nest``.

    Returns:
        A nest of the structure of ``nest`` holding the results.

    Example:
        >>> v, g = {"w": 1.0}, {"w": 0.5}
        >>> ivy.nest.multi_map_nest(lambda w, dw: w - 0.1 * dw, v, g)
        {'w': 0.95}
    """
    return optree.tree_map(fn, nest, *nests, **_OPTS)


def map_nest_with_path(fn: Callable[[tuple, Any], Any], nest: Nest, /) -> Nest:
    """Like :func:`map_nest`, with the leaf's path (a tuple of keys and indices) as first argument.

    Example:
        >>> ivy.nest.map_nest_with_path(lambda p, x: p, {"a": [0, 0]})
        {'a': [('a', 0), ('a', 1)]}
    """
    return optree.tree_map_with_path(fn, nest, **_OPTS)


def flatten_nest(nest: Nest, /) -> tuple[list[Any], optree.PyTreeSpec]:
    """The leaves of ``nest`` in a list, and its structure (a treespec).

    Args:
        nest: nested dicts, lists and tuples.

    Returns:
        ``(leaves, treespec)``; :func:`unflatten_nest` inverts it.

    Example:
        >>> leaves, spec = ivy.nest.flatten_nest({"b": 2, "a": (1, None)})
        >>> leaves
        [1, 2]
    """
    return optree.tree_flatten(nest, **_OPTS)


def unflatten_nest(treespec: optree.PyTreeSpec, leaves: Iterable[Any], /) -> Nest:
    """Rebuild a nest of structure ``treespec`` from ``leaves`` (an iterable, in flatten order).

    Example:
        >>> leaves, spec = ivy.nest.flatten_nest({"a": [1, 2]})
        >>> ivy.nest.unflatten_nest(spec, [x * 10 for x in leaves])
        {'a': [10, 20]}
    """
    return optree.tree_unflatten(treespec, leaves)


def nest_leaves(nest: Nest, /) -> list[Any]:
    """The leaves of ``nest`` in flatten order (sorted dict keys, then list order).

    Example:
        >>> ivy.nest.nest_leaves({"b": 2, "a": [1, None]})
        [1, 2]
    """
    return optree.tree_leaves(nest, **_OPTS)


def nest_structure(nest: Nest, /) -> optree.PyTreeSpec:
    """The structure (treespec) of ``nest``; two nests line up when their structures are equal.

    Example:
        >>> ivy.nest.nest_structure({"a": 1}) == ivy.nest.nest_structure({"a": np.ones(3)})
        True
    """
    return optree.tree_structure(nest, **_OPTS)


def reduce_nest(fn: Callable[[Any, Any], Any], nest: Nest, /, initial: Any = _NO_INITIAL) -> Any:
    """Fold the leaves of ``nest`` with ``fn(accumulated, leaf)``, as ``functools.reduce`` does
    (starting from ``initial`` when given).

    Example:
        >>> ivy.nest.reduce_nest(lambda a, x: a + x, {"a": [1, 2], "b": 3})
        6
    """
    if initial is _NO_INITIAL:
        return optree.tree_reduce(fn, nest, **_OPTS)
    return optree.tree_reduce(fn, nest, initial, **_OPTS)


def is_leaf_nest(nest: Nest, /) -> bool:
    """True when ``nest`` is a single leaf (an array or scalar), False for a node or None.

    Example:
        >>> ivy.nest.is_leaf_nest(np.ones(2)), ivy.nest.is_leaf_nest([np.ones(2)])
        (True, False)
    """
    return optree.tree_is_leaf(nest, **_OPTS)
