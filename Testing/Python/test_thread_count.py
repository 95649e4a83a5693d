"""NumberOfThreads of the threaded filters: every output array (points, cells, field data)
is the same, bit for bit, on 1 and on 3 threads; NumberOfThreadsUsed reports the count; the
automatic count (0) follows the CPU affinity mask (a child process under `taskset -c CPU`
gets 1) and VTK_SMP_MAX_THREADS; the property is clamped to 0..1024; register(threads=)."""
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource

import mobiusregistration
from mobiusregistration import (vtkCorrespondenceRefinement, vtkDenseCorrespondence, vtkMobiusCenter,
                                vtkSO3Register, vtkSphericalConformalMap, vtkSphericalScaleGrid,
                                vtkSymmetryDetection)

# Timings differ from run to run; NumberOfThreadsUsed differs by design.
NOT_COMPARED = {"RefinementStageSeconds", "NumberOfThreadsUsed"}


def surface(theta, phi, bend):
    """A closed genus-0 surface without symmetry: a bent, pear-shaped sphere."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(theta)
    sphere.SetPhiResolution(phi)
    sphere.Update()
    mesh = sphere.GetOutput()
    p = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    q = np.column_stack([2 * x + 1.2 * y * y, y + bend * x * x, 0.6 * z + 0.3 * x * y])
    mesh.GetPoints().SetData(numpy_to_vtk(q, deep=True))
    return mesh


def centered_map(mesh):
    conformal = vtkSphericalConformalMap()
    conformal.SetInputData(mesh)
    center = vtkMobiusCenter()
    center.SetInputConnection(conformal.GetOutputPort())
    center.Update()
    return center.GetOutput()


def arrays(data):
    """name -> numpy array of every point, cell and field array, and the points."""
    found = {"points": vtk_to_numpy(data.GetPoints().GetData()).copy()}
    for kind, attributes in (("point", data.GetPointData()), ("cell", data.GetCellData()),
                             ("field", data.GetFieldData())):
        for a in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(a)
            if array is not None and array.GetName() not in NOT_COMPARED:
                found[f"{kind}:{array.GetName()}"] = vtk_to_numpy(array).copy()
    return found


def run(make, threads):
    algorithm = make()
    algorithm.SetNumberOfThreads(threads)
    algorithm.Update()
    output = algorithm.GetOutput()
    used = output.GetFieldData().GetArray("NumberOfThreadsUsed")
    assert used is not None and used.GetValue(0) == threads, (type(algorithm).__name__, threads)
    assert output.GetNumberOfPoints() > 0, type(algorithm).__name__
    return arrays(output)


# About 10,000 triangles: the rasterizer splits them into several parts.
source = centered_map(surface(80, 64, 0.3))
target = centered_map(surface(72, 60, -0.2))


def scale_grid():
    grid = vtkSphericalScaleGrid()
    grid.SetInputData(source)
    grid.SetResolution(64)
    return grid


def registration():
    register = vtkSO3Register()
    register.SetSourceData(source)
    register.SetTargetData(target)
    register.SetResolution(64)
    register.SetTransformModeToRotationsAndReflections()
    return register


aligned = registration()
aligned.Update()
aligned = aligned.GetOutput()


def dense():
    correspondence = vtkDenseCorrespondence()
    correspondence.SetSourceData(aligned)
    correspondence.SetTargetData(target)
    return correspondence


def refined():
    refinement = vtkCorrespondenceRefinement()
    refinement.SetSourceData(aligned)
    refinement.SetTargetData(target)
    refinement.SetBasisSize(30)
    return refinement


def symmetry():
    detection = vtkSymmetryDetection()
    detection.SetInputData(source)
    detection.SetResolution(32)
    detection.SetBasisSize(30)
    return detection


for make in (scale_grid, registration, dense, refined, symmetry):
    one, three = run(make, 1), run(make, 3)
    assert one.keys() == three.keys(), (make.__name__, one.keys() ^ three.keys())
    for name in one:
        same = one[name].dtype == three[name].dtype and one[name].tobytes() == three[name].tobytes()
        assert same, f"{make.__name__}: {name} differs between 1 and 3 threads"
    print(f"{make.__name__}: {len(one)} arrays identical on 1 and 3 threads")

# The property: clamped, printed.
grid = vtkSphericalScaleGrid()
for value, expected in ((-2, 0), (0, 0), (5, 5), (5000, 1024)):
    grid.SetNumberOfThreads(value)
    assert grid.GetNumberOfThreads() == expected, (value, grid.GetNumberOfThreads())
assert "NumberOfThreads: 1024" in str(grid)

# The automatic count, in child processes (the affinity mask and the environment are the
# process's): one per CPU of the affinity mask, at most VTK_SMP_MAX_THREADS.
CHILD = """
import sys
from vtkmodules.vtkFiltersSources import vtkSphereSource
from mobiusregistration import vtkSphericalConformalMap, vtkSphericalScaleGrid
sphere = vtkSphereSource()
conformal = vtkSphericalConformalMap()
conformal.SetInputConnection(sphere.GetOutputPort())
grid = vtkSphericalScaleGrid()
grid.SetInputConnection(conformal.GetOutputPort())
grid.SetResolution(16)
grid.SetNumberOfThreads(int(sys.argv[1]))
grid.Update()
print("threads used", int(grid.GetOutput().GetFieldData().GetArray("NumberOfThreadsUsed").GetValue(0)))
"""


# The same interpreter (pvpython's sys.executable names no file: then pvpython itself).
interpreter = sys.executable if os.path.isfile(sys.executable) else shutil.which("pvpython")
child = os.path.join(tempfile.mkdtemp(), "child.py")
with open(child, "w") as f:
    f.write(CHILD)


def threads_used(requested, prefix=(), limit=None):
    environment = dict(os.environ)
    environment.pop("VTK_SMP_MAX_THREADS", None)
    if limit is not None:
        environment["VTK_SMP_MAX_THREADS"] = limit
    done = subprocess.run([*prefix, interpreter, child, str(requested)], env=environment,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return int(done.stdout.split("threads used")[-1])


cpus = sorted(os.sched_getaffinity(0))
assert threads_used(0) == len(cpus), (threads_used(0), cpus)
pinned = ("taskset", "-c", str(cpus[0]))
assert threads_used(0, pinned) == 1
assert threads_used(3, pinned) == 3  # an explicit count is kept
assert threads_used(0, limit="1") == 1
assert threads_used(0, limit="1000") == len(cpus)
assert threads_used(0, limit="junk") == len(cpus)
print(f"automatic count: {len(cpus)} (affinity), 1 under taskset -c {cpus[0]}, 1 with VTK_SMP_MAX_THREADS=1")

# register(threads=): passed to the filters, reported, checked.
small = surface(24, 16, 0.3)
vertices = vtk_to_numpy(small.GetPoints().GetData())
faces = vtk_to_numpy(small.GetPolys().GetConnectivityArray()).reshape(-1, 3)
result = mobiusregistration.register((vertices, faces), (vertices, faces), resolution=32, refine=False, threads=2)
assert result.fields["NumberOfThreadsUsed"] == 2, result.fields["NumberOfThreadsUsed"]
for bad in (-1, 1025, 1.5, "2", True):
    try:
        mobiusregistration.register((vertices, faces), (vertices, faces), threads=bad)
    except ValueError as error:
        assert "threads" in str(error)
    else:
        raise AssertionError(f"threads={bad!r} accepted")
print("register(threads=2): NumberOfThreadsUsed 2; bad counts refused")
