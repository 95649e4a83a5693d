"""Area and angle distortion of the centered spherical map at each generalized-centering
degree (the paper's Figure 5), on real meshes. Run with Debian's python3 and the module's
package folder on PYTHONPATH:

    PYTHONPATH=build/lib/python3/dist-packages python3 Benchmarks/centering_distortion.py \
        build/data/meshes/{hand,cow,elephant,bull}.off --degrees 1 2 3 4

Per mesh and degree: area distortion, the standard deviation over the surface (area-weighted)
of log(sphere area share / surface area share) of the triangles (0: area-preserving), and
angle distortion, the area-weighted mean of the triangles' quasi-conformal ratio
sigma_max / sigma_min of the linear map from the surface triangle to the sphere triangle
(1: conformal); the advection steps taken and the norm of the moments left (the
generalized centering stops at its tolerance, its iteration cap, or when no step can lower
the moments without flipping a triangle). Degree 1 is the Moebius centering (conformal up to discretization);
higher degrees trade angle distortion for area distortion.

Every run checks its figures: the per-triangle area ratios and quasi-conformal ratios
computed here must agree with the filter's own LogAreaRatio and QuasiConformalDistortion
cell arrays, and degree 1 must take no advection step. With --expect-tradeoff it also
checks Figure 5 itself: every higher degree converges and has lower area distortion and
higher angle distortion than degree 1 (true of the hand at degree 2, not of every mesh and
degree). A failed check is printed and the exit status is 1.
"""
import argparse
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from mobiusregistration import vtkMobiusCenter, vtkSphericalConformalMap, vtkSurfaceMeshReader


def distortion(centered):
    """Area and angle distortion of a centered map, and where its per-triangle figures
    disagree with the filter's cell arrays (an empty list if nowhere)."""
    sphere = vtk_to_numpy(centered.GetPoints().GetData()).astype(float)
    surface = vtk_to_numpy(centered.GetPointData().GetArray("SurfacePoints")).astype(float)
    triangles = vtk_to_numpy(centered.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    surface_area = vtk_to_numpy(centered.GetCellData().GetArray("SurfaceArea")).astype(float)

    def frames(points):
        a, b, c = (points[triangles[:, k]] for k in range(3))
        e1, e2 = b - a, c - a
        return e1, e2, 0.5 * np.linalg.norm(np.cross(e1, e2), axis=1)

    s1, s2, sphere_area = frames(sphere)
    m1, m2, _ = frames(surface)
    weights = surface_area / surface_area.sum()
    log_ratio = np.log(np.maximum(sphere_area / sphere_area.sum(), 1e-300) / weights)
    mean = np.sum(weights * log_ratio)
    area_spread = math.sqrt(np.sum(weights * (log_ratio - mean) ** 2))

    # Each triangle's linear map in orthonormal frames of its two planes: J = S M^-1.
    def local(e1, e2):
        u = e1 / np.linalg.norm(e1, axis=1)[:, None]
        n = np.cross(e1, e2)
        v = np.cross(n / np.linalg.norm(n, axis=1)[:, None], u)
        return np.stack([np.stack([np.sum(e1 * u, 1), np.sum(e2 * u, 1)], 1),
                         np.stack([np.sum(e1 * v, 1), np.sum(e2 * v, 1)], 1)], 1)

    jacobian = local(s1, s2) @ np.linalg.inv(local(m1, m2))
    singular = np.linalg.svd(jacobian, compute_uv=False)
    quasi_conformal = singular[:, 0] / np.maximum(singular[:, 1], 1e-300)

    cells = centered.GetCellData()
    filter_log2_ratio = vtk_to_numpy(cells.GetArray("LogAreaRatio"))
    filter_quasi_conformal = vtk_to_numpy(cells.GetArray("QuasiConformalDistortion"))
    disagreements = []
    if not np.allclose(np.clip(log_ratio / math.log(2), -60, 60), filter_log2_ratio, rtol=0, atol=1e-6):
        disagreements.append("the area ratios disagree with the filter's LogAreaRatio")
    if not np.allclose(quasi_conformal, filter_quasi_conformal, rtol=1e-6):
        disagreements.append("the quasi-conformal ratios disagree with the filter's QuasiConformalDistortion")
    return area_spread, float(np.sum(weights * quasi_conformal)), disagreements


parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("meshes", nargs="+")
parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2, 3, 4])
parser.add_argument("--expect-tradeoff", action="store_true",
                    help="fail unless every degree above 1 converges and trades angle for area distortion")
args = parser.parse_args()
if args.expect_tradeoff and 1 not in args.degrees:
    parser.error("--expect-tradeoff compares with degree 1: list it in --degrees")
failures = []
print("| mesh | degree | area distortion (std of log area ratio) | angle distortion (mean quasi-conformal ratio) "
      "| steps | moments left |")
print("|---|---|---|---|---|---|")
for path in args.meshes:
    reader = vtkSurfaceMeshReader()
    reader.SetFileName(path)
    conformal = vtkSphericalConformalMap()
    conformal.SetInputConnection(reader.GetOutputPort())
    conformal.Update()
    name = path.split('/')[-1]
    figures, degrees = {}, args.degrees
    if conformal.GetOutput().GetNumberOfPoints() == 0:
        print(f"| {name} | cannot be mapped (see the error above) | | | |")
        degrees = []
    for degree in degrees:
        center = vtkMobiusCenter()
        center.SetInputConnection(conformal.GetOutputPort())
        center.SetDegree(degree)
        center.Update()
        centered = center.GetOutput()
        area, angle, disagreements = distortion(centered)
        failures += [f"{name} at degree {degree}: {text}" for text in disagreements]
        fields = centered.GetFieldData()
        steps = fields.GetArray("GeneralizedCenteringIterations").GetValue(0)
        moments = fields.GetArray("CenterOfMassNorm").GetValue(0)
        figures[degree] = area, angle, moments <= center.GetGeneralizedTolerance()
        print(f"| {name} | {degree} | {area:.3f} | {angle:.3f} | {steps:.0f} | {moments:.1e} |", flush=True)
        if degree == 1 and steps != 0:
            failures.append(f"{name}: the Moebius centering (degree 1) took {steps:.0f} advection steps")
    if args.expect_tradeoff and 1 not in figures:
        failures.append(f"{name}: no degree-1 map to compare with")
    elif args.expect_tradeoff:
        area1, angle1, _ = figures[1]
        for degree, (area, angle, converged) in figures.items():
            if degree > 1 and not (converged and area < area1 and angle > angle1):
                failures.append(f"{name} at degree {degree}: no Figure 5 trade-off (converged: {converged}, "
                                f"area distortion {area:.3f} against {area1:.3f}, angle {angle:.3f} against "
                                f"{angle1:.3f})")
for failure in failures:
    print("FAILED:", failure, file=sys.stderr)
sys.exit(1 if failures else 0)
