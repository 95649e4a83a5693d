"""mobiusregistration.register(): file, vtkPolyData and numpy inputs, the refined map's
accuracy on a bent, rotated copy with known correspondence (vertex i <-> vertex i), the
Möbius map with refine=False, transfer() of linear functions (reproduced exactly by
barycentric interpolation), and errors raised with the filter's message."""
import os
import sys
import warnings

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import mobiusregistration
from mobiusregistration import RegistrationError, register

mesh_dir = os.environ.get("MOBIUS_MESH_DIR", "")
hand = os.path.join(mesh_dir, "hand.off")
if not os.path.exists(hand):
    print(f"no example meshes in MOBIUS_MESH_DIR={mesh_dir!r}")
    sys.exit(1)


def read(path):
    reader = mobiusregistration.vtkSurfaceMeshReader()
    reader.SetFileName(path)
    reader.Update()
    polydata = reader.GetOutput()
    vertices = vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)
    faces = vtk_to_numpy(polydata.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return polydata, vertices, faces


def surface_area(vertices, faces):
    corners = vertices[faces]
    return 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum()


hand_polydata, vertices, faces = read(hand)
# The bent copy: bent along the hand's longest axis, then turned by a known rotation.
# Vertex i of the copy is the image of vertex i: the true map is the identity on numbers.
centered = vertices - vertices.mean(axis=0)
axes = np.linalg.svd(centered, full_matrices=False)[2]
local = centered @ axes.T
length = np.ptp(local[:, 0])
local[:, 1] += 0.25 * length * (local[:, 0] / length) ** 2
angle = 0.7
rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
bent = (local @ axes) @ rotation.T
scale = np.sqrt(surface_area(bent, faces))

# File source, numpy target; the refined map by default.
result = register(hand, (bent, faces), resolution=128)
n = len(vertices)
assert result.mapped_points.shape == (n, 3) and result.barycentric.shape == (n, 3)
assert result.target_vertices.shape == (n, 3) and result.target_triangle.shape == (n,)
assert np.array_equal(result.source_vertex, np.arange(n)), "rows are not in the source's vertex order"
assert np.allclose(result.barycentric.sum(axis=1), 1.0, atol=1e-9)
assert result.transform.shape == (3, 3)
assert abs(abs(np.linalg.det(result.transform)) - 1) < 1e-9
assert "RefinementOrthogonalityResidual" in result.quality, result.quality
assert "RegistrationError" in result.quality and "SourceMeanQuasiConformalDistortion" in result.quality
refined_error = np.linalg.norm(result.mapped_points - bent, axis=1).mean() / scale
print(f"refined map: mean error {refined_error:.4f} of sqrt(area); {result!r}")
assert refined_error < 0.03, f"refined map error {refined_error:.4f} of sqrt(area)"

# The mapped points lie on the target: the barycentric combination of the corners.
corners = bent[result.target_vertices]
assert np.allclose(np.einsum("ij,ijk->ik", result.barycentric, corners), result.mapped_points, atol=1e-6 * scale)

# transfer(): a linear function of position is reproduced exactly at the mapped points,
# with one component or several.
coefficients = np.array([[0.3, -1.2, 2.0], [1.0, 0.5, -0.25]])
linear = bent @ coefficients.T + np.array([4.0, -2.0])
transferred = result.transfer(linear)
assert transferred.shape == (n, 2)
assert np.allclose(transferred, result.mapped_points @ coefficients.T + np.array([4.0, -2.0]), atol=1e-6 * scale)
assert np.allclose(result.transfer(linear[:, 0]), transferred[:, 0])
# ... and carries the target's vertex numbers' positions back to the source's: near the truth.
assert np.linalg.norm(result.transfer(bent) - bent, axis=1).mean() / scale < 0.03
try:
    result.transfer(linear[:-1])
    raise AssertionError("transfer() accepted values for the wrong number of vertices")
except ValueError as error:
    assert "one row per target vertex" in str(error)

# Without the refinement's geometric polish (polish=False): the spectral map alone. This
# copy is sheared rather than bent (lengths change by up to 3%), where the polish's
# local rigidity is not quite right: measured 0.0019 without it, 0.0032 with it.
unpolished = register(hand, (bent, faces), resolution=128, polish=False)
unpolished_error = np.linalg.norm(unpolished.mapped_points - bent, axis=1).mean() / scale
print(f"refined map without the geometric polish: mean error {unpolished_error:.4f} of sqrt(area)")
assert unpolished_error < 0.03 and not np.allclose(unpolished.mapped_points, result.mapped_points)
# The polish in one direction only (both_directions=False, as --one-direction): another map,
# near the truth too.
one = register(hand, (bent, faces), resolution=128, both_directions=False)
one_error = np.linalg.norm(one.mapped_points - bent, axis=1).mean() / scale
print(f"refined map polished in one direction only: mean error {one_error:.4f} of sqrt(area)")
assert one_error < 0.03 and not np.allclose(one.mapped_points, result.mapped_points)
# No wall-clock timings in the output (RecordTimings off): the same result in every run.
assert "RefinementStageSeconds" not in result.fields

# The Möbius map alone (vtkDenseCorrespondence), from a vtkPolyData: coarser than refined.
mobius = register(hand_polydata, (bent, faces), resolution=128, refine=False)
mobius_error = np.linalg.norm(mobius.mapped_points - bent, axis=1).mean() / scale
print(f"Möbius map: mean error {mobius_error:.4f} of sqrt(area)")
assert "RefinementOrthogonalityResidual" not in mobius.quality
assert mobius_error < 0.25 and refined_error < mobius_error

# candidate_separation reaches the rotation search: no two candidates nearer than it (at 180
# degrees only a peak and its half-turn remain, where the default keeps 4).
def candidate_angles(registration):
    transforms = np.asarray(registration.fields["CandidateTransforms"]).reshape(-1, 3, 3)
    cosines = [(np.trace(a.T @ b) - 1) / 2 for k, a in enumerate(transforms) for b in transforms[k + 1:]]
    return len(transforms), np.degrees(np.arccos(np.clip(cosines, -1, 1)))
for separation, most in ((60, 4), (180, 2)):
    count, angles = candidate_angles(register(hand, hand, resolution=64, refine=False,
                                              candidate_separation=separation))
    print(f"candidate_separation={separation}: {count} candidates, nearest {angles.min():.1f} degrees apart")
    assert 2 <= count <= most and angles.min() >= separation - 1e-6, (separation, count, angles)
    assert separation != 60 or count == 4

# A mesh with defects is repaired, with a warning naming the repair, and the result has a
# row per vertex as given; with repair=False the filter's message, as a Python exception.
open_faces = faces[1:]  # one triangle removed: a hole
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    repaired = register((vertices, open_faces), hand, resolution=64, refine=False)
assert any("1 hole filled" in str(w.message) for w in caught), [str(w.message) for w in caught]
assert len(repaired.source_vertex) == len(vertices) and repaired.repaired.shape == (len(vertices),)
try:
    register((vertices, open_faces), hand, resolution=64, refine=False, repair=False)
    raise AssertionError("an open mesh was registered without repair")
except RegistrationError as error:
    print("open mesh:", error)
    assert str(error).startswith("source: ") and "FillHoles" in str(error), error
genus_two = os.path.join(mesh_dir, "eight.off")
try:
    register(genus_two, hand, resolution=64, refine=False, repair=False)
    raise AssertionError("a genus-2 mesh was registered without repair")
except RegistrationError as error:
    print("genus 2:", error)
    assert genus_two in str(error) and "genus" in str(error).lower(), error
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    eight = register(genus_two, hand, resolution=64, refine=False)
assert any("2 handles cut" in str(w.message) for w in caught), [str(w.message) for w in caught]
assert np.array_equal(eight.source_vertex, np.arange(315)) and np.isfinite(eight.mapped_points).all()
# The filters turn an empty mesh into an empty output (VTK's convention); register() says so.
try:
    register((np.zeros((0, 3)), np.zeros((0, 3), dtype=int)), hand, resolution=64, refine=False)
    raise AssertionError("an empty mesh was registered")
except RegistrationError as error:
    assert "source" in str(error) and "no points" in str(error), error
try:
    register(os.path.join(mesh_dir, "no-such-mesh.off"), hand)
    raise AssertionError("a missing file was registered")
except RegistrationError as error:
    assert "no-such-mesh.off" in str(error), error
for bad_call, expected in ((lambda: register(hand, hand, resolutoin=64), TypeError),
                           (lambda: register(hand, hand, transform="shear"), ValueError),
                           (lambda: register(hand, (vertices, faces[:, :2])), ValueError),
                           (lambda: register(42, hand), TypeError)):
    try:
        bad_call()
        raise AssertionError(f"no {expected.__name__}")
    except expected:
        pass

# Meshes too small for the refinement's basis (a 226-vertex sphere, fewer than 2 x 200
# vertices): the Möbius map, with a warning; a basis size out of mobius-register's range
# is refused.
from vtkmodules.vtkFiltersSources import vtkSphereSource
sphere = vtkSphereSource()
sphere.SetThetaResolution(16)
sphere.SetPhiResolution(16)
sphere.Update()
assert sphere.GetOutput().GetNumberOfPoints() < 400
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    small = register(sphere.GetOutput(), sphere.GetOutput(), resolution=32, basis_size=200)
assert any("refinement skipped" in str(w.message) for w in caught), [str(w.message) for w in caught]
assert "RefinementOrthogonalityResidual" not in small.quality
for bad in (1, 501, 2.5, True):
    try:
        register(hand, hand, basis_size=bad)
    except ValueError as error:
        assert "basis_size" in str(error)
    else:
        raise AssertionError(f"basis_size={bad!r} accepted")
# What mobius-register refuses, register() refuses (it accepted these and returned wrong maps
# or never ended): a coarse grid, an unreachable tolerance, NaN and infinite times, no candidates;
# and what the filter clamped silently (65 candidates, -1 threads).
for name, bad in (("resolution", 6), ("resolution", 32.0), ("tolerance", 0), ("tolerance", -1), ("tolerance", 5),
                  ("smoothing", float("inf")), ("smoothing", 1e308), ("smoothing", float("nan")),
                  ("candidates", 0), ("candidates", -5), ("candidates", 65), ("candidate", 4),
                  ("threads", -1), ("threads", 1025), ("iterations", 0), ("basis_size", 10 ** 20),
                  ("tolerance", 1j), ("smoothing", 10 ** 400)):
    try:
        register(hand, hand, **{name: bad})
    except ValueError as error:
        assert name in str(error), str(error)
    else:
        raise AssertionError(f"{name}={bad!r} accepted")
# Meshes that numpy would quietly change: complex vertices, fractional face numbers; a NUL
# in a file name.
points_array, faces_array = np.asarray(vertices), np.asarray(faces)
for label, mesh in (("complex vertices", (points_array.astype(complex), faces_array)),
                    ("fractional faces", (points_array, faces_array + 0.7)),
                    ("a NUL in the name", "hand\0.off")):
    try:
        register(mesh, hand)
    except ValueError as error:
        print(f"{label}: {error}")
    else:
        raise AssertionError(f"{label} accepted")
# A ragged faces or vertices list: a message naming the mesh and the row (numpy's own error,
# "setting an array element with a sequence", named neither).
ragged_faces = [list(face) for face in faces_array[:40]] + [[0, 1, 2, 3]] + [list(f) for f in faces_array[40:]]
for label, mesh, words in (("ragged faces", (points_array, ragged_faces), ["target: faces[40] has 4 values", "(n, 3)"]),
                           ("ragged vertices", ([[0.0, 0.0, 0.0], [1.0, 0.0], [0.0, 1.0, 0.0]], faces_array[:1]),
                            ["target: vertices[1] has 2 values"]),
                           ("a number among the faces", (points_array, [[0, 1, 2], 5]),
                            ["target: faces[1] has a single value"])):
    try:
        register(hand, mesh)
    except ValueError as error:
        assert all(w in str(error) for w in words), f"{label}: {error}"
    else:
        raise AssertionError(f"{label} accepted")
# transfer() of values that are not numbers: an error naming the first (None came back as NaN
# without a word, a complex number as its real part).
small = register(hand, hand, refine=False, resolution=32)
count = small.target_vertex_count
for label, values, words in (("None", np.array([None] * count, dtype=object), ["values[0] is None"]),
                             ("a None among numbers", [1.0] * 7 + [None] + [1.0] * (count - 8), ["values[7] is None"]),
                             ("a string", np.array(["a"] * count), ["values[0] is 'a'"]),
                             ("complex", np.full(count, 1 + 2j), ["values[0] is"]),
                             ("ragged rows", [[1.0, 2.0]] * 3 + [[1.0]] + [[1.0, 2.0]] * (count - 4), ["rows of one length"])):
    try:
        small.transfer(values)
    except ValueError as error:
        assert all(w in str(error) for w in words), f"transfer() of {label}: {error}"
    else:
        raise AssertionError(f"transfer() of {label} accepted")
# Numbers in an object array (a list of Python ints, say) are carried like any numbers.
assert np.allclose(small.transfer(np.array([2] * count, dtype=object)), 2.0)
# Two landmarks on two copies of one vertex, which the repair merges into one point, with two
# targets: one could not be kept (it was accepted, and the second missed its target by 0.4
# sqrt(area) without a word): an error naming both.
corner = int(faces_array[0][0])
copy_points = np.vstack([points_array, points_array[corner]])
copy_faces = faces_array.copy()
copy_faces[0][0] = len(points_array)
try:
    register((copy_points, copy_faces), hand, landmarks=[(corner, 10), (len(points_array), 200), (400, 400)],
             resolution=64, refine=False)
except RegistrationError as error:
    assert f"name source vertices {corner} and {len(points_array)}, which are one point" in str(error), error
else:
    raise AssertionError("two landmarks on one merged point accepted")
# A vertex at 1e308: unused, it is a stray point the map still gives a row (it sets no scale);
# used by a triangle, the error names it (both were "every triangle has zero area").
stray = register((np.vstack([points_array, [1e308, 0, 0]]), faces_array), hand, resolution=64, refine=False)
assert len(stray.source_vertex) == len(points_array) + 1 and np.isfinite(stray.mapped_points).all()
spike_points = points_array.astype(float)
spike_points[corner] = [1e308, 0, 0]
try:
    register((spike_points, faces_array), hand, resolution=64, refine=False)
except RegistrationError as error:
    assert f"point {corner} is 1e+308 from the origin" in str(error), error
else:
    raise AssertionError("a triangle's vertex at 1e308 accepted")
# A mirrored pair by rotations only: the hint names register()'s option (transform="both").
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    register(hand, (points_array * [-1.0, 1.0, 1.0], faces_array[:, ::-1]), refine=False, resolution=64)
assert any('pass transform="both"' in str(w.message) for w in caught), [str(w.message) for w in caught]
print("register() checks passed")
