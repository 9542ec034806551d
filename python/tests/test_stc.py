"""antkit.stc against `antkit stc --format json`: the same fields, the same path, the same hash."""
import numpy as np
import pytest

import antkit
from conftest import cli

MAPS = ["movingai/room-32-32-4.map", "movingai/maze-32-32-2.map", "movingai/random-32-32-20.map"]
VARIANTS = ["offline", "online", "ant", "ant-edge", "full"]


@pytest.mark.parametrize("name", MAPS)
@pytest.mark.parametrize("variant", VARIANTS)
def test_stc_equals_the_command(maps_dir, name, variant):
    path = maps_dir / name
    expected, _ = cli("stc", "--map", path, "--variant", variant, "--format", "json")
    r = antkit.stc(antkit.read_map(str(path)), variant)
    got = r.to_dict()
    assert got.pop("closed") is True
    assert got.pop("positions") == len(expected["path"])
    assert got == expected
    assert r.path.dtype == np.int32 and r.path.shape == (len(expected["path"]), 2)
    assert r.hash == expected["hash"]
    # the trace hash of the tour's positions is the run's hash
    assert antkit.tour_hash(r.path, r.width, r.height) == r.hash


def test_stc_with_a_start_and_noise_equals_the_command(maps_dir):
    path = maps_dir / "movingai/random-32-32-10.map"
    x, y = antkit.stc(str(path), "offline").path[37]  # a sub-cell of a free cell
    expected, _ = cli(
        "stc", "--map", path, "--variant", "ant", "--start", f"{x},{y}", "--noise", "0.01",
        "--seed", "3", "--format", "json",
    )
    r = antkit.stc(str(path), "ant", start=(x, y), noise=0.01, seed=3)
    got = r.to_dict()
    got.pop("closed"), got.pop("positions")
    assert got == expected
    assert r.noise_ppm == 10000 and r.seed == 3


def test_stc_bad_input_raises_the_commands_message(maps_dir):
    path = maps_dir / "movingai/room-32-32-4.map"
    m = antkit.read_map(str(path))
    with pytest.raises(antkit.InputError) as e:
        antkit.stc(m, "spiral")
    assert e.value.where == "variant" and "expected offline, online" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.stc(m, "ant", start=(0, 0))  # a wall of the room map
    _, err = cli("stc", "--map", path, "--variant", "ant", "--start", "0,0", status=2)
    assert e.value.where == "start"
    assert err.strip() == f"antkit: error: --start: {e.value.message}"


def test_path_is_read_only_and_the_result_a_mapping(maps_dir):
    r = antkit.stc(str(maps_dir / "movingai/empty-32-32.map"), "offline")
    with pytest.raises(ValueError):
        r.path[0, 0] = 7
    assert r["covered"] == r.covered == r.reachable_subcells == 32 * 32
    assert set(r) >= {"variant", "hash", "covered"}
    with pytest.raises(AttributeError):
        r.nothing
