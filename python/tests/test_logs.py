"""Hardware logs from Python: read_log and replay against `antkit replay`, on the logs the fuzz
corpus keeps (every robot, faults, a cut log, edited logs), and buffon_from_logs on two visits that
`antkit record` made against `antkit emulate` over a real pseudo-terminal."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import antkit
from conftest import CLI, cli

SOURCE = Path(os.environ.get("ANTKIT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
LOGS = sorted((SOURCE / "fuzz/corpus/replay_log").glob("*.jsonl"))


def test_there_are_logs_to_replay():
    assert len(LOGS) >= 8


@pytest.mark.parametrize("log", LOGS, ids=[p.stem for p in LOGS])
def test_replay_equals_the_command(log):
    r = subprocess.run([CLI, "replay", str(log), "--format", "json"], capture_output=True, text=True)
    if r.returncode == 2:  # malformed: the same located message
        with pytest.raises(antkit.InputError) as e:
            antkit.replay(log)
        assert r.stderr.strip() == f"antkit: error: {e.value}"
        return
    expected = json.loads(r.stdout)
    got = antkit.replay(log)
    assert got.to_dict() == expected
    assert r.returncode == (0 if got.identical else 1)
    # reading the log gives the records the replay went through
    data = antkit.read_log(log)
    assert data.header["robot"] == got.robot and data.header["controller"] == got.controller
    assert len(data.records) >= got.steps
    assert data.truncated == got.truncated
    assert (data.stop["reason"] if data.stop else None) == got.stopped
    for rec in data.records[:3]:
        assert set(rec) == {"step", "t_ns", "io", "obs", "cmd", "odo", "state"}
        assert all(isinstance(x["sent"], bytes) for x in rec["io"])


def test_replay_until():
    log = next(p for p in LOGS if p.stem == "khepera_buffon")
    expected, _ = cli("replay", log, "--until", "3", "--format", "json")
    assert antkit.replay(log, until=3).to_dict() == expected
    with pytest.raises(antkit.InputError):
        antkit.replay(log, until=-1)


def record_visit(tmp_path, name, visit):
    emu = subprocess.Popen(
        [CLI, "emulate", "khepera", "--arena", "circle:d=8", "--seed", "5"],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
    )
    try:
        port = emu.stdout.readline().strip()
        out = tmp_path / name
        cli("record", "--device", "khepera", "--port", port, "--controller", "buffon", "--visit",
            visit, "--steps", "1500", "--out", out, "--format", "json")
        return out
    finally:
        emu.terminate()
        emu.wait(timeout=30)


def test_buffon_from_logs_equals_the_command(tmp_path):
    v1 = record_visit(tmp_path, "v1.jsonl", 1)
    v2 = record_visit(tmp_path, "v2.jsonl", 2)
    expected, _ = cli("buffon-from-logs", v1, v2, "--arena", "circle:d=8", "--format", "json")
    got = antkit.buffon_from_logs(v1, v2, arena="circle:d=8")
    assert got.to_dict() == expected
    assert got.area_true == pytest.approx(3.141592653589793 * 16, rel=1e-5)  # a polygon
    # the estimate from the counts alone, by the same arithmetic
    e = antkit.buffon_estimate(
        got.visit1["length"], got.visit2["length"], got.crossings_exact, got.wall_encounters
    )
    assert e.area_raw == pytest.approx(got.area_raw, rel=1e-12)
    assert e.erosion_factor == pytest.approx(got.erosion_factor, rel=1e-12)
    # a bad arena spec is located in the argument `arena`, not in the option --arena
    with pytest.raises(antkit.InputError) as err:
        antkit.buffon_from_logs(v1, v2, arena="circle:d=eight")
    _, stderr = cli("buffon-from-logs", v1, v2, "--arena", "circle:d=eight", status=2)
    assert err.value.where.startswith("arena") and "--" not in str(err.value)
    assert stderr.strip() == f"antkit: error: --{err.value}"
    # the same log twice is refused with the command's message
    with pytest.raises(antkit.InputError) as err:
        antkit.buffon_from_logs(v1, v1)
    _, stderr = cli("buffon-from-logs", v1, v1, status=2)
    assert stderr.strip() == f"antkit: error: {err.value}"


def test_buffon_estimate_closed_form():
    e = antkit.buffon_estimate(1000.0, 1000.0, 100)
    assert e.area_raw == pytest.approx(2 * 1000 * 1000 / (3.141592653589793 * 100))
    assert e.erosion_factor == 1.0 and e.area_corrected == e.area_raw
    lo, hi = e.area_raw_ci
    assert lo < e.area_raw < hi
    none = antkit.buffon_estimate(10.0, 10.0, 0)
    assert none.area_raw is None and none.area_raw_ci[1] is None


def proper_crossings(a, b):
    """The pair loop, exactly, on integer (Q15.16 raw) points: segments that cross at one point
    strictly inside both."""

    def orient(p, q, r):
        v = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
        return (v > 0) - (v < 0)

    n = 0
    for i in range(len(a) - 1):
        for j in range(len(b) - 1):
            p, q, r, s = a[i], a[i + 1], b[j], b[j + 1]
            o1, o2, o3, o4 = orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q)
            n += o1 * o2 < 0 and o3 * o4 < 0
    return n


def test_buffon_from_trails_counts_every_crossing_exactly():
    rng = np.random.default_rng(7)
    t1 = np.cumsum(rng.normal(0, 0.4, size=(300, 2)), axis=0)
    t2 = np.cumsum(rng.normal(0, 0.4, size=(300, 2)), axis=0)
    r = antkit.buffon_from_trails(t1, t2)
    raw = lambda t: [tuple(int(v) for v in np.round(p * 65536)) for p in t]
    assert r.crossings == proper_crossings(raw(t1), raw(t2)) > 0
    length = lambda t: float(np.sum(np.hypot(*np.diff(t, axis=0).T)))
    assert r.length1 == pytest.approx(length(t1), rel=1e-6)
    e = antkit.buffon_estimate(r.length1, r.length2, r.crossings)
    assert r.area_raw == e.area_raw
    with pytest.raises(antkit.InputError) as err:
        antkit.buffon_from_trails(t1, np.array([[0.0, 0.0], [40000.0, 0.0]]))
    assert err.value.where == "trail2[1]"
