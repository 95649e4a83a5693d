"""Center a spherical map with the Mobius Center filter and look at it (pvpython).

Usage:
    pvpython center_map.py --plugin PATH/MobiusRegistration.so [--input MAP.vtp] [--output DIR]

Without --input it makes an off-center spherical map of a bumpy blob: a unit sphere whose
triangles carry (in cell array SurfaceArea) the areas of the blob, moved off center by a
Moebius inversion. It writes DIR/centered.vtp and DIR/centered.png: the map colored by
log area distortion before (left) and after (right) centering.
"""
import argparse
import os
import sys

from paraview.simple import (  # pvpython's usual namespace
    CellSize, ColorBy, CreateView, GetActiveViewOrCreate, GetDisplayProperties, LoadPlugin,
    ProgrammableFilter, PythonCalculator, Render, SaveData, SaveScreenshot, Show, Sphere,
    AssignViewToLayout, CreateLayout, GetColorTransferFunction)
from paraview import servermanager

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", required=True, help="path of MobiusRegistration.so")
parser.add_argument("--input", help="a spherical map (.vtp) with cell array SurfaceArea")
parser.add_argument("--output", default="center_map_output", help="folder for the results")
args = parser.parse_args()
os.makedirs(args.output, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

if args.input:
    from paraview.simple import XMLPolyDataReader
    spherical_map = XMLPolyDataReader(FileName=[args.input])
else:
    sphere = Sphere(Radius=1.0, ThetaResolution=96, PhiResolution=48)
    spherical_map = ProgrammableFilter(Input=sphere)
    spherical_map.Script = """
import numpy as np
from vtkmodules.numpy_interface import dataset_adapter as dsa
mesh = dsa.WrapDataObject(self.GetPolyDataInput())
out = self.GetPolyDataOutput()
out.ShallowCopy(mesh.VTKObject)
x = mesh.Points / np.linalg.norm(mesh.Points, axis=1)[:, None]
# The blob: stretched, with a bulge; SurfaceArea is the area of each triangle on it.
bulge = 1 + 0.8 * np.exp(-4 * np.sum((x - [0.6, 0.6, 0.5]) ** 2, axis=1))
surface = x * [1.7, 1.0, 0.6] * bulge[:, None]
ids = mesh.Polygons.reshape(-1, 4)[:, 1:]
a, b, c = surface[ids[:, 0]], surface[ids[:, 1]], surface[ids[:, 2]]
area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
# Move the map off center by the inversion v -> (1-|c|^2)(v+c)/|v+c|^2 + c.
center = np.array([0.55, 0.2, -0.3])
shifted = x + center
moved = (1 - center @ center) * shifted / np.sum(shifted ** 2, axis=1)[:, None] + center
moved /= np.linalg.norm(moved, axis=1)[:, None]
out.GetPoints().SetData(dsa.numpyTovtkDataArray(moved))
wrapped = dsa.WrapDataObject(out)
wrapped.PointData.append(surface, "SurfacePoints")
wrapped.CellData.append(area, "SurfaceArea")
"""

centered = MobiusCenter(Input=spherical_map)  # noqa: F821 (defined by LoadPlugin)
result = servermanager.Fetch(centered).GetFieldData()
print("|mu| before: %.3g, after: %.3g, inversions: %d" % (
    result.GetArray("InitialCenterOfMassNorm").GetValue(0),
    result.GetArray("CenterOfMassNorm").GetValue(0),
    int(result.GetArray("CenteringIterations").GetValue(0))))
if not result.GetArray("CenterOfMassNorm").GetValue(0) <= 1e-6:
    sys.exit("error: the map is not centered")
# Inline binary data: with Debian bookworm's expat, VTK 9.2 cannot read back many files
# written with the default appended data.
SaveData(os.path.join(args.output, "centered.vtp"), proxy=centered, DataMode="Binary")


def log_area_distortion(source):
    """log((share of surface area) / (share of sphere area)) per triangle."""
    sizes = CellSize(Input=source, ComputeArea=1, ComputeLength=0, ComputeVolume=0, ComputeVertexCount=0)
    return PythonCalculator(Input=sizes, ArrayAssociation="Cell Data", ArrayName="LogAreaDistortion",
                            Expression="log((SurfaceArea / sum(SurfaceArea)) / (Area / sum(Area)))")


layout = CreateLayout("centering")
views = []
for source in (spherical_map, centered):
    view = CreateView("RenderView")
    AssignViewToLayout(view=view, layout=layout)
    display = Show(log_area_distortion(source), view)
    ColorBy(display, ("CELLS", "LogAreaDistortion"))
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [4, 2, 3]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    views.append(view)
lut = GetColorTransferFunction("LogAreaDistortion")
lut.ApplyPreset("Jet", True)
lut.RescaleTransferFunction(-3.0, 3.0)
SaveScreenshot(os.path.join(args.output, "centered.png"), layout, ImageResolution=[800, 400])
print("wrote", os.path.join(args.output, "centered.vtp"), "and centered.png")
