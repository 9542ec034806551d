"""The oracles from Python against `antkit check ... --format json`: the same fields and values on
the repository's maps, for passing tours and for broken ones, in every convention."""
import json

import numpy as np
import pytest

import antkit
from conftest import cli

ROOM = "movingai/random-32-32-10.map"  # 604 reachable sub-cells for STC from its default start


def stc_tour(maps_dir, name=ROOM, variant="ant"):
    return antkit.stc(str(maps_dir / name), variant)


def check_both(tmp_path, map_path, path_xy, *args, **kwargs):
    """check_stc in Python (on the array and on the CSV file) and on the command line."""
    csv = tmp_path / "tour.csv"
    np.savetxt(csv, path_xy, fmt="%d", delimiter=",", header="x,y", comments="")
    flags = []
    if kwargs.get("coverage"):
        flags.append("--coverage")
    if kwargs.get("cells"):
        flags.append("--cells")
    if kwargs.get("start") is not None:
        flags += ["--start", "{},{}".format(*kwargs["start"])]
    r_array = antkit.check_stc(str(map_path), path_xy, **kwargs)
    r_file = antkit.check_stc(str(map_path), str(csv), **kwargs)
    expected, _ = cli("check", "stc", "--map", map_path, "--path", csv, *flags,
                      "--format", "json", status=0 if r_array.ok else 1)
    # the array has no header: the order came from the argument, not from the file
    expected_array = dict(expected, order_from="--order")
    assert r_array.to_dict() == expected_array
    assert r_file.to_dict() == expected
    return r_array


def test_a_passing_tour(tmp_path, maps_dir):
    t = stc_tour(maps_dir)
    r = check_both(tmp_path, maps_dir / ROOM, t.path)
    assert r.ok and bool(r) and r.first_violation is None
    assert r.rule == "exactly-once" and r.covered == t.reachable_subcells


@pytest.mark.parametrize("edit", ["repeat", "skip", "jump", "wall"])
def test_a_broken_tour(tmp_path, maps_dir, edit):
    t = stc_tour(maps_dir).path.copy()
    if edit == "repeat":
        t = np.vstack([t[:10], t[8:9], t[10:]])
    elif edit == "skip":
        t = np.delete(t, 40, axis=0)
    elif edit == "jump":
        t[50] = t[50] + [3, 0]
    else:
        t[20] = [0, 0]
    r = check_both(tmp_path, maps_dir / ROOM, t)
    assert not r.ok and not bool(r)
    v = r.first_violation
    assert set(v) == {"rule", "step", "subcell", "detail"}


def test_coverage_rule(tmp_path, maps_dir):
    t = stc_tour(maps_dir, variant="full")
    r = check_both(tmp_path, maps_dir / ROOM, t.path, coverage=True)
    assert r.ok and r.rule == "coverage"


def test_row_col_order_is_the_same_tour(maps_dir):
    t = stc_tour(maps_dir).path
    xy = antkit.check_stc(str(maps_dir / ROOM), t)
    rc = antkit.check_stc(str(maps_dir / ROOM), t[:, ::-1], order="rc")
    assert rc.ok and rc.order == "rc"
    assert {k: v for k, v in rc.items() if k != "order"} == {
        k: v for k, v in xy.items() if k != "order"
    }
    # the same pairs read as x,y are a transposed tour: refused
    assert not antkit.check_stc(str(maps_dir / ROOM), t[:, ::-1]).ok


def test_cells_mode_equals_the_command(tmp_path, maps_dir):
    # A planner on robot-sized cells: the map of cells, the start a cell, the tour in sub-cells.
    cells = np.ones((4, 5), dtype=bool)
    cells[1, 2] = False
    cmap = antkit.Map.from_array(cells)
    cmap_path = tmp_path / "cells.txt"
    cmap.write(str(cmap_path))
    sub = antkit.Map.from_array(np.kron(cells, np.ones((2, 2), dtype=bool)))
    t = antkit.stc(sub, "offline", start=(2, 2)).path  # starts in cell (1, 1)
    r = check_both(tmp_path, cmap_path, t, start=(1, 1), cells=True)
    assert r.ok and r.cells and r.start_cell == [1, 1] and r.start == [2, 2]
    assert r.reachable_subcells == 4 * (4 * 5 - 1)


def test_lists_of_pairs_and_an_empty_tour(maps_dir):
    t = stc_tour(maps_dir).path
    assert antkit.check_stc(str(maps_dir / ROOM), t.tolist()).ok
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc(str(maps_dir / ROOM), [])
    assert "the tour is empty" in str(e.value)
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc(str(maps_dir / ROOM), np.zeros((3, 3), dtype=int))
    assert e.value.where == "path" and "(n, 2)" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc(str(maps_dir / ROOM), t, order="yx")
    assert e.value.where == "order"


def test_a_bad_tour_file_raises_the_commands_message(tmp_path, maps_dir):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n1,2\n3;4\n")
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc(str(maps_dir / ROOM), str(bad))
    _, err = cli("check", "stc", "--map", maps_dir / ROOM, "--path", bad, status=2)
    assert err.strip() == f"antkit: error: {e.value}"
    assert e.value.where.startswith(f"{bad}:3:")


def test_check_explore_equals_the_command(tmp_path, maps_dir):
    m = maps_dir / "movingai/room-32-32-4.map"
    out, _ = cli("explore", "--map", m, "--algo", "frontier", "--format", "json")
    cells_file = tmp_path / "cells.json"
    cells_file.write_text(json.dumps(out))
    expected, _ = cli("check", "explore", "--map", m, "--cells", cells_file, "--format", "json")
    assert antkit.check_explore(str(m), out["cells"]).to_dict() == expected
    assert antkit.check_explore(str(m), str(cells_file)).to_dict() == expected
    # an S cell on a wall: unsound, with the same message as the command's
    rows = list(out["cells"])
    rows[0] = "S" + rows[0][1:]
    bad = tmp_path / "bad.txt"
    bad.write_text("\n".join(rows) + "\n")
    expected, _ = cli("check", "explore", "--map", m, "--cells", bad, "--format", "json", status=1)
    r = antkit.check_explore(str(m), rows)
    assert not r.ok and r.to_dict() == expected


def test_check_cover_equals_the_command(tmp_path, maps_dir):
    m = maps_dir / "movingai/room-32-32-4.map"
    trace = tmp_path / "trace.csv"
    cli("cover", "--map", m, "--algo", "rw", "--robots", "2", "--limit", "200", "--trace", trace, "--format", "json")
    expected, _ = cli("check", "cover", "--map", m, "--log", trace, "--format", "json")
    r = antkit.check_cover(str(m), str(trace))
    assert r.ok and r.to_dict() == expected
    # the same trace as a (ticks, robots, 3) array
    rows = [list(map(int, l.split(","))) for l in trace.read_text().splitlines()
            if l and not l.startswith("#") and not l.startswith("tick")]
    a = np.zeros((rows[-1][0] + 1, 2, 3), dtype=np.int64)
    for tick, robot, x, y, b in rows:
        a[tick, robot] = (x, y, b)
    ra = antkit.check_cover(str(m), a, sensor=r.sensor)
    assert ra.ok and (ra.viewed, ra.viewable) == (r.viewed, r.viewable)
    a[5, 1] = a[5, 0]  # two robots on one cell
    assert not antkit.check_cover(str(m), a, sensor=r.sensor).ok
    with pytest.raises(antkit.InputError) as e:
        antkit.check_cover(str(m), a)
    assert e.value.where == "sensor" and "required with a trace array" in e.value.message
    # an array's values are located by index, not by a line of a text the caller never wrote
    a[3, 1, 2] = 9
    with pytest.raises(antkit.InputError) as e:
        antkit.check_cover(str(m), a, sensor=r.sensor)
    assert e.value.where == "trace[3, 1]" and "bearing 9 is outside [0, 7]" in e.value.message
    # a trace file without its "# sensor:" line: the argument named as in Python
    bare = tmp_path / "bare.csv"
    bare.write_text("".join(l + "\n" for l in trace.read_text().splitlines() if not l.startswith("#")))
    with pytest.raises(antkit.InputError) as e:
        antkit.check_cover(str(m), bare)
    assert e.value.where == str(bare) and "with sensor=" in e.value.message
    assert "--" not in str(e.value)
    with pytest.raises(antkit.InputError) as e:
        antkit.check_cover(str(m), bare, sensor=300)
    assert e.value.where == "sensor" and "[0, 255]" in e.value.message
