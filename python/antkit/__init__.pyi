# Type stubs of the antkit package (python/antkit/__init__.py and the compiled antkit._antkit).
import os
from collections.abc import Mapping
from typing import Any, Iterator, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, os.PathLike[str]]

class InputError(ValueError):
    """Bad input (a malformed file, an argument of the wrong type, an out-of-range value):
    str() is 'WHERE: MESSAGE', located in a file or at the argument."""

    where: str
    message: str

class Map:
    """A grid map: x the column, y the row counted down from the first row."""

    @property
    def width(self) -> int:
        """The number of columns (cells along x)."""
    @property
    def height(self) -> int:
        """The number of rows (cells along y, counted down from the first row)."""
    @property
    def start(self) -> Optional[Tuple[int, int]]:
        """The map's own start cell (x, y), or None."""
    @property
    def source(self) -> str:
        """The file the map was read from; '' for a map made from an array."""
    @property
    def resolution(self) -> float:
        """Metres per cell (a ROS map's; 1.0 otherwise)."""
    @property
    def origin(self) -> Tuple[float, float, float]:
        """A ROS map's origin (x, y, yaw) of its lower-left pixel; zeros otherwise."""
    @staticmethod
    def from_array(a: npt.ArrayLike, *, start: Optional[Sequence[int]] = ...) -> Map: ...
    def to_array(self) -> npt.NDArray[np.bool_]: ...
    def write(self, path: PathLike) -> None: ...
    def __eq__(self, other: object) -> bool: ...

MapLike = Union[Map, PathLike]

class Result(Mapping[str, Any]):
    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, key: str) -> Any: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...
    def to_dict(self) -> dict[str, Any]: ...

class StcResult(Result):
    @property
    def path(self) -> npt.NDArray[np.int32]: ...
    variant: str
    width: int
    height: int
    start: list[int]
    reachable_subcells: int
    covered: int
    repeats: int
    returned_to_start: bool
    hash: str
    closed: bool
    positions: int

class CheckResult(Result):
    ok: bool
    first_violation: Any
    def __bool__(self) -> bool: ...

def read_map(path: PathLike) -> Map: ...
def stc(
    map: MapLike,
    variant: str,
    start: Optional[Sequence[int]] = ...,
    *,
    noise: Optional[float] = ...,
    seed: int = ...,
) -> StcResult: ...
def tour_hash(path: npt.ArrayLike, width: int, height: int) -> str: ...
def check_stc(
    map: MapLike,
    path: Union[npt.ArrayLike, PathLike],
    start: Optional[Sequence[int]] = ...,
    coverage: bool = ...,
    order: str = ...,
    cells: bool = ...,
) -> CheckResult: ...
def check_explore(map: MapLike, cells: Union[PathLike, Sequence[str]]) -> CheckResult: ...
def check_cover(
    map: MapLike, trace: Union[PathLike, npt.ArrayLike], sensor: Optional[int] = ...
) -> CheckResult: ...
def buffon_estimate(
    length1: float, length2: float, crossings: int, wall_encounters: int = ...
) -> Result: ...
def buffon_from_trails(
    trail1: npt.ArrayLike, trail2: npt.ArrayLike, wall_encounters: int = ...
) -> Result: ...
def buffon_from_logs(
    visit1: PathLike, visit2: PathLike, width: float = ..., arena: Optional[str] = ...
) -> Result: ...
def read_log(path: PathLike) -> Result: ...
def replay(path: PathLike, until: Optional[int] = ...) -> Result: ...

class PoseTrack(Result):
    bag: str
    topic: str
    type: str
    stamp: str
    child_frame: Optional[str]
    messages: int
    poses: npt.NDArray[np.float64]  # (n, 3): x, y, yaw
    t_ns: npt.NDArray[np.int64]
    bag_ns: npt.NDArray[np.uint64]
    header_ns: Optional[npt.NDArray[np.int64]]

def bag_info(path: PathLike) -> Result: ...
def read_bag_poses(
    path: PathLike, topic: str, stamp: str = ..., child_frame: str = ...
) -> PoseTrack: ...
def buffon_from_bags(
    bag1: PathLike,
    bag2: PathLike,
    topic: str,
    width: float = ...,
    stamp: str = ...,
    child_frame: str = ...,
    arena: Optional[str] = ...,
) -> Result: ...
def check_stc_bag(
    map: MapLike,
    bag: PathLike,
    topic: str,
    stamp: str = ...,
    child_frame: str = ...,
    start: Optional[Sequence[int]] = ...,
    coverage: bool = ...,
) -> CheckResult: ...
def check_cover_bag(
    map: MapLike,
    bag: PathLike,
    topics: Sequence[str],
    sensor: int,
    stamp: str = ...,
    child_frame: str = ...,
) -> CheckResult: ...
