"""The package as solid as the command line (issue 42, Python): Hypothesis over every public
function's argument space — types (None, bool, int, float, str, bytes, lists, dicts, objects,
numpy scalars and arrays of every dtype), ranges (negative, zero, huge, NaN, infinities), shapes
(0-D to 3-D, empty), strides and layouts (slices with steps, reversed, transposed, broadcast views
that claim far more cells than they hold), files (real maps, logs, tours, traces, bags and the
fuzz corpora's malformed ones, directories, missing files, pathlib.Path) — asserting that every
call either returns a valid result or raises antkit.InputError: never another exception, never a
crash (a crash ends the pytest process, and the test with it).

Reproducible: ctest passes --hypothesis-seed (ANTKIT_HYPOTHESIS_SEED, printed in pytest's header
by conftest.py); there is no example database. Rerun one failure with the seed it prints."""
import atexit
import math
import os
import pathlib
import shutil
import tempfile
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, event, given, note, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import antkit
from conftest import MAPS, SOURCE

FUZZ = settings(max_examples=int(os.environ.get("ANTKIT_FUZZ_EXAMPLES", "400")),
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])

# ---- files --------------------------------------------------------------------------------------

SCRATCH = pathlib.Path(tempfile.mkdtemp(prefix="antkit_fuzz_"))
atexit.register(shutil.rmtree, SCRATCH, ignore_errors=True)


def corpus(name, n=6):
    return sorted((SOURCE / "fuzz/corpus" / name).glob("*"))[:n]


def _files():
    tour = SCRATCH / "tour.csv"
    tour.write_text("x,y\n0,0\n1,0\n1,1\n0,1\n")
    trace = SCRATCH / "trace.csv"
    trace.write_text("# sensor: 2\ntick,robot,x,y,bearing\n0,0,1,1,0\n1,0,2,1,0\n")
    cells = SCRATCH / "cells.txt"
    cells.write_text("FFF\nFSF\n")
    garbage = SCRATCH / "garbage.map"
    garbage.write_bytes(b"\x00\xff\xfe type octile\nheight 99999999999\n")
    ascii_map = SCRATCH / "small.txt"
    ascii_map.write_text("..#\nS..\n")
    return [tour, trace, cells, garbage, ascii_map]


FILES = (
    _files()
    + [MAPS / "movingai/room-32-32-4.map", MAPS / "movingai/maze-32-32-2.map",
       MAPS / "ros/lab.yaml", SCRATCH, SCRATCH / "missing.map", pathlib.Path("/dev/null")]
    + corpus("tour") + corpus("cover_trace") + corpus("los_cells") + corpus("ascii_map")
    + corpus("replay_log", 12) + corpus("mcap_reader", 8) + corpus("ros_yaml", 4)
)
paths = st.sampled_from(FILES).flatmap(
    lambda p: st.sampled_from([p, str(p), os.fsencode(str(p))]))

# ---- values of every kind -----------------------------------------------------------------------

HUGE = [2**31 - 1, 2**31, -(2**31) - 1, 2**32, 2**63 - 1, 2**63, 2**64, -(2**63), 2**100, -(2**100)]
big_ints = st.sampled_from(HUGE)
reals = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.sampled_from(
    [0.0, -0.0, 0.5, 1.5, 5.0, -1.0, 1e-300, 1e300, 1e9, 32767.99, 32768.0]))
numpy_scalars = st.one_of(
    st.integers(-200, 200).map(np.int64), st.integers(0, 200).map(np.uint8),
    st.integers(-5, 5).map(np.int32), reals.map(np.float64), st.booleans().map(np.bool_),
    st.just(np.float32(2.5)), st.just(np.complex128(1 + 2j)), st.just(np.str_("ant")))

DTYPES = [np.bool_, np.int8, np.int16, np.int32, np.int64, np.uint8, np.uint16, np.uint64,
          np.float16, np.float32, np.float64, np.complex64, np.dtype("U3"), np.dtype("S2"),
          np.dtype("M8[s]"), np.dtype(object)]


def _elements(dtype):
    dtype = np.dtype(dtype)
    if dtype.kind == "O":
        return st.one_of(st.none(), st.integers(-3, 3), st.text(max_size=2))
    if dtype.kind in "iu":
        info = np.iinfo(dtype)
        return st.one_of(st.integers(max(info.min, -3), min(info.max, 40)),
                         st.sampled_from([int(info.min), int(info.max)]))
    return None


@st.composite
def arrays(draw, max_dims=3, max_side=6):
    """A numpy array of any dtype and shape, then maybe a view of it in another layout."""
    dtype = draw(st.sampled_from(DTYPES))
    shape = draw(hnp.array_shapes(min_dims=0, max_dims=max_dims, min_side=0, max_side=max_side))
    a = draw(hnp.arrays(dtype, shape, elements=_elements(dtype)))
    return draw(views(a))


@st.composite
def views(draw, a):
    """a, or a view of it with other strides: stepped, reversed, transposed, broadcast."""
    how = draw(st.sampled_from(["as is", "as is", "as is", "step", "reverse", "transpose",
                                "broadcast", "huge"]))
    note(f"view: {how}")
    if how == "step" and a.ndim >= 1:
        return a[::2]
    if how == "reverse" and a.ndim >= 1:
        return a[::-1]
    if how == "transpose":
        return a.T
    if how == "broadcast":
        return np.broadcast_to(a, (draw(st.integers(1, 4)),) + a.shape)
    if how == "huge" and a.size >= 1:  # a few bytes that claim a very large array
        lead = draw(st.sampled_from([1 << 29, 1 << 40]))  # over every cap: refused at once
        return np.broadcast_to(a.reshape(-1)[:1].reshape((1,) * max(a.ndim, 1)),
                               (lead,) + (a.shape[1:] if a.ndim >= 2 else ()) or (lead,))
    return a


anything = st.deferred(lambda: st.one_of(
    st.none(), st.booleans(), st.integers(-50, 50), big_ints, reals, st.text(max_size=12),
    st.binary(max_size=6), st.complex_numbers(max_magnitude=10), st.just(Fraction(3, 2)),
    st.lists(st.integers(-3, 40), max_size=4), st.lists(st.lists(st.integers(-3, 40), max_size=3), max_size=5),
    st.lists(st.text(max_size=3), max_size=3), st.tuples(reals, reals), st.sets(st.integers(0, 3), max_size=2),
    st.dictionaries(st.text(max_size=2), st.integers(), max_size=2), st.builds(object), numpy_scalars,
    arrays(), paths))


def _numpy_int(v):
    return np.int64(v) if -(2**63) <= v < 2**63 else np.uint64(v)


def ints(lo, hi):
    """Mostly what a caller means, sometimes anything at all."""
    return st.one_of(st.integers(lo, hi), st.integers(lo, hi).map(_numpy_int), anything)


@st.composite
def pairs(draw, lo=-2, hi=12):
    kind = draw(st.sampled_from(["tuple", "list", "array", "none", "none"]))
    x, y = draw(st.integers(lo, hi)), draw(st.integers(lo, hi))
    return {"tuple": (x, y), "list": [x, y], "array": np.array([x, y], dtype=np.int32),
            "none": None}[kind]


@st.composite
def bool_grids(draw, max_side=8):
    h, w = draw(st.integers(1, max_side)), draw(st.integers(1, max_side))
    a = draw(hnp.arrays(np.bool_, (h, w), elements=st.sampled_from([True, True, True, False])))
    return draw(views(a))


@st.composite
def maps(draw):
    kind = draw(st.sampled_from(["array", "array", "file"]))
    if kind == "array":
        a = draw(bool_grids())
        try:
            return antkit.Map.from_array(a)
        except antkit.InputError:
            return antkit.Map.from_array(np.ones((3, 3), dtype=bool))
    return draw(map_files)


@st.composite
def tours(draw, max_len=12):
    kind = draw(st.sampled_from(["walk", "walk", "walk", "list", "list", "float", "path"]))
    if kind in ("walk", "list", "float"):
        n = draw(st.integers(0, max_len))
        steps = draw(st.lists(st.sampled_from([(1, 0), (-1, 0), (0, 1), (0, -1)]),
                              min_size=n, max_size=n))
        if n and draw(st.integers(0, 3)) == 0:  # one move that is not a 4-neighbour's
            steps[draw(st.integers(0, n - 1))] = draw(st.sampled_from([(1, 1), (0, 0), (2, 0)]))
        start = (draw(st.integers(-1, 3)), draw(st.integers(-1, 3)))
        pts = np.cumsum(np.array([start] + steps, dtype=np.int64), axis=0)
        if kind == "list":
            return pts.tolist()
        if kind == "float":
            return pts.astype(np.float64)
        return draw(views(pts.astype(draw(st.sampled_from([np.int64, np.int32, np.uint16, np.int8])))))
    return draw(st.sampled_from(FILES[:1] + corpus("tour")))


# ---- the property -------------------------------------------------------------------------------


def holds(call):
    """The call's result, or None when it raised antkit.InputError (well formed); any other
    exception propagates and fails the test."""
    try:
        r = call()
        event("returned")  # --hypothesis-show-statistics: how often the valid path is reached
        return r
    except antkit.InputError as e:
        event("InputError")
        assert isinstance(e, ValueError)
        assert isinstance(e.where, str) and isinstance(e.message, str) and e.message
        text = str(e)
        assert text == (f"{e.where}: {e.message}" if e.where else e.message)
        assert "incompatible function arguments" not in text, text
        assert not e.where.startswith("--"), text
        note(f"InputError: {text}")
        return None


def integer(v):
    """What a call that returned must have been given where it takes an integer: no float (not
    even 5.0), no bool, nothing truncated on the way."""
    return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))


def valid_map(m):
    assert isinstance(m, antkit.Map) and m.width >= 1 and m.height >= 1
    a = m.to_array()
    assert a.shape == (m.height, m.width) and a.dtype == np.bool_


def near_miss(draw, v):
    """A valid value in a form it must not be taken in: an integer as a float (5.0, 5.5), a bool
    or a str; a pair of integers as floats; an integer array as floats; a str as bytes."""
    if isinstance(v, (bool, np.bool_)):
        return int(v)
    if isinstance(v, (int, np.integer)):
        return draw(st.sampled_from([float(v), float(v) + 0.5, np.float64(v), bool(v % 2), str(v)]))
    if isinstance(v, float):
        return draw(st.sampled_from([str(v), complex(v, 0), np.bool_(v > 0)]))
    if isinstance(v, (tuple, list)) and len(v) == 2 and all(isinstance(x, (int, np.integer)) for x in v):
        d = draw(st.sampled_from([0.0, 0.5]))
        return type(v)(float(x) + d for x in v)
    if isinstance(v, np.ndarray) and v.size > 4096:  # a view claiming more than it holds
        return v.view(np.uint8) if v.dtype.kind == "b" else v[..., :0]
    if isinstance(v, np.ndarray) and v.dtype.kind in "iu":
        return v.astype(np.float64) + draw(st.sampled_from([0.0, 0.5]))
    if isinstance(v, np.ndarray) and v.dtype.kind == "b":
        return v.astype(np.uint8)
    if isinstance(v, str):
        return v.encode()
    return draw(anything)


@st.composite
def arguments(draw, **valid):
    """Keyword arguments: about half the time every one drawn from its valid strategy (which
    holds in-type edge cases of its own), else one of them (or, rarely, all) spoiled: a near miss
    of a valid value (5.0 for 5, (1.5, 0) for (1, 0)) or anything at all, so that each argument's
    refusals are reached with the others valid."""
    names = list(valid)
    k = draw(st.integers(0, 2 * len(names) + 1))
    spoil = names[k] if k < len(names) else "all" if k == 2 * len(names) + 1 else None
    note(f"spoiled: {spoil}")
    out = {}
    for n, s in valid.items():
        if spoil in (n, "all"):
            out[n] = near_miss(draw, draw(s)) if draw(st.booleans()) else draw(anything)
        else:
            out[n] = draw(s)
    return out


def call(f, kwargs):
    return holds(lambda: f(**kwargs))


MAP_FILES = [MAPS / "movingai/room-32-32-4.map", MAPS / "movingai/maze-32-32-2.map",
             SCRATCH / "small.txt", MAPS / "ros/lab.yaml"] + corpus("ascii_map")
map_files = st.sampled_from(MAP_FILES).flatmap(
    lambda p: st.sampled_from([p, str(p), os.fsencode(str(p))]))


@FUZZ
@given(st.one_of(map_files, paths, anything))
def test_read_map(path):
    m = holds(lambda: antkit.read_map(path))
    if m is not None:
        valid_map(m)


@FUZZ
@given(arguments(a=st.one_of(bool_grids(), arrays(max_dims=3)), start=pairs(-1, 9)))
def test_map_from_array(kw):
    m = call(antkit.Map.from_array, kw)
    if m is not None:
        valid_map(m)
        np.testing.assert_array_equal(m.to_array(), np.asarray(kw["a"]))
        if kw["start"] is not None:
            assert all(integer(v) for v in kw["start"])
            assert m.start == tuple(int(v) for v in kw["start"])


names = st.text(alphabet="abcXYZ019._-", min_size=1, max_size=10)


@FUZZ
@given(bool_grids(), st.one_of(
    st.tuples(names, st.sampled_from([".map", ".txt", ".ascii", ".yaml", ".pgm", ""])).map(
        lambda t: SCRATCH / "out" / (t[0] + t[1])),
    anything.filter(lambda v: not (isinstance(v, (str, bytes)) or hasattr(v, "__fspath__")))))
def test_map_write(a, path):
    # Only paths under the scratch folder are written (the tests run in the source tree).
    (SCRATCH / "out").mkdir(exist_ok=True)
    m = holds(lambda: antkit.Map.from_array(a))
    assume(m is not None)
    if holds(lambda: m.write(path)) is None and isinstance(path, pathlib.Path) and path.suffix in (".map", ".txt", ".ascii"):
        back = antkit.read_map(path)
        assert (back.width, back.height) == (m.width, m.height)


VARIANTS = ["offline", "online", "ant", "ant-edge", "full"]
noises = st.sampled_from([None] * 8 + [0.0, 0.01, 0.5, 1.0, 0.1234567, -0.1, 2.0])
seeds = st.one_of(st.integers(0, 2**64 - 1), st.integers(0, 2**63 - 1).map(np.int64))


@FUZZ
@given(arguments(map=maps(), variant=st.sampled_from(VARIANTS + ["spiral", ""]),
                 start=st.one_of(st.none(), pairs(0, 7)), noise=noises, seed=seeds))
def test_stc(kw):
    r = call(antkit.stc, kw)
    if r is not None:
        assert r.path.dtype == np.int32 and r.path.ndim == 2 and r.path.shape[1] == 2
        assert r.positions == len(r.path) and 0 <= r.covered <= r.reachable_subcells
        if len(r.path):
            assert antkit.tour_hash(r.path, r.width, r.height) == r.hash
        assert integer(kw["seed"]) and r.get("seed", int(kw["seed"])) == int(kw["seed"])
        if kw["start"] is not None:
            assert all(integer(v) for v in kw["start"])
            assert r.start == [int(v) for v in kw["start"]]


sides = st.one_of(st.integers(6, 12), st.integers(1, 12).map(np.int16), st.integers(-2, 12))


@FUZZ
@given(arguments(path=tours(), width=sides, height=sides))
def test_tour_hash(kw):
    h = call(antkit.tour_hash, kw)
    if h is not None:
        assert isinstance(h, str) and len(h) == 16 and int(h, 16) >= 0
        assert integer(kw["width"]) and integer(kw["height"])
        p = np.asarray(kw["path"]).astype(np.int64).reshape(-1, 2)
        assert ((p >= 0) & (p < [kw["width"], kw["height"]])).all()
        assert (np.abs(np.diff(p, axis=0)).sum(axis=1) == 1).all()


flags = st.one_of(st.booleans(), st.booleans().map(np.bool_))


@FUZZ
@given(arguments(map=maps(), path=tours(), start=pairs(-1, 12), coverage=flags,
                 order=st.sampled_from(["xy", "rc", "yx"]), cells=flags))
def test_check_stc(kw):
    r = call(antkit.check_stc, kw)
    if r is not None:
        assert isinstance(r.ok, bool) and bool(r) == r.ok
        assert (r.first_violation is None) == r.ok


@st.composite
def cell_rows(draw):
    kind = draw(st.sampled_from(["rows", "rows", "chars", "path"]))
    if kind in ("rows", "chars"):
        w, h = draw(st.integers(0, 5)), draw(st.integers(0, 5))
        rows = ["".join(draw(st.lists(st.sampled_from("FSLBNOFFFFx?é\0"), min_size=w,
                                      max_size=w + draw(st.integers(0, 1)))))
                for _ in range(h)]
        return rows if kind == "rows" else [list(r) for r in rows]
    return draw(paths)


@st.composite
def explore_cases(draw):
    """A map and rows of its size (letters of every state, sometimes one that is not)."""
    a = draw(hnp.arrays(np.bool_, (draw(st.integers(1, 5)), draw(st.integers(1, 5)))))
    letters = "FSLBNO" if draw(st.booleans()) else "FSLBNOx\0é"
    rows = ["".join(draw(st.sampled_from(letters)) for _ in range(a.shape[1]))
            for _ in range(a.shape[0])]
    return antkit.Map.from_array(a), rows


@FUZZ
@given(st.one_of(explore_cases().map(lambda c: {"map": c[0], "cells": c[1]}),
                 arguments(map=maps(), cells=cell_rows())))
def test_check_explore(kw):
    r = call(antkit.check_explore, kw)
    if r is not None:
        assert isinstance(r.ok, bool)


@st.composite
def traces(draw):
    kind = draw(st.sampled_from(["array", "array", "path"]))
    if kind == "array":
        t, n = draw(st.integers(0, 4)), draw(st.integers(0, 3))
        dtype = draw(st.sampled_from([np.int64, np.int8, np.uint64, np.float64, np.int32]))
        kind = np.dtype(dtype).kind
        elements = {"i": st.integers(-2, 9), "u": st.integers(0, 9), "f": st.floats(-2, 9)}[kind]
        a = draw(hnp.arrays(dtype, (t, n, draw(st.sampled_from([3, 3, 3, 2]))), elements=elements))
        return draw(views(a))
    return draw(paths)


@FUZZ
@given(arguments(map=maps(), trace=traces(),
                 sensor=st.one_of(st.integers(0, 6), st.none(), st.integers(-2, 300))))
def test_check_cover(kw):
    r = call(antkit.check_cover, kw)
    if r is not None:
        assert isinstance(r.ok, bool)
        if kw["sensor"] is not None:
            assert integer(kw["sensor"]) and r.sensor == kw["sensor"]


lengths = st.one_of(st.floats(0, 1e10), st.integers(0, 10**6), st.just(Fraction(7, 2)),
                    st.integers(0, 100).map(np.int32))
counts = st.one_of(st.integers(0, 10**6), st.integers(0, 2**64 - 1), st.integers(0, 99).map(np.uint8))


@FUZZ
@given(arguments(length1=lengths, length2=lengths, crossings=counts, wall_encounters=counts))
def test_buffon_estimate(kw):
    r = call(antkit.buffon_estimate, kw)
    if r is not None:
        assert r.erosion_factor >= 1.0
        assert integer(kw["crossings"]) and integer(kw["wall_encounters"])
        assert r.area_raw is None or (r.area_raw >= 0 and math.isfinite(r.area_raw))


@st.composite
def trails(draw):
    kind = draw(st.sampled_from(["array", "array", "list"]))
    n = draw(st.integers(0, 8))
    dtype = draw(st.sampled_from([np.float64, np.float64, np.float32, np.int64, np.int16, np.bool_,
                                  np.complex64]))
    elements = (st.floats(allow_nan=True, allow_infinity=True, width=32)
                if np.dtype(dtype).kind in "fc" and draw(st.booleans())
                else st.floats(-100, 100, width=32) if np.dtype(dtype).kind in "fc" else None)
    a = draw(hnp.arrays(dtype, (n, draw(st.sampled_from([2, 2, 2, 3]))), elements=elements))
    return a.tolist() if kind == "list" else draw(views(a))


@FUZZ
@given(arguments(trail1=trails(), trail2=trails(), wall_encounters=counts))
def test_buffon_from_trails(kw):
    r = call(antkit.buffon_from_trails, kw)
    if r is not None:
        assert r.crossings >= 0 and r.length1 >= 0 and r.length2 >= 0
        assert integer(kw["wall_encounters"]) and r.wall_encounters == kw["wall_encounters"]


LOGS = corpus("replay_log", 12)
logs = st.sampled_from(LOGS).flatmap(lambda p: st.sampled_from([p, str(p)]))
ARENAS = ["circle:d=8", "square:area=20", "circle:d=abc", "circle:d=1e999", "", "x.wkt", "ring"]
widths = st.one_of(st.sampled_from([0.1, 0.05, 0.005, 11.0]), reals)


@FUZZ
@given(arguments(visit1=logs, visit2=logs, width=widths,
                 arena=st.one_of(st.none(), st.sampled_from(ARENAS))))
def test_buffon_from_logs(kw):
    r = call(antkit.buffon_from_logs, kw)
    if r is not None:
        assert r.crossings_exact >= 0


@FUZZ
@given(arguments(path=st.one_of(logs, paths), until=st.one_of(st.none(), st.integers(0, 50))))
def test_read_log_and_replay(kw):
    data = holds(lambda: antkit.read_log(kw["path"]))
    if data is not None:
        assert isinstance(data.records, list)
    r = call(antkit.replay, kw)
    if r is not None:
        assert isinstance(r.identical, bool)
        assert kw["until"] is None or integer(kw["until"])


# ---- bags: the corpus's MCAP files always; node's bags where node is (the ros_bags fixture) -----

TOPICS = ["/odom", "/pose", "/amcl_pose", "/tf", "/cmd_vel", "/chatter", "/nothing", ""]
topics = st.sampled_from(TOPICS)
stamps = st.sampled_from(["bag", "header", "sideways"])
frames = st.sampled_from(["base_link", "laser", "odom", ""])


def bag_paths(ros_bags):
    names = ["walk1.mcap", "walk1.db3", "walk2_bag", "walk2_zstd.mcap", "walk2_lz4.mcap",
             "tour.mcap", "tour_repeat.mcap", "cover.mcap", "cover_collide.mcap"]
    bags = ([ros_bags / n for n in names] if ros_bags else []) + corpus("mcap_reader", 8) + [
        SCRATCH, SCRATCH / "no.mcap"]
    return st.sampled_from(bags).flatmap(lambda p: st.sampled_from([p, str(p)]))


@pytest.fixture(scope="module")
def bags_or_corpus(request):
    """node's bags, or None where node is absent: the corpus's MCAP files are fuzzed either way."""
    try:
        return request.getfixturevalue("ros_bags")
    except pytest.skip.Exception as e:
        print(f"bag properties on the fuzz corpus's MCAP files alone: {e}")
        return None


def test_bag_functions(bags_or_corpus):
    """Hypothesis inside one test, so that the session fixture (node's bags) is made once."""
    bag = bag_paths(bags_or_corpus)
    free = SCRATCH / "fuzz_free.yaml"
    free.write_text("image: fuzz_free.pgm\nresolution: 0.5\norigin: [-1.0, -2.0, 0.0]\n"
                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    (SCRATCH / "fuzz_free.pgm").write_bytes(b"P5\n4 2\n255\n" + b"\xfe" * 8)

    @FUZZ
    @given(st.one_of(bag, anything))
    def info(path):
        r = holds(lambda: antkit.bag_info(path))
        if r is not None:
            assert r.messages == sum(t["messages"] for t in r.topics)

    @FUZZ
    @given(arguments(path=bag, topic=topics, stamp=stamps, child_frame=frames))
    def poses(kw):
        r = call(antkit.read_bag_poses, kw)
        if r is not None:
            n = len(r.poses)
            assert n >= 1 and r.poses.shape == (n, 3) and r.t_ns.shape == (n,)

    @FUZZ
    @given(arguments(bag1=bag, bag2=bag, topic=topics, width=widths, stamp=stamps,
                     child_frame=frames, arena=st.one_of(st.none(), st.sampled_from(ARENAS))))
    def buffon(kw):
        r = call(antkit.buffon_from_bags, kw)
        if r is not None:
            assert r.crossings_exact >= 0 and r.unit == "m"

    @FUZZ
    @given(arguments(map=st.one_of(st.just(free), st.just(str(free)), maps()), bag=bag,
                     topic=topics, stamp=stamps, child_frame=frames, start=pairs(-1, 5),
                     coverage=flags))
    def check(kw):
        r = call(antkit.check_stc_bag, kw)
        if r is not None:
            assert isinstance(r.ok, bool) and r.poses >= 1

    @FUZZ
    @given(arguments(map=st.one_of(st.just(free), st.just(str(free)), maps()), bag=bag,
                     topics=st.one_of(st.lists(st.sampled_from(TOPICS + ["/r0/pose", "/r1/pose"]),
                                               max_size=3), anything),
                     sensor=st.one_of(st.integers(-2, 300), anything), stamp=stamps,
                     child_frame=frames))
    def cover(kw):
        r = call(antkit.check_cover_bag, kw)
        if r is not None:
            assert isinstance(r.ok, bool) and r.robots == len(kw["topics"]) >= 1
            assert integer(kw["sensor"])

    info()
    poses()
    buffon()
    check()
    cover()
