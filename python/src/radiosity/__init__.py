"""View factors, radiative heat exchange and radiosity solves, from Python.

The package runs the same code as the ``radiosity`` program, with the same options, defaults and
checks: a keyword argument is the command line's option of the same name (``patch_size=0.05`` is
``--patch-size 0.05``, ``hemicube_jitter=True`` is ``--hemicube-jitter``), and the same options
and seed give the same numbers, bit for bit, as the program.

    >>> import radiosity
    >>> vf = radiosity.view_factors("scenes/cornell-box.gltf", rays=100_000)
    >>> vf.names, vf.matrix.shape
    >>> heat = radiosity.exchange("scenes/cornell-box.gltf",
    ...                           properties={"floor": {"emissivity": 0.9, "temperature": 300}},
    ...                           default_emissivity=0.8, default_temperature=290)
    >>> heat.net_heat

Functions: :func:`load_scene`, :func:`view_factors`, :func:`exchange`, :func:`solve`,
:func:`devices`. Errors raise :class:`InputError`, :class:`FileError` or
:class:`RuntimeFailure`; what the program prints as a warning is issued as a
:class:`RadiosityWarning` through Python's :mod:`warnings`.
"""

import csv as _csv
import json as _json
import os as _os
import shutil as _shutil
import tempfile as _tempfile
import warnings as _warnings

import numpy as _np

from .errors import FileError, InputError, RadiosityError, RadiosityWarning, RuntimeFailure
from . import _radiosity as _core

__all__ = [
    "__version__", "load_scene", "view_factors", "exchange", "solve", "devices",
    "Scene", "ViewFactors", "Exchange", "Solution",
    "RadiosityError", "InputError", "FileError", "RuntimeFailure", "RadiosityWarning",
]

#: The program's version: ``radiosity --version`` prints ``radiosity <__version__>``.
__version__ = _core.version


# --- keyword arguments to the command line's arguments ---------------------------------------

def _number(value):
    if isinstance(value, bool):
        raise InputError("expected a number, not %r" % value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(value)  # the shortest text that reads back as the same double
    return str(value)


def _option_text(value):
    if isinstance(value, (list, tuple, _np.ndarray)):
        return ",".join(_number(v) for v in value)  # colours: R,G,B
    if isinstance(value, (int, float)):
        return _number(value)
    return _os.fspath(value) if isinstance(value, _os.PathLike) else str(value)


def _arguments(options, refused=()):
    """``{"patch_size": 0.05, "hemicube_jitter": True}`` -> ``["--patch-size", "0.05", "--hemicube-jitter"]``.

    None and False leave an option out (the program's default)."""
    argv = []
    for key, value in options.items():
        if key in refused:
            raise InputError("%s= is not an option here: %s" % (key, refused[key]))
        if value is None or value is False:
            continue
        name = "--" + key.replace("_", "-")
        if value is True:
            argv.append(name)
        else:
            argv += [name, _option_text(value)]
    return argv


def _files(scene):
    if isinstance(scene, (str, bytes, _os.PathLike)):
        return [_os.fsdecode(scene)]
    return [_os.fsdecode(p) for p in scene]


def _scene_arguments(scene, options):
    """The scene's files and options: a :class:`Scene` brings those it was loaded with, which
    keyword arguments given here override."""
    if isinstance(scene, Scene):
        merged = dict(scene.options)
        merged.update({k: v for k, v in options.items() if v is not None})
        return list(scene.files), merged
    return _files(scene), options


def _warn(messages, stacklevel=3):
    for message in messages:
        _warnings.warn(message, RadiosityWarning, stacklevel=stacklevel)


# --- the scene ---------------------------------------------------------------------------------

class Scene:
    """A scene as the program reads it: one glTF file (.gltf, .glb), or OBJ, STL and PLY files.

    Made by :func:`load_scene`. Every function that takes a scene path also takes a Scene, and then
    reads the same files with the options the Scene was loaded with (``unit``, ``patch_size``,
    ``max_patches``), unless given again.

    Attributes:
        files: the scene's files.
        names: the surface sides, as view factors and reports name them (``name:back`` for the
            back of a double-sided surface).
        areas: their areas (m^2), a NumPy array.
        patch_counts: the patches of each surface side.
        faces, patches: the triangles read and the patches they were meshed into.
        patch_size: the longest patch edge (m) used.
        has_emitters: whether anything in the file emits light (``solve`` needs it).
        warnings: what the loader warned of (also issued as :class:`RadiosityWarning`).
    """

    def __init__(self, files, options, info):
        self.files = tuple(files)
        self.options = dict(options)
        self.names = list(info["names"])
        self.areas = info["areas"]
        self.patch_counts = info["patches"]
        self.faces = info["faces"]
        self.patches = info["patch_count"]
        self.patch_size = info["patch_size"]
        self.has_emitters = info["emitters"]
        self.warnings = list(info["warnings"])

    def __len__(self):
        return len(self.names)

    def __repr__(self):
        return "<radiosity.Scene %s: %d surface sides, %d faces, %d patches>" % (
            ", ".join(self.files), len(self.names), self.faces, self.patches)


def load_scene(path, unit=None, patch_size=None, max_patches=None):
    """Reads a scene and meshes it into patches, as every command of the program does.

    Args:
        path: a glTF file (.gltf, .glb), or an OBJ, STL or PLY file, or a list of OBJ, STL and PLY
            files read together into one scene (names that repeat get ``@2``, ``@3``).
        unit: the length unit of OBJ, STL and PLY coordinates: ``"m"`` (default), ``"cm"``,
            ``"mm"``, ``"in"`` or ``"ft"``; refused with glTF, which is in metres.
        patch_size: the longest patch edge in metres (default: 1/32 of the scene's diagonal).
        max_patches: refuse meshes with more patches than this (default 10,000,000).

    Returns:
        a :class:`Scene`.

    Raises:
        FileError: the file is missing, malformed or holds no triangles (the message names the
            file and the problem, as the program's does).
        InputError: an option's value is wrong.
    """
    options = {"unit": unit, "patch_size": patch_size, "max_patches": max_patches}
    options = {k: v for k, v in options.items() if v is not None}
    files = _files(path)
    info = _core.scene_info(["viewfactors"] + files + _arguments(options))
    _warn(info["warnings"])
    return Scene(files, options, info)


def devices():
    """The OpenCL devices, as ``radiosity devices`` lists them: a list of dicts with ``index`` (what
    ``device=`` takes), ``platform``, ``name``, ``type``, ``compute_units``, ``global_memory``
    (bytes), ``version`` and ``driver``."""
    return _core.devices()


# --- view factors ------------------------------------------------------------------------------

class ViewFactors:
    """View factors between the surface sides (or patches) of a scene, from :func:`view_factors`.

    Attributes:
        names: the rows' and columns' names: surface sides, or ``<surface>#<k>`` patches.
        areas: their areas (m^2).
        matrix: F, a dense NumPy float64 array (n x n): ``matrix[i, j]`` is the fraction of the
            power leaving i (diffusely, from its front) that arrives at j first. Made on first use;
            for large patch matrices prefer :meth:`sparse`.
        stderr: the standard errors of ``matrix``'s entries, same shape: sqrt(F (1 - F) / N) for
            ray estimates (an upper bound: the rays are stratified), NaN where the method gives
            no statistical estimate (hemicube, gather), 0 where F is 0.
        missed: per row, the fraction that reached nothing (left the scene, or stopped on the
            black back of a single-sided face).
        level, method, enforce: what was asked. ``largest_change`` and ``closed_rows``: what the
            correction (``enforce``) changed, as the program reports on standard error.
        patch_centroids, patch_normals, patch_corners, patch_areas, patch_surfaces,
        surface_names: at ``level="patch"``, where each patch is (the scene's coordinates in
            metres: centroid (n x 3), unit normal (n x 3), corners (n x 3 x 3, counter-clockwise
            seen from the patch's side), area, and the index of its surface side in
            ``surface_names``), as ``radiosity viewfactors --patches`` writes them.
        warnings: what the program warned of (also issued as :class:`RadiosityWarning`).
    """

    def __init__(self, result, level, method):
        self._table = result["table"]
        self.names = list(result["names"])
        self.areas = result["areas"]
        self.missed = result["missed"]
        self.level = level
        self.method = method
        self.enforce = result["enforce"]
        self.largest_change = result["largest_change"]
        self.closed_rows = result["closed_rows"]
        self.summary = result["how"]
        self.device = result["device"]
        self.warnings = list(result["warnings"])
        self._matrix = None
        self._stderr = None
        for key in ("patch_centroids", "patch_normals", "patch_corners", "patch_areas", "patch_surfaces",
                    "surface_names"):
            setattr(self, key, result.get(key))

    @property
    def matrix(self):
        if self._matrix is None:
            self._matrix = self._table.dense(False)
        return self._matrix

    @property
    def stderr(self):
        if self._stderr is None:
            self._stderr = self._table.dense(True)
        return self._stderr

    def sparse(self, errors=False):
        """F (or with ``errors=True`` its standard errors) as a ``scipy.sparse.csr_matrix``, built
        from the entries the program stores (those with F > 0) without a dense matrix between."""
        import scipy.sparse  # only here: the rest of the package does not need SciPy

        data, indices, indptr = self._table.csr(errors)
        n = len(self.names)
        return scipy.sparse.csr_matrix((data, indices, indptr), shape=(n, n))

    def to_csv(self):
        """The text ``radiosity viewfactors`` prints for the same options: ``from,to,F,stderr``."""
        return self._table.csv()

    def to_matrix_market(self):
        """The text ``radiosity viewfactors --format mtx`` prints for the same options."""
        return self._table.mtx()

    def __len__(self):
        return len(self.names)

    def __repr__(self):
        return "<radiosity.ViewFactors %d x %d %s factors (%s)>" % (len(self), len(self), self.level, self.summary)


_VIEW_FACTOR_FILES = {
    "output": "the factors are returned; ViewFactors.to_csv() or to_matrix_market() give the program's text",
    "format": "ViewFactors.to_csv() and to_matrix_market() give both formats",
    "patches": "ViewFactors.patch_centroids and the other patch_ attributes hold the patches' geometry",
    "to_space": "ViewFactors.missed holds the fraction of each row that reached nothing",
    "vtu": "the program's radiosity viewfactors writes files; this function returns arrays",
}


def view_factors(scene, level=None, method=None, rays=None, seed=None, enforce=None, device=None, **options):
    """View factors between surface sides (or patches): ``radiosity viewfactors`` as a function.

    Args:
        scene: a :class:`Scene`, a file path, or a list of OBJ, STL and PLY paths.
        level: ``"surface"`` (default) or ``"patch"``.
        method: ``"shoot"`` (default), ``"hemicube"`` or ``"gather"``.
        rays: with ``method="shoot"`` at the surface level, rays cast from each surface in all
            (default 1,000,000).
        seed: the seed of the sample sequences (default 1): the same seed gives the same bits.
        enforce: ``"none"``, ``"reciprocity"``, ``"closure"`` or ``"both"`` (default: the program's,
            which ``radiosity viewfactors --help`` shows).
        device: an index from :func:`devices`, ``"cpu"``, ``"gpu"`` or part of a device's name.
        **options: any other option of ``radiosity viewfactors``, by its name with ``_`` for
            ``-``: ``patch_size``, ``unit``, ``max_patches``, ``target_error``, ``max_rays``,
            ``rays_per_patch``, ``hemicube_res``, ``hemicube_jitter=True``, ``shadow_rays``,
            ``max_memory`` ... (``radiosity viewfactors --help`` lists them). An option the chosen
            method and level do not read is refused, as the program refuses it.

    Returns:
        a :class:`ViewFactors`.
    """
    files, options = _scene_arguments(scene, options)
    named = {"level": level, "method": method, "rays": rays, "seed": seed, "enforce": enforce, "device": device}
    argv = ["viewfactors"] + files + _arguments(named) + _arguments(options, _VIEW_FACTOR_FILES)
    result = _core.view_factors(argv)
    _warn(result["warnings"])
    return ViewFactors(result, level or "surface", method or "shoot")


# --- heat exchange -----------------------------------------------------------------------------

class Exchange:
    """Radiative heat exchange between grey, diffuse surface sides, from :func:`exchange`.

    Per surface side (NumPy arrays in the order of ``names``): ``areas`` (m^2), ``emissivity``,
    ``temperature`` (K: given, or solved for where a heat flux was imposed), ``net_heat`` (W,
    positive when the surface loses heat), ``net_flux`` (W/m^2), ``radiosity`` and
    ``irradiance`` (W/m^2), ``net_heat_stderr`` (W) and ``temperature_stderr`` (K), the standard
    errors from the spread of independent batches (NaN when a batch alone has no solution).

    Between surface sides: ``exchange_factors`` (Gebhart's G, n x n: the fraction of what i emits
    that j absorbs after any number of diffuse reflections), ``conductors`` (eps_i A_i G_ij, m^2;
    times sigma (T_i^4 - T_j^4) they give W) and ``view_factors`` (a :class:`ViewFactors` of the
    corrected factors the exchange was solved on).

    ``to_environment``: the W that leave an open scene (0 in a closed one). ``to_csv()`` and
    ``exchange_csv()`` give the text ``radiosity exchange`` writes to ``--output`` and
    ``--exchange``.
    """

    def __init__(self, result):
        for key in ("areas", "emissivity", "temperature", "net_heat", "net_flux", "radiosity", "irradiance",
                    "net_heat_stderr", "temperature_stderr", "to_environment", "exchange_factors", "conductors",
                    "rays_per_surface", "enforce", "largest_change", "closed_rows", "error_bars"):
            setattr(self, key, result[key])
        self.names = list(result["names"])
        self.warnings = list(result["warnings"])
        table = result["view_factors"]
        self.view_factors = ViewFactors({"table": table, "names": result["names"], "areas": result["areas"],
                                         "missed": result["missed"], "enforce": result["enforce"],
                                         "largest_change": result["largest_change"],
                                         "closed_rows": result["closed_rows"],
                                         "how": "%d rays per surface" % result["rays_per_surface"], "device": "",
                                         "warnings": []}, "surface", "shoot")
        self._csv = result["csv"]
        self._exchange_csv = result["exchange_csv"]

    def to_csv(self):
        """The net heats as ``radiosity exchange`` prints them: ``surface,area,emissivity,...``."""
        return self._csv

    def exchange_csv(self):
        """The exchange factors and conductors as ``radiosity exchange --exchange FILE`` writes them."""
        return self._exchange_csv

    def __len__(self):
        return len(self.names)

    def __repr__(self):
        return "<radiosity.Exchange %d surface sides, net heats sum to %.6g W, environment takes %.6g W>" % (
            len(self), float(_np.sum(self.net_heat)), self.to_environment)


_EXCHANGE_FILES = {
    "output": "the results are returned; Exchange.to_csv() gives the program's text",
    "exchange": "Exchange.exchange_factors and conductors hold them; Exchange.exchange_csv() gives the text",
    "exchange_format": "Exchange.exchange_csv() gives the CSV text",
    "vtu": "the program's radiosity exchange writes files; this function returns arrays",
}


def _properties_file(properties, folder):
    """A dict ``{surface: {"emissivity": e, "temperature": T}}`` (or ``"heat_flux": q`` instead of the
    temperature) as the properties CSV the program reads."""
    path = _os.path.join(folder, "properties.csv")
    with open(path, "w", newline="") as out:
        writer = _csv.writer(out, lineterminator="\n")
        writer.writerow(["surface", "emissivity", "temperature", "heat_flux"])
        for name, row in properties.items():
            if not isinstance(row, dict):
                raise InputError("properties[%r] must be a dict with emissivity and temperature or heat_flux" % name)
            unknown = set(row) - {"emissivity", "temperature", "heat_flux"}
            if unknown:
                raise InputError("properties[%r]: unknown key %s (emissivity, temperature, heat_flux)" %
                                 (name, ", ".join(sorted(unknown))))
            cells = [row.get(k) for k in ("emissivity", "temperature", "heat_flux")]
            writer.writerow([name] + ["" if v is None else _number(v) for v in cells])
    return path


def exchange(scene, properties, rays=None, batches=None, seed=None, enforce=None, device=None,
             default_emissivity=None, default_temperature=None, environment_temperature=None, **options):
    """Radiative heat exchange between grey, diffuse, opaque surfaces: ``radiosity exchange`` as a
    function (the net-radiation method on the surface view factors, corrected for reciprocity and
    closure first by default).

    Args:
        scene: a :class:`Scene`, a file path, or a list of OBJ, STL and PLY paths.
        properties: a properties CSV file (header ``surface,emissivity,temperature`` or
            ``surface,emissivity,heat_flux``, or both), or a dict of the same:
            ``{"floor": {"emissivity": 0.9, "temperature": 300}, "lamp": {"emissivity": 1,
            "heat_flux": 0}}`` (temperatures in K; a heat flux in W/m^2 imposed, positive when the
            surface loses heat, its temperature then solved for).
        default_emissivity, default_temperature: for the surfaces the properties do not list.
        environment_temperature: K of the black environment an open scene loses to (default 0).
        rays: rays from each surface over all batches (default 1,000,000).
        batches: independent estimates whose spread gives the standard errors (default 8).
        seed, enforce, device: as for :func:`view_factors` (``enforce`` defaults to ``"both"`` here).
        **options: ``patch_size``, ``unit``, ``max_patches`` (``radiosity exchange --help``).

    Returns:
        an :class:`Exchange`.
    """
    files, options = _scene_arguments(scene, options)
    named = {"rays": rays, "batches": batches, "seed": seed, "enforce": enforce, "device": device,
             "default_emissivity": default_emissivity, "default_temperature": default_temperature,
             "environment_temperature": environment_temperature}
    folder = None
    try:
        if isinstance(properties, dict):
            folder = _tempfile.mkdtemp(prefix="radiosity-")
            path = _properties_file(properties, folder)
        else:
            path = _os.fspath(properties)
        argv = (["exchange"] + files + ["--properties", path] + _arguments(named) +
                _arguments(options, _EXCHANGE_FILES))
        try:
            result = _core.exchange(argv)
        except InputError as e:
            if folder is None or path not in str(e):
                raise
            # Name the dict, not the file made from it.
            message = str(e).replace(path, "properties")
            error = type(e)(message)
            if isinstance(e, FileError):
                error.path, error.problem = "properties", e.problem
            raise error from None
    finally:
        if folder is not None:
            _shutil.rmtree(folder, ignore_errors=True)
    _warn(result["warnings"])
    return Exchange(result)


# --- solve -------------------------------------------------------------------------------------

class Solution:
    """A radiosity solution, from :func:`solve`.

    Attributes:
        report: ``report.json`` as a dict, exactly what the program writes for the same options
            (the scene, method, device, mesh counts, stages' seconds, why it stopped, the energy
            balance per channel, every surface side's mean radiosity; ``docs/reference/report.schema.json``).
        surface_names, surface_areas (m^2), surface_radiosity (W/m^2, area-weighted mean B, n x 3
            RGB), surface_patches, surface_elements: per surface side, from the report.
        element_centroids (m, scene coordinates, n x 3), element_normals (n x 3), element_areas
            (m^2), element_reflectance (rho, n x 3), element_radiosity (B, W/m^2, n x 3),
            element_irradiance (H, the light arriving before it is reflected: B = E + rho H),
            element_surfaces (index into surface_names), element_patches, element_levels: per
            element, what ``elements.csv`` holds, at full precision.
        output: the folder the program's files were written to, or None when they were not kept.
        warnings: what the program warned of (also issued as :class:`RadiosityWarning`).
    """

    def __init__(self, result, output):
        self.report = _json.loads(result["report"])
        self.output = output
        self.warnings = list(result["warnings"])
        for key, value in result.items():
            if key.startswith("element_"):
                setattr(self, key, value)
        surfaces = self.report["surfaces"]
        self.surface_names = [s["name"] for s in surfaces]
        self.surface_areas = _np.array([s["area"] for s in surfaces], dtype=float)
        self.surface_radiosity = _np.array([s["radiosity"] for s in surfaces], dtype=float).reshape(-1, 3)
        self.surface_patches = _np.array([s["patches"] for s in surfaces], dtype=int)
        self.surface_elements = _np.array([s["elements"] for s in surfaces], dtype=int)

    @property
    def stopped(self):
        """Why the solve stopped: ``tolerance``, ``max-shots``, ``time-limit``, ``interrupted`` ..."""
        return self.report["solve"]["stopped"]

    def __repr__(self):
        return "<radiosity.Solution %d surface sides, %d elements, stopped: %s>" % (
            len(self.surface_names), len(self.element_areas), self.stopped)


def solve(scene, output=None, progress=False, **options):
    """Lights a scene by radiosity: ``radiosity solve`` as a function.

    Args:
        scene: a :class:`Scene`, a file path, or a list of OBJ, STL and PLY paths.
        output: a folder for the program's files (render.exr, render.png, lit.glb, report.json,
            and elements.csv with ``element_csv=True``), as ``--output``; by default they are
            written to a temporary folder and removed.
        progress: show the progress display on standard error (the program's, without
            ``--quiet``).
        **options: any option of ``radiosity solve`` by its name with ``_`` for ``-``:
            ``rays``, ``tolerance``, ``seed``, ``method``, ``solver``, ``patch_size``,
            ``width``, ``height``, ``render``, ``sky=(r, g, b)``, ``adaptive=True`` ...
            (``radiosity solve --help``). SIGINT (Ctrl-C) stops the solve after its current
            batch, which then reports ``stopped: interrupted``.

    Returns:
        a :class:`Solution`.
    """
    files, options = _scene_arguments(scene, options)
    options = dict(options)
    if options.pop("quiet", None) is not None:
        raise InputError("quiet= is not an option here: use progress=True to show the progress display")
    folder = None
    try:
        if output is None:
            folder = _tempfile.mkdtemp(prefix="radiosity-solve-")
            target = _os.path.join(folder, "out")
        else:
            target = _os.fspath(output)
        argv = ["solve"] + files + ["--output", target] + _arguments(options)
        if not progress:
            argv.append("--quiet")
        result = _core.solve(argv)
    finally:
        if folder is not None:
            _shutil.rmtree(folder, ignore_errors=True)
    _warn(result["warnings"])
    return Solution(result, None if output is None else target)
