"""Spread particles evenly over triangle meshes: the pipeline of the
`meshparticles` program, in-process (docs/PYTHON.md).

    import meshparticles as mp
    mesh = mp.read_mesh("meshes/sphere.off")
    result = mp.run(mesh, n=256, seed=3)
    result.positions        # (256, 3) float64
    result.save("out")      # the files of `meshparticles run --out out`

Options take the command line's names with `-` as `_` (--rebuild-every is
rebuild_every=); None means the command line's default. A value of the wrong
type raises TypeError naming the keyword (n=2.7 is refused, not truncated);
errors the command line reports in one line raise ValueError with that line;
no usable OpenCL runtime or device raises DeviceError. A long call stops with
KeyboardInterrupt on Ctrl-C (main thread), or with Cancelled once the
threading.Event given as cancel= is set (any thread).
"""
from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import Cancelled, DeviceError, Mesh, MeshWarning, __version__, read_mesh

__all__ = [
    "Cancelled",
    "DeviceError",
    "Mesh",
    "MeshWarning",
    "Result",
    "__version__",
    "as_mesh",
    "batch",
    "compare",
    "devices",
    "geodesics",
    "quality",
    "read_mesh",
    "run",
]

PathLike = Union[str, bytes, "os.PathLike[str]", "os.PathLike[bytes]"]
# threading.Event, multiprocessing.Event: anything with is_set().
CancelEvent = Any


def _fan(polygons: "list[np.ndarray]") -> np.ndarray:
    """Triangles from polygons of 3 or more vertex ids, each fanned from its
    first vertex, as the program's readers do."""
    triangles = [np.stack([p[0].repeat(len(p) - 2), p[1:-1], p[2:]], axis=1) for p in polygons if len(p) >= 3]
    return np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)


def _vtk_cell_array(flat: Any) -> "list[np.ndarray]":
    """Polygons from VTK's flat cell layout [n, id_1 .. id_n, n, ...] (pyvista's `.faces`)."""
    flat = np.asarray(flat, dtype=np.int64).ravel()
    polygons, at = [], 0
    while at < len(flat):
        count = int(flat[at])
        if count < 0 or at + 1 + count > len(flat):
            raise ValueError(f"faces: a cell of {count} vertices at position {at} runs past the array")
        polygons.append(flat[at + 1 : at + 1 + count])
        at += 1 + count
    return polygons


def as_mesh(mesh: Any) -> Mesh:
    """A Mesh from a Mesh, a mesh file's path, or an object of the usual mesh
    libraries: `.vertices` (V x 3) and `.faces` (F x 3) as trimesh has them;
    `.points` and a flat VTK cell array `.faces` as pyvista's PolyData has
    them (polygons fanned, no strips); `.points` and `.cells` blocks as
    meshio's Mesh has them ("triangle", "quad" and "polygon" blocks used,
    others ignored). The arrays are copied and checked as a file's would be."""
    if isinstance(mesh, Mesh):
        return mesh
    if isinstance(mesh, (str, bytes, os.PathLike)):
        return read_mesh(mesh)
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return Mesh(np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces))
    if hasattr(mesh, "points") and hasattr(mesh, "faces"):
        if getattr(mesh, "n_strips", 0):
            raise ValueError("triangle strips: call .triangulate() on the PolyData first")
        return Mesh(np.asarray(mesh.points, dtype=np.float64), _fan(_vtk_cell_array(mesh.faces)))
    if hasattr(mesh, "points") and hasattr(mesh, "cells"):
        polygons = [np.asarray(cell, dtype=np.int64) for block in mesh.cells
                    if block.type in ("triangle", "quad", "polygon") for cell in block.data]
        return Mesh(np.asarray(mesh.points, dtype=np.float64)[:, :3], _fan(polygons))
    raise TypeError(
        f"expected a meshparticles.Mesh, a mesh file's path, or a mesh object (trimesh, pyvista or meshio), "
        f"got {type(mesh).__name__}"
    )


class Result:
    """What run() computed. `positions` and `vertices` are NumPy copies, made
    once; `report` and `quality` are fresh dicts on each access."""

    def __init__(self, output: _core.RunOutput) -> None:
        self._output = output
        self.positions: np.ndarray = output.positions  # (n, 3) float64: each particle's point on the surface
        self.vertices: np.ndarray = output.vertices  # (n,) int64: its nearest input vertex (the file's id)
        # Where each particle lies on the input surface, as particles.csv has it: an input triangle
        # (corner ids, the file's) and the barycentric weights that give the point.
        self.triangles: np.ndarray = output.triangles  # (n, 3) int64
        self.weights: np.ndarray = output.weights  # (n, 3) float64

    @property
    def report(self) -> Dict[str, Any]:
        """report.json's content (params.out empty, no outputs or report_sha256: save() adds them from the files)."""
        return json.loads(self._output.report_json())

    @property
    def quality(self) -> Dict[str, Any]:
        """report.json's "quality": nn_min, nn_mean, nn_std, nn_cv, rho, cover, energy, stacked, d_hex."""
        return json.loads(self._output.quality_json())

    @property
    def trace(self) -> List[Dict[str, Any]]:
        """Per iteration, as report.json records it: for spread its "sweeps"
        (moved, ms, min_spacing, mean_spacing in d_hex), for the paper's
        method its "trace" (energy, moved, ms, ...)."""
        return self.report[self._output.trace_key]

    @property
    def seconds(self) -> float:
        """Wall time of the run: distances, particles and quality."""
        return self._output.seconds

    @property
    def device(self) -> str:
        """"serial" or the OpenCL device's name."""
        return self._output.device

    def save(self, directory: PathLike) -> None:
        """Writes the six files of `meshparticles run --out DIRECTORY` in place
        of DIRECTORY at once; refuses a directory holding other files."""
        self._output.save(directory)

    def __repr__(self) -> str:
        return f"<meshparticles.Result: {len(self.positions)} particles on {self.device}, {self.seconds:.3f} s>"


def run(
    mesh: Any,
    n: int = 1024,
    *,
    method: Optional[str] = None,
    vertices_per_particle: Optional[float] = None,
    relax_rounds: Optional[int] = None,
    iterations: Optional[int] = None,
    backend: Optional[str] = None,
    scheme: Optional[str] = None,
    colors: Optional[int] = None,
    init: Optional[str] = None,
    start_vertex: Optional[int] = None,
    seed: Optional[int] = None,
    sigma: Optional[float] = None,
    potential: Optional[str] = None,
    geodesic: Optional[str] = None,
    distances: Optional[str] = None,
    cutoff: Optional[float] = None,
    device: Optional[str] = None,
    wg: Optional[int] = None,
    tile: Optional[int] = None,
    weights: Optional[str] = None,
    rebuild_every: Optional[int] = None,
    tuning_file: Optional[PathLike] = None,
    cache_dir: Optional[PathLike] = None,
    no_cache: bool = False,
    threads: Optional[int] = None,
    quiet: bool = False,
    cancel: Optional[CancelEvent] = None,
) -> Result:
    """`meshparticles run` on `mesh` with `n` particles; see `meshparticles run
    --help` for each option. The GIL is released while it runs; setting the
    event `cancel` (a threading.Event) from another thread stops it with
    Cancelled."""
    output = _core.run(
        as_mesh(mesh),
        n=n,
        method=method,
        vertices_per_particle=vertices_per_particle,
        relax_rounds=relax_rounds,
        iterations=iterations,
        backend=backend,
        scheme=scheme,
        colors=colors,
        init=init,
        start_vertex=start_vertex,
        seed=seed,
        sigma=sigma,
        potential=potential,
        geodesic=geodesic,
        distances=distances,
        cutoff=cutoff,
        device=device,
        wg=wg,
        tile=tile,
        weights=weights,
        rebuild_every=rebuild_every,
        tuning_file=tuning_file,
        cache_dir=cache_dir,
        no_cache=no_cache,
        threads=threads,
        quiet=quiet,
        cancel=cancel,
    )
    return Result(output)


def _measure(core_function: Any, mesh: Any, point_sets: Sequence[Any], *, refine: Union[str, int, None],
             cache_dir: Optional[PathLike], **options: Any) -> Dict[str, Any]:
    """quality() and compare(): each set (an array or a Result) as a float64
    array, the options as the core takes them, its JSON back as a dict."""
    arrays = [np.asarray(p.positions if isinstance(p, Result) else p, dtype=np.float64) for p in point_sets]
    text = core_function(as_mesh(mesh), *arrays, refine=None if refine is None else str(refine),
                         cache_dir=cache_dir, **options)
    return json.loads(text)


def quality(
    mesh: Any,
    points: Any,
    *,
    sigma: Optional[float] = None,
    potential: Optional[str] = None,
    geodesic: Optional[str] = None,
    refine: Union[str, int, None] = None,
    distances: Optional[str] = None,
    cutoff: Optional[float] = None,
    cache_dir: Optional[PathLike] = None,
    no_cache: bool = False,
    threads: Optional[int] = None,
    quiet: bool = False,
    cancel: Optional[CancelEvent] = None,
) -> Dict[str, Any]:
    """`meshparticles quality MESH PARTICLES --json` on `points` (P x 3, or a
    Result): the points made vertices of a measuring mesh (the input where
    they lie on its vertices, else inserted into a refined copy where they
    are) and measured by geodesic distances."""
    return _measure(_core.quality_json, mesh, [points], refine=refine, cache_dir=cache_dir, sigma=sigma,
                    potential=potential, geodesic=geodesic, distances=distances, cutoff=cutoff,
                    no_cache=no_cache, threads=threads, quiet=quiet, cancel=cancel)


def compare(
    mesh: Any,
    a: Any,
    b: Any,
    *,
    sigma: Optional[float] = None,
    potential: Optional[str] = None,
    geodesic: Optional[str] = None,
    refine: Union[str, int, None] = None,
    distances: Optional[str] = None,
    cutoff: Optional[float] = None,
    cache_dir: Optional[PathLike] = None,
    no_cache: bool = False,
    threads: Optional[int] = None,
    quiet: bool = False,
    cancel: Optional[CancelEvent] = None,
) -> Dict[str, Any]:
    """`meshparticles compare MESH A B --json` on two point sets (P x 3, or
    Results): "a" and "b" measured as quality() measures one, on the same
    measuring mesh, and "mean_distance_a_to_b" / "mean_distance_b_to_a", the
    mean geodesic distance from each set's particles to the other's nearest."""
    return _measure(_core.compare_json, mesh, [a, b], refine=refine, cache_dir=cache_dir, sigma=sigma,
                    potential=potential, geodesic=geodesic, distances=distances, cutoff=cutoff,
                    no_cache=no_cache, threads=threads, quiet=quiet, cancel=cancel)


def batch(
    inputs: Union[PathLike, Sequence[PathLike]],
    out: PathLike,
    n: Optional[int] = None,
    *,
    spacing: Optional[float] = None,
    per_area: Optional[float] = None,
    force: bool = False,
    strict: bool = False,
    cancel: Optional[CancelEvent] = None,
    **run_options: Any,
) -> Dict[str, Any]:
    """`meshparticles batch INPUTS --out OUT`: `run` on every mesh of `inputs`
    (files, folders, .txt lists), a folder of run files per mesh in `out`,
    resumed where a complete output of the same mesh and options is there
    (`force=True` recomputes). n per mesh: `n` (default 1024), or from
    `spacing` (the hexagonal spacing, mesh units) or `per_area` (particles
    per unit of area). `run_options`: run()'s keywords. Returns summary.json:
    a mesh refused or failed is a row with its status and reason, not an
    exception."""
    paths = [inputs] if isinstance(inputs, (str, bytes, os.PathLike)) else list(inputs)
    text = _core.batch_json(paths, out, n=n, spacing=spacing, per_area=per_area, force=force, strict=strict,
                            cancel=cancel, **run_options)
    return json.loads(text)


def devices(device: Optional[str] = None) -> List[Dict[str, Any]]:
    """The OpenCL devices (`meshparticles devices`), the one a run would pick
    marked "selected". Raises DeviceError without a runtime or device."""
    return _core.devices(device=device or "")


def geodesics(
    mesh: Any,
    sources: Union[int, Sequence[int]],
    max_distance: Optional[float] = None,
    *,
    geodesic: str = "fmm",
    cancel: Optional[CancelEvent] = None,
) -> np.ndarray:
    """Geodesic distances from each source (an input vertex id) to every input
    vertex: a (len(sources), V) float64 array, +inf beyond `max_distance`
    (0 or more; None or inf: no limit), in another component, or at a vertex
    the reader dropped."""
    ids = [sources] if np.ndim(sources) == 0 else list(sources)
    return _core.geodesics(as_mesh(mesh), ids, max_distance=max_distance, geodesic=geodesic, cancel=cancel)
