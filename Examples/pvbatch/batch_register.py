"""Register a collection of meshes to one template, in parallel over MPI ranks (pvbatch).

Usage:
    mpiexec -n 4 pvbatch --mpi --symmetric batch_register.py \
        --plugin BUILD/lib/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so \
        --template TEMPLATE_MESH --output DIR MESH [MESH ...]

Each rank takes every size-th mesh and registers it to the template with Mobius Registration
(vtkMobiusRegistration: the whole job, as mobius-register runs it; --no-refine keeps the
paper's Möbius-only map) and writes DIR/<mesh>-to-template.vtp (the mesh placed on the
template surface, with TargetCellId, TargetBarycentric, MappedPoints, the template's point
arrays and every stage's field data; two meshes of one file name, which would write one
file, are refused). Rank 0 gathers one summary line per mesh into DIR/summary.csv; a mesh
that cannot be mapped gets its error message there and does not stop the others. Each rank
runs the threaded filters with its share of the cores (--threads, default: max(1, cores / K),
cores the CPUs of its affinity mask, K the ranks of the node sharing them).
"""
import argparse
import csv
import math
import os
import sys

from mpi4py import MPI

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", required=True, help="path of MobiusRegistration.so (the build tree)")
parser.add_argument("--template", required=True, help="the mesh every other one is registered to")
parser.add_argument("--output", default="batch_output", help="folder for the results")
parser.add_argument("--resolution", type=int, default=256, help="SO3 Register resolution")
parser.add_argument("--no-refine", action="store_true",
                    help="keep the Möbius map (Dense Correspondence) instead of refining it")
parser.add_argument("--no-repair", action="store_true",
                    help="refuse a mesh that is no closed genus-0 surface instead of repairing it")
parser.add_argument("--max-failures", type=int, default=0,
                    help="exit with status 1 when more meshes than this fail (default 0)")
parser.add_argument("--threads", type=int, default=0, metavar="N",
                    help="threads per rank, 0 to 1024 (default 0: this rank's share of the cores)")
parser.add_argument("meshes", nargs="+")
args = parser.parse_args()

# The filters' Python package sits beside the plugin: from <libdir>/paraview-5.11/plugins/
# MobiusRegistration/ up to the folder holding python3/dist-packages (lib/, also when the
# libdir is lib/x86_64-linux-gnu). Installed under /usr it is importable anyway.
folder = os.path.dirname(os.path.abspath(args.plugin))
for _ in range(5):
    folder = os.path.dirname(folder)
    candidate = os.path.join(folder, "python3", "dist-packages")
    if os.path.isdir(os.path.join(candidate, "mobiusregistration")):
        sys.path.insert(0, candidate)
        break
from mobiusregistration import FilterMessages, vtkMobiusRegistration, vtkSurfaceMeshReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402

comm = MPI.COMM_WORLD
rank, size = comm.Get_rank(), comm.Get_size()


def registration_for(source_path, watch=lambda algorithm: algorithm):
    """The whole job for one mesh onto the template, with this script's options; `watch`
    is given the readers and the filter (to collect their errors)."""
    registration = watch(vtkMobiusRegistration())
    for port, path in ((0, source_path), (1, args.template)):
        reader = watch(vtkSurfaceMeshReader())
        reader.SetFileName(path)
        registration.SetInputConnection(port, reader.GetOutputPort())
    registration.SetSourceName(source_path)
    registration.SetTargetName(args.template)
    registration.SetResolution(args.resolution)
    registration.SetRefine(not args.no_refine)
    registration.SetRepair(not args.no_repair)
    registration.SetNumberOfThreads(args.threads)
    return registration


# The options, checked before any work by the rules mobius-register follows, in its words.
problem = registration_for(args.template).CheckParameters(vtkMobiusRegistration.COMMAND_LINE_NAMES)
if problem:
    if rank == 0:
        print(f"batch_register: {problem}", file=sys.stderr)
    sys.exit(2)


def share_of_cores():
    """max(1, cores / K): the CPUs of this rank's affinity mask over the ranks of the node
    whose masks overlap it (ranks bound to their own cores keep them all)."""
    cores = os.sched_getaffinity(0)
    node = comm.Split_type(MPI.COMM_TYPE_SHARED)
    sharing = sum(1 for other in node.allgather(sorted(cores)) if cores & set(other))
    node.Free()
    return max(1, len(cores) // sharing)


threads = args.threads or share_of_cores()


# Each mesh's output is named by its file name: two meshes of one name (in two folders)
# would write one file.
named = {}
for path in args.meshes:
    name = os.path.splitext(os.path.basename(path))[0]
    if named.setdefault(name, path) != path:
        if rank == 0:
            print(f"batch_register: {named[name]} and {path} would both write "
                  f"{os.path.join(args.output, name + '-to-template.vtp')}; rename one of the files",
                  file=sys.stderr)
        sys.exit(2)

os.makedirs(args.output, exist_ok=True)
rows = []
for path in args.meshes[rank::size]:
    name = os.path.splitext(os.path.basename(path))[0]
    errors = FilterMessages()
    registration = registration_for(path, errors.watch)
    registration.SetNumberOfThreads(threads)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(registration.GetOutputPort())
    writer.SetDataModeToBinary()  # bookworm's expat cannot read VTK 9.2's appended data back
    output = os.path.join(args.output, f"{name}-to-template.vtp")
    writer.SetFileName(output)
    # A mesh that cannot be mapped (a degenerate conformal map included) is the filter's
    # error, naming the mesh; the writer then has nothing to write.
    if writer.Write() != 1 or errors.messages:
        if os.path.exists(output):
            os.remove(output)
        rows.append([path, "failed", "", "", "; ".join(errors.messages) or "cannot write " + output])
        continue
    field = registration.GetOutput().GetFieldData()
    trace = sum(field.GetArray("Registration.Rotation").GetComponent(0, k) for k in (0, 4, 8))
    angle = math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1) / 2))))
    error = field.GetArray("Registration.RegistrationError").GetValue(0)
    rows.append([path, "ok", f"{error:.6g}", f"{angle:.4f}", output])

all_rows = comm.gather(rows, root=0)
if rank == 0:
    with open(os.path.join(args.output, "summary.csv"), "w", newline="") as f:
        table = csv.writer(f)
        table.writerow(["mesh", "status", "registration_error", "rotation_degrees", "output_or_error"])
        for rank_rows in all_rows:
            table.writerows(rank_rows)
    done = sum(1 for rank_rows in all_rows for row in rank_rows if row[1] == "ok")
    print(f"registered {done} of {len(args.meshes)} meshes to {args.template} on {size} ranks; "
          f"see {os.path.join(args.output, 'summary.csv')}")
failed = comm.bcast(len(args.meshes) - done if rank == 0 else None, root=0)
if failed > args.max_failures:
    if rank == 0:
        print(f"{failed} meshes failed, more than --max-failures {args.max_failures}", file=sys.stderr)
    sys.exit(1)
