"""The Python package against the installed build (scripts/test_python.sh
installs it into a fresh venv first; this file installs nothing).

Runs on the committed meshes. The comparison with the program's own output
needs build/meshparticles (or $MESHPARTICLES_CLI) and is skipped without it.
"""
import json
import os
import re
import signal
import subprocess
import sys
import time
import types
from pathlib import Path

import numpy as np
import pytest

import meshparticles as mp

ROOT = Path(__file__).resolve().parents[2]
SPHERE = ROOT / "meshes" / "sphere.off"
TETRAHEDRON = ROOT / "meshes" / "tetrahedron.off"
N = 64
PAPER = dict(method="paper", backend="serial-field")  # the paper's method, on the host


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    """One distance cache for the module: the sphere's table is computed once."""
    return tmp_path_factory.mktemp("cache")


@pytest.fixture(scope="module")
def sphere():
    return mp.read_mesh(SPHERE)


@pytest.fixture(scope="module")
def paper_run(sphere, cache):
    return mp.run(sphere, n=N, seed=5, cache_dir=cache, quiet=True, **PAPER)


@pytest.fixture(scope="module")
def spread_run(sphere, cache):
    return mp.run(sphere, n=N, seed=5, cache_dir=cache, quiet=True)


def cli():
    program = os.environ.get("MESHPARTICLES_CLI") or ROOT / "build" / "meshparticles"
    return program if Path(program).is_file() else None


def on_surface(mesh, points, tolerance=1e-9):
    """Whether each point lies on some triangle of the mesh (within tolerance)."""
    v = mesh.vertices
    a, b, c = (v[mesh.faces[:, k]] for k in range(3))
    ab, ac = b - a, c - a
    normal = np.cross(ab, ac)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    found = np.zeros(len(points), dtype=bool)
    for i, p in enumerate(points):
        ap = p - a
        height = np.abs(np.einsum("ij,ij->i", ap, normal))
        # Barycentric coordinates of p's projection on each triangle's plane.
        d00, d01, d11 = (np.einsum("ij,ij->i", x, y) for x, y in ((ab, ab), (ab, ac), (ac, ac)))
        d20, d21 = np.einsum("ij,ij->i", ap, ab), np.einsum("ij,ij->i", ap, ac)
        denominator = d00 * d11 - d01 * d01
        w1 = (d11 * d20 - d01 * d21) / denominator
        w2 = (d00 * d21 - d01 * d20) / denominator
        inside = (w1 >= -tolerance) & (w2 >= -tolerance) & (w1 + w2 <= 1 + tolerance)
        found[i] = np.any(inside & (height <= tolerance))
    return found


def test_version_is_cmakes():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    assert mp.__version__ == re.search(r"project\(meshparticles\s+VERSION\s+([0-9.]+)", cmake).group(1)


def test_read_mesh(sphere):
    assert sphere.vertices.shape == (4000, 3) and sphere.vertices.dtype == np.float64
    assert sphere.faces.shape == (7996, 3)
    assert sphere.faces.min() >= 0 and sphere.faces.max() < 4000
    assert sphere.warnings == []
    assert sphere.label == str(SPHERE)


def test_mesh_from_arrays_round_trips(sphere):
    again = mp.Mesh(sphere.vertices, sphere.faces.astype(np.int32))
    np.testing.assert_array_equal(again.vertices, sphere.vertices)
    np.testing.assert_array_equal(again.faces, sphere.faces)
    assert again.area == pytest.approx(sphere.area)


def test_objects_with_vertices_and_faces_are_meshes(sphere):
    like_trimesh = types.SimpleNamespace(vertices=sphere.vertices.tolist(), faces=sphere.faces)
    mesh = mp.as_mesh(like_trimesh)
    np.testing.assert_array_equal(mesh.vertices, sphere.vertices)
    assert mp.as_mesh(str(SPHERE)).vertices.shape == (4000, 3)


def test_pyvista_and_meshio_layouts_are_meshes(sphere):
    # A quad (0 1 2 3) beside a triangle (2 1 4): fanned as the readers do.
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0.5, 0]], dtype=float)
    fanned = [[0, 1, 2], [0, 2, 3], [2, 1, 4]]
    like_pyvista = types.SimpleNamespace(points=points, faces=np.array([4, 0, 1, 2, 3, 3, 2, 1, 4]), n_strips=0)
    np.testing.assert_array_equal(mp.as_mesh(like_pyvista).faces, fanned)
    block = lambda kind, data: types.SimpleNamespace(type=kind, data=np.array(data))
    like_meshio = types.SimpleNamespace(points=points, cells=[block("quad", [[0, 1, 2, 3]]), block("line", [[0, 1]]),
                                                              block("triangle", [[2, 1, 4]])])
    np.testing.assert_array_equal(mp.as_mesh(like_meshio).faces, fanned)
    with pytest.raises(ValueError, match="runs past the array"):
        mp.as_mesh(types.SimpleNamespace(points=points, faces=np.array([4, 0, 1])))
    # The whole sphere through pyvista's layout: the same mesh.
    flat = np.hstack([np.full((len(sphere.faces), 1), 3), sphere.faces]).ravel()
    again = mp.as_mesh(types.SimpleNamespace(points=sphere.vertices, faces=flat))
    np.testing.assert_array_equal(again.faces, sphere.faces)


def test_unreferenced_vertex_warns_and_is_dropped():
    tetrahedron = mp.read_mesh(TETRAHEDRON)
    vertices = np.vstack([tetrahedron.vertices, [[9.0, 9.0, 9.0]]])
    with pytest.warns(mp.MeshWarning):
        mesh = mp.Mesh(vertices, tetrahedron.faces)
    assert len(mesh.warnings) == 1 and "unreferenced" in mesh.warnings[0]
    assert mesh.vertices.shape == tetrahedron.vertices.shape
    assert mesh.input_vertex_count == len(vertices)
    distances = mp.geodesics(mesh, [0])
    assert distances.shape == (1, len(vertices)) and np.isinf(distances[0, -1])


def test_paper_run_lies_on_vertices(sphere, paper_run):
    assert paper_run.positions.shape == (N, 3) and paper_run.vertices.shape == (N,)
    np.testing.assert_array_equal(paper_run.positions, sphere.vertices[paper_run.vertices])
    assert len(np.unique(paper_run.vertices)) == N
    assert paper_run.report["params"]["backend"] == "serial-field"
    assert paper_run.quality["nn_min"] > 0


def test_spread_run_lies_on_the_surface(sphere, spread_run):
    assert spread_run.positions.shape == (N, 3)
    assert on_surface(sphere, spread_run.positions).all()
    assert spread_run.report["params"]["method"] == "spread"
    assert spread_run.seconds > 0


def test_same_seed_same_particles(sphere, cache, paper_run, spread_run):
    again = mp.run(sphere, n=N, seed=5, cache_dir=cache, quiet=True, **PAPER)
    np.testing.assert_array_equal(again.positions, paper_run.positions)
    again = mp.run(sphere, n=N, seed=5, cache_dir=cache, quiet=True)
    np.testing.assert_array_equal(again.positions, spread_run.positions)


def test_save_writes_the_run_files(paper_run, tmp_path):
    out = tmp_path / "out"
    paper_run.save(out)
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["particles.particles", "particles.csv", "particles.ply", "mesh_distance.vtk", "mesh_distance.vtp", "report.json"])
    points = np.loadtxt(out / "particles.particles")
    np.testing.assert_allclose(points, paper_run.positions, rtol=1e-8)
    report = json.loads((out / "report.json").read_text())
    assert report["params"]["out"] == str(out)
    assert report["version"] == mp.__version__
    assert report["quality"] == paper_run.quality
    paper_run.save(out)  # a run's own directory is replaced


def test_save_refuses_a_directory_of_other_files(paper_run, tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(ValueError, match="notes.txt"):
        paper_run.save(tmp_path)


@pytest.mark.skipif(cli() is None, reason="needs build/meshparticles or $MESHPARTICLES_CLI")
@pytest.mark.parametrize("options", [["--backend", "serial-field"], []], ids=["paper", "spread"])
def test_same_particles_as_the_program(options, cache, tmp_path):
    command = [str(cli()), "run", str(SPHERE), "-n", str(N), "--seed", "5", "-q", "--cache-dir", str(cache),
               "--out", str(tmp_path / "cli")] + options
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    python_options = PAPER if options else {}
    mp.run(SPHERE, n=N, seed=5, cache_dir=cache, quiet=True, **python_options).save(tmp_path / "python")
    for name in ("particles.particles", "particles.csv"):
        assert (tmp_path / "python" / name).read_text() == (tmp_path / "cli" / name).read_text()


def test_quality_of_a_run(sphere, paper_run, cache):
    measured = mp.quality(sphere, paper_run, cache_dir=cache, quiet=True)
    assert measured["n"] == N and measured["refinement_levels"] == 0
    assert measured["quality"]["nn_mean"] == pytest.approx(paper_run.quality["nn_mean"])


def test_geodesics(sphere):
    distances = mp.geodesics(sphere, [0, 100])
    assert distances.shape == (2, 4000)
    assert distances[0, 0] == 0 and distances[1, 100] == 0
    assert distances[0, 100] == pytest.approx(distances[1, 0], rel=0.02)
    near = mp.geodesics(sphere, 0, max_distance=0.3)
    assert np.isinf(near).any() and (near[np.isfinite(near)] <= 0.3).all()


def test_devices_or_device_error():
    try:
        listed = mp.devices()
    except mp.DeviceError:
        return
    assert all({"index", "name", "type", "selected"} <= set(d) for d in listed)


def test_errors_are_value_errors_with_the_programs_message(sphere, tmp_path):
    with pytest.raises(ValueError, match=r"n: expected a whole number from 1 to \d+, got 0"):
        mp.run(sphere, n=0)
    with pytest.raises(ValueError, match="unknown method 'fast'"):
        mp.run(sphere, n=N, method="fast")
    with pytest.raises(ValueError, match="no such file"):
        mp.read_mesh(tmp_path / "missing.off")
    with pytest.raises(ValueError):
        mp.Mesh(np.zeros((3, 3)), np.array([[0, 1, 7]]))
    with pytest.raises(ValueError, match=r"\(V, 3\)"):
        mp.Mesh(np.zeros((3, 2)), np.array([[0, 1, 2]]))
    with pytest.raises(TypeError, match="particles"):
        mp.run(sphere, particles=5)
    with pytest.raises(ValueError, match="is not a vertex"):
        mp.geodesics(sphere, [4000])


def test_no_opencl_runtime_is_a_device_error(tmp_path):
    # The ICD loader reads OCL_ICD_VENDORS once, when OpenCL is first used: a fresh process.
    script = (
        "import sys, meshparticles as mp\n"
        "try:\n"
        f"    mp.run({str(SPHERE)!r}, n=8, backend='field', iterations=1, quiet=True, no_cache=True)\n"
        "except mp.DeviceError as e:\n"
        "    print(e); sys.exit(0)\n"
        "sys.exit(1)\n"
    )
    environment = dict(os.environ, OCL_ICD_VENDORS=str(tmp_path / "no-vendors"))
    done = subprocess.run([sys.executable, "-c", script], env=environment, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "no OpenCL platform found" in done.stdout
    assert issubclass(mp.DeviceError, RuntimeError)


def test_ctrl_c_stops_a_long_run_and_writes_nothing(tmp_path):
    # A run of many seconds (spread on the sphere refined to a million vertices),
    # interrupted a second in: KeyboardInterrupt, and no output directory.
    # Inside the run, not after it: the sweeps never print their final line
    # (Python alone would raise KeyboardInterrupt only once run() returned).
    script = (
        "import sys, time, meshparticles as mp\n"
        f"mesh = mp.read_mesh({str(SPHERE)!r})\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    result = mp.run(mesh, n=1024, vertices_per_particle=400)\n"
        f"    result.save({str(tmp_path / 'out')!r})\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True); sys.exit(0)\n"
        "print('finished', flush=True); sys.exit(1)\n"
    )
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.0)
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=120)
    assert child.returncode == 0 and out.strip() == "interrupted", out + err
    assert "spread: " not in err, err
    assert not (tmp_path / "out").exists()


def test_surface_locations_give_back_each_point(spread_run, paper_run):
    # Input triangles and weights, as particles.csv has them: they rebuild the points.
    sphere_vertices = mp.read_mesh(SPHERE).vertices
    for result in (spread_run, paper_run):
        assert result.triangles.shape == (N, 3) and result.weights.shape == (N, 3)
        rebuilt = np.einsum("ik,ikj->ij", result.weights, sphere_vertices[result.triangles])
        np.testing.assert_allclose(rebuilt, result.positions, atol=1e-9)
        assert (result.weights >= -1e-12).all() and np.allclose(result.weights.sum(axis=1), 1)


def test_trace_is_the_reports(spread_run, paper_run):
    assert spread_run.trace == spread_run.report["sweeps"] and len(spread_run.trace) >= 1
    assert "moved" in spread_run.trace[0] and "min_spacing" in spread_run.trace[0]
    assert paper_run.trace == paper_run.report["trace"] and "energy" in paper_run.trace[0]


def test_compare_two_runs(sphere, paper_run, spread_run, cache):
    compared = mp.compare(sphere, paper_run, spread_run, cache_dir=cache, quiet=True)
    assert compared["a"]["n"] == N and compared["b"]["n"] == N
    assert compared["mean_distance_a_to_b"] > 0 and compared["mean_distance_b_to_a"] > 0
    itself = mp.compare(sphere, paper_run, paper_run, cache_dir=cache, quiet=True)
    assert itself["mean_distance_a_to_b"] == 0 and itself["a"]["quality"] == itself["b"]["quality"]


@pytest.mark.skipif(cli() is None, reason="needs build/meshparticles or $MESHPARTICLES_CLI")
def test_compare_as_the_program(sphere, paper_run, spread_run, cache, tmp_path):
    paper_run.save(tmp_path / "a")
    spread_run.save(tmp_path / "b")
    command = [str(cli()), "compare", str(SPHERE), str(tmp_path / "a" / "particles.particles"),
               str(tmp_path / "b" / "particles.particles"), "--json", "-q", "--cache-dir", str(cache)]
    program = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
    ours = mp.compare(SPHERE, paper_run, spread_run, cache_dir=cache, quiet=True)
    for key in ("refinement", "refinement_levels", "measured_vertices"):
        assert ours[key] == program[key], key
    assert ours["a"]["quality"]["nn_cv"] == pytest.approx(program["a"]["quality"]["nn_cv"], rel=1e-6)
    assert ours["mean_distance_a_to_b"] == pytest.approx(program["mean_distance_a_to_b"], rel=1e-6)


def test_batch_runs_each_mesh_and_resumes(tmp_path, cache):
    inputs = [ROOT / "meshes" / "torus.off", TETRAHEDRON, tmp_path / "missing.off"]
    (tmp_path / "missing.off").write_text("OFF\n3 1 0\n0 0 0\n")  # truncated: refused, the others go on
    summary = mp.batch(inputs, tmp_path / "out", n=4, cache_dir=cache, quiet=True)
    statuses = {Path(row["mesh"]).name: row["status"] for row in summary["meshes"]}
    assert statuses == {"torus.off": "ok", "tetrahedron.off": "ok", "missing.off": "refused"}
    assert summary["version"] == mp.__version__
    torus = next(row for row in summary["meshes"] if row["mesh"].endswith("torus.off"))
    files = sorted(p.name for p in (tmp_path / "out" / torus["output"]).iterdir())
    assert files == sorted(["particles.particles", "particles.csv", "particles.ply", "mesh_distance.vtk",
                            "mesh_distance.vtp", "report.json"])
    # The same particles as run() with the same options.
    alone = mp.run(inputs[0], n=4, cache_dir=cache, quiet=True)
    np.testing.assert_allclose(np.loadtxt(tmp_path / "out" / torus["output"] / "particles.particles"),
                               alone.positions, rtol=1e-8)
    again = mp.batch(inputs, tmp_path / "out", n=4, cache_dir=cache, quiet=True)
    assert [row["status"] for row in again["meshes"]] == [row["status"] for row in summary["meshes"]]
    with pytest.raises(ValueError, match="at most one of n, spacing and per_area"):
        mp.batch(inputs, tmp_path / "other", n=4, spacing=0.1)
    with pytest.raises(TypeError, match="frobnicate"):
        mp.batch(inputs, tmp_path / "other", frobnicate=1)


# Issue 50, items 10-14: keywords, values the program refuses, paths, cancelling.

WHOLE_KEYWORDS = ["n", "iterations", "relax_rounds", "seed", "start_vertex", "threads", "colors", "wg", "tile",
                  "rebuild_every"]


@pytest.mark.parametrize("keyword", WHOLE_KEYWORDS)
@pytest.mark.parametrize("value", [2.7, "3", float("nan"), True, np.float64(2.0)], ids=repr)
def test_whole_number_keywords_refuse_what_int_would_convert(keyword, value):
    # int() would truncate 2.7 and parse "3": refused by type, naming the keyword, before any work.
    tetrahedron = mp.read_mesh(TETRAHEDRON)
    with pytest.raises(TypeError, match=rf"^{keyword}: expected an integer, got \w"):
        mp.run(tetrahedron, **{keyword: value})


def test_whole_number_keywords_take_numpy_integers(tmp_path):
    result = mp.run(TETRAHEDRON, n=np.int64(2), iterations=np.uint8(0), seed=np.int32(4), no_cache=True, quiet=True)
    assert len(result.positions) == 2
    with pytest.raises(TypeError, match=r"^n: expected an integer, got float"):
        mp.batch([TETRAHEDRON], tmp_path / "out", n=2.7)
    for sources in (1.5, [0, 1.5], ["0"], [True]):
        with pytest.raises(TypeError, match=r"^sources: expected an integer, got"):
            mp.geodesics(TETRAHEDRON, sources)
    with pytest.raises(ValueError, match=r"^sources: expected a whole number from 0 to \d+, got -1$"):
        mp.geodesics(TETRAHEDRON, [-1])
    assert mp.geodesics(TETRAHEDRON, np.array([0, 3])).shape == (2, 4)


@pytest.mark.parametrize("keyword", ["sigma", "vertices_per_particle", "cutoff"])
@pytest.mark.parametrize("value", [float("inf"), float("nan"), 0, -1.0])
def test_positive_numbers_are_finite_and_above_zero_as_the_programs(keyword, value):
    # The program's words (--sigma: expected a finite number above 0, got "inf"), without the dashes.
    with pytest.raises(ValueError, match=rf"^{keyword}: expected a finite number above 0, got "):
        mp.run(TETRAHEDRON, n=2, no_cache=True, quiet=True, **{keyword: value})


def test_other_calls_refuse_what_the_program_refuses(sphere, paper_run, tmp_path):
    points = paper_run.positions
    for measure in (lambda **o: mp.quality(sphere, points, **o), lambda **o: mp.compare(sphere, points, points, **o)):
        with pytest.raises(ValueError, match=r"^sigma: expected a finite number above 0, got inf$"):
            measure(sigma=float("inf"), no_cache=True)
        with pytest.raises(ValueError, match=r"^cutoff: expected a finite number above 0, got inf$"):
            measure(cutoff=float("inf"), no_cache=True)
        with pytest.raises(TypeError, match=r"^sigma: expected a number, got str$"):
            measure(sigma="1", no_cache=True)
    for keyword in ("spacing", "per_area"):
        with pytest.raises(ValueError, match=rf"^{keyword}: expected a finite number above 0, got inf$"):
            mp.batch([TETRAHEDRON], tmp_path / "out", **{keyword: float("inf")})
    for limit in (-1, -0.5, float("nan"), float("-inf")):
        with pytest.raises(ValueError, match=r"^max_distance: expected a number from 0 up"):
            mp.geodesics(sphere, [0], max_distance=limit)
    at_zero = mp.geodesics(sphere, [0], max_distance=0)
    assert at_zero[0, 0] == 0 and np.isinf(at_zero[0, 1:]).all()
    assert np.isfinite(mp.geodesics(sphere, [0], max_distance=float("inf"))).all()


@pytest.mark.parametrize("keyword", ["backend", "method", "scheme", "init", "potential", "geodesic", "distances",
                                     "device", "weights"])
def test_empty_words_are_refused_not_the_default(keyword):
    with pytest.raises(ValueError, match=rf"^{keyword}: an empty value is not allowed"):
        mp.run(TETRAHEDRON, n=2, **{keyword: ""})
    with pytest.raises(TypeError, match=rf"^{keyword}: expected a string, got int$"):
        mp.run(TETRAHEDRON, n=2, **{keyword: 1})


def test_flags_are_true_or_false():
    with pytest.raises(TypeError, match=r"^quiet: expected True or False, got str$"):
        mp.run(TETRAHEDRON, n=2, quiet="no")
    with pytest.raises(TypeError, match=r"^no_cache: expected True or False, got int$"):
        mp.run(TETRAHEDRON, n=2, no_cache=1)


def test_a_nul_in_a_path_is_a_value_error_as_open_raises(paper_run, tmp_path):
    with pytest.raises(ValueError, match=r"^cache_dir: embedded null byte$"):
        mp.run(TETRAHEDRON, n=2, cache_dir=str(tmp_path / "cache\x00suffix"), quiet=True)
    assert not (tmp_path / "cache").exists()
    with pytest.raises(ValueError, match=r"^tuning_file: embedded null byte$"):
        mp.run(TETRAHEDRON, n=2, tuning_file=str(tmp_path / "t\x00.json"), no_cache=True)
    with pytest.raises(ValueError, match=r"^path: embedded null byte$"):
        mp.read_mesh(str(TETRAHEDRON) + "\x00.off")
    with pytest.raises(ValueError, match=r"^path: embedded null byte$"):
        mp.read_mesh(bytes(TETRAHEDRON) + b"\x00")
    with pytest.raises(ValueError, match=r"^directory: embedded null byte$"):
        paper_run.save(str(tmp_path / "out\x00x"))
    assert not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match=r"^inputs: embedded null byte$"):
        mp.batch([str(TETRAHEDRON) + "\x00"], tmp_path / "batch")
    with pytest.raises(ValueError, match=r"^out: embedded null byte$"):
        mp.batch([TETRAHEDRON], str(tmp_path / "batch\x00x"))
    with pytest.raises(TypeError, match=r"^path: expected str, bytes or os.PathLike object, not int$"):
        mp.read_mesh(3)
    with pytest.raises(ValueError, match=r"^cache_dir: an empty path"):
        mp.run(TETRAHEDRON, n=2, cache_dir="")


def test_paths_that_are_not_utf8(tmp_path):
    # Linux names are bytes: b"\xff.off" is a file name, seen in Python as "\udcff.off".
    folder = os.fsencode(tmp_path)
    name = folder + b"/\xff.off"
    with open(name, "wb") as copy:
        copy.write((ROOT / "tests" / "data" / "unreferenced_vertices.off").read_bytes())
    with pytest.warns(mp.MeshWarning, match=r"\\xff\.off"):
        mesh = mp.read_mesh(os.fsdecode(name))
    assert mesh.label == os.fsdecode(name)  # opens the same file again
    assert "\\xff.off" in repr(mesh) and "\\xff.off" in mesh.warnings[0]
    with pytest.warns(mp.MeshWarning):
        assert mp.read_mesh(name).input_vertex_count == mesh.input_vertex_count
    with pytest.raises(ValueError, match=r"\\xfe-missing\.off: no such file"):
        mp.read_mesh(folder + b"/\xfe-missing.off")
    result = mp.run(mesh, n=2, no_cache=True, quiet=True)
    assert result.report["mesh"]["path"] == os.fsencode(tmp_path).decode() + "/\\xff.off"
    out = folder + b"/\xfe-out"
    result.save(out)
    report = json.loads(open(out + b"/report.json", "rb").read())
    assert report["params"]["out"].endswith("/\\xfe-out") and report["mesh"]["path"].endswith("/\\xff.off")
    summary = mp.batch([name], folder + b"/\xfd-batch", n=2, no_cache=True, quiet=True)
    assert summary["meshes"][0]["status"] == "ok" and summary["meshes"][0]["mesh"].endswith("/\\xff.off")
    again = mp.batch([name], folder + b"/\xfd-batch", n=2, no_cache=True, quiet=True)
    # Resumed: the escaped path in report.json is this mesh's (a rerun would time itself anew).
    assert again["meshes"][0]["seconds_total"] == summary["meshes"][0]["seconds_total"], again


def test_cancel_stops_a_run_on_another_thread(sphere):
    # Ctrl-C reaches the main thread only: a run on another thread stops by its event.
    import threading
    event, outcome = threading.Event(), {}

    def work():
        started = time.monotonic()
        try:
            mp.run(sphere, n=1024, vertices_per_particle=400, quiet=True, no_cache=True, cancel=event)
            outcome["result"] = "finished"
        except mp.Cancelled as cancelled:
            outcome["result"] = str(cancelled)
        outcome["seconds"] = time.monotonic() - started

    worker = threading.Thread(target=work, daemon=True)
    worker.start()
    time.sleep(1.0)
    event.set()
    worker.join(timeout=30)
    assert not worker.is_alive() and "cancel" in outcome["result"], outcome
    assert outcome["seconds"] < 10, outcome
    with pytest.raises(TypeError, match=r"^cancel: expected a threading.Event"):
        mp.run(sphere, n=2, cancel=True)
    # A set event stops geodesics too, between its sources.
    with pytest.raises(mp.Cancelled):
        mp.geodesics(sphere, range(4000), cancel=event)


def test_mesh_takes_lists_and_names_what_it_refuses():
    mesh = mp.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    assert mesh.vertices.shape == (3, 3) and mesh.faces.tolist() == [[0, 1, 2]]
    with pytest.raises(TypeError, match=r"^faces: expected integer vertex indices$"):
        mp.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2.5]])
    with pytest.raises(ValueError, match=r"^vertices: expected an array of shape \(V, 3\)$"):
        mp.Mesh([[0, 0], [1, 0]], [[0, 1, 2]])
    with pytest.raises(TypeError, match=r"^vertices: expected a \(V, 3\) array of numbers"):
        mp.Mesh([["a", "b", "c"]] * 3, [[0, 1, 2]])
    # Real numbers only: NumPy would cast these to doubles without a word.
    triangle = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    for dtype in ("datetime64[D]", "timedelta64[s]", "bool", "complex128"):
        refusal = rf"^vertices: expected a \(V, 3\) array of numbers, got dtype {re.escape(dtype)}$"
        with pytest.raises(TypeError, match=refusal):
            mp.Mesh(triangle.astype(dtype), [[0, 1, 2]])
    for dtype in ("int8", "uint16", "float16", "float32", "longdouble"):
        assert mp.Mesh(triangle.astype(dtype), [[0, 1, 2]]).vertices.tolist() == triangle.tolist()


def test_a_huge_unsigned_index_is_reported_as_given():
    faces = np.array([[0, 1, 2**63 + 1]], dtype=np.uint64)
    with pytest.raises(ValueError, match=r"face 0 refers to vertex 9223372036854775809, out of range"):
        mp.Mesh(np.zeros((3, 3)), faces)


def test_out_of_memory_while_building_a_mesh_names_the_stage():
    # Under an address-space limit just above what the arrays take: the copy into the mesh fails.
    script = (
        "import resource, numpy as np, meshparticles as mp\n"
        "count = 4_000_000\n"
        "vertices = np.random.default_rng(1).random((count, 3))\n"
        "faces = np.arange(3 * count, dtype=np.int64).reshape(count, 3) % count\n"
        "used = int(open('/proc/self/statm').read().split()[0]) * resource.getpagesize()\n"
        "resource.setrlimit(resource.RLIMIT_AS, (used + (64 << 20),) * 2)\n"
        "try:\n"
        "    mp.Mesh(vertices, faces)\n"
        "except ValueError as e:\n"
        "    print(e)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert "<arrays>: out of memory while building the mesh" in done.stdout, done.stdout + done.stderr
