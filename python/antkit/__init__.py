"""antkit from Python: deterministic, verified kernels for ant-inspired robots.

The same library as the ``antkit`` command, on numpy arrays and plain Python types:

* maps: :func:`read_map`, :meth:`Map.from_array`, :meth:`Map.to_array`, :meth:`Map.write`;
* Spanning Tree Coverage: :func:`stc` (offline, online, ant, ant-edge, full) and :func:`tour_hash`;
* the oracles for anyone's planner: :func:`check_stc`, :func:`check_explore`, :func:`check_cover`;
* paper 000's Buffon measurement: :func:`buffon_estimate`, :func:`buffon_from_trails`,
  :func:`buffon_from_logs`;
* hardware logs: :func:`read_log`, :func:`replay`;
* ROS 2 bags (.mcap, .db3, bag folders): :func:`bag_info`, :func:`read_bag_poses`,
  :func:`buffon_from_bags`, :func:`check_stc_bag`, :func:`check_cover_bag`.

Every result is the command's ``--format json`` object (the same keys, values and meanings),
readable as a mapping (``r["covered"]``) and as attributes (``r.covered``); ``to_dict()`` gives the
JSON object itself. Coordinates are ``(x, y)``: x the column, y the row counted down from the map's
first row; one map cell is one robot-sized sub-cell unless ``cells=True`` says otherwise.

Bad input raises :class:`InputError`, a ``ValueError`` whose message is the command's, with its
place (a file, ``FILE:LINE:COL``, or the argument: ``start``, ``path[3]``) in ``.where`` and the
reason in ``.message``. That includes an argument of the wrong type (no ``TypeError``) and a file
that cannot be read (no ``OSError``). Integer arguments (coordinates, counts, seeds, widths of a
tour's map) take ``int`` or a numpy integer and refuse every float, ``5.0`` included, as
``range()`` does; lengths and probabilities take any real number (``int``, ``float``, numpy
scalars) that is finite. ``bool`` is neither an integer nor a real number here. Paths are ``str``
or any ``os.PathLike`` (``pathlib.Path``). Long calls release the GIL.
"""
from __future__ import annotations

import copy
import decimal
import numbers
import operator
import os
from collections.abc import Mapping, Set
from typing import Any, Iterator, Optional, Sequence, Tuple, Union

import numpy as np

from . import _antkit
from ._antkit import InputError, Map

__version__: str = _antkit.__version__

__all__ = [
    "InputError",
    "Map",
    "Result",
    "StcResult",
    "CheckResult",
    "read_map",
    "stc",
    "tour_hash",
    "check_stc",
    "check_explore",
    "check_cover",
    "buffon_estimate",
    "buffon_from_trails",
    "buffon_from_logs",
    "read_log",
    "replay",
    "PoseTrack",
    "bag_info",
    "read_bag_poses",
    "buffon_from_bags",
    "check_stc_bag",
    "check_cover_bag",
]

PathLike = Union[str, "os.PathLike[str]"]
MapLike = Union[Map, PathLike]


def _error(where: str, message: str) -> InputError:
    """An InputError as the compiled module raises them: str() is 'WHERE: MESSAGE'."""
    e = InputError(f"{where}: {message}" if where else message)
    e.where, e.message = where, message
    return e


def _show(value: Any) -> str:
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{text} ({type(value).__name__})"


def _is_path(value: Any) -> bool:
    return isinstance(value, str) or hasattr(value, "__fspath__")


def _path(value: Any, name: str) -> str:
    """A file's path as the C++ side takes it: str or os.PathLike (bytes paths decoded as the file
    system does); never with a NUL, which would cut the name short."""
    if not (_is_path(value) or isinstance(value, bytes)):
        raise _error(name, f"expected a path (str or os.PathLike), not {_show(value)}")
    try:
        text = os.fsdecode(os.fspath(value))
    except (TypeError, ValueError, UnicodeError) as e:
        raise _error(name, f"not a usable path: {e}") from None
    if "\0" in text:
        raise _error(name, "a path cannot hold a NUL character")
    if not text:
        raise _error(name, "an empty path")
    try:
        text.encode("utf-8")
    except UnicodeError:  # lone surrogates (bytes that are not UTF-8): the library takes UTF-8
        raise _error(name, f"{text!r} is not UTF-8: antkit takes UTF-8 paths") from None
    return text


def _int(value: Any, name: str, lo: Optional[int] = None, hi: Optional[int] = None) -> int:
    """An integer argument: int or a numpy integer (anything with __index__), never a float (not
    even 5.0) and never a bool; in [lo, hi] when given."""
    if isinstance(value, (bool, np.bool_)) or not hasattr(type(value), "__index__"):
        raise _error(name, f"expected an integer, not {_show(value)}")
    try:
        v = operator.index(value)  # numpy: only integer scalars and 0-d integer arrays have one
    except TypeError:
        raise _error(name, f"expected an integer, not {_show(value)}") from None
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        lo_text = "" if lo is None else str(lo)
        hi_text = "" if hi is None else str(hi)
        raise _error(name, f"{v} is outside [{lo_text}, {hi_text}]")
    return v


def _real(value: Any, name: str) -> float:
    """A real argument: int, float or a numpy number (not bool, str or complex), finite."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise _error(name, f"expected a real number, not {_show(value)}")
    try:
        v = float(value)
    except (OverflowError, ValueError):
        raise _error(name, f"{value!r} is not a finite number") from None
    if v != v or v in (float("inf"), float("-inf")):
        raise _error(name, f"{v!r} is not a finite number")
    return v


def _bool(value: Any, name: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise _error(name, f"expected True or False, not {_show(value)}")
    return bool(value)


def _str(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise _error(name, f"expected a str, not {_show(value)}")
    if "\0" in value:
        raise _error(name, "cannot hold a NUL character")
    try:
        value.encode("utf-8")
    except UnicodeError:
        raise _error(name, f"{value!r} is not valid Unicode text") from None
    return value


def _optional_str(value: Any, name: str) -> Optional[str]:
    return None if value is None else _str(value, name)


_I32 = (-(2**31), 2**31 - 1)
_U64 = (0, 2**64 - 1)


def _pair(value: Any, name: str) -> Optional[Tuple[int, int]]:
    """None, or a pair (x, y) of integers (a tuple, a list, a numpy array of two integers)."""
    if value is None:
        return None
    try:
        if isinstance(value, (str, bytes, Mapping, Set)) or len(value) != 2:
            raise TypeError
        x, y = value
    except (TypeError, ValueError):  # no len(), a 0-d array, a set of one, ...
        raise _error(name, f"expected a pair (x, y) of integers, not {_show(value)}") from None
    if isinstance(x, (bool, np.bool_)) or isinstance(y, (bool, np.bool_)) or not (
        hasattr(type(x), "__index__") and hasattr(type(y), "__index__")
    ):
        raise _error(name, f"expected a pair (x, y) of integers, not {_show(value)}")
    return _int(x, name, *_I32), _int(y, name, *_I32)


def _array(value: Any, name: str) -> np.ndarray:
    """An array argument as numpy reads it; what numpy cannot make an array of is bad input."""
    if isinstance(value, np.ndarray):
        return value
    if isinstance(value, (str, bytes)) or value is None:
        raise _error(name, f"expected an array, not {_show(value)}")
    try:
        return np.asarray(value)
    except (TypeError, ValueError, OverflowError) as e:
        raise _error(name, f"not an array: {e}") from None


def _pairs(value: Any, name: str) -> np.ndarray:
    """An (n, 2) integer array (or an empty sequence); the compiled side checks shape and dtype."""
    a = _array(value, name)
    if a.ndim == 1 and a.size == 0:
        return np.zeros((0, 2), dtype=np.int64)
    return a


def read_map(path: PathLike) -> Map:
    """Reads a map: MovingAI (.map), ROS (.yaml and its image) or ASCII (.txt, .ascii; 'S' the
    start), by the name's extension. ``path``: str or os.PathLike. InputError at FILE:LINE:COL when
    malformed, naming the file when it cannot be read."""
    return _antkit._read_map(_path(path, "path"))


def _map_from_array(a: Any, *, start: Optional[Sequence[int]] = None) -> Map:
    """A map from a 2-D bool array, True = free, a[y, x] (row = y): any layout (views, strides,
    broadcasts); at most 2^20 cells a side and 2^28 cells in all, as for map files. ``start``: an
    optional free (x, y), as an ASCII map's 'S'."""
    return Map._from_array(_array(a, "a"), _pair(start, "start"))


def _map_write(self: Map, path: PathLike) -> None:
    """Writes the map: MovingAI (.map) or ASCII (.txt, .ascii; the start as 'S'), by the name's
    extension (ROS maps are read-only); written whole or not at all. ``path``: str or
    os.PathLike."""
    self._write(_path(path, "path"))


Map.from_array = staticmethod(_map_from_array)
Map.write = _map_write
# Shown as antkit.Map and antkit.InputError, where users import them from.
Map.__module__ = InputError.__module__ = __name__


def _map(value: MapLike) -> Map:
    if isinstance(value, Map):
        return value
    if _is_path(value):
        return read_map(value)
    raise _error("map", f"expected an antkit.Map or a map file's path, not {_show(value)}")


def _read_text(path: PathLike, name: str) -> Tuple[str, str]:
    """A text file's contents (bytes that are not UTF-8 replaced, so that the parser names the
    place) and its name for messages; a file that cannot be read is an InputError naming it."""
    p = _path(path, name)
    try:
        with open(p, "rb") as f:
            return f.read().decode("utf-8", errors="replace"), p
    except OSError as e:
        raise _error(p, f"cannot read it: {e.strerror or e}") from None


def tour_hash(path: Any, width: int, height: int) -> str:
    """The trace hash of a tour given as its (x, y) positions (an (n, 2) integer array or a list
    of pairs), the start first, on a map of width x height sub-cells: antkit stc's "hash" for the
    same tour. Every position must lie on the map and each be a 4-neighbour of the one before
    (InputError at ``path[i]`` otherwise)."""
    return _antkit._tour_hash(
        _pairs(path, "path"), _int(width, "width", *_I32), _int(height, "height", *_I32)
    )


class Result(Mapping):
    """A result: the ``antkit`` command's JSON object, as a read-only mapping and attributes."""

    __slots__ = ("_fields",)

    def __init__(self, fields: dict) -> None:
        object.__setattr__(self, "_fields", fields)

    def __getattr__(self, name: str) -> Any:
        try:
            return self._fields[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no field {name!r}") from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key: str) -> Any:
        return self._fields[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._fields)

    def __len__(self) -> int:
        return len(self._fields)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._fields))

    def to_dict(self) -> dict:
        """The JSON object as the command prints it (a deep copy)."""
        return copy.deepcopy(self._fields)

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={v!r}" for k, v in self._fields.items())
        return f"{type(self).__name__}({inner})"


class StcResult(Result):
    """A tour of :func:`stc`: ``path`` an (n, 2) int32 array of (x, y) sub-cells, the start first;
    the fields of ``antkit stc --format json`` (variant, width, height, start, reachable_subcells,
    covered, repeats, returned_to_start, hash; noise_ppm and seed with noise) and two more:
    ``closed`` (the controller stopped rather than being cut off) and ``positions`` (len(path))."""

    __slots__ = ("_path",)

    def __init__(self, fields: dict, path: np.ndarray) -> None:
        super().__init__(fields)
        path.setflags(write=False)
        object.__setattr__(self, "_path", path)

    @property
    def path(self) -> np.ndarray:
        return self._path

    def to_dict(self) -> dict:
        """The JSON object of ``antkit stc --format json``, its "path" a list of [x, y] pairs (with
        the two fields the command does not print, closed and positions)."""
        out = super().to_dict()
        out["path"] = self._path.tolist()
        return out


class CheckResult(Result):
    """An oracle's verdict: ``ok``; for check_stc ``rule`` (the rule checked: exactly-once or
    coverage); ``first_violation`` (None when ok; for check_stc a dict with ``rule``, ``step``,
    ``subcell`` and ``detail``, for check_explore and check_cover a message); and the counts of the
    command's JSON. ``bool(result)`` is ``result.ok``."""

    __slots__ = ()

    def __bool__(self) -> bool:
        return bool(self._fields["ok"])


def stc(
    map: MapLike,
    variant: str,
    start: Optional[Sequence[int]] = None,
    *,
    noise: Optional[float] = None,
    seed: int = 0,
) -> StcResult:
    """Runs Spanning Tree Coverage on ``map`` (``antkit stc``).

    ``variant``: "offline", "online", "ant", "ant-edge" or "full". ``start``: the start sub-cell
    (x, y); by default the map's own start, else the first place of the largest region. ``noise``:
    the probability that a mark is misread (ant and ant-edge only; at most six decimals, as on the
    command line), drawn from ``seed``'s stream.
    """
    m = _map(map)
    # The probability as the command reads it: its shortest decimal (repr), written out without an
    # exponent, so that a value with more than six decimals is refused as on the command line.
    text = None if noise is None else format(decimal.Decimal(repr(_real(noise, "noise"))), "f")
    fields, path = _antkit._stc(
        m, _str(variant, "variant"), _pair(start, "start"), text, _int(seed, "seed", *_U64)
    )
    return StcResult(fields, path)


def check_stc(
    map: MapLike,
    path: Any,
    start: Optional[Sequence[int]] = None,
    coverage: bool = False,
    order: str = "xy",
    cells: bool = False,
) -> CheckResult:
    """Checks a coverage tour against the map (``antkit check stc``).

    ``path``: an (n, 2) integer array or a list of pairs, in ``order`` ("xy": column, row; "rc":
    row, col, numpy's), or a tour file (JSON, CSV with an optional x,y / row,col / y,x header, or
    antkit's binary path). ``start`` is always (x, y); by default the tour file's start, else the
    map's, else the tour's first position. Exactly once (STC's promise): every sub-cell of the free
    2 x 2 cells 4-connected to the start's cell entered once, 4-adjacent moves, ending next to the
    start. ``coverage=True``: every free sub-cell 4-connected to the start at least once, repeats
    counted. ``cells=True``: the map and ``start`` are in robot-sized cells (2 x 2 sub-cells each),
    the tour in sub-cells, starting in any sub-cell of the start cell.
    """
    m = _map(map)
    tour = _path(path, "path") if _is_path(path) else _pairs(path, "path")
    return CheckResult(
        _antkit._check_stc(
            m,
            tour,
            _pair(start, "start"),
            _bool(coverage, "coverage"),
            _str(order, "order"),
            _bool(cells, "cells"),
        )
    )


def check_explore(map: MapLike, cells: Any) -> CheckResult:
    """Checks LOS exploration cell states against the true map (``antkit check explore``): S, LOS
    and S+LOS cells must be free, O cells not free.

    ``cells``: a file (``antkit explore``'s JSON, a JSON array of rows, or text rows), or the rows
    as a sequence of strings, one letter per cell (F S L B N O; B for S+LOS).
    """
    m = _map(map)
    if _is_path(cells):
        text, source = _read_text(cells, "cells")
        return CheckResult(_antkit._check_explore_text(m, text, source))
    if isinstance(cells, bytes) or not isinstance(cells, Sequence) and not isinstance(
        cells, np.ndarray
    ):
        raise _error("cells", f"expected a file or a sequence of row strings, not {_show(cells)}")
    if isinstance(cells, np.ndarray) and cells.ndim != 1:
        raise _error("cells", f"expected a sequence of row strings, not a {cells.ndim}-D array")
    if len(cells) > 1 << 15:  # the library's cap, before a loop over what a view only claims
        raise _error("cells", f"{len(cells)} rows, more than 32768")
    rows = []
    for i, row in enumerate(cells):
        if isinstance(row, (list, tuple)) and all(isinstance(c, str) for c in row):
            row = "".join(row)
        rows.append(_str(row, f"cells[{i}]"))
    return CheckResult(_antkit._check_explore_rows(m, rows))


def check_cover(map: MapLike, trace: Any, sensor: Optional[int] = None) -> CheckResult:
    """Checks a coverage run's trace (``antkit check cover``): legal moves and turns, no two robots
    on one cell, and the coverage it claims recomputed from its poses.

    ``trace``: a file (``antkit cover --trace``), or an integer array of shape (ticks, robots, 3)
    holding each robot's (x, y, bearing) after each tick, tick 0 the start (bearing 0..7, 0 east,
    counter-clockwise in 45-degree steps with y down). ``sensor``: the sensor distance in cells
    (required for an array; a file's "# sensor:" line otherwise).
    """
    m = _map(map)
    sensor_value = None if sensor is None else _int(sensor, "sensor", -(2**63), 2**63 - 1)
    if _is_path(trace):
        text, source = _read_text(trace, "trace")
        return CheckResult(_antkit._check_cover_text(m, text, source, sensor_value))
    return CheckResult(_antkit._check_cover_array(m, _array(trace, "trace"), sensor_value))


def buffon_estimate(
    length1: float, length2: float, crossings: int, wall_encounters: int = 0
) -> Result:
    """Paper 000's area estimate from two trails (Buffon-Crofton): A = 2 L1 L2 / (pi N) with its
    95 % interval (N Poisson), and the erosion correction 1 + kappa E / (L1 + L2) from E wall
    encounters. Lengths in body diameters (rounded to the kernel's Q15.16). Fields: area_raw,
    area_raw_ci, erosion_factor, area_corrected (the arena's area), area_corrected_ci; an area or
    interval end is None when N cannot give it."""
    return Result(
        _antkit._buffon_estimate(
            _real(length1, "length1"),
            _real(length2, "length2"),
            _int(crossings, "crossings", *_U64),
            _int(wall_encounters, "wall_encounters", *_U64),
        )
    )


def buffon_from_trails(trail1: Any, trail2: Any, wall_encounters: int = 0) -> Result:
    """Paper 000's estimate from two trails given as points ((n, 2) arrays, in body diameters):
    the exact proper crossings of the two polylines (the kernel's predicate, on the points rounded
    to its Q15.16 coordinates, |x|, |y| < 32768), their lengths, and :func:`buffon_estimate`'s
    fields. Fields: length1, length2, crossings, wall_encounters, area_raw, area_raw_ci,
    erosion_factor, area_corrected, area_corrected_ci."""
    return Result(
        _antkit._buffon_from_trails(
            _points(trail1, "trail1"),
            _points(trail2, "trail2"),
            _int(wall_encounters, "wall_encounters", *_U64),
        )
    )


def _points(value: Any, name: str) -> np.ndarray:
    """An (n, 2) array of real coordinates (integers or floats; not bool, complex or objects)."""
    a = _array(value, name)
    if a.ndim == 1 and a.size == 0:
        return np.zeros((0, 2), dtype=np.float64)
    if a.dtype.kind not in "iuf":
        raise _error(name, f"expected an (n, 2) array of real numbers, not dtype {a.dtype}")
    return a


def buffon_from_logs(
    visit1: PathLike, visit2: PathLike, width: float = 0.1, arena: Optional[str] = None
) -> Result:
    """Paper 000's measurement from two recorded visits' odometry (``antkit buffon-from-logs``):
    the erosion-corrected area with its interval, the raw closed form, BC and the exact crossing
    count. ``arena``: a named spec or a .wkt file when the logs' headers do not name it."""
    return Result(
        _antkit._buffon_from_logs(
            _path(visit1, "visit1"),
            _path(visit2, "visit2"),
            _real(width, "width"),
            _optional_str(arena, "arena"),
        )
    )


def read_log(path: PathLike) -> Result:
    """Reads a hardware log (``antkit record``'s JSON Lines): ``header`` (robot, controller,
    params, seed, ...), ``records`` (each with step, t_ns, io [{sent, received} as bytes], obs,
    cmd, odo, state), ``stop`` (the stop record, or None when the log has none) and ``truncated``
    (its last line was cut). Nothing is replayed: see :func:`replay`."""
    return Result(_antkit._read_log(_path(path, "path")))


def replay(path: PathLike, until: Optional[int] = None) -> Result:
    """Replays a hardware log through the controller its header names and checks every byte,
    observation, command and state hash (``antkit replay``): identical, first_divergence (step,
    field, expected, actual), complete (the log ends with its stop record), hash, ..."""
    return Result(
        _antkit._replay(
            _path(path, "path"), None if until is None else _int(until, "until", 0, 2**63 - 1)
        )
    )


# ---- ROS 2 bags ---------------------------------------------------------------------------------


class PoseTrack(Result):
    """One pose topic of a bag (:func:`read_bag_poses`): ``bag``, ``topic``, ``type`` (its ROS 2
    type), ``stamp`` ("bag" or "header": which time ``t_ns`` holds), ``child_frame`` (for a
    tf2_msgs/msg/TFMessage topic, else None), ``messages`` (on the topic), and numpy columns, one
    row per pose in the bag's order: ``poses`` (n, 3) float64 of (x, y, yaw) in metres and
    radians, ``t_ns`` (n,) int64 (the chosen stamp), ``bag_ns`` (n,) uint64 (bag time) and
    ``header_ns`` (n,) int64 (header.stamp; None for a Twist topic, which has none). The arrays
    are read-only; ``to_dict()`` gives them as lists."""

    __slots__ = ()

    def __init__(self, fields: dict) -> None:
        for key in ("poses", "t_ns", "bag_ns", "header_ns"):
            if isinstance(fields.get(key), np.ndarray):
                fields[key].setflags(write=False)
        super().__init__(fields)

    def to_dict(self) -> dict:
        """The fields, the arrays as lists."""
        out = {}
        for k, v in self._fields.items():
            out[k] = v.tolist() if isinstance(v, np.ndarray) else copy.deepcopy(v)
        return out


_STAMPS = "stamp: 'bag' (when the bag recorded it) or 'header' (the message's header.stamp)"


def bag_info(path: PathLike) -> Result:
    """A ROS 2 bag's contents (``antkit bag info``): ``bag``, ``storage`` ("mcap" or "sqlite3"),
    ``files``, ``messages``, ``start_ns``, ``end_ns`` (bag time, ns since the epoch; None without
    messages), ``duration_s`` and ``topics`` (each ``topic``, ``type``, ``encoding``,
    ``messages``, ``start_ns``, ``end_ns``). ``path``: an .mcap or .db3 file or a bag folder with
    metadata.yaml."""
    return Result(_antkit._bag_info(_path(path, "path")))


def read_bag_poses(
    path: PathLike, topic: str, stamp: str = "bag", child_frame: str = "base_link"
) -> PoseTrack:
    """The poses of one topic of a ROS 2 bag, as ``check stc --bag`` and ``buffon-from-logs
    --topic`` read them: nav_msgs/msg/Odometry, geometry_msgs/msg/PoseStamped,
    PoseWithCovarianceStamped, a Twist integrated over bag time from the origin, or a
    tf2_msgs/msg/TFMessage's ``child_frame``. ``stamp``: "bag" or "header" (not for a Twist).
    InputError, located in the bag, for a topic it does not hold, a type antkit does not decode or
    a message that does not decode."""
    return PoseTrack(
        _antkit._read_bag_poses(
            _path(path, "path"),
            _str(topic, "topic"),
            _str(stamp, "stamp"),
            _str(child_frame, "child_frame"),
        )
    )


def buffon_from_bags(
    bag1: PathLike,
    bag2: PathLike,
    topic: str,
    width: float = 0.1,
    stamp: str = "bag",
    child_frame: str = "base_link",
    arena: Optional[str] = None,
) -> Result:
    """Paper 000's measurement from two bags' pose topics taken as two random walks, in the bags'
    metres (``antkit buffon-from-logs --topic``): the poses to the kernel's Q15.16 metres, the
    exact proper crossings of the two polylines, BC along walk 2 over walk 1's band of ``width``
    metres (in [0.01, 10]), the area in m² with its 95 % interval. The same fields as
    :func:`buffon_from_logs` (``unit`` "m", every ``*_m2`` equal to its twin, ``visit1`` and
    ``visit2`` with the bag, topic, poses, length and time range). ``arena``: a named spec or a
    .wkt file (lengths in metres) for the true area and the relative error."""
    return Result(
        _antkit._buffon_from_bags(
            _path(bag1, "bag1"),
            _path(bag2, "bag2"),
            _str(topic, "topic"),
            _real(width, "width"),
            _str(stamp, "stamp"),
            _str(child_frame, "child_frame"),
            _optional_str(arena, "arena"),
        )
    )


def check_stc_bag(
    map: MapLike,
    bag: PathLike,
    topic: str,
    stamp: str = "bag",
    child_frame: str = "base_link",
    start: Optional[Sequence[int]] = None,
    coverage: bool = False,
) -> CheckResult:
    """A bag's recorded poses checked as a coverage tour on ``map`` (``antkit check stc --bag``):
    each pose to the map cell it lies in through the map's resolution and origin (a ROS map's;
    1 m and 0 for other maps), the cells between two poses filled in as the robot passed them,
    then :func:`check_stc`'s rules (exactly once, or ``coverage=True``) from ``start`` (x, y; by
    default the map's start, else the first pose's cell). :func:`check_stc`'s fields, and ``bag``,
    ``topic``, ``type``, ``stamp``, ``poses`` and ``first_violation_time_ns`` (the broken rule's
    time in the bag). InputError for a pose off the map, with its time."""
    m = _map(map)
    return CheckResult(
        _antkit._check_stc_bag(
            m,
            _path(bag, "bag"),
            _str(topic, "topic"),
            _str(stamp, "stamp"),
            _str(child_frame, "child_frame"),
            _pair(start, "start"),
            _bool(coverage, "coverage"),
        )
    )


def check_cover_bag(
    map: MapLike,
    bag: PathLike,
    topics: Sequence[str],
    sensor: int,
    stamp: str = "bag",
    child_frame: str = "base_link",
) -> CheckResult:
    """A bag's recorded poses checked as a coverage run on ``map`` (``antkit check cover --bag``):
    each topic of ``topics`` one robot, its cells read as :func:`check_stc_bag` reads them; tick 0
    puts every robot on its first cell, and each later tick is one robot entering its next cell in
    bag time (ties in topic order), the others staying. :func:`check_cover`'s rules and fields
    (free cells, no two robots on one cell, the coverage recomputed with ``sensor`` cells of line
    of sight), and ``bag``, ``stamp``, ``topics`` (each ``topic``, ``type``, ``poses``) and
    ``first_violation_time_ns`` (the broken rule's time in the bag). InputError for a pose off the
    map, with its time, a topic given twice or none."""
    m = _map(map)
    if isinstance(topics, (str, bytes)) or not isinstance(topics, Sequence):
        raise _error("topics", f"expected a sequence of topic names, not {_show(topics)}")
    names = [_str(t, "topics") for t in topics]
    return CheckResult(
        _antkit._check_cover_bag(
            m,
            _path(bag, "bag"),
            names,
            _int(sensor, "sensor", 0, 255),
            _str(stamp, "stamp"),
            _str(child_frame, "child_frame"),
        )
    )
