"""Correspondences across a collection of shapes, over MPI ranks, with cached per-shape work.

Usage (K ranks of ParaView's MPI engine, or one process without mpiexec):
    mpiexec -n K pvbatch --mpi --symmetric register_collection.py \
        --plugin BUILD/lib/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so \
        --output RESULTS [--mode all|template|nearest] MESH [MESH ...]
    pvbatch register_collection.py --plugin ... --output RESULTS MESH [MESH ...]

Per shape, once: the conformal map, its Möbius centering, a rotation-invariant descriptor
(the energy of each spherical-harmonic degree of the scale factors, vtkSphericalScaleGrid's
DegreeEnergies) and, for the spectral refinement, the surface's Laplace-Beltrami eigenbasis
(vtkLaplaceBeltramiBasis, stored beside the centered map as a .npy file that every pair the
shape takes part in maps into memory instead of solving the eigenproblem again). They are
cached in RESULTS/cache under the SHA-256 of the mesh file's bytes
and of the parameters, so a rerun, or a run with meshes added, redoes only what is new; pair
results are cached the same way. Every cache entry is written to a temporary file, flushed to
disk and renamed into place, and its record holds the SHA-256 of the files it stands for: an
entry that cannot be read (cut short, emptied, of another kind, or a file that does not match
its record) is computed again, with a warning naming it. Ranks take shapes, then pairs, one at a time from a shared
counter (dynamic balancing: large meshes do not hold the others up); each rank runs the
threaded filters with its share of the cores (their NumberOfThreads): max(1, cores / K), cores
the CPUs this rank may use (its affinity mask) and K the ranks of the node that share them
(all of the node's ranks, unless the launcher bound them to separate cores). The results do
not depend on the thread count, so any number of ranks gives the same tables.

Modes: `all` registers every pair; `template` every mesh to --template; `nearest` only each
shape's --neighbours nearest shapes by descriptor, for collections too large for all pairs.

Outputs in RESULTS:
- shapes.csv: per mesh, its hash, vertices, status and error (a mesh that cannot be read or
  mapped is recorded there and does not stop the others), seconds and rank;
- pairs.csv: per pair, the transform, determinant, correlation score and coefficient,
  registration error, the refined map's orthogonality residual, distance, seconds, rank;
- distances.csv and distances.png: the symmetric matrix of registration distances
  d = sqrt((1 - rho) / 2), rho the correlation coefficient of the aligned scale-factor
  signals (0: identical up to a conformal change; about 0.7: unrelated), rows and columns
  ordered by an average-linkage clustering (blank or black: pair not registered);
- run.json: what was computed and what came from the cache (damaged_cache_entries: the
  entries that could not be read and were computed again), and the threads of each rank
  (threads_per_rank, indexed by rank);
- with --write-maps, maps/SOURCE-to-TARGET.vtp (Dense Correspondence's data contract); two
  pairs whose names give one file name (shapes a-to-b and c, a and b-to-c) are refused
  before any work.

Shapes are named by their file names without the extension; a name taken by an earlier file
gets -2, -3, ... (a name no other file has).

Exit status: 0 when every mesh and pair succeeded (or at most --max-failures failed), 1 when
more failed, 2 for a usage error or an output folder that cannot be written.
"""
import argparse
import csv
import hashlib
import json
import math
import os
import sys
import tempfile
import time

import numpy

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", help="path of MobiusRegistration.so in a build tree (finds the Python package "
                    "beside it; not needed when the package is installed)")
parser.add_argument("--output", required=True, help="results folder (its cache is reused)")
parser.add_argument("--mode", choices=("all", "template", "nearest"), default="all")
parser.add_argument("--template", help="with --mode template: the mesh every other one is registered to")
parser.add_argument("--neighbours", type=int, default=10, help="with --mode nearest: k (default 10)")
parser.add_argument("--resolution", type=int, default=128, help="SO3 Register resolution (default 128)")
parser.add_argument("--refine", choices=("spectral", "none"), default="spectral",
                    help="refine each pair's map (default) or keep the Möbius map")
parser.add_argument("--write-maps", action="store_true", help="also write each pair's dense map")
parser.add_argument("--threads", type=int, default=0,
                    help="threads per rank, 0 to 1024 (default 0: this rank's share of the cores)")
parser.add_argument("--max-failures", type=int, default=0,
                    help="exit with status 1 when more meshes or pairs than this fail (default 0)")
parser.add_argument("meshes", nargs="+")
args = parser.parse_args()

try:
    from mpi4py import MPI
    comm = MPI.COMM_WORLD
except ImportError:  # one process without MPI
    MPI = comm = None
rank = comm.Get_rank() if comm else 0
size = comm.Get_size() if comm else 1


def fail(message):
    if rank == 0:
        print(f"register_collection: {message}", file=sys.stderr)
    sys.exit(2)


if args.mode == "template" and not args.template:
    fail("--mode template needs --template MESH")
if args.neighbours < 1:
    fail("--neighbours must be at least 1")
for path in args.meshes + ([args.template] if args.template else []):
    if not os.path.isfile(path):
        fail(f"{path}: no such file")

if args.plugin:
    # The filters' Python package sits beside the plugin: from <libdir>/paraview-5.11/plugins/
    # MobiusRegistration/ up to the folder holding python3/dist-packages.
    folder = os.path.dirname(os.path.abspath(args.plugin))
    for _ in range(5):
        folder = os.path.dirname(folder)
        candidate = os.path.join(folder, "python3", "dist-packages")
        if os.path.isdir(os.path.join(candidate, "mobiusregistration")):
            sys.path.insert(0, candidate)
            break


def share_of_cores():
    """Threads for this rank: max(1, cores / K), cores the CPUs of its affinity mask and K the
    ranks on this node whose masks overlap it (a launcher that binds each rank to its own
    cores leaves K = 1; unbound ranks all share the node's cores)."""
    cores = os.sched_getaffinity(0)
    sharing = 1
    if comm:
        node = comm.Split_type(MPI.COMM_TYPE_SHARED)
        sharing = sum(1 for other in node.allgather(sorted(cores)) if cores & set(other))
        node.Free()
    return max(1, len(cores) // sharing)


from mobiusregistration import (  # noqa: E402
    FilterMessages, vtkCenteredSphericalMap, vtkLaplaceBeltramiBasis, vtkMobiusRegistration,
    vtkSphericalScaleGrid, vtkSurfaceMeshReader)
from vtkmodules.util import numpy_support  # noqa: E402
from vtkmodules.vtkCommonCore import (  # noqa: E402
    vtkDoubleArray, vtkLookupTable, vtkStringArray, vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter  # noqa: E402

# --resolution and --threads: the rules mobius-register checks, in its words.
rules = vtkMobiusRegistration()
rules.SetResolution(args.resolution)
rules.SetNumberOfThreads(args.threads)
if rules.CheckParameters(vtkMobiusRegistration.COMMAND_LINE_NAMES):
    fail(rules.CheckParameters(vtkMobiusRegistration.COMMAND_LINE_NAMES))

threads = args.threads if args.threads > 0 else share_of_cores()
threads_per_rank = comm.allgather(threads) if comm else [threads]

# What a cached result depends on besides the mesh (bump the version when the computation
# changes so that old caches are not reused).
# The refinement's eigenbasis: its size (the refinement's BasisSize) and the kind of basis
# (vtkLaplaceBeltramiBasis's; the refinement refuses a stored basis of another kind anyway).
BASIS_SIZE = 80
# Version 3: records name the SHA-256 of the files they stand for.
SHAPE_PARAMETERS = {"version": 3, "descriptor_resolution": 64,
                    "basis": {"size": BASIS_SIZE, "kind": "intrinsic Delaunay, lumped mass, v1"}
                    if args.refine == "spectral" else None}
PAIR_PARAMETERS = {"version": 2, "resolution": args.resolution, "refine": args.refine}
DESCRIPTOR_DEGREES = 16


def digest(*parts):
    h = hashlib.sha256()
    for part in parts:
        h.update(part if isinstance(part, bytes) else json.dumps(part, sort_keys=True).encode())
    return h.hexdigest()


def file_digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def warn(message):
    print(f"register_collection: warning: {message}", file=sys.stderr, flush=True)


def sync_folder(folder):
    """Puts a rename in `folder` on disk (the entry, not only the file's bytes)."""
    descriptor = os.open(folder, os.O_RDONLY)
    try:
        os.fsync(descriptor)
    finally:
        os.close(descriptor)


def write_atomically(path, write):
    """Runs write(temporary file name), puts the file on disk (fsync) and renames it to `path`:
    a run killed at any moment leaves the old file or the new one, never a part of one, and a
    failure leaves nothing behind. Returns the SHA-256 of what was written; OSError when it
    cannot be written."""
    folder = os.path.dirname(path) or "."
    try:
        handle, temporary = tempfile.mkstemp(dir=folder, prefix=os.path.basename(path) + ".", suffix=".partial")
    except OSError as error:
        raise OSError(error.errno, error.strerror, folder) from None  # the folder, not a made-up name
    os.close(handle)
    try:
        write(temporary)
        with open(temporary, "rb") as f:
            digest = hashlib.sha256(f.read()).hexdigest()
            os.fsync(f.fileno())
        os.replace(temporary, path)
    except BaseException as error:
        try:
            os.remove(temporary)
        except OSError:
            pass
        if isinstance(error, OSError) and error.filename == temporary:
            raise OSError(error.errno, error.strerror, path) from None
        raise
    sync_folder(folder)
    return digest


def write_json(path, value):
    def write(temporary):
        with open(temporary, "w") as f:
            json.dump(value, f, indent=1)
    return write_atomically(path, write)


def write_polydata(data, path):
    def write(temporary):
        writer = vtkXMLPolyDataWriter()
        messages = FilterMessages()
        messages.watch(writer)
        writer.SetInputData(data)
        writer.SetDataModeToBinary()  # bookworm's expat cannot read VTK 9.2's appended data back
        writer.SetFileName(temporary)
        if writer.Write() != 1 or messages.messages:
            raise OSError(f"{path}: cannot write the file ({'; '.join(messages.messages) or 'VTK writer failed'})")
    return write_atomically(path, write)


def write_array(array, path):
    def write(temporary):
        with open(temporary, "wb") as f:
            numpy.save(f, array)
    return write_atomically(path, write)


def write_table(path, rows):
    def write(temporary):
        with open(temporary, "w", newline="") as f:
            csv.writer(f).writerows(rows)
    return write_atomically(path, write)


def os_error_text(error):
    """An OSError as one line naming the file: "PATH: Permission denied"."""
    if error.filename and error.strerror:
        return f"{error.filename}: {error.strerror}"
    return str(error)


def read_polydata(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


class DamagedEntry(Exception):
    """A cache entry that cannot be used: computed again."""


def load_record(path):
    """The JSON object cached at `path`; None when there is none. DamagedEntry when the file
    is not a whole JSON object."""
    try:
        with open(path) as f:
            record = json.load(f)
    except FileNotFoundError:
        return None
    except (OSError, UnicodeDecodeError, ValueError) as error:
        raise DamagedEntry(f"{path}: not a readable record ({error})") from None
    if not isinstance(record, dict):
        raise DamagedEntry(f"{path}: not a record (a JSON {type(record).__name__})")
    return record


def require(record, path, **kinds):
    """Each named field of `record` of its kind (a type, or a tuple of types); DamagedEntry
    naming the first that is not."""
    for name, kind in kinds.items():
        value = record.get(name)
        if isinstance(value, bool) or not isinstance(value, kind):  # no field is a bool
            raise DamagedEntry(f"{path}: the record's {name!r} is missing or malformed")


def file_digest_or_none(path):
    try:
        return file_digest(path)
    except OSError:
        return None


def require_file(path, digest, what):
    """The file at `path` is the one the record names (its SHA-256); DamagedEntry if not."""
    if not isinstance(digest, str):
        raise DamagedEntry(f"{path}: the record names no {what}")
    found = file_digest_or_none(path)
    if found is None:
        raise DamagedEntry(f"{path}: the {what} is missing")
    if found != digest:
        raise DamagedEntry(f"{path}: the {what} is not the one its record names (damaged or replaced)")


def field_value(data, name, component=0):
    array = data.GetFieldData().GetArray(name)
    return array.GetComponent(0, component) if array else float("nan")


def dynamic_for(count, cost, work):
    """Runs work(i) for i in range(count) over all ranks and returns every result on every
    rank. Tasks go out from a counter on rank 0 that each rank increments atomically (MPI
    one-sided Fetch_and_op), costliest first, so no rank waits on another's long task."""
    order = sorted(range(count), key=lambda i: -cost[i])
    results = {}
    if size == 1:
        for i in order:
            results[i] = work(i)
        return results
    window = MPI.Win.Allocate(8 if rank == 0 else 0, 8, comm=comm)
    if rank == 0:
        numpy.frombuffer(window.tomemory(), dtype="i8")[0] = 0
    comm.Barrier()
    one, taken = numpy.ones(1, dtype="i8"), numpy.zeros(1, dtype="i8")
    while True:
        window.Lock(0)
        window.Fetch_and_op(one, taken, 0, 0, MPI.SUM)
        window.Unlock(0)
        if taken[0] >= count:
            break
        i = order[int(taken[0])]
        results[i] = work(i)
    comm.Barrier()
    window.Free()
    merged = {}
    for part in comm.allgather(results):
        merged.update(part)
    return merged


# --- names and paths -----------------------------------------------------------------------
meshes = list(dict.fromkeys(os.path.abspath(p) for p in args.meshes))
if args.template:
    template_path = os.path.abspath(args.template)
    if template_path not in meshes:
        meshes.insert(0, template_path)


def shape_names(paths):
    """Each file's name without its extension; a name an earlier file took gets -2, -3, ...,
    the first such name no file has (a-1.off keeps its name beside two files a.off)."""
    stems = [os.path.splitext(os.path.basename(path))[0] for path in paths]
    taken, chosen = set(stems), []
    used = set()
    for stem in stems:
        name, k = stem, 2
        while name in used or (name != stem and name in taken):
            name, k = f"{stem}-{k}", k + 1
        used.add(name)
        chosen.append(name)
    return chosen


names = shape_names(meshes)
cache = os.path.join(args.output, "cache")


def prepare_output():
    """Makes the output's folders and checks that files can be written there; the reason
    when they cannot (the run then stops before any work), else ""."""
    try:
        for folder in ("shapes", "pairs"):
            os.makedirs(os.path.join(cache, folder), exist_ok=True)
        if args.write_maps:
            os.makedirs(os.path.join(args.output, "maps"), exist_ok=True)
        handle, probe = tempfile.mkstemp(dir=args.output, prefix=".probe.")
        os.close(handle)
        os.remove(probe)
    except OSError as error:
        return f"--output {args.output}: cannot write the results there ({os_error_text(error)})"
    return ""


problem = prepare_output() if rank == 0 else None
problem = comm.bcast(problem, root=0) if comm else problem
if problem:
    fail(problem)
started = time.perf_counter()


# --- per shape: centered map and descriptor -------------------------------------------------
def shape_key(path):
    """The cache key of the mesh file at `path`, or the reason it cannot be read (an OSError's
    text): such a mesh fails alone."""
    try:
        return digest(file_digest(path).encode(), SHAPE_PARAMETERS), ""
    except OSError as error:
        return None, f"cannot read the file ({error.strerror or error})"


keyed = [shape_key(p) for p in meshes] if rank == 0 else None
keyed = comm.bcast(keyed, root=0) if comm else keyed
keys = [key for key, _ in keyed]


def shape_files(i):
    """The shape's record, centered map and eigenbasis (n x BASIS_SIZE doubles, row-major).
    The basis is not in the map's VTP: VTK's binary XML is base64, and decoding 11 MB of
    eigenfunctions for a 17,000-vertex mesh took longer than computing them (measured),
    while a .npy is mapped into memory."""
    base = os.path.join(cache, "shapes", keys[i])
    return base + ".json", base + ".vtp", base + ".basis.npy"


NUMBER = (int, float)


def cached_shape(i):
    """Shape i's cached record when the entry is whole: the record of a failure, or a success
    whose map (and basis) are the files the record names. None when there is none;
    DamagedEntry when it cannot be used."""
    record_path, map_path, basis_path = shape_files(i)
    record = load_record(record_path)
    if record is None:
        return None
    require(record, record_path, status=str, error=str, vertices=int, energies=list, seconds=NUMBER, rank=int)
    if record["status"] == "failed":
        return record
    if record["status"] != "ok" or not record["energies"] or \
            not all(isinstance(e, NUMBER) for e in record["energies"]):
        raise DamagedEntry(f"{record_path}: the record's status or energies are malformed")
    require(record, record_path, files=dict)
    require_file(map_path, record["files"].get("map"), "centered map")
    if SHAPE_PARAMETERS["basis"]:
        require(record, record_path, basis=dict)
        basis = record["basis"]
        if not (isinstance(basis.get("eigenvalues"), list) and len(basis["eigenvalues"]) == BASIS_SIZE
                and isinstance(basis.get("mesh"), str)):
            raise DamagedEntry(f"{record_path}: the record's basis is malformed")
        require_file(basis_path, record["files"].get("basis"), "eigenbasis")
    return record


def compute_shape(i):
    """Maps shape i and caches it; its record."""
    record_path, map_path, basis_path = shape_files(i)
    begin = time.perf_counter()
    errors = FilterMessages()
    reader = errors.watch(vtkSurfaceMeshReader())
    reader.SetFileName(meshes[i])
    # The first stages of every registration job (a degenerate conformal map is an error,
    # with its reason), then the shape's descriptor.
    center = errors.watch(vtkCenteredSphericalMap())
    center.SetMeshName(os.path.basename(meshes[i]))
    center.SetInputConnection(reader.GetOutputPort())
    grid = errors.watch(vtkSphericalScaleGrid())
    grid.SetInputConnection(center.GetOutputPort())
    grid.SetResolution(SHAPE_PARAMETERS["descriptor_resolution"])
    grid.SetNumberOfThreads(threads)
    grid.Update()
    record = {"status": "failed", "error": "", "vertices": 0, "energies": [], "rank": rank}
    basis_seconds = 0.0
    if errors.messages or center.GetOutput().GetNumberOfPoints() == 0:
        record["error"] = "; ".join(errors.messages) or "no output"
    else:
        energies = grid.GetOutput().GetFieldData().GetArray("DegreeEnergies")
        record.update(status="ok", vertices=center.GetOutput().GetNumberOfPoints(),
                      energies=[energies.GetValue(l) for l in range(min(DESCRIPTOR_DEGREES, energies.GetNumberOfValues()))],
                      files={})
        if SHAPE_PARAMETERS["basis"]:
            basis_begin = time.perf_counter()
            basis = errors.watch(vtkLaplaceBeltramiBasis())
            basis.SetInputConnection(center.GetOutputPort())
            basis.SetBasisSize(BASIS_SIZE)
            basis.Update()
            basis_seconds = time.perf_counter() - basis_begin
            if errors.messages:
                record.update(status="failed", error="; ".join(errors.messages))
            else:
                fields = basis.GetOutput().GetFieldData()
                record["files"]["basis"] = write_array(numpy_support.vtk_to_numpy(
                    basis.GetOutput().GetPointData().GetArray("LaplaceBeltramiBasis")), basis_path)
                eigenvalues = fields.GetArray("LaplaceBeltramiEigenvalues")
                # Python's float repr round-trips: the eigenvalues come back to the last bit.
                record["basis"] = {
                    "eigenvalues": [eigenvalues.GetValue(j) for j in range(eigenvalues.GetNumberOfValues())],
                    "mesh": fields.GetAbstractArray("LaplaceBeltramiBasisMesh").GetValue(0)}
        if record["status"] == "ok":
            record["files"]["map"] = write_polydata(center.GetOutput(), map_path)
    record["seconds"] = time.perf_counter() - begin
    record["basis_seconds"] = basis_seconds
    write_json(record_path, record)
    return record


def cached_or_computed(read_cache, compute, record_path, failure):
    """The record read_cache() finds, else compute()'s; an entry that cannot be used is
    reported and computed again. What cannot be computed or cached becomes failure(reason),
    never an exception: the other shapes and pairs go on."""
    damaged = []
    try:
        record = read_cache()
        if record is not None:
            record["cached"] = True
            return record
    except DamagedEntry as entry:
        warn(f"cache entry {entry}: computing it again")
        damaged.append(record_path)
    begin = time.perf_counter()
    try:
        record = compute()
    except OSError as error:
        record = failure(f"cannot cache the result ({os_error_text(error)})")
        record["seconds"] = time.perf_counter() - begin
    except Exception as error:  # a failure of this shape or pair, not of the run
        record = failure(f"{type(error).__name__}: {error}")
        record["seconds"] = time.perf_counter() - begin
    record["cached"] = False
    record["damaged"] = damaged
    return record


def map_shape(i):
    """Shape i's record, from the cache or computed (and cached); a mesh that cannot be read
    or mapped gives a failed record."""
    def failure(reason):
        return {"status": "failed", "error": reason, "vertices": 0, "energies": [], "rank": rank, "seconds": 0.0}
    if keys[i] is None:
        return dict(failure(keyed[i][1]), cached=False)
    return cached_or_computed(lambda: cached_shape(i), lambda: compute_shape(i), shape_files(i)[0], failure)


sizes = [os.path.getsize(p) for p in meshes]
shapes = dynamic_for(len(meshes), sizes, map_shape)
ok = [i for i in range(len(meshes)) if shapes[i]["status"] == "ok"]


# --- which pairs ---------------------------------------------------------------------------
def descriptor(i):
    """Degree energies over their sum, square-rooted: a unit vector, blind to size, rotation
    and mirroring; the Euclidean distance between two is a Hellinger-type distance."""
    energies = numpy.array(shapes[i]["energies"])
    return numpy.sqrt(energies / energies.sum())


if args.mode == "all":
    pairs = [(ok[a], ok[b]) for a in range(len(ok)) for b in range(a + 1, len(ok))]
elif args.mode == "template":
    template = meshes.index(template_path)
    if template not in ok:
        if rank == 0:
            print(f"{meshes[template]}: {shapes[template]['error']}", file=sys.stderr)
        sys.exit(1)
    pairs = [(i, template) for i in ok if i != template]
else:
    chosen = set()
    for i in ok:
        others = sorted((numpy.linalg.norm(descriptor(i) - descriptor(j)), j) for j in ok if j != i)
        for _, j in others[:args.neighbours]:
            chosen.add((min(i, j), max(i, j)))
    pairs = sorted(chosen)


def map_path_of(pair):
    return os.path.join(args.output, "maps", f"{names[pair[0]]}-to-{names[pair[1]]}.vtp")


def colliding_maps():
    """Two pairs whose maps would be one file (shapes a-to-b and c, a and b-to-c): the
    reason the run stops, else ""."""
    written = {}
    for pair in pairs:
        path = map_path_of(pair)
        if path in written:
            first = written[path]
            return (f"--write-maps: the pairs {names[first[0]]} -> {names[first[1]]} and "
                    f"{names[pair[0]]} -> {names[pair[1]]} would both write {path}; rename one of the files")
        written[path] = pair
    return ""


if args.write_maps and colliding_maps():
    fail(colliding_maps())


def pair_key(pair):
    return digest(keys[pair[0]].encode(), keys[pair[1]].encode(), PAIR_PARAMETERS)


def attach_basis(data, i):
    """Puts shape i's stored eigenbasis on its centered map, as vtkLaplaceBeltramiBasis made
    it (the refinement checks the fingerprint). The functions are mapped copy-on-write from
    the .npy, not read: the page cache serves every pair and rank that uses them."""
    functions = numpy_support.numpy_to_vtk(numpy.load(shape_files(i)[2], mmap_mode="c"))
    functions.SetName("LaplaceBeltramiBasis")
    data.GetPointData().AddArray(functions)
    eigenvalues = vtkDoubleArray()
    eigenvalues.SetName("LaplaceBeltramiEigenvalues")
    for value in shapes[i]["basis"]["eigenvalues"]:
        eigenvalues.InsertNextValue(value)
    mesh = vtkStringArray()
    mesh.SetName("LaplaceBeltramiBasisMesh")
    mesh.InsertNextValue(shapes[i]["basis"]["mesh"])
    data.GetFieldData().AddArray(eigenvalues)
    data.GetFieldData().AddArray(mesh)


PAIR_NUMBERS = ("determinant", "correlation_score", "correlation_coefficient", "registration_error",
                "orthogonality_residual", "distance", "seconds")


def cached_pair(p):
    """Pair p's cached record when the entry is whole (and, with --write-maps, its map is the
    file the record names); None when there is none or the map is missing; DamagedEntry when
    it cannot be used."""
    record_path = os.path.join(cache, "pairs", pair_key(pairs[p]) + ".json")
    record = load_record(record_path)
    if record is None:
        return None
    require(record, record_path, status=str, transform=list, stored_bases=int, rank=int,
            **{name: NUMBER for name in PAIR_NUMBERS})
    if record["status"] != "ok" or len(record["transform"]) != 9 or \
            not all(isinstance(v, NUMBER) for v in record["transform"]):
        raise DamagedEntry(f"{record_path}: the record's status or transform are malformed")
    if args.write_maps:
        map_path = map_path_of(pairs[p])
        if not os.path.lexists(map_path):
            return None  # maps asked for the first time: the pair is computed again
        # The file a pair of other shapes with the same names wrote, or a damaged one, is
        # not this pair's map.
        require_file(map_path, record.get("map"), "map")
    return record


def compute_pair(p):
    """Registers pair p and caches the result; its record."""
    source, target = pairs[p]
    record_path = os.path.join(cache, "pairs", pair_key(pairs[p]) + ".json")
    begin = time.perf_counter()
    errors = FilterMessages()
    source_map = read_polydata(shape_files(source)[1])
    target_map = read_polydata(shape_files(target)[1])
    if args.refine == "spectral":
        attach_basis(source_map, source)
        attach_basis(target_map, target)
    # The whole job from the cached centered maps on: rotational alignment, correspondence
    # and (spectral) its refinement with the stored bases.
    registration = errors.watch(vtkMobiusRegistration())
    registration.InputsAreCenteredMapsOn()
    registration.SetSourceData(source_map)
    registration.SetTargetData(target_map)
    registration.SetSourceName(names[source])
    registration.SetTargetName(names[target])
    registration.SetResolution(args.resolution)
    registration.SetNumberOfThreads(threads)
    registration.SetRefine(args.refine == "spectral")
    registration.SetBasisSize(BASIS_SIZE)  # the stored bases' size: they are used
    registration.Update()
    result = registration.GetOutput()
    record = {"status": "failed", "error": "", "rank": rank}
    if errors.messages or result.GetNumberOfPoints() == 0:
        record["error"] = "; ".join(errors.messages) or "no output"
    else:
        def aligned(name, component=0):
            return field_value(result, "Registration." + name, component)
        rho = aligned("CorrelationCoefficient")
        record.update(
            status="ok",
            transform=[aligned("Rotation", k) for k in range(9)],
            determinant=aligned("Determinant"),
            correlation_score=aligned("CorrelationScore"),
            correlation_coefficient=rho,
            registration_error=aligned("RegistrationError"),
            orthogonality_residual=field_value(result, "RefinementOrthogonalityResidual"),
            stored_bases=int(sum(field_value(result, "RefinementStoredBasisUsed", k) == 1 for k in range(2))),
            distance=math.sqrt(max(0.0, (1.0 - rho) / 2.0)))
        if args.write_maps:
            record["map"] = write_polydata(result, map_path_of(pairs[p]))
    record["seconds"] = time.perf_counter() - begin
    if record["status"] == "ok":
        write_json(record_path, record)
    return record


def register_pair(p):
    """Pair p's record, from the cache or computed (and cached)."""
    return cached_or_computed(lambda: cached_pair(p), lambda: compute_pair(p),
                              os.path.join(cache, "pairs", pair_key(pairs[p]) + ".json"),
                              lambda reason: {"status": "failed", "error": reason, "rank": rank})


vertices = [shapes[i]["vertices"] for i in range(len(meshes))]
results = dynamic_for(len(pairs), [vertices[s] * vertices[t] for s, t in pairs], register_pair)


# --- tables and picture (rank 0) -----------------------------------------------------------
def cluster_order(distances):
    """Leaf order of an average-linkage clustering (unregistered pairs count as the largest
    distance), so that similar shapes sit next to each other in the matrix."""
    d = numpy.where(numpy.isnan(distances), numpy.nanmax(distances) if numpy.isfinite(distances).any() else 1.0,
                    distances)
    clusters = {i: [i] for i in range(len(d))}
    while len(clusters) > 1:
        ids = sorted(clusters)
        best = None
        for a in range(len(ids)):
            for b in range(a + 1, len(ids)):
                link = d[numpy.ix_(clusters[ids[a]], clusters[ids[b]])].mean()
                if best is None or link < best[0]:
                    best = (link, ids[a], ids[b])
        _, a, b = best
        clusters[a] = clusters[a] + clusters.pop(b)
    return next(iter(clusters.values())) if clusters else []


def write_heat_map(distances, labels, path):
    """The distance matrix as a picture, row 0 at the top: with matplotlib (Debian's
    python3-matplotlib) labelled, with a colour bar; without it, plain pixels."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as pyplot
    except ImportError:
        write_heat_map_pixels(distances, path)
        return
    n = len(distances)
    size = 2.0 + 0.32 * n
    figure, axes = pyplot.subplots(figsize=(size + 1.2, size))
    masked = numpy.ma.masked_invalid(numpy.array(distances, dtype=float))
    colormap = matplotlib.colormaps["viridis"].copy()
    colormap.set_bad("black")
    shown = axes.imshow(masked, cmap=colormap, vmin=0.0, vmax=math.sqrt(0.5), interpolation="nearest")
    axes.set_xticks(range(n), labels, rotation=90, fontsize=8)
    axes.set_yticks(range(n), labels, fontsize=8)
    axes.set_title("registration distance (black: not registered)", fontsize=9)
    figure.colorbar(shown, ax=axes, fraction=0.046, pad=0.04, label="d = sqrt((1 - correlation) / 2)")
    figure.tight_layout()
    write_atomically(path, lambda temporary: figure.savefig(temporary, dpi=100, format="png"))
    pyplot.close(figure)


def write_heat_map_pixels(distances, path, cell=24):
    """Each matrix entry as a cell x cell block of pixels: dark blue 0 .. yellow 0.71
    (sqrt(1/2), unrelated signals); black where no pair was registered. Row 0 at the top."""
    n = len(distances)
    table = vtkLookupTable()
    table.SetRange(0.0, math.sqrt(0.5))
    table.SetHueRange(0.67, 0.15)
    table.Build()
    image = vtkImageData()
    image.SetDimensions(n * cell, n * cell, 1)
    colors = vtkUnsignedCharArray()
    colors.SetNumberOfComponents(3)
    colors.SetNumberOfTuples(n * cell * n * cell)
    rgb = [0.0, 0.0, 0.0]
    for y in range(n * cell):
        row = n - 1 - y // cell  # VTK images start at the bottom
        for x in range(n * cell):
            value = distances[row][x // cell]
            if math.isnan(value):
                color = (0, 0, 0)
            else:
                table.GetColor(value, rgb)
                color = tuple(int(255 * c) for c in rgb)
            colors.SetTuple3(y * n * cell + x, *color)
    image.GetPointData().SetScalars(colors)
    def write(temporary):
        writer = vtkPNGWriter()
        writer.SetInputData(image)
        writer.SetFileName(temporary)
        if writer.Write() != 1:
            raise OSError(f"{path}: cannot write the picture")
    write_atomically(path, write)


def write_tables():
    """shapes.csv, pairs.csv, distances.csv and .png, run.json; OSError when one cannot be
    written."""
    rows = [["shape", "file", "sha256_key", "vertices", "status", "error", "seconds", "rank", "cached"]]
    for i, path in enumerate(meshes):
        s = shapes[i]
        rows.append([names[i], path, (keys[i] or "")[:16], s["vertices"], s["status"], s["error"],
                     f"{s['seconds']:.3f}", s["rank"], int(s["cached"])])
    write_table(os.path.join(args.output, "shapes.csv"), rows)
    rows = [["source", "target", "status", "transform", "determinant", "correlation_score",
             "correlation_coefficient", "registration_error", "orthogonality_residual",
             "distance", "error", "seconds", "rank", "cached"]]
    for p in sorted(range(len(pairs)), key=lambda p: (names[pairs[p][0]], names[pairs[p][1]])):
        r, (s, t) = results[p], pairs[p]
        if r["status"] == "ok":
            numbers = [" ".join(f"{v:.6f}" for v in r["transform"]), f"{r['determinant']:.0f}",
                       f"{r['correlation_score']:.6g}", f"{r['correlation_coefficient']:.6f}",
                       f"{r['registration_error']:.6g}", f"{r['orthogonality_residual']:.6g}",
                       f"{r['distance']:.6f}"]
        else:
            numbers = [""] * 7
        rows.append([names[s], names[t], r["status"], *numbers, r["error"], f"{r['seconds']:.3f}",
                     r["rank"], int(r["cached"])])
    write_table(os.path.join(args.output, "pairs.csv"), rows)
    matrix = numpy.full((len(ok), len(ok)), numpy.nan)
    numpy.fill_diagonal(matrix, 0.0)
    where = {shape: k for k, shape in enumerate(ok)}
    for p, (s, t) in enumerate(pairs):
        if results[p]["status"] == "ok":
            matrix[where[s], where[t]] = matrix[where[t], where[s]] = results[p]["distance"]
    order = cluster_order(matrix)
    ordered = matrix[numpy.ix_(order, order)]
    rows = [["shape"] + [names[ok[k]] for k in order]]
    for row, k in enumerate(order):
        rows.append([names[ok[k]]] + ["" if numpy.isnan(v) else f"{v:.6f}" for v in ordered[row]])
    write_table(os.path.join(args.output, "distances.csv"), rows)
    if len(ok) > 0:
        write_heat_map(ordered.tolist(), [names[ok[k]] for k in order], os.path.join(args.output, "distances.png"))
    write_json(os.path.join(args.output, "run.json"), summary)


pair_failures = sum(1 for r in results.values() if r["status"] != "ok")
shape_failures = len(meshes) - len(ok)
tables_written = True
if rank == 0:
    seconds = time.perf_counter() - started
    summary = {
        "ranks": size, "threads_per_rank": threads_per_rank, "seconds": seconds, "mode": args.mode,
        "shapes": len(meshes), "shapes_failed": shape_failures,
        "shapes_computed": sum(1 for s in shapes.values() if not s["cached"]),
        "pairs": len(pairs), "pairs_failed": pair_failures,
        "pairs_computed": sum(1 for r in results.values() if not r["cached"]),
        "shape_seconds": sum(s["seconds"] for s in shapes.values() if not s["cached"]),
        "basis_seconds": sum(s.get("basis_seconds", 0.0) for s in shapes.values() if not s["cached"]),
        "pairs_with_stored_bases": sum(1 for r in results.values() if not r["cached"] and r.get("stored_bases") == 2),
        "pair_seconds": sum(r["seconds"] for r in results.values() if not r["cached"]),
        "damaged_cache_entries": sorted(path for r in [*shapes.values(), *results.values()]
                                        for path in r.get("damaged", [])),
    }
    try:
        write_tables()
    except OSError as error:
        tables_written = False
        print(f"register_collection: cannot write the tables ({os_error_text(error)})", file=sys.stderr)
    print(f"{len(ok)} of {len(meshes)} shapes mapped ({summary['shapes_computed']} computed), "
          f"{len(pairs) - pair_failures} of {len(pairs)} pairs registered ({summary['pairs_computed']} computed) "
          f"on {size} ranks x {'/'.join(map(str, sorted(set(threads_per_rank))))} threads in {seconds:.1f} s; "
          f"see {args.output}")
    for i in range(len(meshes)):
        if shapes[i]["status"] != "ok":
            print(f"{meshes[i]}: {shapes[i]['error']}", file=sys.stderr)
tables_written = comm.bcast(tables_written, root=0) if comm else tables_written
# Every rank waits for rank 0's tables: a rank leaving early with a failure status would make
# mpiexec kill rank 0 while it still writes them.
if comm:
    comm.Barrier()
if not tables_written:
    sys.exit(1)
if shape_failures + pair_failures > args.max_failures:
    if rank == 0:
        print(f"{shape_failures + pair_failures} failures, more than --max-failures {args.max_failures}",
              file=sys.stderr)
    sys.exit(1)
