#!/usr/bin/python3
"""Our particles against MeshLab's Poisson-disk sampling, on the same yardstick.

    scripts/compare_samplers.py [MESH ...] [-n 256,1024] [--config NAME=ARGS ...] [--ours-args ARGS]
                                [--repeat K] [--json FILE] [--keep DIR] [--no-warmup] [--binary FILE]
                                [--meshlab-timeout S] [--vertex-only] [--no-farthest]
    scripts/compare_samplers.py --corpus [--limit K] [--max-vertices V] [-n ...]

What it compares, per mesh and particle count n:
- ours: `meshparticles run MESH -n N -q` once per named configuration
  (`--config NAME=ARGS`, repeatable; default: `default` with no extra
  arguments and `farthest start` with `--iterations 0`), each with the extra
  arguments of `--ours-args` appended. `farthest start` is always run: the
  targets measure against it (give a config of that name to change it;
  `--no-farthest` leaves it out, and its cover check with it).
- MeshLab vertex Poisson disk: `generate_sampling_poisson_disk(samplenum=n,
  exactnumflag=True, subsample=True)`, a subset of the mesh's vertices;
- MeshLab surface Poisson disk: the same with subsample=False, points
  anywhere on the surface (measured as `quality` measures points between
  vertices: snapped to the nearest vertex, of a refined mesh where needed).

Why: MeshLab's Poisson-disk sampler is the tool people reach for to spread
points evenly over a mesh, so it is the peer our particle system has to beat.
Every sample is written as a `.particles` file and measured with our own
yardstick, `meshparticles quality MESH FILE --json` (geodesic nn_cv, rho =
nn_min / d_hex, cover = covering radius / d_hex; docs/QUALITY.md), so every
row is measured the same way, and on one mesh and n at the same refinement
(where the yardstick refines the mesh to measure points between vertices,
every sample is measured at the finest level any of them needed: the
covering radius depends on it). For each ours configuration other than the
farthest start, a second table checks the project's targets against MeshLab's
vertex sampler: nn_cv / MeshLab nn_cv <= 0.8, rho - MeshLab rho >= +0.05,
cover <= MeshLab's cover, and cover <= 1.1 x the farthest start's cover.

Times: ours is the wall time of the whole `run` process (mesh input, geodesic
distances from the cache, the particles, six output files), with the
report's `seconds.total` beside it (and in the JSON the process's peak
memory, `peak_rss_bytes`, from wait4); MeshLab is the filter call alone
(time.perf_counter around it; loading the mesh is not counted, the JSON has
it as `load_seconds`; MeshLab is given up on a mesh and n after
`--meshlab-timeout` seconds, default 300). `--vertex-only` runs (and
measures) MeshLab's vertex sampler alone.
One untimed warm-up run per mesh fills the distance cache and the OpenCL
kernel cache first (`--no-warmup` skips it). `--repeat K` times everything K times,
alternating ours and MeshLab, and reports min..max; the metrics come from
the first repetition.

MeshLab runs in a virtual environment of its own, `$MESHPARTICLES_PEER_VENV`
(default `${XDG_CACHE_HOME:-~/.cache}/meshparticles/peer-venv`), made on first
use with `pip install pymeshlab`; this script re-invokes itself there with
`--meshlab-worker`. pymeshlab is never a dependency of meshparticles. The
driver itself needs only Python 3's standard library.

`--corpus`: instead of the committed meshes, the meshes of Debian's
libcgal-demo (installed with apt-get if missing, unpacked as
scripts/real_meshes.sh does), every one `meshparticles info` accepts with at
least 4 vertices per particle; `--limit K` takes the first K, `--max-vertices
V` drops larger meshes.

Progress goes to stderr, the tables to stdout. Exit status: 0; 1 when a run or
a measurement failed (its row says why); 2 for a missing binary or mesh, or
bad arguments.
"""
import argparse
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROG = "compare_samplers"
ROOT = Path(__file__).resolve().parent.parent
DEFAULT_MESHES = ["meshes/sphere.off", "meshes/torus.off", "meshes/atrium.off"]
DEFAULT_CONFIGS = {"default": "", "farthest start": "--iterations 0"}
FARTHEST = "farthest start"
# (row label, file stem, subsample): MeshLab's two Poisson-disk samplers.
MESHLAB_SAMPLERS = [("MeshLab vertex Poisson", "meshlab-vertex", True),
                    ("MeshLab surface Poisson", "meshlab-surface", False)]
MESHLAB_VERTEX = MESHLAB_SAMPLERS[0][0]

# The project's targets against MeshLab's vertex sampler and the farthest start.
TARGET_CV_RATIO = 0.8  # nn_cv / MeshLab vertex nn_cv <= this
TARGET_RHO_GAIN = 0.05  # rho - MeshLab vertex rho >= this
TARGET_FARTHEST_COVER = 1.1  # cover <= this x the farthest start's cover

CGAL_ARCHIVE = Path("/usr/share/doc/libcgal-dev/data.tar.gz")
CORPUS_VERTICES_PER_PARTICLE = 4


class Failure(Exception):
    """A run or a measurement that failed: the row records it, the others go on."""


def progress(message):
    print(f"{PROG}: {message}", file=sys.stderr, flush=True)


def die(message):
    print(f"{PROG}: error: {message}", file=sys.stderr, flush=True)
    sys.exit(2)


def cache_home():
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")


def run_program(command, runner=subprocess.run, **options):
    """subprocess.run (or RUNNER), with a program that cannot start (removed, or relinked by a build) as a one-line error."""
    try:
        return runner(command, **options)
    except OSError as error:
        die(f"{command[0]}: cannot run it ({error.strerror}; is a build replacing it?)")


def last_line(text):
    lines = [line for line in text.strip().splitlines() if line.strip()]
    return lines[-1] if lines else "(no message)"


# ---------------------------------------------------------------- MeshLab side

def meshlab_worker(mesh, n, out_dir, result_path, stems):
    """Runs inside the peer venv: MeshLab's samplers named by STEMS on MESH, points to files, timings to RESULT."""
    import importlib.metadata

    import numpy as np
    import pymeshlab

    result = {"pymeshlab": importlib.metadata.version("pymeshlab"), "samplers": {}}
    for label, stem, subsample in MESHLAB_SAMPLERS:
        if stem not in stems:
            continue
        meshes = pymeshlab.MeshSet()
        loading = time.perf_counter()
        meshes.load_new_mesh(mesh)
        load_seconds = time.perf_counter() - loading
        input_vertices = meshes.current_mesh().vertex_number()
        start = time.perf_counter()
        meshes.generate_sampling_poisson_disk(samplenum=n, exactnumflag=True, subsample=subsample)
        seconds = time.perf_counter() - start
        if meshes.mesh_number() != 2:
            raise RuntimeError(f"{label}: expected the samples as a new layer, got {meshes.mesh_number()} layers")
        points = meshes.current_mesh().vertex_matrix()
        path = Path(out_dir) / f"{stem}.particles"
        np.savetxt(path, points, fmt="%.9g")
        result["samplers"][label] = {"seconds": seconds, "points": int(len(points)), "file": str(path),
                                     "meshlab_vertices": int(input_vertices), "load_seconds": load_seconds}
    Path(result_path).write_text(json.dumps(result))


def make_venv(venv, what):
    """VENV's interpreter, the virtual environment made first where it has none (WHAT names it in the message)."""
    python = venv / "bin" / "python"
    if not python.exists():
        progress(f"making the {what} virtual environment {venv}")
        made = subprocess.run([sys.executable, "-m", "venv", "--clear", str(venv)], capture_output=True, text=True)
        if made.returncode != 0:
            die(f"{venv}: cannot make a virtual environment ({last_line(made.stderr)}; "
                "on Debian: apt-get install python3-venv)")
    return python


def peer_venv_python():
    """The peer venv's interpreter, with pymeshlab installed (made on first use)."""
    venv = Path(os.environ.get("MESHPARTICLES_PEER_VENV") or cache_home() / "meshparticles" / "peer-venv")
    python = make_venv(venv, "MeshLab")
    if subprocess.run([str(python), "-c", "import pymeshlab"], capture_output=True).returncode != 0:
        progress(f"installing pymeshlab into {venv} (pip)")
        installed = subprocess.run([str(python), "-m", "pip", "install", "--quiet", "pymeshlab"],
                                   stdout=sys.stderr, stderr=subprocess.PIPE, text=True)
        if installed.returncode != 0:
            die(f"{venv}: pip install pymeshlab failed ({last_line(installed.stderr)})")
    return python


def run_meshlab(python, mesh, n, out_dir, timeout, samplers):
    """SAMPLERS (of MESHLAB_SAMPLERS) in the peer venv: {label: {seconds, points, file, ...}}, and pymeshlab's version."""
    out_dir.mkdir(parents=True, exist_ok=True)
    result_path = out_dir / "meshlab.json"
    command = [str(python), str(Path(__file__).resolve()), "--meshlab-worker", str(mesh), str(n), str(out_dir),
               str(result_path), ",".join(stem for _, stem, _ in samplers)]
    try:
        # The vertex sampler loops for ever when asked for more points than the mesh has vertices.
        worker = run_program(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise Failure(f"MeshLab did not finish in {timeout} s")
    if worker.returncode != 0:
        raise Failure(f"MeshLab failed: {last_line(worker.stderr)}")
    try:
        result = json.loads(result_path.read_text())
    except (OSError, ValueError) as error:
        raise Failure(f"MeshLab worker left no readable result ({error})")
    return result["samplers"], result["pymeshlab"]


# -------------------------------------------------------------- our side

def check_binary(binary):
    if not (binary.is_file() and os.access(binary, os.X_OK)):
        die(f"{binary}: no meshparticles binary there (build first: cmake --build build; or set --binary)")


def mesh_vertices(binary, mesh):
    """Vertices `meshparticles info` counts, or raises Failure with its reason."""
    info = run_program([str(binary), "info", str(mesh), "--json"], capture_output=True, text=True)
    if info.returncode != 0:
        raise Failure(last_line(info.stderr).replace("meshparticles: error: ", ""))
    return int(json.loads(info.stdout)["vertices"])


def run_ours(binary, mesh, n, args, out_dir):
    """One `meshparticles run`: its wall time, the report's figures and the particle file."""
    command = [str(binary), "run", str(mesh), "-n", str(n), "--out", str(out_dir), "-q", *args]
    start = time.perf_counter()
    run = run_program(command, runner=subprocess.Popen, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    errors = run.stderr.read()
    _, status, usage = os.wait4(run.pid, 0)  # this child's own peak memory, not the other children's
    run.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - start
    run.stderr.close()
    if run.returncode != 0:
        raise Failure(f"run failed (exit {run.returncode}): {errors and last_line(errors)}")
    try:
        report = json.loads((out_dir / "report.json").read_text())
    except (OSError, ValueError) as error:
        raise Failure(f"run left no readable report.json ({error})")
    return {"seconds": wall, "report_total": report["seconds"]["total"], "file": str(out_dir / "particles.particles"),
            "iterations_run": report.get("iterations_run"), "stopped": report.get("stopped"),
            "device": report.get("device"), "params": report.get("params"),
            "peak_rss_bytes": usage.ru_maxrss * 1024}


def measure_quality(binary, mesh, particles, refine=None, cutoff=None):
    """`meshparticles quality MESH FILE --json [--refine L] [--cutoff D]`: the whole answer (metrics under "quality")."""
    command = [str(binary), "quality", str(mesh), str(particles), "--json", "-q"]
    if refine is not None:
        command += ["--refine", str(refine)]
    if cutoff is not None:
        command += ["--cutoff", str(cutoff)]
    measured = run_program(command, capture_output=True, text=True)
    if measured.returncode != 0:
        raise Failure(f"quality failed: {last_line(measured.stderr)}")
    try:
        return json.loads(measured.stdout)
    except ValueError:
        raise Failure(f"quality printed no JSON: {last_line(measured.stdout)}")


def count_points(path):
    with open(path) as lines:
        return sum(1 for line in lines if line.strip())


# -------------------------------------------------------------- meshes

def corpus_directory():
    """Debian libcgal-demo's meshes, unpacked under the cache as scripts/real_meshes.sh does."""
    if not CGAL_ARCHIVE.is_file():
        sudo = [] if os.geteuid() == 0 else ["sudo"]
        if sudo and not shutil.which("sudo"):
            die(f"{CGAL_ARCHIVE}: missing; install libcgal-demo as root (apt-get install libcgal-demo)")
        progress("installing libcgal-demo (apt-get)")
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        for command in (["apt-get", "update", "-qq"],
                        ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "libcgal-demo"]):
            if subprocess.run(sudo + command, stdout=subprocess.DEVNULL, env=env).returncode != 0:
                die(f"{CGAL_ARCHIVE}: missing, and apt-get install libcgal-demo failed")
    cache = cache_home() / "meshparticles" / "cgal-data"
    meshes = cache / "data" / "meshes"
    if not meshes.is_dir():
        cache.mkdir(parents=True, exist_ok=True)
        if subprocess.run(["tar", "-xzf", str(CGAL_ARCHIVE), "-C", str(cache), "data/meshes"]).returncode != 0:
            die(f"{CGAL_ARCHIVE}: cannot unpack data/meshes into {cache}")
    return meshes


def corpus_cases(binary, counts, limit, max_vertices):
    """(mesh, vertices) for every corpus mesh `info` accepts with >= 4 vertices per particle for some n."""
    cases = []
    for mesh in sorted(corpus_directory().iterdir()):
        if limit is not None and len(cases) >= limit:
            break
        try:
            vertices = mesh_vertices(binary, mesh)
        except Failure as refused:
            progress(f"{mesh.name}: refused by info, left out ({refused})")
            continue
        if max_vertices is not None and vertices > max_vertices:
            continue
        if vertices < CORPUS_VERTICES_PER_PARTICLE * min(counts):
            continue
        cases.append((mesh, vertices))
    return cases


def named_cases(binary, paths, max_vertices):
    """(mesh, vertices) for meshes named on the command line; a missing or refused one ends the script."""
    cases = []
    for path in paths:
        mesh = Path(path)
        if not mesh.is_file():
            die(f"{mesh}: no such mesh file")
        try:
            vertices = mesh_vertices(binary, mesh)
        except Failure as refused:
            die(f"{mesh}: refused by meshparticles info ({refused})")
        if max_vertices is not None and vertices > max_vertices:
            progress(f"{mesh.name}: {vertices} vertices, over --max-vertices {max_vertices}: skipped")
            continue
        cases.append((mesh, vertices))
    return cases


# -------------------------------------------------------------- one mesh, one n

def compare_case(binary, python, mesh, vertices, n, configs, repeat, meshlab_timeout, work, samplers=MESHLAB_SAMPLERS,
                 quality_cutoff=None):
    """The rows for one mesh and n: each ours configuration, then MeshLab's SAMPLERS, all measured
    (by `quality --cutoff QUALITY_CUTOFF` where given)."""
    base = {"mesh": mesh.name, "mesh_path": str(mesh), "vertices": vertices, "n": n}
    rows = {}
    for name, args in configs.items():
        rows[name] = dict(base, sampler=f"ours: {name}", kind="ours", config=name, args=args,
                          seconds=[], report_total=[])
    for label, _, subsample in samplers:
        rows[label] = dict(base, sampler=label, kind="meshlab", subsample=subsample, seconds=[], points_per_repeat=[])
    files = {}  # row key -> the particle file of the first repetition, to measure
    pymeshlab_version = None
    for repetition in range(repeat):
        tag = f"{mesh.name} n={n}" + (f" [{repetition + 1}/{repeat}]" if repeat > 1 else "")
        for index, (name, args) in enumerate(configs.items()):
            out = work / (f"ours-{index}" if repetition == 0 else "ours-timing")
            time_ours(binary, mesh, n, args, out, rows[name], files if repetition == 0 else None, f"{tag}: ours {name}")
        out = work / ("meshlab" if repetition == 0 else "meshlab-timing")
        version = time_meshlab(python, mesh, n, out, meshlab_timeout, rows, files if repetition == 0 else None, tag,
                               samplers)
        pymeshlab_version = version or pymeshlab_version
    for key, row in rows.items():
        measure_row(binary, mesh, row, files.get(key), cutoff=quality_cutoff)
    remeasure_at_common_refinement(binary, mesh, rows.values(), cutoff=quality_cutoff)
    return list(rows.values()), pymeshlab_version


def time_ours(binary, mesh, n, args, out, row, files, tag):
    """One timed run of ours into ROW; on the first repetition (FILES given) its particle file too."""
    if "error" in row:
        return  # failed in an earlier repetition: it would again
    try:
        ran = run_ours(binary, mesh, n, args, out)
    except Failure as failure:
        row["error"] = str(failure)
        progress(f"{tag}: {failure}")
        return
    row["seconds"].append(ran["seconds"])
    row["report_total"].append(ran["report_total"])
    row.setdefault("peak_rss_bytes", []).append(ran["peak_rss_bytes"])
    if files is not None:
        files[row["config"]] = ran["file"]
        row.update(iterations_run=ran["iterations_run"], stopped=ran["stopped"], device=ran["device"],
                   params=ran["params"])
    progress(f"{tag}: {ran['seconds']:.3f} s (report {ran['report_total']:.3f} s)")


def time_meshlab(python, mesh, n, out, timeout, rows, files, tag, samplers=MESHLAB_SAMPLERS):
    """One timed call of MeshLab's SAMPLERS into ROWS; returns pymeshlab's version (None on failure)."""
    if "error" in rows[MESHLAB_VERTEX]:
        return None  # failed in an earlier repetition: it would again
    try:
        sampled, version = run_meshlab(python, mesh, n, out, timeout, samplers)
    except Failure as failure:
        for label, _, _ in samplers:
            rows[label]["error"] = str(failure)
        progress(f"{tag}: {failure}")
        return None
    for label, sample in sampled.items():
        rows[label]["seconds"].append(sample["seconds"])
        rows[label]["points_per_repeat"].append(sample["points"])
        rows[label]["meshlab_vertices"] = sample["meshlab_vertices"]
        rows[label].setdefault("load_seconds", []).append(sample.get("load_seconds"))
        if files is not None:
            files[label] = sample["file"]
        progress(f"{tag}: {label}: {sample['points']} points, {sample['seconds']:.3f} s")
    return version


def measure_row(binary, mesh, row, particles, refine=None, cutoff=None):
    """Our yardstick on the row's particle file: points, the quality metrics, how it measured them."""
    if particles is None:
        row.setdefault("error", "no sample")
        return
    try:
        measured = measure_quality(binary, mesh, particles, refine, cutoff)
    except Failure as failure:
        row["error"] = str(failure)
        progress(f"{mesh.name} n={row['n']}: {row['sampler']}: {failure}")
        return
    row["points"] = count_points(particles)
    row["quality"] = measured.get("quality", measured)
    # How it was measured: largest_snap, and where the yardstick has them, refinement_levels, measured_vertices.
    row["measurement"] = {key: value for key, value in measured.items() if key not in ("quality", "mesh", "particles")}
    if cutoff is not None:
        row["measurement"]["cutoff"] = cutoff  # quality's balls, in spacings (its default: 7)
    row["particles"] = particles  # under --keep, else removed at the end


def remeasure_at_common_refinement(binary, mesh, rows, cutoff=None):
    """Measure every sample of one mesh and n on the same refined mesh.

    `quality` measures points on the input's vertices on the input itself (MeshLab's vertex
    samples), and points between them on a refined mesh (`refinement` in its answer): spread's
    working mesh when every point lies on it (our default run's particles; it holds the input's
    vertices too), else the fewest uniform midpoint
    rounds that bring every point near a vertex (`refinement_levels`). The covering radius is the
    largest distance from any *measured* vertex, so on different meshes the covers are not
    comparable (MeshLab vertex on the torus, n = 1024: 0.677 at level 0, 0.917 at 3). Every sample
    is measured again where the others are: on spread's working mesh if any was measured there
    (other points are snapped to its vertices, `largest_snap` says how far), else at the finest
    uniform level any needed. A yardstick without refinement has nothing to do.
    """
    measured = [row for row in rows if "refinement_levels" in row.get("measurement", {})]
    where = {(row["measurement"].get("refinement", "uniform"), row["measurement"]["refinement_levels"])
             for row in measured}
    if len(where) < 2:
        return
    spread = any(kind == "spread" for kind, _ in where)
    common = ("spread", None) if spread else ("uniform", max(levels for _, levels in where))
    for row in measured:
        auto = (row["measurement"].get("refinement", "uniform"), row["measurement"]["refinement_levels"])
        if auto[0] == common[0] and (spread or auto[1] == common[1]):
            continue
        refine = "spread" if spread else common[1]
        progress(f"{row['mesh']} n={row['n']}: {row['sampler']}: measured again at refinement {refine} (auto {auto[0]} {auto[1]})")
        row.pop("quality")  # a failure must not leave the other mesh's figures
        measure_row(binary, mesh, row, row["particles"], refine=refine, cutoff=cutoff)
        row.setdefault("measurement", {})["auto_refinement"] = list(auto)


def target_checks(rows):
    """The targets for each ours configuration but the farthest start, per mesh and n."""
    checks = []
    by_case = {}
    for row in rows:
        by_case.setdefault((row["mesh_path"], row["n"]), {})[row["sampler"]] = row
    for (_, n), case in by_case.items():
        reference = case.get(MESHLAB_VERTEX, {}).get("quality")
        farthest = case.get(f"ours: {FARTHEST}", {}).get("quality")
        for row in case.values():
            if row["kind"] != "ours" or row["config"] == FARTHEST:
                continue
            ours = row.get("quality")
            check = {"mesh": row["mesh"], "n": n, "config": row["config"]}
            check["cv_ratio"] = ratio(ours, reference, "nn_cv")
            check["rho_gain"] = difference(ours, reference, "rho")
            check["cover"] = value(ours, "cover")
            check["meshlab_cover"] = value(reference, "cover")
            check["farthest_cover_limit"] = (None if value(farthest, "cover") is None
                                             else TARGET_FARTHEST_COVER * farthest["cover"])
            check["pass"] = {
                "cv_ratio": passes(check["cv_ratio"], lambda x: x <= TARGET_CV_RATIO),
                "rho_gain": passes(check["rho_gain"], lambda x: x >= TARGET_RHO_GAIN),
                "cover_vs_meshlab": passes_pair(check["cover"], check["meshlab_cover"]),
                "cover_vs_farthest": passes_pair(check["cover"], check["farthest_cover_limit"]),
            }
            checks.append(check)
    return checks


def value(quality, key):
    return None if quality is None else quality.get(key)


def ratio(a, b, key):
    if value(a, key) is None or not value(b, key):
        return None
    return a[key] / b[key]


def difference(a, b, key):
    if value(a, key) is None or value(b, key) is None:
        return None
    return a[key] - b[key]


def passes(x, rule):
    return None if x is None else bool(rule(x))


def passes_pair(x, limit):
    return None if x is None or limit is None else x <= limit


# -------------------------------------------------------------- tables

def seconds_cell(values, digits=3):
    if not values:
        return "–"
    low, high = min(values), max(values)
    return f"{low:.{digits}f}" if len(values) == 1 else f"{low:.{digits}f}..{high:.{digits}f}"


def number(x, pattern):
    return "–" if x is None else format(x, pattern)


def results_table(rows):
    lines = ["| mesh | V | n | sampler | points | nn_cv | rho | cover | seconds | report s |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        head = f"| {row['mesh']} | {row['vertices']} | {row['n']} | {row['sampler']} |"
        if "quality" not in row:
            lines.append(f"{head} FAILED: {row.get('error', '?')} | | | | | |")
            continue
        quality = row["quality"]
        points = str(row["points"])
        if quality.get("stacked"):
            points += f" ({quality['stacked']} stacked)"
        report = seconds_cell(row.get("report_total", []))
        lines.append(f"{head} {points} | {number(quality.get('nn_cv'), '.4f')} | {number(quality.get('rho'), '.3f')}"
                     f" | {number(quality.get('cover'), '.3f')} | {seconds_cell(row['seconds'])} | {report} |")
    return "\n".join(lines)


def refinement_summary(rows):
    """"sphere.off n=256: spread 1, ..." from the yardstick's answers ("" when it does not refine)."""
    levels = {}
    for row in rows:
        level = row.get("measurement", {}).get("refinement_levels")
        if level is not None:
            levels[f"{row['mesh']} n={row['n']}"] = f"{row['measurement'].get('refinement', 'uniform')} {level}"
    return ", ".join(f"{case}: {level}" for case, level in levels.items())


def verdict(ok):
    return "n/a" if ok is None else ("pass" if ok else "FAIL")


def target_cell(x, pattern, ok, limit=None, limit_pattern=".3f"):
    """"0.712 pass", or with a limit "0.737 vs 0.704 FAIL"; "n/a" when a side is missing."""
    if ok is None:
        return "n/a"
    shown = format(x, pattern) + ("" if limit is None else f" vs {format(limit, limit_pattern)}")
    return f"{shown} {verdict(ok)}"


def targets_table(checks):
    lines = [f"| mesh | n | ours | nn_cv / MeshLab vertex (<= {TARGET_CV_RATIO}) "
             f"| rho - MeshLab vertex (>= +{TARGET_RHO_GAIN}) | cover vs MeshLab vertex (<=) "
             f"| cover vs {TARGET_FARTHEST_COVER} x farthest start (<=) |",
             "|---|---|---|---|---|---|---|"]
    for check in checks:
        ok = check["pass"]
        lines.append(
            f"| {check['mesh']} | {check['n']} | {check['config']} "
            f"| {target_cell(check['cv_ratio'], '.3f', ok['cv_ratio'])} "
            f"| {target_cell(check['rho_gain'], '+.3f', ok['rho_gain'])} "
            f"| {target_cell(check['cover'], '.3f', ok['cover_vs_meshlab'], check['meshlab_cover'])} "
            f"| {target_cell(check['cover'], '.3f', ok['cover_vs_farthest'], check['farthest_cover_limit'])} |")
    return "\n".join(lines)


# -------------------------------------------------------------- arguments

def particle_counts(text):
    try:
        counts = [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected whole numbers separated by commas, got {text!r}")
    if not counts or min(counts) < 1:
        raise argparse.ArgumentTypeError(f"expected particle counts of at least 1, got {text!r}")
    return counts


def named_config(text):
    name, equals, args = text.partition("=")
    if not equals or not name.strip():
        raise argparse.ArgumentTypeError(f'expected NAME="ARGS", got {text!r}')
    return name.strip(), args


def positive(text):
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, got {text!r}")
    return int(text)


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="compare_samplers.py", description="Our particles against MeshLab's Poisson-disk samplers, "
        "measured by `meshparticles quality`.")
    parser.add_argument("meshes", nargs="*", help=f"meshes (default: {' '.join(DEFAULT_MESHES)})")
    parser.add_argument("-n", dest="counts", type=particle_counts, default=[1024],
                        help="particle counts, comma-separated (default 1024)")
    parser.add_argument("--config", type=named_config, action="append", metavar='NAME="ARGS"',
                        help="a named configuration of ours, repeatable (default: default=\"\" and "
                             "\"farthest start\"=\"--iterations 0\"; the farthest start is always added)")
    parser.add_argument("--ours-args", default="", metavar='"ARGS"', help="extra arguments for every run of ours")
    parser.add_argument("--repeat", type=positive, default=1, metavar="K",
                        help="time everything K times, alternating ours and MeshLab; report min..max")
    parser.add_argument("--json", type=Path, metavar="FILE", help="write every row and target check here")
    parser.add_argument("--keep", type=Path, metavar="DIR", help="keep the particle files and run outputs here")
    parser.add_argument("--quality-cutoff", type=float, metavar="D",
                        help="measure every sample with `quality --cutoff D` (default: quality's own, 7 spacings; "
                             "a smaller one where those balls would not fit in memory)")
    parser.add_argument("--meshlab-timeout", type=positive, default=300, metavar="S",
                        help="give up on MeshLab's samplers for one mesh and n after S seconds (default 300)")
    parser.add_argument("--vertex-only", action="store_true", help="MeshLab's vertex sampler alone (no surface sampler)")
    parser.add_argument("--no-farthest", action="store_true",
                        help="leave out the farthest start (unless a --config names it) and its cover check")
    parser.add_argument("--no-warmup", action="store_true", help="no untimed warm-up run per mesh")
    parser.add_argument("--binary", type=Path,
                        default=Path(os.environ.get("MESHPARTICLES_BINARY") or ROOT / "build" / "meshparticles"),
                        help="meshparticles binary (default: $MESHPARTICLES_BINARY, else build/meshparticles)")
    parser.add_argument("--corpus", action="store_true", help="the meshes of Debian's libcgal-demo instead")
    parser.add_argument("--limit", type=positive, metavar="K", help="--corpus: the first K meshes that qualify")
    parser.add_argument("--max-vertices", type=positive, metavar="V", help="leave out meshes of more vertices")
    options = parser.parse_args(argv)
    if options.corpus and options.meshes:
        parser.error("--corpus takes no mesh arguments")
    if options.limit is not None and not options.corpus:
        parser.error("--limit goes with --corpus")
    extra = shlex.split(options.ours_args)
    configs = dict(options.config) if options.config else dict(DEFAULT_CONFIGS)
    if not options.no_farthest:
        configs.setdefault(FARTHEST, DEFAULT_CONFIGS[FARTHEST])
    elif not options.config:
        del configs[FARTHEST]
    options.configs = {name: shlex.split(args) + extra for name, args in configs.items()}
    return options


# -------------------------------------------------------------- main

def main(argv):
    if argv[:1] == ["--meshlab-worker"]:
        mesh, n, out_dir, result_path = argv[1:5]
        stems = argv[5].split(",") if len(argv) > 5 else [stem for _, stem, _ in MESHLAB_SAMPLERS]
        meshlab_worker(mesh, int(n), out_dir, result_path, stems)
        return 0
    options = parse_arguments(argv)
    binary = options.binary.resolve() if options.binary.exists() else options.binary
    check_binary(binary)
    if options.corpus:
        cases = corpus_cases(binary, options.counts, options.limit, options.max_vertices)
        minimum = CORPUS_VERTICES_PER_PARTICLE
    else:
        cases = named_cases(binary, options.meshes or [ROOT / path for path in DEFAULT_MESHES], options.max_vertices)
        minimum = 1
    if not cases:
        die("no mesh to compare on")
    python = peer_venv_python()

    work = options.keep or Path(tempfile.mkdtemp(prefix=f"{PROG}-"))
    rows, skipped, pymeshlab_version = [], [], None
    try:
        for mesh, vertices in cases:
            counts = [n for n in options.counts if n * minimum <= vertices]
            for n in sorted(set(options.counts) - set(counts)):
                note = f"{mesh.name}: n={n} needs at least {n * minimum} vertices, it has {vertices}: skipped"
                skipped.append({"mesh": mesh.name, "n": n, "vertices": vertices, "note": note})
                progress(note)
            if counts and not options.no_warmup:
                progress(f"{mesh.name}: warm-up run (untimed; fills the distance and kernel caches)")
                first = next(iter(options.configs.values()))
                try:
                    run_ours(binary, mesh, counts[0], first, work / mesh.name / "warm-up")
                except Failure as failure:
                    progress(f"{mesh.name}: warm-up: {failure}")
            for n in counts:
                case_rows, version = compare_case(binary, python, mesh, vertices, n, options.configs, options.repeat,
                                                  options.meshlab_timeout, work / mesh.name / f"n{n}",
                                                  MESHLAB_SAMPLERS[:1] if options.vertex_only else MESHLAB_SAMPLERS,
                                                  options.quality_cutoff)
                rows.extend(case_rows)
                pymeshlab_version = version or pymeshlab_version
    finally:
        if options.keep is None:
            shutil.rmtree(work, ignore_errors=True)
            for row in rows:
                row.pop("particles", None)

    checks = target_checks(rows)
    print(results_table(rows))
    print()
    print(targets_table(checks))
    print()
    devices = sorted({row["device"] for row in rows if row.get("device")})
    print(f"pymeshlab {pymeshlab_version}; ours on {', '.join(devices) or '?'}; "
          f"{options.repeat} timing repetition{'s' if options.repeat > 1 else ''}")
    levels = refinement_summary(rows)
    if levels:
        print(f"yardstick's measuring mesh (spread's working mesh or uniform midpoint rounds): {levels}")
    for note in skipped:
        print(f"note: {note['note']}")
    if options.json:
        options.json.write_text(json.dumps({
            "pymeshlab": pymeshlab_version, "binary": str(binary), "devices": devices, "repeat": options.repeat,
            "configs": options.configs, "targets": {"cv_ratio_max": TARGET_CV_RATIO, "rho_gain_min": TARGET_RHO_GAIN,
                                                    "farthest_cover_factor": TARGET_FARTHEST_COVER},
            "rows": rows, "checks": checks, "skipped": skipped}, indent=2) + "\n")
        progress(f"wrote {options.json}")
    return 1 if any("error" in row for row in rows) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
