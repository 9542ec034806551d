"""Maps from Python: read_map, Map.from_array / to_array (True = free, row = y), write."""
import numpy as np
import pytest

import antkit
from conftest import cli


def test_read_map_matches_the_command(maps_dir):
    for name in ["movingai/room-32-32-4.map", "movingai/maze-32-32-2.map", "ros/lab.yaml"]:
        path = maps_dir / name
        m = antkit.read_map(str(path))
        info, _ = cli("map", "info", "--map", path, "--format", "json")
        assert (m.width, m.height) == (info["width"], info["height"])
        a = m.to_array()
        assert a.shape == (m.height, m.width) and a.dtype == np.bool_
        assert int(a.sum()) == info["free"]
        assert m.source == str(path)


def test_from_array_round_trip_and_orientation():
    a = np.zeros((3, 5), dtype=bool)  # 3 rows (y), 5 columns (x)
    a[0, 4] = True  # x = 4, y = 0: the top right corner
    a[2, 0:2] = True
    m = antkit.Map.from_array(a)
    assert (m.width, m.height) == (5, 3)
    assert m.start is None and m.source == ""
    np.testing.assert_array_equal(m.to_array(), a)
    assert antkit.Map.from_array(a, start=(4, 0)).start == (4, 0)


def test_from_array_refuses_what_it_cannot_read():
    with pytest.raises(antkit.InputError, match="bool array") as e:
        antkit.Map.from_array(np.zeros((2, 2), dtype=np.int8))
    assert e.value.where == "a"
    with pytest.raises(antkit.InputError, match="2-D"):
        antkit.Map.from_array(np.zeros(4, dtype=bool))
    with pytest.raises(antkit.InputError) as e:
        antkit.Map.from_array(np.zeros((2, 2), dtype=bool), start=(0, 0))
    assert e.value.where == "start" and "not a free cell" in e.value.message
    assert isinstance(e.value, ValueError)


def test_write_then_read_is_the_same_map(tmp_path, maps_dir):
    m = antkit.read_map(str(maps_dir / "movingai/random-32-32-10.map"))
    for ext in ["map", "txt"]:
        out = tmp_path / f"copy.{ext}"
        m.write(str(out))
        back = antkit.read_map(str(out))
        np.testing.assert_array_equal(back.to_array(), m.to_array())


def test_a_bad_map_raises_the_commands_located_message(tmp_path):
    bad = tmp_path / "bad.map"
    bad.write_text("type octile\nheight 2\nwidth 2\nmap\n..\n.x\n")
    with pytest.raises(antkit.InputError) as e:
        antkit.read_map(str(bad))
    _, err = cli("map", "info", "--map", bad, "--format", "json", status=2)
    assert err.strip() == f"antkit: error: {e.value}"
    assert str(e.value).startswith(str(bad) + ":")
