"""pvpython: the filters by their menu names on a real mesh (CGAL's hand, from libcgal-demo):
OFF reader -> Spherical Conformal Map -> Mobius Center -> Spherical Scale Grid, and
SO3 Register of the hand with a copy turned by a known rotation (ParaView's Transform), which
must find that rotation and map every vertex near its turned counterpart; a Landmarks list of
odd length is an error and an empty Target a warning (both gave an empty or partial result
without a word)."""
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin, mesh_dir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())


def field(proxy, name, component=0):
    return servermanager.Fetch(proxy).GetFieldData().GetArray(name).GetComponent(0, component)


mesh = OpenDataFile(os.path.join(mesh_dir, "hand.off"))  # our OFF reader, by extension
assert mesh.GetXMLName() == "OFFMeshReader", mesh.GetXMLName()
spherical = SphericalConformalMap(Input=mesh)
assert spherical.FillHoles == 0 and spherical.TimeStep == 0.4
spherical.UpdatePipeline()
assert field(spherical, "FlippedTriangles") == 0
assert 1.0 <= field(spherical, "MeanQuasiConformalDistortion") < 1.3

centered = MobiusCenter(Input=spherical)
assert field(centered, "CenterOfMassNorm") <= 1e-10

grid = SphericalScaleGrid(Input=centered, Resolution=32)
grid_data = servermanager.Fetch(grid)
assert grid_data.GetNumberOfCells() == 32 * 32
total = field(grid, "TotalArea")
areas = servermanager.Fetch(centered).GetCellData().GetArray("SurfaceArea")
surface_area = sum(areas.GetValue(i) for i in range(areas.GetNumberOfTuples()))
assert abs(total - surface_area) <= 1e-9 * surface_area, (total, surface_area)

# The copy, turned by 90 degrees about z: x' = (-y, x, z).
turned = Transform(Input=mesh)
turned.Transform = "Transform"
turned.Transform.Rotate = [0.0, 0.0, 90.0]
expected = [0, -1, 0, 1, 0, 0, 0, 0, 1]
turned_centered = MobiusCenter(Input=SphericalConformalMap(Input=turned))
registration = SO3Register(Source=centered, Target=turned_centered, Resolution=64)
rotation = [field(registration, "Rotation", k) for k in range(9)]
# The angle of expected^T rotation: 0 when the registration found the turn.
relative_trace = sum(expected[3 * i + k] * rotation[3 * i + k] for i in range(3) for k in range(3))
angle = math.degrees(math.acos(max(-1.0, min(1.0, (relative_trace - 1) / 2))))
print(f"pipeline on hand.off: the 90 degree turn found to within {angle:.4f} deg, "
      f"error {field(registration, 'RegistrationError'):.2e}")
assert field(registration, "Determinant") == 1
assert angle < 1.0, (angle, rotation)

# Every source vertex lands near its turned counterpart (the same vertex of the copy).
correspondence = DenseCorrespondence(Source=registration, Target=turned_centered)
result = servermanager.Fetch(correspondence)
truth = servermanager.Fetch(turned)
mapped = result.GetPointData().GetArray("MappedPoints")
ids = result.GetPointData().GetArray("InputPointId")
bounds = truth.GetBounds()
diagonal = math.dist(bounds[0::2], bounds[1::2])
errors = [math.dist(mapped.GetTuple3(k), truth.GetPoint(int(ids.GetTuple1(k))))
          for k in range(result.GetNumberOfPoints())]
mean_error = sum(errors) / len(errors) / diagonal
print(f"mean distance to the true counterpart: {100 * mean_error:.3f}% of the diagonal")
assert len(errors) == truth.GetNumberOfPoints(), (len(errors), truth.GetNumberOfPoints())
assert mean_error < 0.005, mean_error

# Mobius Registration, the whole job in one filter: the same map as the chain above, bit for
# bit, with the alignment's figures under "Registration.".
whole = MobiusRegistration(Source=mesh, Target=turned, Resolution=64, Refine=0)  # noqa: F821
whole_result = servermanager.Fetch(whole)
whole_mapped = whole_result.GetPointData().GetArray("MappedPoints")
assert whole_result.GetNumberOfPoints() == result.GetNumberOfPoints()
assert all(whole_mapped.GetTuple3(k) == mapped.GetTuple3(k) for k in range(result.GetNumberOfPoints()))
assert [field(whole, "Registration.Rotation", k) for k in range(9)] == rotation
print("Mobius Registration: the chain's map, bit for bit")

# The stage filters take landmarks by the same property (point ids of their input maps): SO3
# Register orders its candidates by the landmarks' sphere angles, Dense Correspondence and
# Refine Correspondence put each source landmark exactly on its target point.
pairs = [(0, 0), (400, 400), (900, 900)]
flat = [i for pair in pairs for i in pair]
guided = SO3Register(Source=centered, Target=turned_centered, Resolution=64, Landmarks=flat)
guided_data = servermanager.Fetch(guided).GetFieldData()
angles = guided_data.GetArray("CandidateLandmarkAngles")
assert angles is not None and angles.GetNumberOfTuples() >= 1, "no CandidateLandmarkAngles"
assert all(angles.GetValue(0) <= angles.GetValue(k) for k in range(angles.GetNumberOfTuples()))
for stage in (DenseCorrespondence(Source=guided, Target=turned_centered, Landmarks=flat),
              RefineCorrespondence(Source=guided, Target=turned_centered, Landmarks=flat)):  # noqa: F821
    data = servermanager.Fetch(stage)
    stage_mapped = data.GetPointData().GetArray("MappedPoints")
    stage_ids = data.GetPointData().GetArray("InputPointId")
    rows = {int(stage_ids.GetTuple1(k)): k for k in range(data.GetNumberOfPoints())}
    for source_id, target_id in pairs:
        gap = math.dist(stage_mapped.GetTuple3(rows[source_id]), truth.GetPoint(target_id))
        assert gap <= 1e-9 * diagonal, (stage.GetXMLName(), source_id, gap)
print("landmarks on SO3 Register, Dense Correspondence and Refine Correspondence: respected")


def messages(proxy):
    """The errors and warnings the proxy's VTK filter reports from now on (builtin session)."""
    caught = {"ErrorEvent": [], "WarningEvent": []}
    for event in caught:
        def record(obj, name, text=None, event=event):
            caught[event].append(str(text))
        record.CallDataType = "string0"
        proxy.GetClientSideObject().AddObserver(event, record)
    return caught


# An odd number of landmark values: an error naming it (the last value was dropped silently
# by ParaView's pairs of two), not a registration with one landmark fewer.
odd = MobiusRegistration(Source=mesh, Target=turned, Resolution=64, Refine=0,  # noqa: F821
                         Landmarks=[0, 0, 400, 400, 900])
caught = messages(odd)
odd.UpdatePipeline()
assert any("Landmarks holds 5 values, an odd number" in e and "900" in e for e in caught["ErrorEvent"]), caught
assert servermanager.Fetch(odd).GetNumberOfPoints() == 0
odd.Landmarks = flat
odd.UpdatePipeline()
assert servermanager.Fetch(odd).GetFieldData().GetArray("LandmarkCount").GetValue(0) == 3
# An empty Target (a clip that keeps nothing): a warning naming it with the empty output.
nothing = Clip(Input=mesh, ClipType="Plane")  # noqa: F821
nothing.ClipType.Origin = [0.0, 0.0, 1e9]
nothing.ClipType.Normal = [0.0, 0.0, 1.0]
nothing.Invert = 0
empty_target = ExtractSurface(Input=nothing)  # noqa: F821
hollow = MobiusRegistration(Source=mesh, Target=empty_target, Resolution=64, Refine=0)  # noqa: F821
caught = messages(hollow)
hollow.UpdatePipeline()
assert servermanager.Fetch(empty_target).GetNumberOfPoints() == 0
assert any("Target is empty" in w for w in caught["WarningEvent"]), caught
print("an odd Landmarks list: an error; an empty Target: a warning")
