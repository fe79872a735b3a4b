"""ivy.nest: map, multi-map, flatten and unflatten over nested dicts, lists and tuples."""

from __future__ import annotations

import collections

import numpy as np
import pytest

import ivy
from ivy import nest
from tests.helpers import is_native, native, numpy_of


def _sample(backend):
    """A nest with every kind of node, and arrays of ``backend`` as leaves."""
    a = native(np.arange(3.0), backend)
    b = native(np.ones((2, 2)), backend)
    c = native(np.full(2, 5.0), backend)
    return {"z": [a, (b, None)], "a": {"c": c, "d": ()}}, [c, a, b]


def test_arrays_of_every_backend_are_leaves(backend):
    n, expected = _sample(backend)
    leaves, spec = nest.flatten_nest(n)
    assert len(leaves) == 3 and spec.num_leaves == 3
    # sorted dict keys: "a" before "z"; then list and tuple order
    for got, want in zip(leaves, expected):
        assert got is want
    assert nest.nest_leaves(n) == leaves
    assert nest.is_leaf_nest(expected[0])


def test_unflatten_inverts_flatten_and_keeps_key_order(backend):
    n, _ = _sample(backend)
    leaves, spec = nest.flatten_nest(n)
    back = nest.unflatten_nest(spec, leaves)
    assert list(back) == ["z", "a"]  # each dict's own insertion order
    assert type(back["z"]) is list and type(back["z"][1]) is tuple
    assert back["z"][1][1] is None and back["a"]["d"] == ()
    assert nest.nest_structure(back) == spec
    with pytest.raises(ValueError):
        nest.unflatten_nest(spec, leaves[:2])


def test_map_nest_keeps_structure_and_none(backend):
    n, _ = _sample(backend)
    xp = getattr(ivy, backend)
    doubled = nest.map_nest(lambda x: xp.multiply(x, 2), n)
    assert doubled["z"][1][1] is None and doubled["a"]["d"] == ()
    assert is_native(doubled["a"]["c"], backend)
    np.testing.assert_array_equal(numpy_of(doubled["z"][0]), [0.0, 2.0, 4.0])
    np.testing.assert_array_equal(numpy_of(doubled["z"][1][0]), np.full((2, 2), 2.0))
    assert nest.nest_structure(doubled) == nest.nest_structure(n)


def test_multi_map_nest_is_leafwise(backend):
    n, _ = _sample(backend)
    xp = getattr(ivy, backend)
    grads = nest.map_nest(xp.ones_like, n)
    updated = nest.multi_map_nest(lambda p, g: p - 0.5 * g, n, grads)
    np.testing.assert_array_equal(numpy_of(updated["a"]["c"]), [4.5, 4.5])
    np.testing.assert_array_equal(numpy_of(updated["z"][0]), [-0.5, 0.5, 1.5])
    three = nest.multi_map_nest(lambda a, b, c: a + b + c, [1, (2,)], [10, (20,)], [100, (200,)])
    assert three == [111, (222,)]


def test_multi_map_nest_rejects_mismatched_structures():
    with pytest.raises(ValueError, match="key"):
        nest.multi_map_nest(lambda a, b: a, {"a": 1}, {"b": 1})
    with pytest.raises(ValueError):
        nest.multi_map_nest(lambda a, b: a, [1, 2], [1])


def test_none_is_an_empty_node_not_a_leaf():
    calls = []
    out = nest.map_nest(lambda x: calls.append(x) or x, {"a": None, "b": [None, 1]})
    assert calls == [1]
    assert out == {"a": None, "b": [None, 1]}
    assert nest.nest_leaves(None) == []
    assert not nest.is_leaf_nest(None)


def test_dicts_with_different_insertion_orders_line_up():
    a = {"x": 1, "y": 2}
    b = {"y": 20, "x": 10}
    assert nest.multi_map_nest(lambda p, q: p + q, a, b) == {"x": 11, "y": 22}


def test_named_tuples_ordered_dicts_and_scalars():
    Pair = collections.namedtuple("Pair", "first second")
    n = collections.OrderedDict(b=Pair(1, 2.0), a=[3])
    out = nest.map_nest(lambda x: x * 10, n)
    assert type(out) is collections.OrderedDict and list(out) == ["b", "a"]
    assert out["b"] == Pair(10, 20.0) and type(out["b"]) is Pair
    assert nest.map_nest(lambda x: x + 1, 5) == 6  # a single leaf is a nest too


def test_map_nest_with_path_and_reduce():
    paths = nest.map_nest_with_path(lambda p, x: p, {"w": [0, 0], "b": 0})
    assert paths == {"w": [("w", 0), ("w", 1)], "b": ("b",)}
    assert nest.reduce_nest(lambda acc, x: acc + x, {"a": [1, 2], "b": 3}) == 6
    assert nest.reduce_nest(lambda acc, x: acc + x, {"a": [1, 2]}, 10) == 13
    assert nest.reduce_nest(lambda acc, x: acc + x, [], 0) == 0


def test_exposed_as_ivy_nest():
    assert ivy.nest is nest
    for name in nest.__all__:
        assert callable(getattr(ivy.nest, name))
