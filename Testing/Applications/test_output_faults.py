"""mobius-register's outputs are complete or absent, whatever goes wrong while it writes them:

- write failures at many byte offsets of OUT.csv and OUT.vtp (a file size limit, `ulimit -f`,
  with SIGXFSZ ignored: the writes fail with EFBIG as on a full disk): exit status 1, one line
  naming the file, no OUT.* and no temporary left; above the limit, outputs identical to an
  unlimited run's;
- the same limit with SIGXFSZ's default action, and SIGINT, SIGTERM, SIGHUP sent while the
  temporary files exist: the program dies by the signal and leaves nothing;
- symbolic links planted at every temporary name the former scheme would use: never followed;
  a link at OUT.csv is never replaced;
- concurrent runs on one OUT without --force: exactly one wins, the others fail and leave
  the winner's files intact; a file the user creates at OUT.csv during a run stays;
- a standard output that cannot be written (/dev/full): exit status 1.

Usage: test_output_faults.py MOBIUS_REGISTER WORK_FOLDER"""
import os
import resource
import shutil
import signal
import subprocess
import sys

import mesh_files
from cli_harness import Harness

program, work = os.path.abspath(sys.argv[1]), sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
harness = Harness(program, work)
check = harness.check
FAST = ["--resolution", "32", "--refine", "none", "--quiet"]


def write_mesh(name, mesh):
    with open(os.path.join(work, name), "wb") as f:
        f.write(mesh_files.off_bytes(*mesh))
    return name


def start(arguments, file_limit=None, ignore_xfsz=True, stdout=subprocess.PIPE):
    """mobius-register started in the work folder; `file_limit` in bytes (RLIMIT_FSIZE)."""
    def limits():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN if ignore_xfsz else signal.SIG_DFL)
        if file_limit is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (file_limit, file_limit))
    return subprocess.Popen([program, *arguments], cwd=work, stdout=stdout, stderr=subprocess.PIPE,
                            text=True, errors="replace", preexec_fn=limits)


def run(arguments, **options):
    process = start(arguments, **options)
    out, err = process.communicate(timeout=600)
    return process.returncode, out, err


def read(name):
    with open(os.path.join(work, name), "rb") as f:
        return f.read()


def temporaries():
    return [f for f in os.listdir(work) if ".partial-" in f]


def check_nothing_left(label, output):
    left = harness.leftovers(output + ".")
    check(not left and not temporaries(), f"{label}: left {left + temporaries()}")


small = write_mesh("small.off", mesh_files.lumpy_sphere(3))      # 642 vertices: fast runs
large = write_mesh("large.off", mesh_files.lumpy_sphere(5))      # 10,242: a run of seconds
code, _, err = run([small, small, "-o", "reference", *FAST])
check(code == 0, f"reference run: {code} {err!r}")
reference = {ext: read("reference." + ext) for ext in ("csv", "vtp")}
size = {ext: len(data) for ext, data in reference.items()}
print("output sizes", size)

# --- Write failures at many byte offsets: all or nothing. --------------------------------
# The CSV is written first, so a limit below its size fails the CSV (its last write
# included), and a limit between the two sizes fails the VTP after a complete CSV.
largest = max(size.values())
limits = {0, 1, 4095, 4096, 4097}
limits |= {size[ext] + d for ext in size for d in (-1, 0, 1)}
limits |= {largest * k // 24 for k in range(25)}
for limit in sorted(limits):
    output = f"limit{limit}"
    arguments = [small, small, "-o", output, *FAST]
    code, _, err = run(arguments, file_limit=limit)
    if limit >= largest:
        check(code == 0 and err == "", f"limit {limit}: {code} {err!r}")
        for ext in ("csv", "vtp"):
            path = f"{output}.{ext}"
            check(os.path.exists(os.path.join(work, path)) and read(path) == reference[ext],
                  f"limit {limit}: {path} differs from the reference run's")
    else:
        failing = "csv" if limit < size["csv"] else "vtp"
        harness.check_one_line_error(arguments, code, err,
                                     [f"{output}.{failing}", "cannot write", "File too large"], [])
        check_nothing_left(f"limit {limit}", output)

# SIGXFSZ not ignored: the program dies by it, and its temporaries go with it.
for limit in sorted({size["csv"] // 2, (size["csv"] + size["vtp"]) // 2}):
    output = f"killed{limit}"
    code, _, err = run([small, small, "-o", output, *FAST], file_limit=limit, ignore_xfsz=False)
    check(code == -signal.SIGXFSZ, f"SIGXFSZ at {limit}: exit {code} {err!r}")
    check_nothing_left(f"SIGXFSZ at {limit}", output)


# --- SIGINT, SIGTERM, SIGHUP while the temporary files exist. ---------------------------
def signal_while_writing(sig, output):
    """Sends `sig` as soon as a temporary file appears; whether it came in time, and the
    exit code."""
    process = start([large, large, "-o", output, *FAST])
    landed = False
    while process.poll() is None:
        if temporaries():
            process.send_signal(sig)
            landed = True
            break
    process.communicate(timeout=600)
    return landed, process.returncode


for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
    killed_while_writing = 0
    for attempt in range(5):
        output = f"signal{sig}-{attempt}"
        landed, code = signal_while_writing(sig, output)
        complete = all(os.path.exists(os.path.join(work, f"{output}.{e}")) for e in ("csv", "vtp"))
        # Complete outputs (the signal came during the final renames, which it waits for)
        # or none at all.
        check(complete or not harness.leftovers(output + "."),
              f"{sig.name}: partial outputs {harness.leftovers(output + '.')}")
        check(not temporaries(), f"{sig.name}: temporaries left {temporaries()}")
        check(code in (0, -sig), f"{sig.name}: exit code {code}")
        if landed and code == -sig and not complete:
            killed_while_writing += 1
            print(f"{sig.name} arrived while writing at attempt {attempt + 1}")
            break
    check(killed_while_writing > 0, f"{sig.name} never arrived while the outputs were written")

# --- Symbolic links planted at the names of the former temporaries (OUT.csv.partial-PID):
# a run must neither follow them nor move them into place.
with open(os.path.join(work, "victim"), "w") as f:
    f.write("precious")
with open("/proc/sys/kernel/ns_last_pid") as f:
    next_pid = int(f.read()) + 1
planted = [f"planted.{ext}.{kind}-{pid}" for ext in ("csv", "vtp") for kind in ("partial", "previous")
           for pid in range(next_pid, next_pid + 200)]
for name in planted:
    os.symlink("victim", os.path.join(work, name))
code, _, err = run([small, small, "-o", "planted", *FAST])
check(code == 0 and read("planted.csv") == reference["csv"], f"planted links: {code} {err!r}")
check(read("victim") == b"precious", "planted links: the file they point to was written")
check(all(os.path.islink(os.path.join(work, name)) for name in planted),
      "planted links: a link was replaced or removed")
for name in planted:
    if os.path.lexists(os.path.join(work, name)):
        os.remove(os.path.join(work, name))

# A link at OUT.csv, even one to nowhere, is something there: kept without --force, and not
# replaced with it either (only regular files are).
os.symlink("nowhere", os.path.join(work, "linked.csv"))
for options, words in (([], ["exists already"]), (["--force"], ["not a regular file"])):
    arguments = [small, small, "-o", "linked", *FAST, *options]
    code, _, err = run(arguments)
    harness.check_one_line_error(arguments, code, err, ["linked.csv", *words], [])
    check(os.readlink(os.path.join(work, "linked.csv")) == "nowhere" and not temporaries()
          and not os.path.exists(os.path.join(work, "linked.vtp")), f"{options}: the link at OUT.csv")

# --- Concurrent runs on one OUT without --force: exactly one wins. ---------------------
targets = {scale: write_mesh(f"scaled{scale}.off", mesh_files.scaled(mesh_files.lumpy_sphere(3), scale))
           for scale in (1, 2, 3, 4)}
for round in range(3):
    output = f"race{round}"
    processes = {scale: start([small, target, "-o", output, *FAST]) for scale, target in targets.items()}
    results = {scale: (p.wait(timeout=600), p.stderr.read()) for scale, p in processes.items()}
    winners = [scale for scale, (code, _) in results.items() if code == 0]
    check(len(winners) == 1, f"race {round}: {len(winners)} runs succeeded: {results}")
    for scale, (code, err) in results.items():
        if code != 0:
            check(code == 1 and "exists already" in err and len(err.strip().splitlines()) == 1,
                  f"race {round}: a loser's message: {code} {err!r}")
    if len(winners) == 1:
        # The files are the winner's: its target, 1 to 4 times the source's size.
        rows = read(f"{output}.csv").decode().splitlines()[1:]
        mapped_x = [abs(float(row.split(",")[8])) for row in rows]
        check(len(rows) == 642 and abs(max(mapped_x) / max(abs(p[0]) for p in mesh_files.lumpy_sphere(3)[0])
                                       - winners[0]) < 1e-6,
              f"race {round}: OUT.csv is not the winner's (scale {winners[0]})")
        check(not temporaries(), f"race {round}: temporaries left")

# --- A file created at OUT.csv while the program runs is not replaced. -----------------
# Created as soon as the temporary files appear: long after the start-up check, before the
# outputs are moved into place.
process = start([large, large, "-o", "appeared", *FAST])
while process.poll() is None and not temporaries():
    pass
with open(os.path.join(work, "appeared.csv"), "w") as f:
    f.write("the user's")
_, err = process.communicate(timeout=600)
harness.check_one_line_error(["appeared"], process.returncode, err,
                             ["appeared.csv", "exists already", "while the program ran"], [])
check(read("appeared.csv") == b"the user's", "the file that appeared during the run was replaced")
check(not os.path.exists(os.path.join(work, "appeared.vtp")) and not temporaries(),
      "a run refused at the end left files")

# --- A standard output that cannot be written. ------------------------------------------
with open("/dev/full", "w") as full:
    code, _, err = run([small, small, "-o", "full", "--resolution", "32", "--refine", "none", "--json", "--quiet"],
                       stdout=full)
    check(code == 1 and len(err.strip().splitlines()) == 1 and "standard output" in err,
          f"--json to /dev/full: {code} {err!r}")
    code, _, err = run(["--help"], stdout=full)
    check(code == 1 and "standard output" in err, f"--help to /dev/full: {code} {err!r}")
    # Nothing to write is no failure.
    code, _, err = run([small, small, "-o", "quiet", *FAST], stdout=full)
    check(code == 0 and err == "", f"--quiet with /dev/full: {code} {err!r}")

harness.finish()
