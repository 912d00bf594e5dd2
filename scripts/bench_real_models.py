#!/usr/bin/python3
"""Our particles against four public Poisson-disk samplers and ACVD, on real meshes: quality and time.

    scripts/bench_real_models.py [-n 256,1024,4096] [--models DIR] [--only NAME,...] [--limit K]
                                 [--max-vertices V] [--binary PATH] [--json FILE] [--markdown FILE]
                                 [--no-python] [--module-source DIR] [--timeout S] [--keep DIR]
    scripts/bench_real_models.sh ...   (the same)

Meshes: those of Debian's libcgal-demo (installed with apt-get if missing, unpacked under
${XDG_CACHE_HOME:-~/.cache}/meshparticles/cgal-data as scripts/real_meshes.sh does), then any
.off/.ply/.obj/.stl in `--models DIR`. A mesh is taken when `meshparticles info --strict` accepts
it (a manifold: no non-manifold edge or vertex, no repeated triangle), and each n only where the
mesh has at least 4 vertices per particle. `--only cow,bull` keeps the meshes of those names (with
or without the extension), `--max-vertices V` drops larger ones, `--limit K` keeps the first K
that qualify from each source. Refused and skipped meshes are listed on stderr and in the JSON.

Samplers, for each mesh and n:
- ours: `meshparticles run MESH -n N -q` (the default run), as a whole process;
  and in-process, `meshparticles.run(mesh, n)` of the Python module;
- MeshLab vertex / surface Poisson disk: pymeshlab's `generate_sampling_poisson_disk(samplenum=n,
  exactnumflag=True, subsample=True / False)`, as scripts/compare_samplers.py calls it;
- Open3D: `TriangleMesh.sample_points_poisson_disk(n)` (exactly n points);
- pcu: point-cloud-utils' `sample_mesh_poisson_disk(v, f, n)` (about n points: the count it gave
  is recorded, and shown where it is not n);
- pyacvd: `pyacvd.Clustering(mesh)`, subdivided until it has 100 vertices a cluster, then
  `cluster(n)`, the clusters' centroids (ACVD's clusters grown over mesh edges: not on the
  surface; `quality` measures them at their nearest surface points).
Each peer reads the file with its own reader; where that fails, with trimesh's, else
pymeshlab's (the JSON's `loader` says which).

The peers and the Python module live in a virtual environment made on first use:
$MESHPARTICLES_PEER_VENV, default ${XDG_CACHE_HOME:-~/.cache}/meshparticles/peer-venv (pip install
pymeshlab open3d point-cloud-utils trimesh pycpd pyacvd; Open3D needs Debian's libusb-1.0-0, installed with apt-
get if missing). Unless `--no-python`, the module is built into it from `--module-source` (default:
this checkout) on every start, with pip as scripts/test_python.sh does but without build isolation
(scikit-build-core and ninja installed in the venv), its CMake build kept in the venv (module-
build/, a folder per source folder): the first build takes minutes, a rebuild of an unchanged
checkout seconds, and nothing under build/ is touched. A failed build is reported and the in-
process column left empty. Each sampler runs in a worker process of its own (this script re-invoked
in the venv with `--worker`), one per mesh, so one that crashes or passes `--timeout` seconds
(default 900) fails that mesh alone.

Timing: one untimed warm-up per mesh and sampler (at the mesh's first n) first; for ours it
fills the distance and kernel caches. Then, per n:
- ours run s: wall time of the whole `run` process (reading the mesh, distances from the cache,
  the particles, the quality figures, six output files), with the report's seconds.total in
  brackets; peak MiB: the process's peak resident memory (wait4);
- ours in-process s: the `meshparticles.run(mesh, n)` call alone, the mesh already read, in a
  process that has run once already;
- quality share: the report's seconds.quality / seconds.total (the run measuring its own result);
- each peer "load+sample / call": reading the file plus sampling, and the sampling call alone;
- ours / MeshLab vertex: ours run s over MeshLab vertex load+sample.

Quality: every point set (ours and each peer's) is written as a .particles file and measured by
`meshparticles quality MESH FILE --json` (docs/QUALITY.md): geodesic nn_cv (spread of nearest-
neighbour distances, 0 for a regular lattice), rho (closest pair over the hexagonal spacing d_hex,
1 for a hexagonal packing), cover (farthest point of the surface from a particle over d_hex,
0.58 for a hexagonal lattice). Points between vertices are inserted into a refined mesh by
`quality` itself; every set of one mesh and n is measured on the same refined mesh
(compare_samplers.remeasure_at_common_refinement), so the covers compare.

Output: progress on stderr; on stdout (and `--markdown FILE`) a quality table (nn_cv / rho / cover
per sampler), a time table and a summary over all rows (mesh and n): the share where ours has
rho >= 0.90 and nn_cv <= 0.02, the medians of our rho and nn_cv, the share where our cover <=
MeshLab vertex's, the share where our run <= 5 x MeshLab vertex load+sample, and the share where
seconds.quality <= 10% of seconds.total. A row where ours failed counts as a miss; a comparison
with a failed peer is left out of its share. `--json FILE` writes every row. `--keep DIR` keeps
the point sets and run outputs.

Exit status: 0; 1 when one of our runs or measurements failed (peers failing do not count);
2 for bad arguments, a missing binary or no mesh. The driver needs only Python 3's standard
library.
"""
import argparse
import hashlib
import json
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare_samplers as shared  # noqa: E402  (the yardstick's helpers, shared with that script)

PROG = "bench_real_models"
shared.PROG = PROG  # the shared helpers' messages under this script's name
ROOT = Path(__file__).resolve().parent.parent
DEFAULT_COUNTS = [256, 1024, 4096]
VERTICES_PER_PARTICLE = 4
ACVD_VERTICES_PER_CLUSTER = 100  # subdivided to this: on cow at 256, rho 0.35 / 0.48 / 0.50 / 0.39 after 0 to 3 levels
MODEL_EXTENSIONS = {".off", ".ply", ".obj", ".stl"}
DEFAULT_TIMEOUT = 900

OURS = "ours"
IN_PROCESS = "python"  # the worker timing meshparticles.run in-process
MESHLAB_VERTEX = "meshlab-vertex"
# (key, label, pip package it needs): the peers, in table order.
PEERS = [(MESHLAB_VERTEX, "MeshLab vertex", "pymeshlab"),
         ("meshlab-surface", "MeshLab surface", "pymeshlab"),
         ("open3d", "Open3D", "open3d"),
         ("pcu", "pcu", "point-cloud-utils"),
         ("acvd", "pyacvd", "pyacvd")]
# pycpd: scripts/cpd_baseline.py's registrations, in this venv too.
PEER_PACKAGES = {"pymeshlab": "pymeshlab", "open3d": "open3d", "point-cloud-utils": "point_cloud_utils",
                 "trimesh": "trimesh", "pycpd": "pycpd", "pyacvd": "pyacvd"}  # pip name -> import name
# What building the Python module in the venv needs (pip name -> import name).
MODULE_BUILD_PACKAGES = {"scikit-build-core": "scikit_build_core", "ninja": "ninja", "numpy": "numpy"}
LABELS = dict([(OURS, "ours"), (IN_PROCESS, "ours in-process")] + [(key, label) for key, label, _ in PEERS])

# The summary's yardsticks.
GOOD_RHO = 0.90
GOOD_CV = 0.02
TIME_FACTOR = 5.0  # ours run <= this x MeshLab vertex load+sample
QUALITY_SHARE = 0.10  # seconds.quality <= this x seconds.total

progress = shared.progress
die = shared.die
Failure = shared.Failure


# ================================================================ worker (inside the peer venv)

def read_with_fallback(path, native):
    """(mesh, loader): NATIVE(path), else triangle arrays from trimesh, else from pymeshlab."""
    try:
        return native(path), "native"
    except Exception as native_error:  # noqa: BLE001  (any reader's failure sends us to the next)
        reason = f"{type(native_error).__name__}: {native_error}"
    for name, arrays in (("trimesh", trimesh_arrays), ("pymeshlab", pymeshlab_arrays)):
        try:
            return arrays(path), name
        except Exception as error:  # noqa: BLE001
            reason += f"; {name}: {type(error).__name__}: {error}"
    raise RuntimeError(f"no reader read it ({reason})")


def loader_with_fallback(native, from_arrays):
    """load(path) -> (mesh, loader): NATIVE(path), else FROM_ARRAYS(vertices, faces) of another reader's arrays."""
    def load(path):
        mesh, loader = read_with_fallback(path, native)
        if loader != "native":
            mesh = from_arrays(*mesh)
        return mesh, loader

    return load


def trimesh_arrays(path):
    import trimesh
    mesh = trimesh.load(path, process=False, force="mesh")
    return checked_arrays(mesh.vertices, mesh.faces)


def pymeshlab_arrays(path):
    import pymeshlab
    meshes = pymeshlab.MeshSet()
    meshes.load_new_mesh(path)
    return checked_arrays(meshes.current_mesh().vertex_matrix(), meshes.current_mesh().face_matrix())


def checked_arrays(vertices, faces):
    import numpy as np
    vertices = np.ascontiguousarray(vertices, dtype=np.float64)
    faces = np.ascontiguousarray(faces, dtype=np.int32)
    if faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        raise ValueError(f"no triangles (faces {faces.shape})")
    return vertices, faces


def meshlab_sampler(subsample):
    import pymeshlab

    def native(path):
        meshes = pymeshlab.MeshSet()
        meshes.load_new_mesh(path)
        if meshes.current_mesh().face_number() == 0:
            raise ValueError("no faces")
        return meshes

    def from_arrays(vertices, faces):
        meshes = pymeshlab.MeshSet()
        meshes.add_mesh(pymeshlab.Mesh(vertex_matrix=vertices, face_matrix=faces))
        return meshes

    load = loader_with_fallback(native, from_arrays)

    def sample(meshes, n):
        meshes.generate_sampling_poisson_disk(samplenum=n, exactnumflag=True, subsample=subsample)
        if meshes.mesh_number() != 2:
            raise RuntimeError(f"expected the samples as a new layer, got {meshes.mesh_number()} layers")
        return meshes.current_mesh().vertex_matrix(), {}

    return load, sample, "pymeshlab"


def open3d_sampler():
    import open3d

    def native(path):
        mesh = open3d.io.read_triangle_mesh(path)
        if not mesh.has_triangles():
            raise ValueError("no triangles")
        return mesh

    def from_arrays(vertices, faces):
        return open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(vertices),
                                            open3d.utility.Vector3iVector(faces))

    load = loader_with_fallback(native, from_arrays)

    def sample(mesh, n):
        import numpy as np
        return np.asarray(mesh.sample_points_poisson_disk(number_of_points=n).points), {}

    return load, sample, "open3d"


def pcu_sampler():
    import point_cloud_utils as pcu

    def load(path):
        return read_with_fallback(path, lambda file: checked_arrays(*pcu.load_mesh_vf(file)))

    def sample(mesh, n):
        vertices, faces = mesh
        face_ids, barycentric = pcu.sample_mesh_poisson_disk(vertices, faces, num_samples=n)
        return pcu.interpolate_barycentric_coords(faces, face_ids, barycentric, vertices), {}

    return load, sample, "point-cloud-utils"


def acvd_sampler():
    """ACVD (Valette and Chassery 2004): n clusters of vertices grown over the mesh's edges, their centroids.

    pyacvd asks for a mesh much denser than the clusters: subdivided (each level four times the
    triangles) until it has at least ACVD_VERTICES_PER_CLUSTER vertices per cluster; the load
    column holds the reading, the call the subdivision and the clustering.
    """
    import numpy as np
    import pyacvd
    import pyvista

    def native(path):
        mesh = pyvista.read(path)
        if not isinstance(mesh, pyvista.PolyData) or mesh.n_cells == 0:
            raise ValueError("no surface")
        return mesh.triangulate()

    def from_arrays(vertices, faces):
        cells = np.hstack([np.full((len(faces), 1), 3, dtype=np.int64), faces.astype(np.int64)]).ravel()
        return pyvista.PolyData(vertices, cells)

    load = loader_with_fallback(native, from_arrays)

    def sample(mesh, n):
        clusters = pyacvd.Clustering(mesh)
        levels = 0
        while mesh.n_points * 4 ** levels < ACVD_VERTICES_PER_CLUSTER * n and levels < 3:
            levels += 1
        if levels:
            clusters.subdivide(levels)
        clusters.cluster(n)
        return np.asarray(clusters.cluster_centroid), {"subdivisions": levels}

    return load, sample, "pyacvd"


def in_process_sampler():
    """Ours through the Python module; its report's seconds ride along with the points."""
    import warnings

    import meshparticles

    def load(path):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the mesh's warnings: info has shown them
            return meshparticles.read_mesh(path), "native"

    def sample(mesh, n):
        result = meshparticles.run(mesh, n=n, quiet=True)
        seconds = result.report["seconds"]
        return result.positions, {"report_total": seconds["total"], "report_quality": seconds["quality"],
                                  "device": result.device}

    return load, sample, "meshparticles"


# Each makes load(path) -> (mesh, loader) and sample(mesh, n) -> (points, extra figures), and names its package.
WORKER_SAMPLERS = {MESHLAB_VERTEX: lambda: meshlab_sampler(True), "meshlab-surface": lambda: meshlab_sampler(False),
                   "open3d": open3d_sampler, "pcu": pcu_sampler, "acvd": acvd_sampler, IN_PROCESS: in_process_sampler}


def load_and_sample(load, sample, path, n):
    """One load plus sample: points, loader, and the seconds of the load, the call and the two together."""
    start = time.perf_counter()
    mesh, loader = load(path)
    loaded = time.perf_counter()
    points, extra = sample(mesh, n)
    done = time.perf_counter()
    return points, dict(extra, loader=loader, load_seconds=loaded - start, call_seconds=done - loaded,
                        seconds=done - start)


def worker(key, mesh, counts, out_dir, result_path):
    """Runs inside the venv: sampler KEY on MESH at each n, an untimed warm-up first; RESULT after each n."""
    import importlib.metadata

    import numpy as np

    load, sample, package = WORKER_SAMPLERS[key]()
    result = {"package": package, "version": importlib.metadata.version(package), "counts": {}}
    try:
        load_and_sample(load, sample, mesh, counts[0])  # warm-up, untimed
    except Exception as error:  # noqa: BLE001  (recorded per n below, where it will fail again)
        print(f"warm-up: {type(error).__name__}: {error}", file=sys.stderr)
    for n in counts:
        try:
            points, timing = load_and_sample(load, sample, mesh, n)
            path = Path(out_dir) / f"{key}-{n}.particles"
            np.savetxt(path, points, fmt="%.9g")
            result["counts"][str(n)] = dict(timing, points=int(len(points)), file=str(path))
        except Exception as error:  # noqa: BLE001  (the row records any failure of the peer)
            result["counts"][str(n)] = {"error": f"{type(error).__name__}: {error}"}
        write_atomically(Path(result_path), json.dumps(result))


def write_atomically(path, text):
    partial = path.with_suffix(".partial")
    partial.write_text(text)
    partial.replace(path)


# ================================================================ the peer venv

def peer_venv():
    return Path(os.environ.get("MESHPARTICLES_PEER_VENV") or shared.cache_home() / "meshparticles" / "peer-venv")


def imports(python, module):
    return subprocess.run([str(python), "-c", f"import {module}"], capture_output=True).returncode == 0


def prepare_venv(module_source):
    """The venv's python and {sampler key: why it cannot run} for the samplers it lacks.

    Makes the venv on first use, installs the peers that are missing, and (MODULE_SOURCE given)
    builds the Python module into it.
    """
    venv = peer_venv()
    python = shared.make_venv(venv, "peers'")
    ensure_libusb()
    missing = [package for package, module in PEER_PACKAGES.items() if not imports(python, module)]
    if missing:
        install_packages(python, missing)
    unavailable = {}
    for key, _, package in PEERS:
        if not imports(python, PEER_PACKAGES[package]):
            unavailable[key] = f"{package} does not import in {venv}"
    if module_source is None:
        unavailable[IN_PROCESS] = "--no-python"
    else:
        reason = build_module(python, venv, module_source)
        if reason:
            unavailable[IN_PROCESS] = reason
    for key, reason in unavailable.items():
        progress(f"{LABELS[key]}: left out ({reason})")
    return python, unavailable


def ensure_libusb():
    """Debian's libusb-1.0-0, which Open3D's wheel links; installed with apt-get if missing."""
    if shutil.which("dpkg-query") is None:
        return  # not Debian: pip's wheel has to find it on its own
    status = subprocess.run(["dpkg-query", "-W", "-f=${Status}", "libusb-1.0-0"], capture_output=True, text=True)
    if status.stdout == "install ok installed":
        return
    sudo = [] if os.geteuid() == 0 else ["sudo", "-n"]
    if sudo and shutil.which("sudo") is None:
        progress("libusb-1.0-0 is missing (apt-get install it as root): Open3D may not import")
        return
    progress("installing libusb-1.0-0 for Open3D (apt-get)")
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    for command in (["apt-get", "update", "-qq"], ["apt-get", "install", "-y", "-qq", "libusb-1.0-0"]):
        if subprocess.run(sudo + command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env).returncode:
            progress("apt-get install libusb-1.0-0 failed (run it as root): Open3D may not import")
            return


def install_packages(python, packages):
    """pip install PACKAGES together, and one by one if that fails (so one bad package spoils none else)."""
    progress(f"installing {' '.join(packages)} into the peers' venv (pip)")
    command = [str(python), "-m", "pip", "install", "--quiet"]
    if subprocess.run(command + packages, stdout=sys.stderr).returncode == 0 or len(packages) == 1:
        return
    for package in packages:
        if subprocess.run(command + [package], stdout=sys.stderr).returncode != 0:
            progress(f"pip install {package} failed")


def build_module(python, venv, source):
    """pip install SOURCE (the Python module) into the venv; None, or why it failed."""
    if not (source / "pyproject.toml").is_file():
        return f"{source}: no pyproject.toml there"
    tools = [package for package, module in MODULE_BUILD_PACKAGES.items() if not imports(python, module)]
    if shutil.which("cmake") is None:
        tools.append("cmake")
    if tools:
        install_packages(python, tools)
    progress(f"building the Python module from {source} into {venv} (pip; the first build takes minutes)")
    # Without build isolation the build's tools keep their paths, so the kept build is incremental;
    # one build folder per source folder, as CMake refuses a build folder made for another source.
    build_dir = venv / "module-build" / hashlib.sha1(str(source).encode()).hexdigest()[:12]
    command = [str(python), "-m", "pip", "install", "--verbose", "--force-reinstall", "--no-deps",
               "--no-build-isolation", f"--config-settings=build-dir={build_dir}", str(source)]
    log_path = venv / "module-build.log"
    build = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=venv)
    with open(log_path, "w") as log:
        for line in build.stdout:
            log.write(line)
            stripped = line.strip()
            if stripped.startswith("[") and "/" in stripped.split("]")[0]:  # "[12/92] Building ...": visibly moving
                progress(f"module build {stripped[:100]}")
    if build.wait() != 0:
        return f"the module's build failed ({log_path}): {first_build_error(log_path.read_text())}"
    # From the venv's directory, so that the checkout's python/ folder is not what imports.
    check = subprocess.run([str(python), "-c", "import meshparticles"], capture_output=True, text=True, cwd=venv)
    if check.returncode != 0:
        return f"the module built but does not import: {shared.last_line(check.stderr)}"
    return None


def first_build_error(log):
    """The first line of a build log that names an error (CMake's, the compiler's), past pip's own."""
    lines = [line.strip() for line in log.splitlines() if line.strip()]
    pips = ("ERROR:", "error: subprocess-exited-with-error", "error: metadata-generation-failed")
    errors = [line for line in lines if "error" in line.lower() and not line.startswith(pips)]
    return (errors or lines or ["(no output)"])[0]


def run_worker(python, key, mesh, counts, out_dir, timeout):
    """Sampler KEY's worker on MESH: {n: timing and file, or error}, and {package: version} when it started."""
    out_dir.mkdir(parents=True, exist_ok=True)
    result_path = out_dir / f"{key}.json"
    command = [str(python), str(Path(__file__).resolve()), "--worker", key, str(mesh),
               ",".join(map(str, counts)), str(out_dir), str(result_path)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=out_dir)
        ending = None if done.returncode == 0 else exit_reason(done.returncode, done.stderr)
    except subprocess.TimeoutExpired:
        ending = f"did not finish in {timeout} s"
    try:
        result = json.loads(result_path.read_text())
    except (OSError, ValueError):
        result = {"counts": {}}
    rows = {n: result["counts"].get(str(n)) or {"error": ending or "the worker left no result"} for n in counts}
    return rows, {result["package"]: result["version"]} if "package" in result else {}


def exit_reason(code, errors):
    if code < 0:
        return f"the worker died ({signal.Signals(-code).name})"
    return f"the worker failed (exit {code}): {shared.last_line(errors)}"


# ================================================================ meshes

def candidate_files(models, only):
    """(path, source) of the corpus meshes, then of the --models folder; ONLY keeps those names."""
    files = [(path, "cgal") for path in sorted(shared.corpus_directory().iterdir())]
    if models is not None:
        files += [(path, "models") for path in sorted(models.iterdir())
                  if path.suffix.lower() in MODEL_EXTENSIONS and path.is_file()]
    if only:
        wanted = set(only)
        files = [(path, source) for path, source in files if path.name in wanted or path.stem in wanted]
        found = {name for path, _ in files for name in (path.name, path.stem)}
        for name in sorted(wanted - found):
            progress(f"--only {name}: no such mesh")
    return files


def strict_vertices(binary, mesh):
    """Vertices of a mesh `meshparticles info --strict` accepts (a manifold), or raises Failure with its reason."""
    info = shared.run_program([str(binary), "info", str(mesh), "--json", "--strict"], capture_output=True, text=True)
    if info.returncode != 0:
        raise Failure(shared.last_line(info.stderr).replace("meshparticles: error: ", ""))
    return int(json.loads(info.stdout)["vertices"])


def select_meshes(binary, files, counts, limit, max_vertices):
    """The meshes to run, as (path, source, vertices, their counts), and the notes on those left out."""
    chosen, notes, taken = [], [], {}
    for path, source in files:
        if limit is not None and taken.get(source, 0) >= limit:
            continue
        try:
            vertices = strict_vertices(binary, path)
        except Failure as refused:
            notes.append(f"{path.name}: refused by info --strict ({refused})")
            continue
        if max_vertices is not None and vertices > max_vertices:
            notes.append(f"{path.name}: {vertices} vertices, over --max-vertices {max_vertices}")
            continue
        fitting = [n for n in counts if n * VERTICES_PER_PARTICLE <= vertices]
        for n in counts:
            if n not in fitting:
                notes.append(f"{path.name}: n={n} needs {n * VERTICES_PER_PARTICLE} vertices, it has {vertices}")
        if fitting:
            chosen.append((path, source, vertices, fitting))
            taken[source] = taken.get(source, 0) + 1
    return chosen, notes


# ================================================================ one mesh

def bench_mesh(binary, python, unavailable, mesh, source, vertices, counts, work, timeout):
    """The rows (one per n) for one mesh: ours (process and in-process) and every peer, all measured."""
    name = mesh.name if source == "cgal" else f"{mesh.name} (models)"
    rows = [{"mesh": name, "path": str(mesh), "source": source, "vertices": vertices, "n": n, "samplers": {}}
            for n in counts]
    progress(f"{name}: warm-up run of ours (untimed; fills the distance and kernel caches)")
    try:
        shared.run_ours(binary, mesh, counts[0], [], work / "warm-up")
    except Failure as failure:
        progress(f"{name}: warm-up: {failure}")
    for row in rows:
        row["samplers"][OURS] = time_ours(binary, mesh, row, work / f"ours-{row['n']}")
    versions = {}
    for key in [IN_PROCESS] + [key for key, _, _ in PEERS]:
        if key in unavailable:
            for row in rows:
                sampled(row, key).update(error=unavailable[key], not_run=True)
            continue
        progress(f"{name}: {LABELS[key]} at n = {', '.join(map(str, counts))}")
        results, version = run_worker(python, key, mesh, counts, work / "peers", timeout)
        versions.update(version)
        for row in rows:
            sampled(row, key).update(results[row["n"]])
            report_peer(row, key)
    for row in rows:
        measure(binary, mesh, row)
    return rows, versions


def sampled(row, key):
    """The row's record for KEY: the in-process timing lives under ours."""
    if key == IN_PROCESS:
        return row["samplers"][OURS].setdefault("in_process", {})
    return row["samplers"].setdefault(key, {"sampler": LABELS[key], "mesh": row["mesh"], "n": row["n"]})


def time_ours(binary, mesh, row, out):
    """One timed `meshparticles run`, with the report's seconds.total and seconds.quality."""
    record = {"sampler": LABELS[OURS], "mesh": row["mesh"], "n": row["n"]}
    try:
        ran = shared.run_ours(binary, mesh, row["n"], [], out)
        seconds = json.loads((out / "report.json").read_text())["seconds"]
    except (Failure, OSError, ValueError, KeyError) as failure:
        progress(f"{row['mesh']} n={row['n']}: ours: {failure}")
        return dict(record, error=str(failure))
    record.update(seconds=ran["seconds"], report_total=seconds["total"], report_quality=seconds.get("quality"),
                  peak_rss_bytes=ran["peak_rss_bytes"], device=ran["device"], stopped=ran["stopped"],
                  file=ran["file"])
    progress(f"{row['mesh']} n={row['n']}: ours {ran['seconds']:.3f} s (report {seconds['total']:.3f} s)")
    return record


def report_peer(row, key):
    record = sampled(row, key)
    tag = f"{row['mesh']} n={row['n']}: {LABELS[key]}"
    if "error" in record:
        progress(f"{tag}: {record['error']}")
    else:
        progress(f"{tag}: {record['points']} points, {record['seconds']:.3f} s (call {record['call_seconds']:.3f} s)")


def measure(binary, mesh, row):
    """Every point set of the row by `quality`, then again where needed on one common refined mesh."""
    records = []
    for key, record in row["samplers"].items():
        if "error" in record:
            continue
        shared.measure_row(binary, mesh, record, record.pop("file"))
        records.append(record)
    shared.remeasure_at_common_refinement(binary, mesh, records)


# ================================================================ tables and summary

def number(x, pattern):
    return "–" if x is None else format(x, pattern)


def quality_of(row, key):
    return row["samplers"].get(key, {}).get("quality")


def quality_cell(row, key):
    record = row["samplers"].get(key, {})
    quality = record.get("quality")
    if quality is None:
        return "not run" if record.get("not_run") else "failed" if record else "–"
    cell = " / ".join(number(quality.get(name), pattern)
                      for name, pattern in (("nn_cv", ".3f"), ("rho", ".3f"), ("cover", ".3f")))
    if record.get("points") not in (None, row["n"]):
        cell += f" ({record['points']} pts)"
    if quality.get("stacked"):
        cell += f" ({quality['stacked']} stacked)"
    return cell


def quality_table(rows):
    keys = [OURS] + [key for key, _, _ in PEERS]
    lines = ["| mesh | V | n | " + " | ".join(LABELS[key] for key in keys) + " |",
             "|---|---|---|" + "---|" * len(keys)]
    for row in rows:
        cells = " | ".join(quality_cell(row, key) for key in keys)
        lines.append(f"| {row['mesh']} | {row['vertices']} | {row['n']} | {cells} |")
    return "\n".join(lines)


def peer_time_cell(record):
    if "seconds" not in record:
        return "not run" if record.get("not_run") else "failed" if record else "–"
    return f"{record['seconds']:.3f} / {record['call_seconds']:.3f}"


def run_ratio(row):
    """Ours run s over MeshLab vertex load+sample, or None."""
    ours, meshlab = row["samplers"][OURS], row["samplers"].get(MESHLAB_VERTEX, {})
    if "seconds" not in ours or not meshlab.get("seconds"):
        return None
    return ours["seconds"] / meshlab["seconds"]


def quality_share(row):
    ours = row["samplers"][OURS]
    if ours.get("report_quality") is None or not ours.get("report_total"):
        return None
    return ours["report_quality"] / ours["report_total"]


def time_table(rows):
    peers = [key for key, _, _ in PEERS]
    lines = ["| mesh | n | ours run s (report) | peak MiB | ours in-process s | quality share | "
             + " | ".join(f"{LABELS[key]} load+sample / call s" for key in peers) + " | ours / MeshLab vertex |",
             "|---|---|---|---|---|---|" + "---|" * (len(peers) + 1)]
    for row in rows:
        ours = row["samplers"][OURS]
        if "seconds" in ours:
            run = f"{ours['seconds']:.3f} ({ours['report_total']:.3f})"
            memory = f"{ours['peak_rss_bytes'] / 2**20:.0f}"
        else:
            run, memory = "failed", "–"
        in_process = ours.get("in_process", {})
        python = f"{in_process['call_seconds']:.3f}" if "call_seconds" in in_process else "–"
        share, ratio = quality_share(row), run_ratio(row)
        lines.append(f"| {row['mesh']} | {row['n']} | {run} | {memory} | {python} | "
                     f"{'–' if share is None else f'{share:.0%}'} | "
                     + " | ".join(peer_time_cell(row["samplers"].get(key, {})) for key in peers)
                     + f" | {'–' if ratio is None else f'{ratio:.1f}x'} |")
    return "\n".join(lines)


def share_line(text, hits, total):
    if total == 0:
        return f"- {text}: no row to judge"
    return f"- {text}: {hits} of {total} ({hits / total:.0%})"


def summary(rows):
    """The summary block: shares and medians over all rows."""
    ours = [quality_of(row, OURS) for row in rows]
    measured = [quality for quality in ours if quality]
    good = sum(1 for q in measured if q.get("rho") is not None and q["rho"] >= GOOD_RHO
               and q.get("nn_cv") is not None and q["nn_cv"] <= GOOD_CV)
    covers = [cover_at_most_meshlab(row) for row in rows if (quality_of(row, MESHLAB_VERTEX) or {}).get("cover")]
    ratios = [run_ratio(row) for row in rows if row["samplers"].get(MESHLAB_VERTEX, {}).get("seconds")]
    shares = [quality_share(row) for row in rows]
    lines = [f"Summary over {len(rows)} row{'s' * (len(rows) != 1)} (mesh and n; "
             f"ours failed on {len(rows) - len(measured)}):",
             share_line(f"ours rho >= {GOOD_RHO:.2f} and nn_cv <= {GOOD_CV}", good, len(rows)),
             f"- median of our rho: {median(q.get('rho') for q in measured)}, "
             f"of our nn_cv: {median(q.get('nn_cv') for q in measured)}",
             share_line("our cover <= MeshLab vertex's (rows where MeshLab's is defined)", sum(covers), len(covers)),
             share_line(f"our run <= {TIME_FACTOR:g} x MeshLab vertex load+sample (rows where MeshLab ran)",
                        sum(1 for r in ratios if r is not None and r <= TIME_FACTOR), len(ratios)),
             share_line(f"seconds.quality <= {QUALITY_SHARE:.0%} of seconds.total",
                        sum(1 for s in shares if s is not None and s <= QUALITY_SHARE), len(rows))]
    return "\n".join(lines)


def cover_at_most_meshlab(row):
    """Whether our cover is at most MeshLab vertex's (a failed or undefined cover of ours: no)."""
    ours = (quality_of(row, OURS) or {}).get("cover")
    return ours is not None and ours <= quality_of(row, MESHLAB_VERTEX)["cover"]


def median(values):
    values = [value for value in values if value is not None]
    return "–" if not values else f"{statistics.median(values):.4f}"


def failures(rows):
    """"mesh n=N sampler: reason" for every failed run, peer or measurement (not for those not run)."""
    lines = []
    for row in rows:
        records = [(LABELS[key], record) for key, record in row["samplers"].items()]
        records.append(("ours in-process", row["samplers"][OURS].get("in_process", {})))
        lines += [f"- {row['mesh']} n={row['n']}: {label}: {record['error']}"
                  for label, record in records if "error" in record and not record.get("not_run")]
    return lines


def report(rows, versions, notes, unavailable, binary):
    devices = sorted({row["samplers"][OURS].get("device") for row in rows} - {None})
    parts = ["## Quality: nn_cv / rho / cover, by `meshparticles quality`", "", quality_table(rows), "",
             "## Time: seconds (peers: load+sample / the sampling call alone)", "", time_table(rows), "",
             summary(rows), "",
             f"ours: {binary} on {', '.join(devices) or '?'}; "
             + ", ".join(f"{package} {version}" for package, version in sorted(versions.items()))]
    parts += [f"Not run: {LABELS[key]} ({reason})" for key, reason in unavailable.items()]
    failed = failures(rows)
    if failed:
        parts += ["", "Failures:", *failed]
    if notes:
        parts += ["", f"Left out: {len(notes)} (mesh or n; the JSON lists them)"]
    return "\n".join(parts)


# ================================================================ arguments and main

def forget_files(rows):
    """Drops the rows' paths into the work folder, removed at the end unless --keep."""
    for row in rows:
        for record in row["samplers"].values():
            record.pop("particles", None)
            record.pop("file", None)
            record.get("in_process", {}).pop("file", None)


def name_list(text):
    names = [part.strip() for part in text.split(",")]
    if not all(names):
        raise argparse.ArgumentTypeError(f"expected names separated by commas, got {text!r}")
    return names


def folder(text):
    path = Path(text)
    if not path.is_dir():
        raise argparse.ArgumentTypeError(f"{text}: no such folder")
    return path


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="bench_real_models.py", description="Ours against MeshLab, Open3D and "
                                     "point-cloud-utils Poisson-disk sampling on real meshes: quality and time.")
    parser.add_argument("-n", dest="counts", type=shared.particle_counts, default=DEFAULT_COUNTS,
                        help="particle counts, comma-separated (default 256,1024,4096)")
    parser.add_argument("--models", type=folder, metavar="DIR", help="extra meshes (.off/.ply/.obj/.stl) to add")
    parser.add_argument("--only", type=name_list, metavar="NAME[,NAME...]",
                        help="only these meshes (file name or stem)")
    parser.add_argument("--limit", type=shared.positive, metavar="K",
                        help="the first K qualifying meshes of each source")
    parser.add_argument("--max-vertices", type=shared.positive, metavar="V", help="leave out meshes of more vertices")
    parser.add_argument("--binary", type=Path, default=ROOT / "build" / "meshparticles",
                        help="meshparticles binary (default build/meshparticles)")
    parser.add_argument("--json", type=Path, metavar="FILE", help="write every row here")
    parser.add_argument("--markdown", type=Path, metavar="FILE", help="write the tables and summary here too")
    parser.add_argument("--no-python", action="store_true", help="no in-process timing (no module build)")
    parser.add_argument("--module-source", type=folder, default=ROOT, metavar="DIR",
                        help="the checkout to build the Python module from (default: this one)")
    parser.add_argument("--timeout", type=shared.positive, default=DEFAULT_TIMEOUT, metavar="S",
                        help=f"give up on a peer for one mesh (all n) after S seconds (default {DEFAULT_TIMEOUT})")
    parser.add_argument("--keep", type=Path, metavar="DIR", help="keep the point sets and run outputs here")
    return parser.parse_args(argv)


def main(argv):
    if argv[:1] == ["--worker"]:
        key, mesh, counts, out_dir, result_path = argv[1:6]
        worker(key, mesh, [int(n) for n in counts.split(",")], out_dir, result_path)
        return 0
    options = parse_arguments(argv)
    started = time.perf_counter()
    binary = options.binary.resolve() if options.binary.exists() else options.binary
    shared.check_binary(binary)
    files = candidate_files(options.models, options.only)
    meshes, notes = select_meshes(binary, files, sorted(set(options.counts)), options.limit, options.max_vertices)
    for note in notes:
        progress(f"left out: {note}")
    if not meshes:
        die("no mesh to benchmark")
    python, unavailable = prepare_venv(None if options.no_python else options.module_source.resolve())

    work = options.keep or Path(tempfile.mkdtemp(prefix=f"{PROG}-"))
    rows, versions = [], {}
    try:
        for index, (mesh, source, vertices, counts) in enumerate(meshes, 1):
            progress(f"mesh {index} of {len(meshes)}: {mesh.name}, {vertices} vertices, n = {counts}")
            mesh_rows, mesh_versions = bench_mesh(binary, python, unavailable, mesh, source, vertices, counts,
                                                  work / f"{source}-{mesh.name}", options.timeout)
            rows += mesh_rows
            versions.update(mesh_versions)
    finally:
        if options.keep is None:
            shutil.rmtree(work, ignore_errors=True)
            forget_files(rows)

    text = report(rows, versions, notes, unavailable, binary)
    print(text)
    if options.markdown:
        options.markdown.write_text(text + "\n")
        progress(f"wrote {options.markdown}")
    if options.json:
        options.json.write_text(json.dumps({"binary": str(binary), "counts": options.counts, "versions": versions,
                                            "rows": rows, "left_out": notes}, indent=2) + "\n")
        progress(f"wrote {options.json}")
    progress(f"done in {time.perf_counter() - started:.0f} s")
    ours_failed = any("quality" not in row["samplers"][OURS] for row in rows)
    return 1 if ours_failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
