"""Detect the bilateral symmetry of a mesh with the Detect Symmetry filter (pvpython).

Usage:
    pvpython detect_symmetry.py --plugin PATH/MobiusRegistration.so --input MESH [--output DIR]

Runs Detect Symmetry (centered, refined), prints the symmetry distance and the mirror plane,
mirrors a point array across the shape (the array `Height`, made here from the vertex
positions, read at each vertex's mirror image: `Height_Target`), and writes DIR/symmetry.vtp
and DIR/symmetry.png: the mesh colored by its per-vertex asymmetry |v - m(m(v))| / sqrt(area).
"""
import argparse
import os

from paraview.simple import (  # pvpython's usual namespace
    Calculator, ColorBy, CreateView, GetColorTransferFunction, LoadPlugin, OpenDataFile,
    SaveData, SaveScreenshot, Show)
from paraview import servermanager

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", required=True, help="path of MobiusRegistration.so")
parser.add_argument("--input", required=True, help="a closed genus-0 mesh (.off .obj .ply .stl .vtp .vtk)")
parser.add_argument("--output", default="detect_symmetry_output", help="folder for the results")
parser.add_argument("--resolution", type=int, default=128, help="scale-factor grid size")
parser.add_argument("--max-distance", type=float, default=1.0,
                    help="exit with an error if the symmetry distance is larger (for tests)")
args = parser.parse_args()
os.makedirs(args.output, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

mesh = OpenDataFile(args.input)
# Any point array is mirrored along: here the height of each vertex.
height = Calculator(Input=mesh, ResultArrayName="Height", Function="coordsY")
symmetry = DetectSymmetry(Input=height, Resolution=args.resolution)  # noqa: F821 (from the plugin)
symmetry.UpdatePipeline()
result = servermanager.Fetch(symmetry)
fields = result.GetFieldData()
distance = fields.GetArray("SymmetryDistance").GetValue(0)
normal = [fields.GetArray("MirrorPlaneNormal").GetComponent(0, k) for k in range(3)]
candidates = fields.GetArray("CandidateSymmetryDistances")
print(f"symmetry distance {distance:.4f} (0: symmetric, 0.71: no better than unrelated)")
print("mirror plane normal on the sphere", [round(x, 4) for x in normal],
      f"twist {fields.GetArray('MirrorPlaneTwist').GetValue(0):.4f} rad")
print("candidate distances", [round(candidates.GetValue(c), 4) for c in range(candidates.GetNumberOfTuples())])
print(f"mean asymmetry {fields.GetArray('MeanAsymmetry').GetValue(0):.4f} of sqrt(area)")
heights = result.GetPointData().GetArray("Height")
mirrored = result.GetPointData().GetArray("Height_Target")
worst = max(abs(heights.GetValue(i) - mirrored.GetValue(i)) for i in range(result.GetNumberOfPoints()))
print(f"largest height difference between a vertex and its mirror image: {worst:.4f}")

SaveData(os.path.join(args.output, "symmetry.vtp"), proxy=symmetry, DataMode="Binary")
view = CreateView("RenderView")
display = Show(symmetry, view)
ColorBy(display, ("POINTS", "Asymmetry"))
display.SetScalarBarVisibility(view, True)
lut = GetColorTransferFunction("Asymmetry")
lut.ApplyPreset("Inferno (matplotlib)", True)
lut.RescaleTransferFunction(0.0, max(1e-6, result.GetPointData().GetArray("Asymmetry").GetRange()[1]))
view.OrientationAxesVisibility = 0
bounds = result.GetBounds()
center = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
view.CameraFocalPoint = center
view.CameraPosition = [center[0] + 1.2, center[1] + 0.8, center[2] + 2.0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
SaveScreenshot(os.path.join(args.output, "symmetry.png"), view, ImageResolution=[800, 500])
print("wrote", os.path.join(args.output, "symmetry.vtp"), "and symmetry.png")
if distance > args.max_distance:
    raise SystemExit(f"symmetry distance {distance} above --max-distance {args.max_distance}")
