# shadetool.pyi: type stubs of the Python module `shadetool` (lib/python). Shapes and dtypes are in
# the comments and the docstrings (help(shadetool.NAME)); numpy.typing has no shape types.
#   V  (n, 3) float64 or float32 vertex positions (the normals read float64 C-contiguous V and
#      int32/uint32 C-contiguous F in place; other layouts are copied once into float64 / uint32)
#   F  (m, k) integer faces (triangles (m, 3); any integer dtype) or (indices, offsets) polygons
#   N  (n, 3) float vertex normals
import os
from typing import Any, Dict, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

FloatArray = npt.NDArray[np.floating[Any]]
IntArray = npt.NDArray[np.integer[Any]]
Faces = Union[IntArray, Tuple[IntArray, IntArray], Sequence[Sequence[int]]]
Vertices = Union[FloatArray, Sequence[Sequence[float]]]
PathLike = Union[str, os.PathLike[str]]
Weight = Literal["uniform", "area", "angle", "max"]
Precision = Literal["double", "float"]
Scene = Union[Dict[str, Any], PathLike]

class Mesh:
    """Indexed flat arrays of a mesh; attributes are NumPy views of the mesh's own arrays."""
    def __init__(
        self,
        vertices: Vertices,
        faces: Faces,
        vertex_normals: Optional[FloatArray] = ...,
        face_normals: Optional[FloatArray] = ...,
        vertex_colors: Optional[FloatArray] = ...,
        face_colors: Optional[FloatArray] = ...,
    ) -> None: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_faces(self) -> int: ...
    vertices: npt.NDArray[np.float64]                     # (n, 3)
    faces: npt.NDArray[np.uint32]                        # (m, k); ValueError if face sizes differ
    @property
    def face_indices(self) -> npt.NDArray[np.uint32]: ...  # (C,)
    @property
    def face_offsets(self) -> npt.NDArray[np.uint32]: ...  # (m + 1,)
    vertex_normals: Optional[npt.NDArray[np.float64]]    # (n, 3)
    face_normals: Optional[npt.NDArray[np.float64]]      # (m, 3)
    @property
    def corner_normals(self) -> Optional[npt.NDArray[np.float64]]: ...  # (p, 3) pool
    @property
    def corner_normal_index(self) -> Optional[npt.NDArray[np.uint32]]: ...  # (C,)
    vertex_colors: Optional[npt.NDArray[np.float32]]     # (n, 3 or 4), linear
    face_colors: Optional[npt.NDArray[np.float32]]       # (m, 3 or 4), linear
    @property
    def vertex_quality(self) -> Optional[npt.NDArray[np.float32]]: ...  # (n,)
    @property
    def face_quality(self) -> Optional[npt.NDArray[np.float32]]: ...  # (m,)
    @property
    def vertex_properties(self) -> Dict[str, npt.NDArray[np.float64]]: ...  # name -> (n,)
    @property
    def face_properties(self) -> Dict[str, npt.NDArray[np.float64]]: ...  # name -> (m,)
    @property
    def comments(self) -> List[str]: ...
    precision: Literal["float", "double"]
    def clear_normals(self) -> None: ...
    def copy(self) -> "Mesh": ...

MeshOrVertices = Union[Mesh, Vertices]

def read_mesh(path: PathLike, format: str = ...) -> Mesh: ...
def write_mesh(
    path: PathLike,
    mesh: MeshOrVertices,
    F: Optional[Faces] = ...,
    *,
    vertex_normals: Optional[FloatArray] = ...,
    binary: bool = ...,
    format: str = ...,
) -> None: ...

# (m, 3) float64
def face_normals(V: MeshOrVertices, F: Optional[Faces] = ..., precision: Precision = ...) -> npt.NDArray[np.float64]: ...
# (n, 3) float64
def vertex_normals(
    V: MeshOrVertices, F: Optional[Faces] = ..., weight: Weight = ..., precision: Precision = ...
) -> npt.NDArray[np.float64]: ...
# ((p, 3) float64 pool, uint32 corner index shaped like F: (m, k) or (C,))
def corner_normals(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    crease_deg: Optional[float] = ...,
    weight: Weight = ...,
    precision: Precision = ...,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32]]: ...
# MikkTSpace frames per corner: (m, k, 4) float64 for (m, k) faces, (C, 4) for polygons; xyz, w = +-1
def tangents(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    N: Optional[FloatArray] = ...,
    UV: Optional[FloatArray] = ...,
) -> npt.NDArray[np.float64]: ...
# (F uint32 in F's layout, report) or, with return_normals=True, (F, N (n, 3) float64, report)
def repair(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    weight: Weight = ...,
    remove_degenerate: bool = ...,
    return_normals: bool = ...,
) -> Tuple[Any, ...]: ...
# (V (n, 3) float64, F uint32 in F's layout, N (n, 3) float64 or None)
def transform(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    N: Optional[FloatArray] = ...,
    matrix: Optional[npt.ArrayLike] = ...,
    normals: Literal["transform", "recompute", "drop"] = ...,
) -> Tuple[npt.NDArray[np.float64], Any, Optional[npt.NDArray[np.float64]]]: ...
# (n, 3) per vertex or (m, 3) per face, float64 linear RGB, unclamped
def bake_lighting(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    N: Optional[FloatArray] = ...,
    scene: Optional[Scene] = ...,
    per: Literal["vertex", "face"] = ...,
    model: Optional[Literal["lambert", "phong", "blinn-phong"]] = ...,
    space: Literal["auto", "world", "camera", "object"] = ...,
    shadows: bool = ...,
    samples: int = ...,
    uint8: bool = ...,
    linear: bool = ...,
) -> npt.NDArray[Any]: ...  # float64 linear; uint8=True: the PLY's bytes (sRGB, or linear=True)
# (n,) per vertex or (m,) per face, float32 open fraction in [0, 1]
def occlusion(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    N: Optional[FloatArray] = ...,
    samples: int = ...,
    distance: float = ...,
    per: Literal["vertex", "face"] = ...,
    seed: int = ...,
    uint8: bool = ...,
    linear: bool = ...,
) -> npt.NDArray[Any]: ...  # float32; uint8=True: the PLY's grey bytes (sRGB, or linear=True)
# (height, width, 3): uint8 sRGB (hdr=False) or float32 linear (hdr=True), row 0 at the top
def render(
    V: MeshOrVertices,
    F: Optional[Faces] = ...,
    N: Optional[FloatArray] = ...,
    scene: Optional[Scene] = ...,
    width: int = ...,
    height: int = ...,
    shading: Literal["flat", "gouraud", "phong"] = ...,
    samples: int = ...,
    background: Sequence[float] = ...,
    model: Optional[Literal["lambert", "phong", "blinn-phong"]] = ...,
    space: Literal["auto", "world", "camera", "object"] = ...,
    hdr: bool = ...,
    threads: int = ...,
) -> npt.NDArray[Any]: ...
