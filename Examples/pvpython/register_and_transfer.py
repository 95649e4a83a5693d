"""Register two meshes and transfer a point array from the target to the source (pvpython).

Usage:
    pvpython register_and_transfer.py --plugin PATH/MobiusRegistration.so \
        --source MESH [--target MESH] [--output DIR] [--max-error PERCENT]

Without --target, the target is a bent, rotated copy of the source made here, and the
script also reports how far each source vertex lands from its true counterpart (and, with
--max-error, exits with status 1 when the mean is above that many percent).
The target gets a point array "Height" (its vertical coordinate before the rotation, or
its z coordinate for a given target); the Mobius Registration filter brings it to the
source's vertices. Writes DIR/correspondence.vtp and DIR/correspondence.png.
"""
import argparse
import math
import os
import sys

from paraview.simple import (  # pvpython's usual namespace
    AssignViewToLayout, ColorBy, CreateLayout, CreateView, LoadPlugin, OpenDataFile,
    ProgrammableFilter, SaveData, SaveScreenshot, Show)
from paraview import servermanager

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", required=True, help="path of MobiusRegistration.so")
parser.add_argument("--source", required=True, help="source mesh (.off .obj .ply .stl .vtp .vtk)")
parser.add_argument("--target", help="target mesh (default: a deformed copy of the source)")
parser.add_argument("--output", default="register_output", help="folder for the results")
parser.add_argument("--resolution", type=int, default=128, help="SO3 Register resolution")
parser.add_argument("--max-error", type=float,
                    help="without --target: fail unless the mean distance to the true counterpart is "
                         "below this percentage of the bounding-box diagonal")
args = parser.parse_args()
os.makedirs(args.output, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

source = OpenDataFile(args.source)
if args.target:
    target = ProgrammableFilter(Input=OpenDataFile(args.target))
    target.Script = """
from vtkmodules.numpy_interface import dataset_adapter as dsa
mesh = dsa.WrapDataObject(self.GetPolyDataInput())
out = self.GetPolyDataOutput()
out.ShallowCopy(mesh.VTKObject)
dsa.WrapDataObject(out).PointData.append(mesh.Points[:, 2].copy(), "Height")
"""
else:
    target = ProgrammableFilter(Input=source)
    target.Script = """
import numpy as np
from vtkmodules.numpy_interface import dataset_adapter as dsa
mesh = dsa.WrapDataObject(self.GetPolyDataInput())
out = self.GetPolyDataOutput()
out.DeepCopy(mesh.VTKObject)
p = np.array(mesh.Points)
bent = np.column_stack([p[:, 0], p[:, 1] + 0.08 * np.sin(3 * p[:, 0]), 1.1 * p[:, 2]])
angle, axis = 2.0, np.array([0.6, 0.48, 0.64])
K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
R = np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K
out.GetPoints().SetData(dsa.numpyTovtkDataArray(bent @ R.T))
dsa.WrapDataObject(out).PointData.append(p[:, 1].copy(), "Height")
"""

# The whole job in one filter: conformal maps, centering, rotational alignment, the Möbius map
# refined spectrally (Refine=0 keeps the paper's map alone). OutputGeometry "Source": the
# source surface, carrying the arrays brought over from the target.
correspondence = MobiusRegistration(Source=source, Target=target, Resolution=args.resolution,  # noqa: F821
                                    OutputGeometry="Source")
correspondence.UpdatePipeline()

result = servermanager.Fetch(correspondence)
field = result.GetFieldData()  # each stage's figures under its name, e.g. "Registration."
print("registration error %.4f, %d candidates; %d source vertices carry the target's Height" % (
    field.GetArray("Registration.RegistrationError").GetValue(0),
    field.GetArray("Registration.CandidateScores").GetNumberOfTuples(),
    result.GetPointData().GetArray("Height").GetNumberOfTuples()))
if not args.target:
    # Vertex i of the deformed copy is the counterpart of vertex i of the source. The map's
    # point k is not source vertex k when a repair renumbered the points: InputPointId says
    # which it is (-1: a point a repair created).
    truth = servermanager.Fetch(target)
    mapped = result.GetPointData().GetArray("MappedPoints")
    source_ids = result.GetPointData().GetArray("InputPointId")
    errors = [math.dist(mapped.GetTuple3(k), truth.GetPoint(int(source_ids.GetTuple1(k))))
              for k in range(result.GetNumberOfPoints()) if source_ids.GetTuple1(k) >= 0]
    bounds = truth.GetBounds()
    diagonal = math.dist(bounds[0::2], bounds[1::2])
    mean_error = 100 * sum(errors) / len(errors) / diagonal if errors else math.inf
    print("mean distance to the true counterpart: %.2f%% of the target's bounding-box diagonal" % mean_error)
    if args.max_error is not None and not mean_error < args.max_error:
        print("error: the mean distance is above --max-error %g%%" % args.max_error, file=sys.stderr)
        sys.exit(1)
# Inline binary: bookworm's expat cannot read VTK 9.2's appended data back.
SaveData(os.path.join(args.output, "correspondence.vtp"), proxy=correspondence, DataMode="Binary")

layout = CreateLayout("transfer")
for proxy in (target, correspondence):
    view = CreateView("RenderView")
    AssignViewToLayout(view=view, layout=layout)
    display = Show(proxy, view)
    ColorBy(display, ("POINTS", "Height"))
    view.OrientationAxesVisibility = 0
    view.ResetCamera()
SaveScreenshot(os.path.join(args.output, "correspondence.png"), layout, ImageResolution=[800, 400])
print("wrote", os.path.join(args.output, "correspondence.vtp"), "and correspondence.png")
