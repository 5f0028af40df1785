# Type stubs of the `linemap` extension module (python/linemap_module.cc and
# the files it registers), for editors and type checkers: the module is
# compiled, so they cannot read its signatures from source. Installed next to
# the module (editors, pyright) and as the stub-only package linemap-stubs
# (PEP 561; mypy reads installed modules' stubs only from there). tests/python/test_stubs.py checks that every name and
# parameter here matches what the built module reports.
import os
from typing import Any, ClassVar, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

FREE: int
OCCUPIED: int
UNKNOWN: int

_Path = Union[str, "os.PathLike[str]"]
# .lmap bytes: any contiguous buffer (bytes, bytearray, memoryview, numpy).
_Buffer = Union[bytes, bytearray, memoryview, npt.NDArray[np.uint8]]
_Source = Union[_Path, _Buffer]
_Window = Tuple[int, int, int, int]

class DecodeLimits:
    __hash__: ClassVar[None]  # type: ignore[assignment]  # __eq__ compares the limits
    def __init__(
        self,
        *,
        max_file_bytes: int = 2147483648,
        max_cells: int = 1073741824,
        max_chunk_bytes: int = 1073741824,
        max_inflated_bytes: int = 268435456,
        max_segments: int = 16777216,
        max_chain_length: int = 67108864,
        max_objects: int = 1048576,
        max_threads: int = 0,
    ) -> None: ...
    @property
    def max_file_bytes(self) -> int: ...
    @max_file_bytes.setter
    def max_file_bytes(self, value: int) -> None: ...
    @property
    def max_cells(self) -> int: ...
    @max_cells.setter
    def max_cells(self, value: int) -> None: ...
    @property
    def max_chunk_bytes(self) -> int: ...
    @max_chunk_bytes.setter
    def max_chunk_bytes(self, value: int) -> None: ...
    @property
    def max_inflated_bytes(self) -> int: ...
    @max_inflated_bytes.setter
    def max_inflated_bytes(self, value: int) -> None: ...
    @property
    def max_segments(self) -> int: ...
    @max_segments.setter
    def max_segments(self, value: int) -> None: ...
    @property
    def max_chain_length(self) -> int: ...
    @max_chain_length.setter
    def max_chain_length(self, value: int) -> None: ...
    @property
    def max_objects(self) -> int: ...
    @max_objects.setter
    def max_objects(self, value: int) -> None: ...
    @property
    def max_threads(self) -> int: ...
    @max_threads.setter
    def max_threads(self, value: int) -> None: ...

class Map:
    def __init__(
        self,
        cells: npt.NDArray[np.uint8],
        resolution: float = 0.05,
        origin: Sequence[float] = (0.0, 0.0, 0.0),
    ) -> None: ...
    @property
    def cells(self) -> npt.NDArray[np.uint8]: ...
    @cells.setter
    def cells(self, value: npt.NDArray[np.uint8]) -> None: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def resolution(self) -> float: ...
    @resolution.setter
    def resolution(self, value: float) -> None: ...
    @property
    def origin(self) -> Tuple[float, float, float]: ...
    @origin.setter
    def origin(self, value: Sequence[float]) -> None: ...
    @property
    def occupied_thresh(self) -> float: ...
    @property
    def free_thresh(self) -> float: ...
    @property
    def negate(self) -> bool: ...
    @property
    def mode(self) -> str: ...
    @property
    def tolerance(self) -> Optional[int]: ...
    def set_thresholds(self, occupied_thresh: float, free_thresh: float) -> None: ...
    @staticmethod
    def from_occupancy_grid(
        data: Union[npt.ArrayLike, Sequence[int]],
        width: int,
        height: int,
        resolution: float,
        origin: Sequence[float] = (0.0, 0.0, 0.0),
        *,
        occupied_thresh: float = 0.65,
        free_thresh: float = 0.25,
        max_cells: Optional[int] = None,
    ) -> Map: ...
    def to_occupancy_grid(self, frame_id: str = "map") -> dict[str, Any]: ...

def load(
    path: _Path,
    max_cells: Optional[int] = None,
    window_cells: Optional[_Window] = None,
    *,
    limits: Optional[DecodeLimits] = None,
) -> Map: ...
def save(
    path: _Path,
    map: Map,
    tolerance: int = 0,
    vectors: bool = True,
    straight_walls: bool = False,
    compact: bool = False,
    max_tolerance_cells: int = 67108864,
    *,
    metadata: Optional[Mapping[str, Any]] = None,
) -> None: ...
def convert(
    source: _Path,
    path: _Path,
    tolerance: int = 0,
    vectors: bool = True,
    straight_walls: bool = False,
    compact: bool = False,
    max_tolerance_cells: int = 67108864,
    *,
    metadata: Optional[Mapping[str, Any]] = None,
) -> None: ...
def encode(
    map: Map,
    tolerance: int = 0,
    vectors: bool = True,
    straight_walls: bool = False,
    compact: bool = False,
    max_tolerance_cells: int = 67108864,
    *,
    metadata: Optional[Mapping[str, Any]] = None,
) -> bytes: ...
def decode(
    data: _Buffer, max_cells: Optional[int] = None, *, limits: Optional[DecodeLimits] = None
) -> Map: ...
def vectors(
    source: _Source,
    max_cells: Optional[int] = None,
    window_cells: Optional[_Window] = None,
    *,
    limits: Optional[DecodeLimits] = None,
) -> dict[str, Any]: ...
def info(source: _Source, *, limits: Optional[DecodeLimits] = None) -> dict[str, Any]: ...
def room_at(
    source: _Source,
    x: float,
    y: float,
    max_cells: Optional[int] = None,
    *,
    limits: Optional[DecodeLimits] = None,
) -> Optional[dict[str, Any]]: ...
def eval(
    original: Union[Map, _Path],
    decoded: Union[Map, _Path],
    *,
    max_cells: Optional[int] = None,
    tolerance: Optional[int] = None,
    limits: Optional[DecodeLimits] = None,
) -> dict[str, Any]: ...
def lines(
    map: Map,
    method: str = "linemap",
    *,
    epsilon: Optional[float] = None,
    straight_walls: bool = False,
    pose: Optional[Sequence[float]] = None,
) -> dict[str, Any]: ...
def segment(
    map: Map,
    *,
    method: Optional[str] = None,
    pose: Optional[Sequence[float]] = None,
    doors: Optional[Sequence[float]] = None,
    max_room_area: Optional[float] = None,
    paper_border: bool = False,
) -> dict[str, Any]: ...
def plan(
    map: Map,
    start: Sequence[float],
    goal: Sequence[float],
    *,
    robot_width: float = 0.4,
    robot_length: float = 0.4,
    margin: float = 0.05,
    d_min: float = 0.1,
    d_max: float = 5.0,
) -> dict[str, Any]: ...
