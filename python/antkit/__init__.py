"""antkit from Python: deterministic, verified kernels for ant-inspired robots.

The same library as the ``antkit`` command, on numpy arrays and plain Python types:

* maps: :func:`read_map`, :meth:`Map.from_array`, :meth:`Map.to_array`, :meth:`Map.write`;
* Spanning Tree Coverage: :func:`stc` (offline, online, ant, ant-edge, full) and :func:`tour_hash`;
* the oracles for anyone's planner: :func:`check_stc`, :func:`check_explore`, :func:`check_cover`;
* paper 000's Buffon measurement: :func:`buffon_estimate`, :func:`buffon_from_trails`,
  :func:`buffon_from_logs`;
* hardware logs: :func:`read_log`, :func:`replay`.

Every result is the command's ``--format json`` object (the same keys, values and meanings),
readable as a mapping (``r["covered"]``) and as attributes (``r.covered``); ``to_dict()`` gives the
JSON object itself. Coordinates are ``(x, y)``: x the column, y the row counted down from the map's
first row; one map cell is one robot-sized sub-cell unless ``cells=True`` says otherwise.

Bad input raises :class:`InputError`, a ``ValueError`` whose message is the command's, with its
place (a file, ``FILE:LINE:COL``, or the argument) in ``.where`` and the reason in ``.message``.
Long calls release the GIL.
"""
from __future__ import annotations

import copy
import decimal
import os
from collections.abc import Mapping
from typing import Any, Iterator, Optional, Sequence, Tuple, Union

import numpy as np

from . import _antkit
from ._antkit import InputError, Map, read_map, tour_hash

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
]

PathLike = Union[str, "os.PathLike[str]"]
MapLike = Union[Map, PathLike]


def _is_path(value: Any) -> bool:
    return isinstance(value, str) or hasattr(value, "__fspath__")


def _map(value: MapLike) -> Map:
    if isinstance(value, Map):
        return value
    if _is_path(value):
        return read_map(os.fspath(value))
    raise TypeError(f"expected an antkit.Map or a map file's path, not {type(value).__name__}")


def _read_text(path: PathLike) -> Tuple[str, str]:
    """A text file's contents (bytes that are not UTF-8 replaced, so that the parser names the
    place) and its name for messages."""
    with open(os.fspath(path), "rb") as f:
        return f.read().decode("utf-8", errors="replace"), os.fspath(path)


def _pair(value: Optional[Sequence[int]], name: str) -> Optional[Tuple[int, int]]:
    if value is None:
        return None
    try:
        x, y = value
        return int(x), int(y)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a pair (x, y) of integers, not {value!r}") from None


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
    # The probability as the command reads it: its shortest decimal (repr), written out without an
    # exponent, so that a value with more than six decimals is refused as on the command line.
    text = None if noise is None else format(decimal.Decimal(repr(float(noise))), "f")
    fields, path = _antkit._stc(_map(map), variant, _pair(start, "start"), text, int(seed))
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
    return CheckResult(
        _antkit._check_stc(
            _map(map), path, _pair(start, "start"), bool(coverage), order, bool(cells)
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
        text, source = _read_text(cells)
    else:
        rows = ["".join(row) if not isinstance(row, str) else row for row in cells]
        text, source = "\n".join(rows) + "\n", "cells"
    return CheckResult(_antkit._check_explore_text(m, text, source))


def check_cover(map: MapLike, trace: Any, sensor: Optional[int] = None) -> CheckResult:
    """Checks a coverage run's trace (``antkit check cover``): legal moves and turns, no two robots
    on one cell, and the coverage it claims recomputed from its poses.

    ``trace``: a file (``antkit cover --trace``), or an integer array of shape (ticks, robots, 3)
    holding each robot's (x, y, bearing) after each tick, tick 0 the start (bearing 0..7, 0 east,
    counter-clockwise in 45-degree steps with y down). ``sensor``: the sensor distance in cells
    (required for an array; a file's "# sensor:" line otherwise).
    """
    m = _map(map)
    if _is_path(trace):
        text, source = _read_text(trace)
    else:
        a = np.asarray(trace)
        if a.ndim != 3 or a.shape[2] != 3 or a.dtype.kind not in "iu":
            raise TypeError(
                "check_cover: trace is a file or an integer array of shape (ticks, robots, 3), "
                f"not {a.dtype} of shape {a.shape}"
            )
        lines = ["tick,robot,x,y,bearing"]
        for t in range(a.shape[0]):
            for r in range(a.shape[1]):
                x, y, b = a[t, r]
                lines.append(f"{t},{r},{x},{y},{b}")
        text, source = "\n".join(lines) + "\n", "trace"
    return CheckResult(
        _antkit._check_cover_text(m, text, source, None if sensor is None else int(sensor))
    )


def buffon_estimate(
    length1: float, length2: float, crossings: int, wall_encounters: int = 0
) -> Result:
    """Paper 000's area estimate from two trails (Buffon-Crofton): A = 2 L1 L2 / (pi N) with its
    95 % interval (N Poisson), and the erosion correction 1 + kappa E / (L1 + L2) from E wall
    encounters. Lengths in body diameters (rounded to the kernel's Q15.16). Fields: area_raw,
    area_raw_ci, erosion_factor, area_corrected (the arena's area), area_corrected_ci; an area or
    interval end is None when N cannot give it."""
    return Result(
        _antkit._buffon_estimate(float(length1), float(length2), int(crossings), int(wall_encounters))
    )


def buffon_from_trails(trail1: Any, trail2: Any, wall_encounters: int = 0) -> Result:
    """Paper 000's estimate from two trails given as points ((n, 2) arrays, in body diameters):
    the exact proper crossings of the two polylines (the kernel's predicate, on the points rounded
    to its Q15.16 coordinates, |x|, |y| < 32768), their lengths, and :func:`buffon_estimate`'s
    fields. Fields: length1, length2, crossings, wall_encounters, area_raw, area_raw_ci,
    erosion_factor, area_corrected, area_corrected_ci."""
    return Result(
        _antkit._buffon_from_trails(np.asarray(trail1), np.asarray(trail2), int(wall_encounters))
    )


def buffon_from_logs(
    visit1: PathLike, visit2: PathLike, width: float = 0.1, arena: Optional[str] = None
) -> Result:
    """Paper 000's measurement from two recorded visits' odometry (``antkit buffon-from-logs``):
    the erosion-corrected area with its interval, the raw closed form, BC and the exact crossing
    count. ``arena``: a named spec or a .wkt file when the logs' headers do not name it."""
    return Result(
        _antkit._buffon_from_logs(os.fspath(visit1), os.fspath(visit2), float(width), arena)
    )


def read_log(path: PathLike) -> Result:
    """Reads a hardware log (``antkit record``'s JSON Lines): ``header`` (robot, controller,
    params, seed, ...), ``records`` (each with step, t_ns, io [{sent, received} as bytes], obs,
    cmd, odo, state), ``stop`` (the stop record, or None when the log has none) and ``truncated``
    (its last line was cut). Nothing is replayed: see :func:`replay`."""
    return Result(_antkit._read_log(os.fspath(path)))


def replay(path: PathLike, until: Optional[int] = None) -> Result:
    """Replays a hardware log through the controller its header names and checks every byte,
    observation, command and state hash (``antkit replay``): identical, first_divergence (step,
    field, expected, actual), complete (the log ends with its stop record), hash, ..."""
    return Result(_antkit._replay(os.fspath(path), None if until is None else int(until)))
