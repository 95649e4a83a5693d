"""Test of register_collection.py: the same pairs, to the last digit, on 2 MPI ranks (one thread
each) as on one process (a thread per core), the threads of each rank in run.json, a failing
mesh recorded without stopping the others, the cache (a rerun computes nothing; pairs refined
again from cached shapes, with their stored eigenbases, come out as in the cold run; a
byte-identical copy is recognized; a new mesh computes only itself and its pairs), the
nearest mode, and what a run meets in the wild: a damaged cache (each entry computed again,
with a warning naming it), an unreadable mesh, an output that cannot be written, a read-only
cache, map names that would collide.

Usage: python3 test_register_collection.py MPIEXEC PVBATCH PLUGIN DRIVER MESH_DIR SCRATCH
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

mpiexec, pvbatch, plugin, driver, mesh_dir, scratch = sys.argv[1:7]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)


def write_twins(hand, path):
    """Two hands side by side in one file: two parts of one size, which no repair maps (which
    one is the user's choice), so the mesh is refused."""
    with open(hand) as f:
        tokens = f.read().split()
    points, faces = int(tokens[1]), int(tokens[2])
    xyz = [float(t) for t in tokens[4:4 + 3 * points]]
    rows, at = [], 4 + 3 * points
    for _ in range(faces):
        rows.append([int(t) for t in tokens[at + 1:at + 1 + int(tokens[at])]])
        at += 1 + int(tokens[at])
    with open(path, "w") as f:
        f.write(f"OFF\n{2 * points} {2 * faces} 0\n")
        for shift in (0.0, 10.0):
            f.writelines(f"{xyz[3 * i] + shift} {xyz[3 * i + 1]} {xyz[3 * i + 2]}\n" for i in range(points))
        for shift in (0, points):
            f.writelines(" ".join(map(str, [len(r)] + [v + shift for v in r])) + "\n" for r in rows)


twins = os.path.join(scratch, "twins.off")
write_twins(os.path.join(mesh_dir, "hand.off"), twins)
meshes = [os.path.join(mesh_dir, name) for name in ("hand.off", "cow.off", "bull.off")] + [twins]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED:", message)


def run(ranks, output, *extra, meshes=meshes, user=None):
    """The driver on `ranks` ranks; `user`: a uid and HOME to run it as (see unprivileged)."""
    command = ([mpiexec, "--oversubscribe", "-n", str(ranks)] if ranks > 1 else []) + [pvbatch]
    command += ["--mpi", "--symmetric"] if ranks > 1 else []
    command += [driver, "--plugin", plugin, "--output", output, "--resolution", "64", *extra, *meshes]
    environment = None
    if user:
        command = ["setpriv", f"--reuid={user[0]}", f"--regid={user[0]}", "--clear-groups"] + command
        environment = dict(os.environ, HOME=user[1])
    done = subprocess.run(command, capture_output=True, text=True, timeout=900, env=environment)
    print(" ".join(command), "->", done.returncode, done.stdout.strip(), done.stderr.strip()[-600:], sep="\n")
    return done


def table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_summary(output):
    with open(os.path.join(output, "run.json")) as f:
        return json.load(f)


NUMBERS = ("determinant", "correlation_score", "correlation_coefficient", "registration_error",
           "orthogonality_residual", "distance")


def same_pairs(a, b):
    """Equal up to row order, apart from timing, rank and cache columns: every number as
    written (the filters give the same bits on any number of threads)."""
    key = lambda row: (row["source"], row["target"])  # noqa: E731
    a, b = sorted(a, key=key), sorted(b, key=key)
    if [key(r) for r in a] != [key(r) for r in b]:
        return False
    for x, y in zip(a, b):
        if x["status"] != y["status"]:
            return False
        if [x[c] for c in NUMBERS + ("transform",)] != [y[c] for c in NUMBERS + ("transform",)]:
            print("differ:", x, y, sep="\n")
            return False
    return True


# 1. Two ranks: twins.off (two hands) fails and is recorded; the three others make 3 pairs.
parallel = os.path.join(scratch, "two-ranks")
done = run(2, parallel)
check(done.returncode == 1, "one failed mesh is more than --max-failures 0: exit status 1")
check("twins.off: Cannot map the mesh to the sphere: 2 connected components" in done.stderr,
      "the failure is named")
shapes = {row["shape"]: row for row in table(os.path.join(parallel, "shapes.csv"))}
check([shapes[n]["status"] for n in ("hand", "cow", "bull", "twins")] == ["ok", "ok", "ok", "failed"],
      "shapes.csv statuses")
check("comparable size" in shapes["twins"]["error"], "shapes.csv keeps the error")
pairs = table(os.path.join(parallel, "pairs.csv"))
check(len(pairs) == 3 and all(r["status"] == "ok" for r in pairs), "three pairs registered")
check(all(r["determinant"] == "1" for r in pairs), "rotations only by default")
check({r["rank"] for r in pairs} <= {"0", "1"}, "ranks recorded")
with open(os.path.join(parallel, "distances.csv"), newline="") as f:
    rows = list(csv.reader(f))
order = rows[0][1:]
check(sorted(order) == ["bull", "cow", "hand"], "the matrix has the three mapped shapes")
matrix = [[float(v) for v in row[1:]] for row in rows[1:]]
for i in range(3):
    check(matrix[i][i] == 0.0, "zero diagonal")
    for j in range(3):
        check(matrix[i][j] == matrix[j][i], "symmetric matrix")
        check(i == j or 0.05 < matrix[i][j] < math.sqrt(0.5), f"distance of different shapes {matrix[i][j]}")
check(os.path.getsize(os.path.join(parallel, "distances.png")) > 100, "heat map written")
# Each rank's share of the cores: max(1, cores / 2) unbound, its own cores when mpiexec binds.
cores = len(os.sched_getaffinity(0))
threads = run_summary(parallel)["threads_per_rank"]
check(len(threads) == 2 and all(1 <= t <= max(1, cores // 2) for t in threads),
      f"two ranks, each with its share of the {cores} cores: {threads}")
summary = run_summary(parallel)
check(summary["pairs_with_stored_bases"] == 3 and summary["basis_seconds"] > 0,
      f"each shape's eigenbasis computed once, in the shape step, and used by its pairs: {summary}")

# 2. One process (pvbatch without MPI): the same pairs.
serial = os.path.join(scratch, "one-process")
run(1, serial, "--max-failures", "1")
check(run_summary(serial)["threads_per_rank"] == [cores], "one process: a thread per core it may use")
check(same_pairs(pairs, table(os.path.join(serial, "pairs.csv"))), "one process and two ranks agree")

# 3. A rerun computes nothing and gives the same table.
done = run(2, parallel, "--max-failures", "1")
summary = run_summary(parallel)
check(done.returncode == 0, "rerun succeeds with --max-failures 1")
check(summary["shapes_computed"] == 0 and summary["pairs_computed"] == 0, f"rerun from the cache: {summary}")
check(same_pairs(pairs, table(os.path.join(parallel, "pairs.csv"))), "cached pairs unchanged")

# 3b. The pairs refined again, from the cached shapes and their stored eigenbases: the table of
#     the cold run, to the last digit.
shutil.rmtree(os.path.join(parallel, "cache", "pairs"))
run(1, parallel, "--max-failures", "1")
summary = run_summary(parallel)
check(summary["shapes_computed"] == 0 and summary["pairs_computed"] == 3 and
      summary["pairs_with_stored_bases"] == 3, f"pairs recomputed from cached shapes: {summary}")
check(same_pairs(pairs, table(os.path.join(parallel, "pairs.csv"))), "cached shapes give the cold run's pairs")

# 4. A byte-identical copy under another name comes from the cache; a turned copy of the hand
#    (new bytes) is computed with its pairs only, and is the hand's nearest shape.
copy = os.path.join(scratch, "hand-copy.off")
shutil.copyfile(meshes[0], copy)
turned = os.path.join(scratch, "hand-turned.off")
with open(meshes[0]) as f:
    lines = [line for line in f.read().split("\n") if line.strip() and not line.startswith("#")]
count = int(lines[1].split()[0])
c, s = math.cos(0.9), math.sin(0.9)
for k in range(2, 2 + count):
    x, y, z = (float(v) for v in lines[k].split()[:3])
    lines[k] = f"{c * x - s * z:.9g} {y:.9g} {s * x + c * z:.9g}"
with open(turned, "w") as f:
    f.write("\n".join(lines) + "\n")
done = run(2, parallel, "--max-failures", "1", "--mode", "nearest", "--neighbours", "1",
           meshes=meshes + [copy, turned])
summary = run_summary(parallel)
check(summary["shapes_computed"] == 1, f"only the turned hand is mapped: {summary}")
pairs = table(os.path.join(parallel, "pairs.csv"))
names = {(r["source"], r["target"]): r for r in pairs}
check(("hand", "hand-turned") in names, f"the turned hand is the hand's nearest shape: {sorted(names)}")
if ("hand", "hand-turned") in names:
    # 0.025 at resolution 64 (the grid samples the turned signal differently); other shapes > 0.3.
    check(float(names[("hand", "hand-turned")]["distance"]) < 0.05, "a turned copy is at distance ~0")
check(len(pairs) <= 5, "nearest mode registers at most one pair per shape")

# Options out of range: mobius-register's rules and words (status 2, nothing computed).
done = run(1, os.path.join(scratch, "refused"), "--resolution", "6")
check(done.returncode == 2 and "--resolution needs an even integer, at least 8, not 6" in done.stderr,
      f"--resolution 6 refused as mobius-register refuses it: {done.returncode} {done.stderr!r}")


# 5. What a run meets in the wild. Every case ends in a result or one clear line, never a
#    Python traceback.
def no_traceback(done, label):
    check("Traceback" not in done.stderr, f"{label}: a traceback: {done.stderr[-800:]!r}")


wild = os.path.join(scratch, "wild")
small = meshes[:2]  # hand and cow: one pair, refined with stored bases
clean = os.path.join(wild, "clean")
done = run(1, clean, "--write-maps", meshes=small)
check(done.returncode == 0, "the clean run for the damage cases")
clean_pairs = table(os.path.join(clean, "pairs.csv"))


def entries(output, folder, suffix):
    return sorted(os.path.join(output, "cache", folder, f) for f in os.listdir(os.path.join(output, "cache", folder))
                  if f.endswith(suffix))


def cut(path, keep=None, text=None):
    """The file cut to `keep` bytes (half when None), or replaced by `text`."""
    if text is not None:
        with open(path, "w") as f:
            f.write(text)
        return
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        f.truncate(size // 2 if keep is None else keep)


# 5a. A damaged cache entry, each kind alone: computed again with a warning naming it, the
#     same table as from a whole cache (it used to end every later run in a traceback:
#     JSONDecodeError, "mmap length is greater than file size"; a damaged centered map made its
#     pairs fail on every rerun).
damages = {
    "shape record cut short": ("shapes", ".json", dict()),
    "shape record emptied": ("shapes", ".json", dict(keep=0)),
    "shape record of another kind": ("shapes", ".json", dict(text="[]")),
    "centered map cut short": ("shapes", ".vtp", dict()),
    "eigenbasis cut short": ("shapes", ".basis.npy", dict()),
    "pair record cut short": ("pairs", ".json", dict()),
    "pair record of another kind": ("pairs", ".json", dict(text="[]")),
    "pair record without its fields": ("pairs", ".json", dict(text='{"status": "ok"}')),
}
for number, (label, (folder, suffix, how)) in enumerate(damages.items()):
    damaged = os.path.join(wild, f"damaged{number}")
    shutil.copytree(clean, damaged)
    entry = entries(damaged, folder, suffix)[0]
    cut(entry, **how)
    done = run(1, damaged, "--write-maps", meshes=small)
    no_traceback(done, label)
    record = os.path.join(os.path.dirname(entry), os.path.basename(entry).split(".")[0] + ".json")
    check(done.returncode == 0 and f"cache entry {entry}" in done.stderr and "computing it again" in done.stderr,
          f"{label}: no warning naming {entry}: {done.returncode} {done.stderr[-600:]!r}")
    if done.returncode == 0:
        named = run_summary(damaged).get("damaged_cache_entries")
        check(named == [record], f"{label}: run.json names {named}, not {record}")
        check(same_pairs(clean_pairs, table(os.path.join(damaged, "pairs.csv"))), f"{label}: other results")
        again = run(1, damaged, "--write-maps", meshes=small)
        check(again.returncode == 0 and "warning" not in again.stderr and
              run_summary(damaged)["pairs_computed"] == 0, f"{label}: the rerun is not wholly cached")
    check(not [f for _, _, files in os.walk(damaged) for f in files if f.endswith(".partial")],
          f"{label}: temporary files left")

# 5b. A map of the same name that another pair wrote (shapes named a-to-b and c, then a and
#     b-to-c, in two runs on one output) is not this pair's map: a rerun computed it again
#     instead of taking it for its own. Within one run the two names are refused.
named = os.path.join(wild, "names")
os.makedirs(named)
for name, mesh in (("a-to-b", 0), ("c", 1), ("a", 1), ("b-to-c", 0)):
    shutil.copyfile(meshes[mesh], os.path.join(named, name + ".off"))
colliding = [os.path.join(named, n + ".off") for n in ("a-to-b", "c", "a", "b-to-c")]
done = run(1, os.path.join(wild, "collide"), "--write-maps", "--refine", "none", meshes=colliding)
no_traceback(done, "colliding map names")
check(done.returncode == 2 and "would both write" in done.stderr and "a-to-b-to-c.vtp" in done.stderr,
      f"colliding map names in one run not refused: {done.returncode} {done.stderr[-400:]!r}")
shared = os.path.join(wild, "shared")
for group in (colliding[:2], colliding[2:], colliding[:2]):
    done = run(1, shared, "--write-maps", "--refine", "none", "--mode", "all", meshes=group)
check(done.returncode == 0 and "maps/a-to-b-to-c.vtp" in done.stderr and "computing it again" in done.stderr
      and run_summary(shared)["pairs_computed"] == 1,
      f"another pair's map taken for this pair's: {done.returncode} {done.stderr[-500:]!r}")

# 5c. Shapes named after their files: a name two files share gets -2 (a third file named
#     hand-2 keeps its own name).
twins = os.path.join(wild, "twins")
for folder in ("one", "two"):
    os.makedirs(os.path.join(twins, folder))
    shutil.copyfile(meshes[0], os.path.join(twins, folder, "hand.off"))
shutil.copyfile(meshes[1], os.path.join(twins, "hand-2.off"))
done = run(1, os.path.join(wild, "twins-out"), "--refine", "none", "--write-maps",
           meshes=[os.path.join(twins, f) for f in ("one/hand.off", "two/hand.off", "hand-2.off")])
shapes = [row["shape"] for row in table(os.path.join(wild, "twins-out", "shapes.csv"))] if done.returncode == 0 else []
check(done.returncode == 0 and shapes == ["hand", "hand-3", "hand-2"], f"names of same-named files: {shapes}")

# batch_register.py names its outputs by the meshes' file names: two files of one name were
# written to one output; they are refused.
batch = subprocess.run([pvbatch, os.path.join(os.path.dirname(driver), "batch_register.py"), "--plugin", plugin,
                        "--template", meshes[1], "--output", os.path.join(wild, "batch"), "--resolution", "64",
                        os.path.join(twins, "one", "hand.off"), os.path.join(twins, "two", "hand.off")],
                       capture_output=True, text=True, timeout=600)
check(batch.returncode == 2 and "would both write" in batch.stderr and "hand-to-template.vtp" in batch.stderr,
      f"batch_register.py with two files of one name: {batch.returncode} {batch.stderr[-400:]!r}")

# 5d. Permissions: an unreadable mesh fails alone (it stopped the whole collection with a
#     traceback), a read-only cache with new work fails that work with a message, an output
#     folder that cannot be written stops the run before any work (status 2). As root,
#     permissions do not hold: those runs are an unprivileged user's (setpriv).
def unprivileged(folder):
    """A uid to run as and a HOME for it; None when this process is not root (permissions
    hold for it); False when it is root and that user cannot read the driver, the plugin or
    the meshes (a clone under root's own 0700 home, as in a fresh chroot): then the checks
    that need permissions to hold are skipped."""
    if os.geteuid() != 0:
        return None
    home = os.path.join(folder, "home")
    os.makedirs(home, exist_ok=True)
    os.chown(home, 65534, 65534)
    needed = [driver, plugin] + small
    readable = subprocess.run(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups",
                               "sh", "-c", 'for f; do test -r "$f" || exit 1; done', "sh", *needed])
    if readable.returncode != 0:
        print("SKIPPED: the permission checks (an unprivileged user cannot read", " or ".join(needed), ")")
        return False
    return 65534, home


def owned_by_user(path, user):
    if user:
        for folder, _, files in os.walk(path):
            for name in [folder] + [os.path.join(folder, f) for f in files]:
                os.chown(name, user[0], user[0])


user = unprivileged(wild)
if user is not False:
    secret = os.path.join(wild, "secret.off")
    shutil.copyfile(meshes[3], secret)
    os.chmod(secret, 0)
    readable = os.path.join(wild, "readable")
    os.makedirs(readable)
    owned_by_user(readable, user)
    done = run(1, readable, "--refine", "none", meshes=small + [secret], user=user)
    no_traceback(done, "unreadable mesh")
    rows = {row["shape"]: row for row in table(os.path.join(readable, "shapes.csv"))} \
        if os.path.exists(os.path.join(readable, "shapes.csv")) else {}
    check(done.returncode == 1 and rows.get("secret", {}).get("error") == "cannot read the file (Permission denied)"
          and rows["hand"]["status"] == rows["cow"]["status"] == "ok" and len(table(os.path.join(readable, "pairs.csv"))) == 1,
          f"an unreadable mesh stops the others: {done.returncode} {done.stderr[-400:]!r} {rows}")

    locked = os.path.join(wild, "locked")
    shutil.copytree(clean, locked)
    owned_by_user(locked, user)
    for folder in ("shapes", "pairs"):
        path = os.path.join(locked, "cache", folder)
        if user:
            os.chown(path, 0, 0)
        os.chmod(path, 0o555)
    done = run(1, locked, "--write-maps", meshes=small + [meshes[2]], user=user)
    no_traceback(done, "read-only cache")
    rows = {row["shape"]: row for row in table(os.path.join(locked, "shapes.csv"))} \
        if os.path.exists(os.path.join(locked, "shapes.csv")) else {}
    check(done.returncode == 1 and "cannot cache the result" in rows.get("bull", {}).get("error", "")
          and os.path.join(locked, "cache", "shapes") + ": Permission denied" in rows["bull"]["error"]
          and rows["hand"]["cached"] == "1", f"a read-only cache with new work: {done.returncode} {done.stderr[-400:]!r}")

a_file = os.path.join(wild, "a-file")
open(a_file, "w").close()
for output, label, as_user in ((a_file, "an output that is a file", None),
                               (os.path.join(a_file, "below"), "an output below a file", None),
                               (wild if user else "/proc/results", "an output that cannot be written", user)):
    done = run(1, output, "--refine", "none", meshes=small, user=as_user)
    no_traceback(done, label)
    lines = done.stderr.strip().splitlines()
    check(done.returncode == 2 and len(lines) == 1 and f"--output {output}: cannot write the results there" in lines[0],
          f"{label}: {done.returncode} {done.stderr[-400:]!r}")

print("PASSED" if not failures else f"{len(failures)} checks failed")
sys.exit(1 if failures else 0)
