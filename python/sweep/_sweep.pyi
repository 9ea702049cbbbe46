"""Types of sweep's compiled module (src/module.cpp); the arrays are read-only numpy views."""
from os import PathLike
from typing import Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
_Path = Union[str, PathLike[str]]

class SwpError(ValueError):
    file: str
    line: int  # 1-based; 0 when the error is not about a place in a file
    column: int

class ObjectInfo:
    name: str
    kind: str
    category: str  # "curve", "surface", "material" or "rider"
    points: int

class Surface:
    name: str
    kind: str
    positions: npt.NDArray[np.float32]  # (N, 3)
    normals: npt.NDArray[np.float32]  # (N, 3), unit length, pointing out
    uvs: npt.NDArray[np.float32]  # (N, 2), or (0, 2)
    indices: npt.NDArray[np.uint32]  # (M, 3), counterclockwise from outside
    vertex_count: int
    triangle_count: int

class Curve:
    name: str
    kind: str
    planar: bool
    closed: bool
    frames: npt.NDArray[np.float64]  # (N, 4, 3): V, T, N, B per sample
    positions: npt.NDArray[np.float64]  # (N, 3): frames[:, 0]
    parameters: npt.NDArray[np.float64]  # (N,)

class SnapshotResult:
    status: str  # "pass", "warning", "FAIL", "new", "updated" or "error"
    passed: bool
    message: str
    objects: list[str]  # the attribution's lines
    changed_objects: list[str]  # names of the objects whose geometry or material changed
    reference: str

class Document:
    can_undo: bool
    can_redo: bool
    modified: bool
    file: str
    def objects(self) -> list[ObjectInfo]: ...
    def surfaces(self) -> list[Surface]: ...
    def curves(self) -> list[Curve]: ...
    def surface(self, name: str) -> Surface: ...
    def curve(self, name: str) -> Curve: ...
    def curve_range(self, name: str) -> tuple[float, float]: ...
    def evaluate_curve(
        self, name: str, parameters: npt.ArrayLike
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def curve_points(self, name: str, parameters: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
    def point(self, object: str, index: int) -> tuple[float, float, float]: ...
    def set_point(self, object: str, index: int, position: Sequence[float]) -> None: ...
    def set_field(self, object: str, field: str, value: float) -> None: ...
    def undo(self) -> bool: ...
    def redo(self) -> bool: ...
    def text(self) -> str: ...
    def save(self, path: _Path) -> None: ...
    def export(self, prefix: _Path, format: str = "obj") -> list[PathLike[str]]: ...
    def render(
        self,
        width: int = 640,
        height: int = 480,
        mode: str = "smooth",
        color: str = "material",
        yaw: float = 30.0,
        pitch: float = 20.0,
    ) -> npt.NDArray[np.uint8]: ...
    def _repr_png_(self) -> bytes: ...

def load(
    path: _Path, frames: str = "rmf", seam: str = "full", tolerance: float = 0.0, uvs: bool = False
) -> Document: ...
def parse(
    text: str,
    name: str = "<string>",
    frames: str = "rmf",
    seam: str = "full",
    tolerance: float = 0.0,
    uvs: bool = False,
) -> Document: ...
def compare_images(
    actual: npt.NDArray[np.uint8],
    reference: npt.NDArray[np.uint8],
    threshold: float = 0.1,
    max_diff_pixels: int = 8,
) -> dict[str, object]: ...
def save_png(rgba: npt.NDArray[np.uint8], path: _Path) -> None: ...
def check_snapshot(
    document: Document,
    folder: _Path,
    name: str,
    mode: str = "smooth",
    width: int = 320,
    height: int = 240,
    threshold: float = 0.1,
    max_diff_pixels: int = 8,
    update: bool = False,
) -> SnapshotResult: ...
