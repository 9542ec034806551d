"""Bad input from Python (issue 42, Python): every refusal an antkit.InputError located in
Python's words (arguments, indexes), never pybind11's TypeError naming a private function, an
OSError, a command-line option or a line of a text the caller never wrote; and no crash on inputs
that only claim to be large (broadcast views)."""
import pathlib

import numpy as np
import pytest

import antkit

ROOM = "movingai/room-32-32-4.map"


@pytest.fixture(scope="module")
def room(maps_dir):
    return antkit.read_map(maps_dir / ROOM)


def refused(call, where=None, says=None):
    with pytest.raises(antkit.InputError) as e:
        call()
    err = e.value
    assert isinstance(err, ValueError)
    assert str(err) == (f"{err.where}: {err.message}" if err.where else err.message)
    text = str(err)
    assert "incompatible function arguments" not in text and "_antkit" not in text
    assert " --" not in text and not err.where.startswith("--"), text
    if where is not None:
        assert err.where == where, text
    if says is not None:
        assert says in err.message, text
    return err


def test_a_huge_broadcast_array_is_refused_not_a_crash():
    # a few bytes that claim 2^40 cells: each side within the old per-side cap of 2^30
    refused(lambda: antkit.Map.from_array(np.broadcast_to(np.True_, (1 << 20, 1 << 20))),
            "a", "over the cap of 268435456 cells")
    refused(lambda: antkit.Map.from_array(np.broadcast_to(np.True_, (1 << 21, 1))), "a",
            "each side from 1 to 1048576")
    refused(lambda: antkit.Map.from_array(np.zeros((0, 3), dtype=bool)), "a")


def test_views_of_any_layout_read_as_their_values():
    base = np.random.default_rng(3).random((9, 14)) < 0.6
    for view in [base[::2, ::3], base[::-1, :], base.T, base[1:8:3, ::-2],
                 np.broadcast_to(base[0], (4, 14))]:
        assert not view.flags.c_contiguous or view is base
        np.testing.assert_array_equal(antkit.Map.from_array(view).to_array(), view)
    tour = np.array([[0, 0], [1, 0], [1, 1], [0, 1]] * 2)[::2]  # (0,0), (1,1): not a tour
    refused(lambda: antkit.tour_hash(tour, 4, 4), "path[1]", "not a 4-neighbour")
    good = np.array([[0, 0, 9], [1, 0, 9], [1, 1, 9]])[:, :2]  # a non-contiguous (3, 2) view
    assert antkit.tour_hash(good, 2, 2) == antkit.tour_hash(good.copy(), 2, 2)


def test_floats_are_not_truncated(room):
    refused(lambda: antkit.stc(room, "offline", start=(1.5, 0)), "start", "integers")
    refused(lambda: antkit.buffon_estimate(100, 100, 5.7), "crossings", "expected an integer")
    # integer-valued floats are refused too, as range() refuses them
    refused(lambda: antkit.buffon_estimate(100, 100, 5.0), "crossings")
    refused(lambda: antkit.stc(room, "offline", start=(5.0, 3)), "start")
    refused(lambda: antkit.stc(room, "ant", seed=1.0), "seed")
    refused(lambda: antkit.tour_hash([[0, 0]], 4.0, 4), "width")
    refused(lambda: antkit.tour_hash(np.array([[0.0, 0.0]]), 4, 4), "path", "dtype float64")
    # numpy integers are integers
    a = antkit.buffon_estimate(100, 100, np.int64(5), np.uint8(0))
    assert a.area_raw == antkit.buffon_estimate(100, 100, 5).area_raw
    start = antkit.stc(room, "offline").path[2]  # a sub-cell of a free cell, numpy int32 x 2
    s = antkit.stc(room, "offline", start=start)
    assert s.start == start.tolist() and isinstance(start[0], np.int32)
    refused(lambda: antkit.stc(room, "offline", start=(True, 3)), "start")


def test_wrong_types_are_input_errors(room, maps_dir, tmp_path):
    refused(lambda: antkit.stc(room, 3), "variant")
    refused(lambda: antkit.stc(3, "offline"), "map")
    refused(lambda: antkit.stc(room, "ant", noise="0.1"), "noise")
    refused(lambda: antkit.stc(room, "ant", seed=-1), "seed")
    refused(lambda: antkit.check_stc(room, [[0, 0]], order=3), "order")
    refused(lambda: antkit.check_stc(room, [[0, 0]], coverage="yes"), "coverage")
    refused(lambda: antkit.check_stc(room, object()), "path")
    refused(lambda: antkit.check_stc(room, [[0, 0], [1]]), "path")
    refused(lambda: antkit.Map.from_array("free"), "a")
    refused(lambda: antkit.Map.from_array([[1, 0]]), "a", "bool array")
    refused(lambda: antkit.Map.from_array(np.ones((2, 2), dtype=bool), start=3), "start")
    refused(lambda: antkit.buffon_estimate("1", 1, 1), "length1")
    refused(lambda: antkit.buffon_estimate(float("inf"), 1, 1), "length1")
    refused(lambda: antkit.buffon_estimate(1, 1, -1), "crossings")
    refused(lambda: antkit.buffon_estimate(1, 1, 2**64), "crossings")
    refused(lambda: antkit.buffon_from_trails([[0, 0]], [[0j, 1]]), "trail2")
    refused(lambda: antkit.buffon_from_trails([[0, 0]], "trail"), "trail2")
    refused(lambda: antkit.check_cover(room, [[1, 2, 3]], sensor=1), "trace", "(ticks, robots, 3)")
    refused(lambda: antkit.check_cover(room, np.zeros((1, 1, 3)), sensor=1), "trace", "dtype float64")
    refused(lambda: antkit.check_cover(room, np.zeros((1, 1, 3), dtype=int), sensor="1"), "sensor")
    refused(lambda: antkit.check_explore(room, 7), "cells")
    refused(lambda: antkit.check_explore(room, ["F" * 32, 5]), "cells[1]")
    refused(lambda: antkit.replay(maps_dir / ROOM, until=2.5), "until")
    refused(lambda: antkit.read_log(None), "path")
    refused(lambda: antkit.read_map(3), "path")
    refused(lambda: antkit.read_map("a\0b.map"), "path", "NUL")


def test_unreadable_files_are_input_errors_not_oserrors(room, tmp_path):
    missing = tmp_path / "missing.txt"
    refused(lambda: antkit.check_explore(room, missing), str(missing), "No such file")
    refused(lambda: antkit.check_cover(room, missing), str(missing))
    refused(lambda: antkit.check_explore(room, tmp_path), str(tmp_path))  # a directory
    refused(lambda: antkit.read_map(tmp_path / "missing.map"))
    refused(lambda: antkit.read_log(missing))
    refused(lambda: antkit.replay(missing))
    refused(lambda: room.write(tmp_path / "no" / "such" / "dir.map"))


def test_paths_may_be_pathlib(room, maps_dir, tmp_path):
    m = antkit.read_map(pathlib.Path(maps_dir / ROOM))
    assert m == room and m.source == str(maps_dir / ROOM)
    for ext in ["map", "txt"]:
        out = tmp_path / f"copy.{ext}"
        room.write(out)
        assert antkit.read_map(out) == antkit.read_map(str(out))
    assert antkit.stc(pathlib.Path(maps_dir / ROOM), "offline").covered > 0


def test_messages_speak_python(room, maps_dir, tmp_path):
    # testing's check names --start; Python names the argument
    e = refused(lambda: antkit.check_stc(room, [[0, 0]], start=(0, 0)), "start", "not a free")
    e = refused(lambda: antkit.check_cover(room, np.zeros((1, 1, 3), dtype=int), sensor=999), "sensor")
    # a cell-state row located by its index and column, not a line of an internal text
    e = refused(lambda: antkit.check_explore(room, ["F" * 32] * 3 + ["F" * 31 + "Z"] + ["F" * 32] * 28),
                "cells[3]", "column 31: 'Z' is not a cell state")
    e = refused(lambda: antkit.check_explore(room, ["F" * 32, "F" * 30]), "cells[1]", "has 30 cells")


def test_tour_hash_refuses_what_is_not_a_tour():
    ok = [[0, 0], [1, 0], [1, 1], [0, 1]]
    h = antkit.tour_hash(ok, 2, 2)
    assert len(h) == 16 and int(h, 16) >= 0
    assert antkit.tour_hash(np.array(ok, dtype=np.uint16), 2, 2) == h
    refused(lambda: antkit.tour_hash(ok, -2, 2), "width", "[1, 1048576]")
    refused(lambda: antkit.tour_hash(ok, 2, 0), "height")
    refused(lambda: antkit.tour_hash(ok, 2**40, 2), "width")
    refused(lambda: antkit.tour_hash(ok, 1, 2), "path[1]", "off the 1x2 map")
    refused(lambda: antkit.tour_hash([[0, 0], [-1, 0]], 2, 2), "path[1]", "off the")
    refused(lambda: antkit.tour_hash([[0, 0], [1, 1]], 2, 2), "path[1]", "not a 4-neighbour")
    refused(lambda: antkit.tour_hash([[0, 0], [0, 0]], 2, 2), "path[1]", "not a 4-neighbour")
    refused(lambda: antkit.tour_hash([[0, 0], [0, 2]], 3, 3), "path[1]", "not a 4-neighbour")
    assert antkit.tour_hash([], 2, 2) == antkit.tour_hash(np.zeros((0, 2), dtype=int), 2, 2)


def test_docstrings():
    assert "Bad input" in antkit.InputError.__doc__ and "where" in antkit.InputError.__doc__
    assert issubclass(antkit.InputError, ValueError)
    assert antkit.InputError.__module__ == "antkit" and antkit.Map.__module__ == "antkit"
    for name in ["width", "height", "start", "source", "resolution", "origin"]:
        doc = getattr(antkit.Map, name).__doc__
        assert doc and len(doc) > 20, name
    for f in [antkit.Map.from_array, antkit.Map.write, antkit.Map.to_array, antkit.read_map,
              antkit.tour_hash, antkit.bag_info, antkit.read_bag_poses, antkit.buffon_from_bags,
              antkit.check_stc_bag]:
        assert f.__doc__ and len(f.__doc__) > 40, f


def test_the_stubs_keep_in_step():
    """__init__.pyi names every public name, Map's properties and each function's parameters."""
    import ast
    import inspect

    tree = ast.parse((pathlib.Path(antkit.__file__).parent / "__init__.pyi").read_text())
    top = {n.name: n for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert set(antkit.__all__) <= set(top), set(antkit.__all__) - set(top)
    stub_map = {n.name for n in top["Map"].body if isinstance(n, ast.FunctionDef)}
    assert {"width", "height", "start", "source", "resolution", "origin", "from_array",
            "to_array", "write"} <= stub_map
    for name, node in top.items():
        f = getattr(antkit, name, None)
        if isinstance(node, ast.FunctionDef) and callable(f):
            stub = [a.arg for a in node.args.args + node.args.kwonlyargs]
            assert stub == list(inspect.signature(f).parameters), name


def test_rows_that_a_view_only_claims_are_refused_at_once(room):
    rows = np.broadcast_to(np.array(["FFF"]), (1 << 40,))  # 2^40 rows in a few bytes
    refused(lambda: antkit.check_explore(room, rows), "cells", "more than 32768")
