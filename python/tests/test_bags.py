"""ROS 2 bags from Python against the command line (`antkit bag info`, `buffon-from-logs --topic`,
`check stc --bag`), on bags written at test time by independent writers under node
(tests/support/write_bags.mjs): walk 1 along the x axis, (0, 0) to (10, 0); walk 2 a zigzag
(0.25 + i, (-1)^i) crossing it nine times; bag time of message i 1.7e18 + i * 0.1 s, header.stamp
0.25 s earlier."""
import math
from pathlib import Path

import numpy as np
import pytest

import antkit
from conftest import cli

T0 = 1_700_000_000_000_000_000
STEP = 100_000_000


@pytest.mark.parametrize("name", ["walk1.mcap", "walk1.db3", "walk2_bag", "walk2_zstd.mcap"])
def test_bag_info_equals_the_command(ros_bags, name):
    expected, _ = cli("bag", "info", ros_bags / name, "--format", "json")
    got = antkit.bag_info(ros_bags / name)  # a pathlib.Path
    assert got.to_dict() == expected
    assert antkit.bag_info(str(ros_bags / name)).to_dict() == expected


def test_bag_info_fields(ros_bags):
    info = antkit.bag_info(ros_bags / "walk1.mcap")
    assert info.storage == "mcap" and info.messages == 66 and info.duration_s == 1.0
    odom = next(t for t in info.topics if t["topic"] == "/odom")
    assert odom["type"] == "nav_msgs/msg/Odometry" and odom["messages"] == 11
    assert (odom["start_ns"], odom["end_ns"]) == (T0, T0 + 10 * STEP)
    assert antkit.bag_info(ros_bags / "walk2_bag").storage == "sqlite3"


@pytest.mark.parametrize("topic", ["/odom", "/pose", "/amcl_pose", "/tf"])
def test_read_bag_poses_walk1(ros_bags, topic):
    t = antkit.read_bag_poses(ros_bags / "walk1.mcap", topic)
    assert t.topic == topic and t.stamp == "bag" and len(t.poses) == 11
    assert t.poses.dtype == np.float64 and t.poses.shape == (11, 3)
    np.testing.assert_allclose(t.poses[:, 0], np.arange(11.0))
    np.testing.assert_allclose(t.poses[:, 1:], 0.0, atol=1e-12)
    np.testing.assert_array_equal(t.t_ns, T0 + STEP * np.arange(11))
    np.testing.assert_array_equal(t.bag_ns, t.t_ns.astype(np.uint64))
    np.testing.assert_array_equal(t.header_ns, t.t_ns - 250_000_000)
    assert t.child_frame == ("base_link" if topic == "/tf" else None)
    with pytest.raises(ValueError):
        t.poses[0, 0] = 1.0  # read-only
    h = antkit.read_bag_poses(ros_bags / "walk1.mcap", topic, stamp="header")
    np.testing.assert_array_equal(h.t_ns, t.t_ns - 250_000_000)
    assert h.to_dict()["poses"][3] == pytest.approx([3.0, 0.0, 0.0], abs=1e-12)


@pytest.mark.parametrize("name", ["walk2_zstd.mcap", "walk2_lz4.mcap", "walk2_bag"])
def test_read_bag_poses_in_every_storage(ros_bags, name):
    t = antkit.read_bag_poses(str(ros_bags / name), "/odom")
    i = np.arange(10)
    np.testing.assert_allclose(t.poses[:, 0], 0.25 + i)
    np.testing.assert_allclose(t.poses[:, 1], np.where(i % 2, -1.0, 1.0))
    np.testing.assert_allclose(t.poses[:, 2], math.pi / 4)
    assert t.type == "nav_msgs/msg/Odometry" and t.messages == 10


def test_read_bag_poses_twist_and_refusals(ros_bags):
    bag = ros_bags / "walk1.mcap"
    twist = antkit.read_bag_poses(bag, "/cmd_vel")
    assert twist.header_ns is None and twist.poses[0].tolist() == [0.0, 0.0, 0.0]
    assert twist.poses[-1, 0] > 0  # 1 m/s integrated over bag time
    with pytest.raises(antkit.InputError):  # a Twist has no header.stamp
        antkit.read_bag_poses(bag, "/cmd_vel", stamp="header")
    with pytest.raises(antkit.InputError) as e:
        antkit.read_bag_poses(bag, "/nothing")
    assert "/odom" in e.value.message  # the bag's topics listed
    with pytest.raises(antkit.InputError) as e:
        antkit.read_bag_poses(bag, "/chatter")
    assert "std_msgs/msg/String" in str(e.value)
    with pytest.raises(antkit.InputError) as e:
        antkit.read_bag_poses(bag, "/odom", stamp="sideways")
    assert e.value.where == "stamp" and "expected bag or header" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.read_bag_poses(bag, "/tf", child_frame="wheel")
    with pytest.raises(antkit.InputError) as e:
        antkit.read_bag_poses(ros_bags / "nothing.mcap", "/odom")
    assert "nothing.mcap" in e.value.where


@pytest.mark.parametrize(
    "one, two", [("walk1.mcap", "walk2_zstd.mcap"), ("walk1.db3", "walk2_lz4.mcap"), ("walk1.mcap", "walk2_bag")]
)
def test_buffon_from_bags_equals_the_command(ros_bags, one, two):
    a, b = ros_bags / one, ros_bags / two
    expected, _ = cli("buffon-from-logs", "--topic", "/odom", "--width", "0.1", a, b, "--format", "json")
    got = antkit.buffon_from_bags(a, b, "/odom", width=0.1)
    assert got.to_dict() == expected
    assert got.crossings_exact == 9 and got.unit == "m"
    l1, l2 = 10.0, 9 * math.sqrt(5.0)
    assert got.visit1["length"] == pytest.approx(l1) and got.visit2["length"] == pytest.approx(l2)
    assert got.area_m2 == pytest.approx(2 * l1 * l2 / (math.pi * 9))
    e = antkit.buffon_from_bags(a, b, "/odom", arena="square:area=20")
    assert e.area_true == pytest.approx(20.0) and e.relative_error is not None


def test_buffon_from_bags_refusals_speak_python(ros_bags):
    w1, w2 = ros_bags / "walk1.mcap", ros_bags / "walk2_lz4.mcap"
    with pytest.raises(antkit.InputError) as e:
        antkit.buffon_from_bags(w1, w1, "/odom")
    assert "the same bag as" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.buffon_from_bags(w1, w2, "/odom", stamp="sideways")
    assert e.value.where == "stamp"
    with pytest.raises(antkit.InputError) as e:
        antkit.buffon_from_bags(w1, w2, "/odom", width=20)
    assert e.value.where == "width" and "[0.01, 10]" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.buffon_from_bags(w1, w2, "/odom", arena="circle:d=big")
    assert e.value.where.startswith("arena") and "--" not in str(e.value)
    with pytest.raises(antkit.InputError) as e:
        antkit.buffon_from_bags(w1, w2, "/odom", width=float("nan"))
    assert e.value.where == "width"


@pytest.fixture()
def free_map(ros_bags):
    """A 4 x 2 free ROS map, 0.5 m cells, its lower-left corner at (-1, -2) m (write_bags.mjs's
    tours)."""
    (ros_bags / "free.yaml").write_text(
        "image: free.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    (ros_bags / "free.pgm").write_bytes(b"P5\n4 2\n255\n" + b"\xfe" * 8)
    return ros_bags / "free.yaml"


def test_check_stc_bag_equals_the_command(ros_bags, free_map):
    expected, _ = cli("check", "stc", "--map", free_map, "--bag", ros_bags / "tour.mcap", "--topic", "/pose",
                      "--format", "json")
    got = antkit.check_stc_bag(free_map, ros_bags / "tour.mcap", "/pose")
    assert got.to_dict() == expected
    assert got.ok and got.positions == 8 and got.poses == 4 and got.covered == 8
    assert got.first_violation_time_ns is None
    # the same from a Map read first: its resolution and origin go with it
    m = antkit.read_map(free_map)
    assert m.resolution == 0.5 and m.origin == (-1.0, -2.0, 0.0)
    assert antkit.check_stc_bag(m, ros_bags / "tour.mcap", "/pose").to_dict() == expected


def test_check_stc_bag_a_repeat_has_its_time(ros_bags, free_map):
    expected, _ = cli("check", "stc", "--map", free_map, "--bag", ros_bags / "tour_repeat.mcap", "--topic",
                      "/pose", "--format", "json", status=1)
    got = antkit.check_stc_bag(free_map, ros_bags / "tour_repeat.mcap", "/pose")
    assert got.to_dict() == expected
    assert not got.ok and got.first_violation["step"] == 4
    assert got.first_violation["subcell"] == [2, 0]
    # a quarter of the way from the second pose (0.1 s) to the third (0.2 s)
    assert got.first_violation_time_ns == T0 + STEP + STEP // 4
    # at least once: the repeat is allowed, the bottom row's four cells are missed
    c = antkit.check_stc_bag(free_map, ros_bags / "tour_repeat.mcap", "/pose", coverage=True)
    assert c.rule == "coverage" and not c.ok and c.missed == 4, c


def test_check_stc_bag_refusals(ros_bags, free_map):
    with pytest.raises(antkit.InputError) as e:  # walk 1 runs 10 m to the east of a 2 m map
        antkit.check_stc_bag(free_map, ros_bags / "walk1.mcap", "/odom")
    assert "leaves the map" in e.value.message and "walk1.mcap" in e.value.where
    # a map made from an array has 1 m cells from the origin: the tour's poses (negative
    # coordinates) are off it
    grid = antkit.Map.from_array(np.ones((2, 4), dtype=bool))
    assert grid.resolution == 1.0 and grid.origin == (0.0, 0.0, 0.0)
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc_bag(grid, ros_bags / "tour.mcap", "/pose")
    assert "leaves the map" in e.value.message
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc_bag(free_map, ros_bags / "tour.mcap", "/pose", start=(1.5, 0))
    assert e.value.where == "start"
    with pytest.raises(antkit.InputError) as e:
        antkit.check_stc_bag(free_map, ros_bags / "tour.mcap", "/pose", start=(7, 0))
    assert e.value.where == "start" and "--" not in str(e.value)


def test_check_cover_bag_equals_the_command(ros_bags, free_map):
    for name, status in (("cover.mcap", 0), ("cover_collide.mcap", 1)):
        expected, _ = cli("check", "cover", "--map", free_map, "--bag", ros_bags / name, "--topic",
                          "/r0/pose", "--topic", "/r1/pose", "--sensor", "1", "--format", "json",
                          status=status)
        got = antkit.check_cover_bag(free_map, ros_bags / name, ["/r0/pose", "/r1/pose"], 1)
        assert got.to_dict() == expected
        assert got.ok == (status == 0) and got.robots == 2
    # head on along one row: r0 steps onto r1's cell half-way, at 0.05 s
    bad = antkit.check_cover_bag(antkit.read_map(free_map), ros_bags / "cover_collide.mcap",
                                 ("/r0/pose", "/r1/pose"), 1)
    assert bad.first_violation_time_ns == T0 + STEP // 2 and bad.collisions >= 1


def test_check_cover_bag_refusals(ros_bags, free_map):
    cover = ros_bags / "cover.mcap"
    for kwargs, where in ((dict(topics="/r0/pose", sensor=1), "topics"),
                          (dict(topics=["/r0/pose", 3], sensor=1), "topics"),
                          (dict(topics=["/r0/pose", "/r0/pose"], sensor=1), "topic"),
                          (dict(topics=[], sensor=1), "topic"),
                          (dict(topics=["/r0/pose"], sensor=1.0), "sensor"),
                          (dict(topics=["/r0/pose"], sensor=256), "sensor")):
        with pytest.raises(antkit.InputError) as e:
            antkit.check_cover_bag(free_map, cover, **kwargs)
        assert e.value.where == where, (kwargs, e.value)
        assert "--" not in str(e.value)
