"""The Python module against the program: the same options and seed give the same bits, errors
raise the package's exceptions naming the file, warnings go through Python's `warnings`."""

import csv
import io
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import radiosity
from conftest import CORNELL, ROOT

RAYS = 20000  # per surface: enough for every pair of the Cornell box, quick on two cores


def csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@pytest.fixture(scope="module")
def cornell_factors():
    with pytest.warns(radiosity.RadiosityWarning):  # the floor's rays lost on black backs
        return radiosity.view_factors(CORNELL, rays=RAYS, seed=3, enforce="none")  # the rays' own estimates


# --- version, devices, scenes ------------------------------------------------------------------

def test_version_is_the_programs(run):
    assert run("--version").strip() == "radiosity " + radiosity.__version__


def test_devices_lists_what_the_program_lists(run):
    devices = radiosity.devices()
    assert devices and devices[0]["index"] == 0
    listed = run("devices").splitlines()
    assert len(listed) == len(devices)
    for line, d in zip(listed, devices):
        assert line.startswith("%d: %s / %s (" % (d["index"], d["platform"], d["name"]))


def test_load_scene_names_areas_and_counts(cornell_factors):
    scene = radiosity.load_scene(CORNELL)
    assert scene.names == cornell_factors.names
    assert np.array_equal(scene.areas, cornell_factors.areas)
    assert scene.faces == 32 and scene.patches == int(scene.patch_counts.sum()) and scene.has_emitters
    assert len(scene) == 8 and "cornell-box.gltf" in repr(scene)


def test_mesh_files_with_a_unit(run):
    files = [os.path.join(ROOT, "tests", "data", "meshes", f) for f in ("floor.stl", "lamp.stl", "panel.stl")]
    scene = radiosity.load_scene(files, unit="mm")
    assert scene.names == ["floor", "lamp", "panel"]
    vf = radiosity.view_factors(scene, rays=4000)
    assert vf.to_csv() == run("viewfactors", *files, "--unit", "mm", "--rays", 4000)


# --- view factors ------------------------------------------------------------------------------

def test_view_factors_same_bits_as_the_program(run, cornell_factors):
    text = run("viewfactors", CORNELL, "--rays", RAYS, "--seed", 3, "--enforce", "none")
    assert cornell_factors.to_csv() == text
    index = {name: i for i, name in enumerate(cornell_factors.names)}
    rows = csv_rows(text)
    stored = np.zeros_like(cornell_factors.matrix, dtype=bool)
    for r in rows:
        i, j = index[r["from"]], index[r["to"]]
        stored[i, j] = True
        # The program prints F with 9 significant digits and stderr with 3, from these doubles.
        assert "%.9g" % cornell_factors.matrix[i, j] == r["F"]
        assert "%.3g" % cornell_factors.stderr[i, j] == r["stderr"]
    assert np.all(cornell_factors.matrix[~stored] == 0.0)


def test_stderr_shape_and_positivity(cornell_factors):
    f, e = cornell_factors.matrix, cornell_factors.stderr
    assert f.dtype == np.float64 and f.shape == e.shape == (8, 8)
    assert np.all(e[f > 0] > 0) and np.all(e[f == 0] == 0)
    assert np.allclose(e[f > 0], np.sqrt(f * (1 - f) / RAYS)[f > 0], rtol=1e-12)


def test_sparse_equals_dense(cornell_factors):
    sparse = cornell_factors.sparse()
    assert sparse.format == "csr" and sparse.shape == (8, 8)
    assert np.array_equal(sparse.toarray(), cornell_factors.matrix)
    assert np.array_equal(cornell_factors.sparse(errors=True).toarray(), cornell_factors.stderr)


def test_enforce_both_same_bits_and_reciprocal(run):
    with pytest.warns(radiosity.RadiosityWarning):
        vf = radiosity.view_factors(CORNELL, rays=RAYS, enforce="both")
    assert vf.to_csv() == run("viewfactors", CORNELL, "--rays", RAYS, "--enforce", "both")
    g = vf.areas[:, None] * vf.matrix
    assert np.allclose(g, g.T, rtol=1e-12, atol=1e-15) and vf.largest_change > 0


def test_patch_level_matrix_market_and_geometry(run, tmp_path):
    patches = tmp_path / "patches.csv"
    text = run("viewfactors", CORNELL, "--level", "patch", "--patch-size", 0.25, "--rays-per-patch", 500,
               "--format", "mtx", "--patches", patches)
    vf = radiosity.view_factors(CORNELL, level="patch", patch_size=0.25, rays_per_patch=500)
    assert vf.to_matrix_market() == text
    n = len(vf)
    assert vf.matrix.shape == (n, n) and vf.patch_centroids.shape == (n, 3) and vf.patch_corners.shape == (n, 3, 3)
    rows = csv_rows(patches.read_text())
    assert [r["patch"] for r in rows] == vf.names
    for k, r in enumerate(rows):
        assert "%.10g" % vf.patch_centroids[k, 0] == r["centroid_x"]
        assert "%.9g" % vf.patch_normals[k, 1] == r["normal_y"]
        assert "%.9g" % vf.patch_areas[k] == r["area"]
        assert vf.surface_names[vf.patch_surfaces[k]] == r["surface"]
    scene = radiosity.load_scene(CORNELL, patch_size=0.25)
    sums = np.bincount(vf.patch_surfaces, weights=vf.patch_areas)
    assert np.allclose(sums, scene.areas, rtol=1e-6)


# --- heat exchange -----------------------------------------------------------------------------

def test_exchange_same_bits_as_the_program(run, tmp_path):
    spheres = os.path.join(ROOT, "tests", "data", "thermal", "concentric-spheres.gltf")
    properties = os.path.join(ROOT, "tests", "data", "thermal", "spheres.csv")
    gebhart = tmp_path / "gebhart.csv"
    text = run("exchange", spheres, "--properties", properties, "--rays", 40000, "--exchange", gebhart)
    heat = radiosity.exchange(spheres, properties=properties, rays=40000)
    assert heat.to_csv() == text and heat.exchange_csv() == gebhart.read_text()
    for k, r in enumerate(csv_rows(text)):
        assert r["surface"] == heat.names[k]
        assert "%.9g" % heat.net_heat[k] == r["net_heat"]
        assert "%.9g" % heat.temperature[k] == r["temperature"]
    # The closed form of concentric spheres (README, "Heat exchange").
    a1, a2 = heat.areas
    q = 5.670374419e-8 * a1 * (400.0**4 - 300.0**4) / (1 / 0.8 + (a1 / a2) * (1 / 0.5 - 1))
    assert abs(heat.net_heat[0] - q) <= 1e-6 * q
    assert np.allclose(heat.exchange_factors.sum(axis=1), 1.0, atol=1e-9)
    c = heat.conductors
    assert np.allclose(c, c.T, rtol=1e-9)


def test_exchange_properties_as_a_dict(run, tmp_path):
    properties = {"light": {"emissivity": 0.9, "temperature": 600.0},
                  "floor": {"emissivity": 0.7, "heat_flux": 0}}
    path = tmp_path / "properties.csv"
    path.write_text("surface,emissivity,temperature,heat_flux\nlight,0.9,600,\nfloor,0.7,,0\n")
    args = ["--rays", 16000, "--batches", 4, "--default-emissivity", 0.8, "--default-temperature", 300]
    text = run("exchange", CORNELL, "--properties", path, *args)
    heat = radiosity.exchange(CORNELL, properties=properties, rays=16000, batches=4, default_emissivity=0.8,
                              default_temperature=300)
    assert heat.to_csv() == text
    floor = heat.names.index("floor")  # its temperature solved for, its net heat the imposed 0
    assert abs(heat.net_heat[floor]) < 1e-9 and heat.temperature_stderr[floor] > 0
    assert isinstance(heat.view_factors, radiosity.ViewFactors) and heat.view_factors.matrix.shape == (8, 8)


# --- solve -------------------------------------------------------------------------------------

SOLVE = dict(rays=100000, width=16, height=16, patch_size=0.1, tolerance=0.005, element_csv=True)
FAST_SOLVE = dict(rays=20000, width=8, height=8, patch_size=0.1, tolerance=0.01)


def _without_timings(report):
    report = json.loads(json.dumps(report))
    report.pop("seconds")
    report["solve"].pop("rays_per_second")
    return report


def test_solve_report_is_the_programs_and_fits_the_schema(run, tmp_path):
    cli = tmp_path / "cli"
    run("solve", CORNELL, "--output", cli, "--rays", 100000, "--width", 16, "--height", 16, "--patch-size", 0.1,
        "--tolerance", 0.005, "--element-csv", "--quiet")
    solution = radiosity.solve(CORNELL, output=tmp_path / "py", **SOLVE)
    written = json.loads((cli / "report.json").read_text())
    assert _without_timings(solution.report) == _without_timings(written)
    assert json.loads((tmp_path / "py" / "report.json").read_text()) == solution.report
    assert (tmp_path / "py" / "elements.csv").read_bytes() == (cli / "elements.csv").read_bytes()

    sys.path.insert(0, os.path.join(ROOT, "tests", "tools"))
    import validate_report

    assert validate_report.problems(str(tmp_path / "py" / "report.json")) == []
    assert list(validate_report.validator().iter_errors(solution.report)) == []

    # Per surface: the report's; per element: elements.csv's, at full precision.
    assert solution.surface_names == [s["name"] for s in written["surfaces"]]
    assert solution.surface_radiosity.shape == (8, 3) and solution.stopped == written["solve"]["stopped"]
    rows = csv_rows((cli / "elements.csv").read_text())
    assert len(rows) == len(solution.element_areas) == written["mesh"]["elements"]
    for k in range(0, len(rows), 7):
        r = rows[k]
        assert solution.surface_names[solution.element_surfaces[k]] == r["surface"]
        assert int(r["patch"]) == solution.element_patches[k] and int(r["level"]) == solution.element_levels[k]
        assert "%.7g" % solution.element_areas[k] == r["area"]
        for c, channel in enumerate("rgb"):
            assert "%.7g" % solution.element_radiosity[k, c] == r["B_" + channel]
            assert "%.7g" % solution.element_reflectance[k, c] == r["rho_" + channel]
        for c, axis in enumerate("xyz"):
            assert "%.9g" % solution.element_centroids[k, c] == r[axis]
    # The surface means are the elements' area-weighted means.
    for s in range(8):
        mine = solution.element_surfaces == s
        mean = (solution.element_radiosity[mine] * solution.element_areas[mine, None]).sum(0) / \
            solution.element_areas[mine].sum()
        assert np.allclose(mean, solution.surface_radiosity[s], rtol=1e-5)


def test_solve_twice_in_one_process_gives_the_same_bits():
    first = radiosity.solve(CORNELL, **FAST_SOLVE)
    second = radiosity.solve(CORNELL, **FAST_SOLVE)
    assert first.output is None
    assert _without_timings(first.report) == _without_timings(second.report)
    assert np.array_equal(first.element_radiosity, second.element_radiosity)


THREADS_SCRIPT = """
import sys, radiosity
try:  # a call that fails before computing fixes nothing
    radiosity.view_factors("/nonexistent/scene.gltf", rays=20000, threads=2)
except radiosity.FileError:
    pass
vf = radiosity.view_factors(sys.argv[1], rays=20000, threads=1)
sys.stdout.write(vf.to_csv())
cpu = [d for d in radiosity.devices() if d["platform"] == "Portable Computing Language"]
assert cpu and cpu[0]["compute_units"] == 1, cpu
radiosity.view_factors(sys.argv[1], rays=20000, threads=1)  # the same count again: fine
try:
    radiosity.view_factors(sys.argv[1], rays=20000, threads=2)
except radiosity.InputError as e:
    assert "fixed by the process's first computation (threads=1)" in str(e), e
else:
    raise AssertionError("threads=2 after threads=1 was taken")
"""


def test_threads_as_the_program_takes_them(run):
    """threads=1 is the program's --threads 1: one compute unit on PoCL, the program's bits, and
    fixed for the process by its first computation. In a process of its own, since this one's
    first computation has fixed its threads already."""
    env = dict(os.environ, POCL_MAX_PTHREAD_COUNT="2", POCL_CPU_MAX_CU_COUNT="2")
    done = subprocess.run([sys.executable, "-c", THREADS_SCRIPT, CORNELL], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    assert done.stdout == run("viewfactors", CORNELL, "--rays", 20000, "--threads", 1)
    assert done.stdout == run("viewfactors", CORNELL, "--rays", 20000)  # any count: the same bits


# --- errors and warnings -----------------------------------------------------------------------

def test_missing_file_is_a_file_error_naming_it(tmp_path):
    missing = str(tmp_path / "nowhere.gltf")
    with pytest.raises(radiosity.FileError) as caught:
        radiosity.view_factors(missing)
    assert missing in str(caught.value) and caught.value.path == missing
    assert isinstance(caught.value, radiosity.InputError) and isinstance(caught.value, ValueError)


@pytest.mark.parametrize("name,words", [("malformed.gltf", "json"), ("node-cycle.gltf", "cycle"),
                                        ("bad-number.stl", "")])
def test_bad_files_raise_what_the_program_says(run, name, words):
    path = os.path.join(ROOT, "tests", "data", "bad", name)
    with pytest.raises(radiosity.FileError) as caught:
        radiosity.load_scene(path)
    message = str(caught.value)
    assert path in message and words in message.lower()
    done = subprocess.run([os.environ.get("RADIOSITY_PROGRAM", os.path.join(ROOT, "build", "radiosity")),
                           "viewfactors", path], capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.strip() == "radiosity: error: " + message


def test_bad_options_are_input_errors():
    with pytest.raises(radiosity.InputError, match="--rays"):
        radiosity.view_factors(CORNELL, rays=0)
    with pytest.raises(radiosity.InputError, match="--hemicube-res is not used by --method shoot"):
        radiosity.view_factors(CORNELL, hemicube_res=64)
    with pytest.raises(radiosity.InputError, match="--no-such-option"):
        radiosity.view_factors(CORNELL, no_such_option=1)
    with pytest.raises(radiosity.InputError, match="to_csv"):
        radiosity.view_factors(CORNELL, output="f.csv")
    with pytest.raises(radiosity.InputError, match="unit"):
        radiosity.load_scene(CORNELL, unit="mm")  # glTF is in metres


def test_properties_dict_errors_name_the_dict():
    with pytest.raises(radiosity.FileError) as caught:
        radiosity.exchange(CORNELL, properties={"flor": {"emissivity": 0.5, "temperature": 300}},
                           default_emissivity=0.5, default_temperature=300, rays=1000)
    assert caught.value.path == "properties" and "'flor'" in str(caught.value)
    with pytest.raises(radiosity.InputError, match="not listed"):
        radiosity.exchange(CORNELL, properties={"floor": {"emissivity": 0.5, "temperature": 300}}, rays=1000)


def test_a_scene_with_nothing_to_solve_is_refused(tmp_path):
    unlit = tmp_path / "unlit.obj"
    unlit.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(radiosity.InputError, match="nothing to solve"):
        radiosity.solve(unlit, width=8, height=8)


def test_an_output_folder_that_cannot_be_made_is_a_runtime_failure(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(radiosity.RuntimeFailure, match="cannot create the directory"):
        radiosity.solve(CORNELL, output=blocker / "out", **FAST_SOLVE)


def test_warnings_go_through_python_warnings(run):
    with pytest.warns(radiosity.RadiosityWarning, match="'floor' stop on the back of a single-sided face"):
        radiosity.view_factors(CORNELL, rays=2000)
    degenerate = os.path.join(ROOT, "tests", "data", "gltf", "degenerate.gltf")
    with pytest.warns(radiosity.RadiosityWarning, match="degenerate") as caught:
        scene = radiosity.load_scene(degenerate)
    assert scene.warnings and all(w.category is radiosity.RadiosityWarning for w in caught)
    assert issubclass(radiosity.RadiosityWarning, UserWarning)


# --- the example -------------------------------------------------------------------------------

def test_example_prints_the_programs_view_factors(run):
    done = subprocess.run([sys.executable, os.path.join(ROOT, "python", "example.py")], capture_output=True,
                          text=True, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    expected = run("viewfactors", CORNELL, "--rays", 100000)
    assert done.stdout.startswith(expected)
    assert "net heat" in done.stdout and "light" in done.stdout.split(expected, 1)[1]
