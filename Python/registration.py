"""One call for the whole registration, with numpy arrays in and out.

    import mobiusregistration
    result = mobiusregistration.register("source.off", "target.off")
    result.mapped_points          # (n, 3): each source vertex placed on the target
    result.transfer(target_values)  # per-target-vertex values carried to the source

`register` runs vtkMobiusRegistration, the pipeline of the `mobius-register` program: a
conformal map of each mesh onto the sphere (vtkSphericalConformalMap), its centering
(vtkMobiusCenter), the rotation between them (vtkSO3Register) and the dense map, refined
spectrally (vtkCorrespondenceRefinement) unless refine=False (vtkDenseCorrespondence, the
paper's Möbius map). A stage's error, or a degenerate conformal map, raises
RegistrationError with the stage's message; its warnings are Python warnings.
"""
import os
import warnings

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

from .messages import FilterMessages
from .vtkMobiusRegistrationFilters import (
    vtkCorrespondenceRefinement, vtkMobiusRegistration, vtkSO3Register, vtkSphericalConformalMap,
    vtkSurfaceMeshReader)

__all__ = ["register", "Registration", "RegistrationError"]

_TRANSFORM_MODES = {"rotation": 0, "reflection": 1, "both": 2}


def _default_options():
    """The options and their defaults, read from default-constructed filters (whose defaults
    are the core's, as mobius-register's are)."""
    conformal, registration = vtkSphericalConformalMap(), vtkSO3Register()
    refinement = vtkCorrespondenceRefinement()
    transforms = {mode: name for name, mode in _TRANSFORM_MODES.items()}
    candidate = refinement.GetCandidate()
    return {
        "refine": True,  # spectral refinement (False: the Möbius map alone)
        "basis_size": refinement.GetBasisSize(),  # eigenfunctions of the refinement
        "polish": bool(refinement.GetGeometricPolish()),  # the refinement's geometric polish
        # the polish in both directions, averaged (False: mobius-register --one-direction)
        "both_directions": bool(refinement.GetBothDirections()),
        "resolution": registration.GetResolution(),  # scale-factor grid of the SO(3) correlation (even)
        "smoothing": registration.GetSmoothingTime(),  # heat-kernel smoothing time of the scale factors
        "transform": transforms[registration.GetTransformMode()],  # rotation | reflection | both
        "candidates": registration.GetNumberOfCandidates(),  # correlation peaks the refinement starts from
        # smallest angle (degrees) between two candidates (mobius-register --candidate-separation)
        "candidate_separation": registration.GetCandidateSeparation(),
        # the refinement's candidate to keep (mobius-register --candidate); None: it chooses
        "candidate": None if candidate < 0 else candidate,
        "iterations": conformal.GetMaximumNumberOfIterations(),  # maximum conformal flow steps
        "tolerance": conformal.GetConvergenceTolerance(),  # conformal flow convergence tolerance
        # repair a mesh that is no closed genus-0 surface into a genus-0 proxy (False: refuse it)
        "repair": bool(conformal.GetRepair()),
        "fill_holes": bool(conformal.GetFillHoles()),  # with repair=False: close holes instead of refusing
        "keep_largest_component": bool(conformal.GetKeepLargestComponent()),
        "allow_poor_maps": False,  # accept degenerate conformal maps instead of raising
        "threads": registration.GetNumberOfThreads(),  # threads per threaded filter (0: automatic); same results
        # [(source vertex, target vertex), ...]: points whose images are known (mobius-register --landmarks)
        "landmarks": (),
        # 0: the rotation is chosen by the landmarks; 1: a Moebius transform fits 3 of them (--landmark-mode)
        "landmark_mode": vtkMobiusRegistration().GetLandmarkMode(),
    }


# The options and their defaults: the same as mobius-register's.
DEFAULT_OPTIONS = _default_options()


class RegistrationError(RuntimeError):
    """A mesh could not be read or mapped; the message is the filter's."""


class _Errors(FilterMessages):
    """The filters' messages, in register()'s words."""

    # The filters' hints name their properties; here, register()'s options.
    _HINTS = (("set TransformMode to ROTATIONS_AND_REFLECTIONS", 'pass transform="both"'),)

    def warn(self):
        for message in self.warnings:
            for property_words, option_words in self._HINTS:
                message = message.replace(property_words, option_words)
            warnings.warn(message, stacklevel=3)
        self.warnings = []

    def raise_if_any(self, what):
        if self.messages:
            raise RegistrationError(f"{what}: " + "; ".join(self.messages))


def _rows(given, name, what):
    """`given` as a numpy array; ValueError naming the mesh and the row that breaks the shape
    when its rows differ in length (numpy's own error names neither)."""
    try:
        return np.asarray(given)
    except ValueError:
        pass
    lengths = []
    for row in given:
        try:
            lengths.append(len(row))
        except TypeError:
            lengths.append(None)
    first = lengths[0] if lengths else None
    odd = next((k for k, length in enumerate(lengths) if length != first), None)
    if odd is None:
        raise ValueError(f"{name}: {what} must be an array of rows of one length")
    shown = "a single value" if lengths[odd] is None else f"{lengths[odd]} values"
    raise ValueError(f"{name}: {what}[{odd}] has {shown}, {what}[0] {first}: {what} must be an (n, 3) array"
                     + (" of triangles" if what == "faces" else "")) from None


def _as_polydata(mesh, name, errors):
    """A file name, a vtkPolyData, or (vertices, faces) arrays, as a vtkPolyData."""
    if isinstance(mesh, (str, bytes, os.PathLike)):
        path = os.fsdecode(mesh)
        # A C string would end at the NUL: the reader would open another file.
        if "\0" in path:
            raise ValueError(f"{name}: the file name {path!r} holds a NUL character")
        reader = errors.watch(vtkSurfaceMeshReader())
        reader.SetFileName(path)
        reader.Update()
        errors.raise_if_any(path)
        return reader.GetOutput(), path
    if isinstance(mesh, vtkPolyData):
        return mesh, name
    if isinstance(mesh, (tuple, list)) and len(mesh) == 2:
        given_vertices, given_faces = _rows(mesh[0], name, "vertices"), _rows(mesh[1], name, "faces")
        # numpy would drop an imaginary part, and cut 0.7 to vertex 0, without a word.
        if given_vertices.dtype.kind not in "iuf":
            raise ValueError(f"{name}: vertices must be real numbers, got {given_vertices.dtype}")
        if given_faces.dtype.kind not in "iu" and not (
                given_faces.dtype.kind == "f" and np.array_equal(given_faces, np.round(given_faces))):
            raise ValueError(f"{name}: faces must be integer vertex numbers, got {given_faces.dtype} values")
        vertices = np.ascontiguousarray(given_vertices, dtype=np.float64)
        faces = np.ascontiguousarray(given_faces, dtype=np.int64)
        if vertices.ndim != 2 or vertices.shape[1] != 3:
            raise ValueError(f"{name}: vertices must be an (n, 3) array, got shape {vertices.shape}")
        if faces.ndim != 2 or faces.shape[1] != 3:
            raise ValueError(f"{name}: faces must be an (m, 3) array of triangles, got shape {faces.shape}")
        if faces.size and (faces.min() < 0 or faces.max() >= len(vertices)):
            raise ValueError(f"{name}: face vertex numbers must lie in 0..{len(vertices) - 1}")
        points = vtkPoints()
        points.SetData(numpy_to_vtk(vertices, deep=True))
        connectivity = np.hstack([np.full((len(faces), 1), 3, dtype=np.int64), faces]).ravel()
        cells = vtkCellArray()
        cells.SetCells(len(faces), numpy_to_vtkIdTypeArray(connectivity, deep=True))
        polydata = vtkPolyData()
        polydata.SetPoints(points)
        polydata.SetPolys(cells)
        return polydata, name
    raise TypeError(f"{name}: expected a file name, a vtkPolyData or (vertices, faces) arrays, "
                    f"got {type(mesh).__name__}")


def _field_values(polydata):
    """The output's numeric field data arrays, as numpy arrays (single values as floats)."""
    fields = {}
    field_data = polydata.GetFieldData()
    for index in range(field_data.GetNumberOfArrays()):
        array = field_data.GetArray(index)
        if array is None or not array.GetName():
            continue
        values = vtk_to_numpy(array).copy()
        fields[array.GetName()] = float(values.ravel()[0]) if values.size == 1 else values
    return fields


# The stages' field data in vtkMobiusRegistration's output: "<stage>.<name>".
_STAGE_PREFIXES = ("SourceMap.", "TargetMap.", "SourceCentering.", "TargetCentering.",
                   "Registration.", "MobiusCorrespondence.")


class Registration:
    """The map from the source's vertices to points on the target surface.

    Row i of every per-vertex array belongs to source vertex i (numbered as in the input:
    file order, or the rows of the vertices array), listed in `source_vertex`: every vertex
    of the source as given, also when its repair merged, dropped or split some.

    - `target_triangle` (n,): the triangle of the target the vertex lands in (the target's
      triangles as given, polygons split into triangles in order; with repair=False and
      fill_holes, a triangle of its repaired map);
    - `target_vertices` (n, 3): that triangle's corners, numbered as the target's input
      vertices (-1 only for a vertex that fill_holes created with repair=False);
    - `barycentric` (n, 3): the point's barycentric coordinates in that triangle;
    - `mapped_points` (n, 3): the point on the target surface;
    - `repaired` (n,): 0 where the row is the image of the vertex itself; otherwise 1 (the
      source's repair left no point of it: the image of its closest point on the repaired
      surface), plus 2 where the image fell on a patch the target's repair created and was
      moved to the target's own surface (RepairedVertex);
    - `transform` (3, 3): the rotation (or reflection) aligning the two spherical maps;
    - `quality`: the main figures (registration error, conformal distortion of each map,
      refinement residuals when refined); `fields`: every numeric field of the output;
    - `landmark_residuals` (k,): per landmark, the straight-line distance on the target
      between the image of its source vertex and its target vertex, over sqrt(target area);
    - `polydata`: the output vtkPolyData (the source mesh on the target, with all arrays).
    """

    def __init__(self, polydata, target_vertex_count, quality, fields):
        point_data = polydata.GetPointData()

        def point_array(name):
            array = point_data.GetArray(name)
            if array is None:
                raise RegistrationError(f"the correspondence has no {name} array")
            return vtk_to_numpy(array).copy()

        order = slice(None)
        source_vertex = point_array("InputPointId").astype(np.int64).ravel()
        # Repairs may renumber the source's vertices: put the rows back in input order when
        # every input vertex is there once.
        if np.array_equal(np.sort(source_vertex), np.arange(len(source_vertex))):
            order = np.argsort(source_vertex)
        self.source_vertex = source_vertex[order]
        self.target_triangle = point_array("TargetCellId").astype(np.int64).ravel()[order]
        self.target_vertices = point_array("TargetInputPointIds").astype(np.int64).reshape(-1, 3)[order]
        self.barycentric = point_array("TargetBarycentric").reshape(-1, 3)[order]
        self.mapped_points = point_array("MappedPoints").reshape(-1, 3)[order]
        repaired = point_data.GetArray("RepairedVertex")
        self.repaired = (vtk_to_numpy(repaired).astype(np.int64).ravel()[order] if repaired is not None
                         else np.zeros(len(source_vertex), dtype=np.int64))
        self.transform = np.asarray(fields["Rotation"], dtype=float).reshape(3, 3)
        self.landmark_residuals = np.atleast_1d(np.asarray(fields.get("LandmarkResidual", []), dtype=float))
        self.quality = quality
        self.fields = fields
        self.polydata = polydata
        self.target_vertex_count = target_vertex_count

    def __repr__(self):
        figures = ", ".join(f"{key}={value:.4g}" for key, value in self.quality.items())
        return f"<Registration of {len(self.source_vertex)} source vertices: {figures}>"

    def transfer(self, values):
        """Carries per-target-vertex values to the source vertices.

        `values`: shape (number of target vertices,) or (number of target vertices, k), in
        the target's input vertex order. Returns (n,) or (n, k): each source vertex gets
        the barycentric interpolation of the values at the corners of its target triangle.
        Corners that fill_holes created (no input vertex) are left out and the remaining
        weights renormalized.
        """
        values = _numbers(values)
        if values.ndim not in (1, 2) or values.shape[0] != self.target_vertex_count:
            raise ValueError(f"values must have one row per target vertex ({self.target_vertex_count}), "
                             f"got shape {values.shape}")
        valid = self.target_vertices >= 0
        weights = np.where(valid, self.barycentric, 0.0)
        totals = weights.sum(axis=1, keepdims=True)
        weights = np.divide(weights, totals, out=np.full_like(weights, np.nan), where=totals > 0)
        corners = values[np.where(valid, self.target_vertices, 0)]  # (n, 3) or (n, 3, k)
        if values.ndim == 1:
            return np.einsum("ij,ij->i", weights, corners.astype(float))
        return np.einsum("ij,ijk->ik", weights, corners.astype(float))


def _numbers(values):
    """Per-vertex values as a numpy array of real numbers: integers, booleans and floats (NaN
    is the caller's data and carried); ValueError naming the first entry that is not a real
    number (None, a string, a complex number), which numpy would turn into NaN, an error of
    its own or a real part."""
    try:
        values = np.asarray(values)
    except ValueError:
        raise ValueError("values must be an array of numbers, one row per target vertex, "
                         "all rows of one length") from None
    if values.dtype.kind in "biuf":
        return values
    flat = values.ravel()
    for index in range(flat.size):
        entry = flat[index]
        if not isinstance(entry, (int, float, np.integer, np.floating, np.bool_)):
            where = np.unravel_index(index, values.shape)
            position = ", ".join(str(int(k)) for k in where)
            raise ValueError(f"values must be real numbers: values[{position}] is {entry!r}")
    return values.astype(float)


_C_INT = (-2 ** 31, 2 ** 31 - 1)


def _require_int(name, value):
    """An integer option: a Python or NumPy integer that fits a C int (not a bool, not 32.0)."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) \
            or not _C_INT[0] <= value <= _C_INT[1]:
        raise ValueError(f"{name} must be an integer, got {value!r}")


def _require_real(name, value):
    """A real option: a Python or NumPy integer or float (not a bool, not complex) that
    float() takes (an integer beyond a double's range overflows)."""
    try:
        real = not isinstance(value, bool) and isinstance(value, (int, float, np.integer, np.floating)) \
            and float(value) is not None
    except OverflowError:
        real = False
    if not real:
        raise ValueError(f"{name} must be a number, got {value!r}")


def _landmark_pairs(landmarks):
    """The landmarks as a list of (source vertex, target vertex) integer pairs: any sequence
    of pairs, or an (n, 2) integer array. Which vertices are allowed is the filter's rule."""
    try:
        pairs = [tuple(pair) for pair in landmarks]
    except TypeError:
        raise ValueError(f"landmarks must be a list of (source vertex, target vertex) pairs, "
                         f"got {landmarks!r}") from None
    for index, pair in enumerate(pairs):
        if len(pair) != 2 or not all(
                isinstance(vertex, (int, np.integer)) and not isinstance(vertex, bool) for vertex in pair):
            raise ValueError(f"landmarks[{index}] must be a pair of integer vertex numbers "
                             f"(source, target), got {pair!r}")
    return [(int(source), int(target)) for source, target in pairs]


def _registration_filter(options, errors):
    """vtkMobiusRegistration with register()'s options; their values are checked once the
    meshes are there (_check_options)."""
    registration = errors.watch(vtkMobiusRegistration())
    registration.SetMaximumNumberOfIterations(int(options["iterations"]))
    registration.SetConvergenceTolerance(float(options["tolerance"]))
    registration.SetRepair(bool(options["repair"]))
    registration.SetFillHoles(bool(options["fill_holes"]))
    registration.SetKeepLargestComponent(bool(options["keep_largest_component"]))
    registration.SetAllowPoorMaps(bool(options["allow_poor_maps"]))
    registration.SetResolution(int(options["resolution"]))
    registration.SetSmoothingTime(float(options["smoothing"]))
    registration.SetTransformMode(_TRANSFORM_MODES[options["transform"]])
    registration.SetNumberOfCandidates(int(options["candidates"]))
    registration.SetCandidateSeparation(float(options["candidate_separation"]))
    registration.SetRefine(bool(options["refine"]))
    registration.SetBasisSize(int(options["basis_size"]))
    registration.SetGeometricPolish(bool(options["polish"]))
    registration.SetBothDirections(bool(options["both_directions"]))
    registration.SetCandidate(-1 if options["candidate"] is None else int(options["candidate"]))
    registration.SetNumberOfThreads(int(options["threads"]))
    registration.SetLandmarkMode(int(options["landmark_mode"]))
    for source_vertex, target_vertex in _landmark_pairs(options["landmarks"]):
        registration.AddLandmark(_id_type(source_vertex), _id_type(target_vertex))
    return registration


def _id_type(vertex):
    """A vertex number as a vtkIdType takes it: beyond its range (where the wrapping would
    raise its own error) the nearest end, which names no vertex either, as the rules say."""
    return max(-2 ** 63, min(vertex, 2 ** 63 - 1))


def _check_options(registration):
    """The rules every interface shares (ValueError in register()'s words); the landmarks'
    vertices against the meshes given."""
    out_of_range = registration.CheckParameters(vtkMobiusRegistration.PYTHON_NAMES)
    if out_of_range:
        raise ValueError(out_of_range)


def register(source, target, **options):
    """Registers `source` onto `target` and returns a Registration.

    `source`, `target`: a mesh file name (.obj .off .ply .stl .vtp .vtk), a vtkPolyData, or
    a (vertices, faces) pair of arrays ((n, 3) floats, (m, 3) vertex numbers). A mesh that is
    no closed, connected, manifold genus-0 surface is repaired into a genus-0 proxy (repair,
    with a warning and the figures in `fields`); the result still has a row per vertex as given.

    Options (defaults as mobius-register's): refine=True, basis_size=80 (2 to 500), polish=True (end the
    refinement with its geometric polish; False as --no-polish), both_directions=True (polish
    the map the other way too and average each point with its inverse; False as --one-direction),
    resolution=256,
    smoothing=0.0005, transform="rotation" ("reflection", "both"), candidates=4,
    candidate_separation=60 (degrees, 0 to 180, between two candidates),
    candidate=None (keep this candidate's refined map, 0..candidates-1, as --candidate, for a
    map that came out turned while a warning named a near-equal runner-up), iterations=100, tolerance=1e-4,
    repair=True (False: refuse a mesh that is no closed genus-0 surface, as --no-repair),
    fill_holes=False (with repair=False: close holes), keep_largest_component=False (map the
    largest part also when another is not small against it),
    landmarks=() (pairs (source vertex, target vertex) of input vertex numbers whose images
    are known: the rotation is chosen by them and the refinement maps them exactly; their
    residuals are `landmark_residuals`), landmark_mode=0 (1: a Moebius transform sends the
    first 3 landmarks onto their targets instead of the rotation; needs 3 landmarks),
    allow_poor_maps=False, threads=0 (threads of each threaded filter, 0 to 1024; 0 is one
    per core this process may run on, at most VTK_SMP_MAX_THREADS when set; the result is
    the same for any count, and `fields["NumberOfThreadsUsed"]` says what ran).

    Raises RegistrationError (with the filter's message) when a mesh cannot be read or
    mapped, TypeError for an unknown option, ValueError for a malformed one.
    """
    unknown = sorted(set(options) - set(DEFAULT_OPTIONS))
    if unknown:
        raise TypeError(f"register() got unknown option(s) {', '.join(unknown)}; "
                        f"known: {', '.join(DEFAULT_OPTIONS)}")
    options = dict(DEFAULT_OPTIONS, **options)
    if options["transform"] not in _TRANSFORM_MODES:
        raise ValueError(f"transform must be one of {', '.join(_TRANSFORM_MODES)}, got {options['transform']!r}")
    # Python's part of the checks: the types. Which values are allowed is checked below by
    # the filter, in the same place as for mobius-register and the VTK filters.
    for name in ("resolution", "candidates", "threads", "basis_size", "iterations", "landmark_mode"):
        _require_int(name, options[name])
    if options["candidate"] is not None:
        _require_int("candidate", options["candidate"])
    for name in ("tolerance", "smoothing", "candidate_separation"):
        _require_real(name, options[name])

    errors = _Errors()
    registration = _registration_filter(options, errors)
    _check_options(registration)  # the values that do not depend on the meshes, before reading them
    source_mesh, source_name = _as_polydata(source, "source", errors)
    target_mesh, target_name = _as_polydata(target, "target", errors)
    # The filters give an empty output for an empty input (VTK's convention), not an error.
    for mesh, name in ((source_mesh, source_name), (target_mesh, target_name)):
        if mesh.GetNumberOfPoints() == 0:
            raise RegistrationError(f"{name}: the mesh has no points")

    registration.SetSourceData(source_mesh)
    registration.SetTargetData(target_mesh)
    _check_options(registration)
    registration.SetSourceName(source_name)
    registration.SetTargetName(target_name)
    registration.Update()
    errors.warn()
    if errors.messages:
        # One message, the pipeline's, naming the mesh; its hint in this function's words.
        raise RegistrationError(errors.messages[0].replace("set AllowPoorMaps to write the result anyway",
                                                "allow_poor_maps=True accepts it"))

    output = vtkPolyData()
    output.DeepCopy(registration.GetOutput())
    all_fields = _field_values(output)
    fields = {key: value for key, value in all_fields.items() if not key.startswith(_STAGE_PREFIXES)}
    # The rotational alignment's own figures (Rotation, RegistrationError, ...).
    for key, value in all_fields.items():
        if key.startswith("Registration."):
            fields.setdefault(key[len("Registration."):], value)
    quality = {}
    for key in ("RegistrationError", "RefinementOrthogonalityResidual", "RefinementOrientationAgreement"):
        if key in fields:
            quality[key] = fields[key]
    for side in ("Source", "Target"):
        key = side + "Map.MeanQuasiConformalDistortion"
        if key in all_fields:
            quality[side + "MeanQuasiConformalDistortion"] = all_fields[key]
    return Registration(output, target_mesh.GetNumberOfPoints(), quality, fields)
