"""mobius-register as a user runs it: the demo, two meshes, --json, every kind of failure
(hostile files included) with its message, exit code and no partial or overwritten output,
and vertex numbers in the CSV that follow the input files."""
import itertools
import json
import math
import os
import shutil
import struct
import sys

from cli_harness import Harness

program, mesh_dir, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
harness = Harness(program, work)
run, check, expect_failure = harness.run, harness.check, harness.expect_failure

# --help and --version
code, out, _ = run("--help")
check(code == 0 and "usage: mobius-register" in out and "default 256" in out, "--help")
# --help and the parser come from one table: every option listed has its help and is known.
# Four more arguments make each run a usage error (or --help, --version) at once.
for line in (line for line in out.splitlines() if line.startswith("  -")):
    label, _, text = line.strip().partition("  ")
    check(text.strip() != "", f"--help gives no help for {label}")
    for name in (word.rstrip(",") for word in label.split() if word.startswith("-")):
        code, _, err = run(name, "a", "b", "c", "d")
        check(code in (0, 2) and "unknown option" not in err, f"{name}, listed by --help: {code} {err!r}")
code, out, _ = run("--version")
check(code == 0 and out.startswith("mobius-register "), "--version")

# The demo, with the JSON summary.
code, out, err = run("--json")
check(code == 0, f"demo exit code {code}: {err}")
summary = json.loads(out) if code == 0 else {}
for name in ("demo.vtp", "demo.csv", "demo.png"):
    check(os.path.getsize(os.path.join(work, "mobius-demo", name)) > 1000, f"demo output {name}")
if summary:
    rotation = summary["rotation"]
    rows = [rotation[0:3], rotation[3:6], rotation[6:9]]
    orthonormal = all(abs(sum(a * b for a, b in zip(rows[i], rows[j])) - (i == j)) < 1e-9
                      for i in range(3) for j in range(3))
    check(orthonormal and summary["determinant"] == 1, "demo rotation is a rotation")
    # Measured: 0.008 with the refinement (the Möbius map alone: 0.058).
    check(summary["demo_mean_error_over_sqrt_area"] < 0.04,
          f"demo error {summary['demo_mean_error_over_sqrt_area']}")
    check(summary["source_map"]["flipped_triangles"] == 0, "demo source map has no flips")
    # The robust distortion figures: the cow's tail squeezes 0.3% of it (no warning, < 1%).
    source = summary["source_map"]
    check(1 <= source["median_quasi_conformal_distortion"] <= source["p95_quasi_conformal_distortion"]
          <= source["p99_quasi_conformal_distortion"] and 0 <= source["squashed_area_share"] < 0.01
          and 0 < source["smallest_sphere_area_share"] < 1 and source["warning"] is None,
          f"demo source map's robust figures: {source}")
    check([s["name"] for s in summary["stages"]] ==
          ["conformal map (source)", "centering (source)", "conformal map (target)",
           "centering (target)", "rotational alignment", "dense correspondence", "refinement"],
          "demo stages, in order")
    # The two meshes' maps run side by side: the total is the job's wall time, at most the
    # stages' sum and at least the stages that ran alone.
    seconds = [s["seconds"] for s in summary["stages"]]
    check(sum(seconds[4:]) <= summary["total_seconds"] <= sum(seconds) + 0.05,
          f"demo total_seconds {summary['total_seconds']} against the stages {seconds}")
    refinement = summary["refinement"]
    check(refinement is not None and len(refinement["candidates"]) >= 1 and
          0 <= refinement["kept_candidate"] < len(refinement["candidates"]) and
          refinement["basis_size"] == 80, f"demo refinement summary {refinement}")
    # The confidence: what decided, and each candidate's scores; the kept map's stretch is
    # measured, and only when both finalists were finished has a second map one, the kept map
    # then having the lower product of curvature difference and stretch.
    if refinement:
        confidence, candidates = refinement["confidence"], refinement["candidates"]
        kept = candidates[refinement["kept_candidate"]]
        finished = [c for c in candidates if c["map_stretch"] is not None]
        check(confidence["decided_by"] in ("curvature", "curvature and map stretch") and
              kept["map_stretch"] is not None and kept["map_stretch"] >= 0 and
              confidence["map_stretch"] == kept["map_stretch"] and
              confidence["curvature_difference"] == kept["curvature_difference"] and
              all(c["landmark_distance_difference"] == 0 for c in candidates),
              f"demo confidence {confidence} {candidates}")
        if confidence["decided_by"] == "curvature and map stretch":
            other = candidates[confidence["runner_up"]]
            check(len(finished) == 2 and other["map_stretch"] is not None and
                  kept["curvature_difference"] * kept["map_stretch"] <=
                  other["curvature_difference"] * other["map_stretch"],
                  f"demo finished maps {candidates}")
        else:
            check(len(finished) == 1, f"demo: one finished map {candidates}")
with open(os.path.join(work, "mobius-demo", "demo.csv")) as csv:
    header = csv.readline().strip().split(",")
    rows = csv.readlines()
check(header[:2] == ["source_vertex", "target_triangle"] and len(rows) == 2904, "demo CSV")

# Running the demo again keeps the outputs unless --force.
before = os.stat(os.path.join(work, "mobius-demo", "demo.vtp")).st_mtime_ns
code, _, err = run()
check(code == 1 and "exists already" in err and "--force" in err, f"no overwrite: {code} {err}")
check(os.stat(os.path.join(work, "mobius-demo", "demo.vtp")).st_mtime_ns == before, "file kept")
code, _, err = run("--force", "--quiet")
check(code == 0 and err == "", f"--force --quiet: {code} {err}")

# Two meshes given: a mesh against itself.
hand = os.path.join(mesh_dir, "hand.off")
code, out, err = run(hand, hand, "-o", "hand", "--resolution", "64", "--json", "--quiet")
check(code == 0, f"hand against itself: {err}")
if code == 0:
    check(json.loads(out)["registration_error"] < 1e-3, "hand self registration error")
    check(os.path.exists(os.path.join(work, "hand.vtp")) and os.path.exists(os.path.join(work, "hand.csv")),
          "hand outputs")
    limit = os.environ.get("VTK_SMP_MAX_THREADS", "")
    automatic = len(os.sched_getaffinity(0))
    automatic = min(automatic, int(limit)) if limit.isdigit() and int(limit) > 0 else automatic
    check(json.loads(out)["threads"] == automatic, "automatic threads: the affinity's cores")
# --threads: the same map on one thread and on three (the CSV to the last digit).
code, out, err = run(hand, hand, "-o", "hand-3", "--resolution", "64", "--json", "--quiet", "--threads", "3")
check(code == 0 and json.loads(out)["threads"] == 3, f"--threads 3: {code} {err}")
code, out, err = run(hand, hand, "-o", "hand-1", "--resolution", "64", "--json", "--quiet", "--threads", "1")
check(code == 0 and json.loads(out)["threads"] == 1, f"--threads 1: {code} {err}")
if code == 0:
    with open(os.path.join(work, "hand-1.csv")) as one, open(os.path.join(work, "hand-3.csv")) as three:
        check(one.read() == three.read(), "--threads 1 and --threads 3 give the same CSV")


missing = os.path.join(work, "no-such-mesh.off")
expect_failure([missing, hand, "-o", "out1"], [missing, "cannot open"], ["out1"])
with open(os.path.join(work, "mesh.xyz"), "w") as f:
    f.write("1 2 3\n")
expect_failure(["mesh.xyz", hand, "-o", "out2"], ["mesh.xyz", "unknown mesh format"], ["out2"])
eight = os.path.join(mesh_dir, "eight.off")
expect_failure([eight, hand, "-o", "out3", "--no-repair"], [eight, "genus 2"], ["out3"])
expect_failure([hand, hand, "-o", "out4", "--resolution", "33"], ["--resolution"], ["out4"], code_expected=2)
expect_failure([hand, hand, "-o", "out5", "--bogus"], ["unknown option --bogus"], ["out5"], code_expected=2)
shutil.copy(hand, os.path.join(work, "mine.vtp.off"))
code, _, err = run(hand, "mine.vtp.off", "-o", "mine.vtp.off", "--png", "mine.vtp.off", "--force")
check(code == 1 and "is an input mesh" in err, f"output onto an input: {code} {err}")
check(os.path.getsize(os.path.join(work, "mine.vtp.off")) == os.path.getsize(hand), "input kept")
# Options a coarse or unreachable setting (issue: wrong maps with exit 0, a flow that never ends).
expect_failure([hand, hand, "-o", "out7", "--resolution", "6"], ["--resolution", "at least 8"], ["out7"],
               code_expected=2)
expect_failure([hand, hand, "-o", "out8", "--tolerance", "0"], ["--tolerance", "1e-08"], ["out8"], code_expected=2)
code, _, err = run(hand, hand, "-o", "coarse", "--resolution", "16", "--refine", "none")
check(code == 0 and "warning" in err and "Resolution 16" in err and "turned" in err,
      f"--resolution 16 warns that the rotation is coarse: {code} {err!r}")
# "--" ends the options: a mesh whose name starts with a dash.
shutil.copy(hand, os.path.join(work, "-dash.off"))
code, _, err = run("-o", "dashed", "--resolution", "32", "--quiet", "--", "-dash.off", "-dash.off")
check(code == 0 and os.path.exists(os.path.join(work, "dashed.csv")), f"-- ends the options: {code} {err!r}")
# -o naming a folder would write the hidden files sub/.vtp and sub/.csv.
os.makedirs(os.path.join(work, "sub"), exist_ok=True)
expect_failure([hand, hand, "-o", "sub/"], ["sub/", "names a folder", "-o sub/map"], [], code_expected=1)
check(not os.listdir(os.path.join(work, "sub")), "-o sub/ wrote nothing in sub")
# The demo where its folder cannot be made (a file named mobius-demo is in the way).
demo_work = os.path.join(work, "demo-blocked")
os.makedirs(demo_work, exist_ok=True)
open(os.path.join(demo_work, "mobius-demo"), "w").close()
code, _, err = run("--quiet", cwd=demo_work)
check(code == 1 and "mobius-demo" in err and "cannot create" in err and "does not exist" not in err,
      f"demo without its folder: {code} {err!r}")
# A file name that is not UTF-8: --json stays valid JSON.
odd = b"caf\xe9-\xff.off"
shutil.copy(hand, os.path.join(work.encode(), odd))
code, out, err = harness.run(odd.decode("utf-8", "surrogateescape"), hand, "-o", "odd", "--resolution", "32",
                             "--refine", "none", "--json", "--quiet")
try:
    check(code == 0 and "\ufffd" in json.loads(out)["source"], f"--json with a non-UTF-8 name: {code} {out[:200]!r}")
except ValueError as invalid:
    check(False, f"--json with a non-UTF-8 name is not JSON: {invalid}: {out[:200]!r}")
# A file name with a line break: the message stays one line, the name escaped.
with open(os.path.join(work, "two\nlines.off"), "w") as f:
    f.write("x")
code, _, err = run("two\nlines.off", hand, "-o", "newline")
check(code == 1 and len(err.strip().splitlines()) == 1 and "two\\nlines.off" in err and "OFF header" in err,
      f"a file name with a line break: {code} {err!r}")
# VTK's own three lines for an unknown threading backend become one line, none under --quiet.
bogus = dict(os.environ, VTK_SMP_BACKEND_IN_USE="Bogus")
code, _, err = run(hand, hand, "-o", "bogus", "--resolution", "32", "--refine", "none", "--quiet", env=bogus)
check(code == 0 and err == "", f"VTK_SMP_BACKEND_IN_USE=Bogus under --quiet: {code} {err!r}")
code, _, err = run(hand, hand, "-o", "bogus", "--resolution", "32", "--refine", "none", "--force", env=bogus)
warned = [line for line in err.splitlines() if "Bogus" in line]
check(code == 0 and len(warned) == 1 and "Using Sequential instead" not in err,
      f"VTK_SMP_BACKEND_IN_USE=Bogus: {code} {err!r}")

no_display = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
expect_failure([hand, hand, "-o", "out6", "--png", "out6.png", "--resolution", "32"],
               ["out6.png", "X display"], ["out6"], env=no_display)

# Hostile files: each is one line naming the file and the problem, exit status 1, no output
# (and no crash: VTK's readers would write out of bounds on several of them).
tetra_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
ply_header = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
              "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
hostile = {
    "zero.obj": (tetra_v + "f 0 1 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n", ["invalid vertex index '0'"]),
    "far.obj": (tetra_v + "f 1 3 2\nf 1 2 99999\nf 2 3 4\nf 1 4 3\n", ["refers to vertex 99999"]),
    "nan.obj": ("v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n",
                ["vertex 2 (line 3) has a NaN or infinite coordinate"]),
    "far.ply": (ply_header + "3 0 2 1\n3 0 1 1000000\n3 1 2 3\n3 0 3 2\n", ["face 1 refers to vertex 1000000"]),
    "negative.ply": (ply_header + "3 0 2 1\n3 0 1 -5\n3 1 2 3\n3 0 3 2\n", ["face 1 refers to vertex -5"]),
    "past.vtk": ("# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                 "0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 7\n3 0 3 2\n",
                 ["polygon 2 refers to point 7"]),
}
for number, (name, (text, words)) in enumerate(sorted(hostile.items())):
    with open(os.path.join(work, name), "w") as f:
        f.write(text)
    for arguments in ([name, hand], [hand, name]):
        expect_failure([*arguments, "-o", f"hostile{number}"], [name, *words], [f"hostile{number}"])


# Hostile sizes: headers claiming more than the file holds, truncated files. Each must fail
# quickly with one line (VTK's readers would allocate what the header claims, crash on the
# truncated data, or print a warning per missing vertex).
def binary_ply(vertex_count, vertices, faces, byte_order="<"):
    header = ("ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % ("little" if byte_order == "<" else "big", vertex_count, len(faces)))
    data = b"".join(struct.pack(byte_order + "3f", *v) for v in vertices)
    data += b"".join(struct.pack(byte_order + "B3i", 3, *f) for f in faces)
    return header.encode() + data


tetra_points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
tetra_faces = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
whole = binary_ply(4, tetra_points, tetra_faces)
sized = {
    "cut-binary.ply": (whole[:len(whole) - 20], ["face 2", "is missing"]),
    "cut-big-endian.ply": (binary_ply(4, tetra_points, tetra_faces, ">")[:-70], ["vertex 2", "is missing"]),
    "cut-ascii.ply": (ply_header.encode()[:-12], ["the file ends before vertex 2"]),
    "billion.ply": (ply_header.replace("element vertex 4", "element vertex 1000000000").encode(),
                    ["the file ends before vertex 4 of 1000000000"]),
    "billion-binary.ply": (binary_ply(1000000000, tetra_points, tetra_faces), ["vertex 8", "is missing"]),
    "huge.off": (b"OFF\n2000000000 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                 ["claims 2000000000 vertices"]),
    "huge-face.off": (b"OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2000000000 0 1 2\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                      ["face 0 of 4 claims 2000000000 vertices"]),
    "huge.vtk": (b"# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\nPOINTS 2000000000 float\n"
                 b"0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                 ["claims 2000000000 points"]),
    "huge-cells.vtk": (b"# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                       b"0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 2000000000\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                       ["polygons"]),
    "huge.vtp": (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
                 b'<PolyData><Piece NumberOfPoints="2000000000" NumberOfPolys="4">\n'
                 b'<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1'
                 b'</DataArray></Points>\n</Piece></PolyData></VTKFile>\n', ["claims 2000000000 points"]),
    "huge.stl": (b"x" * 80 + struct.pack("<I", 2000000000) + b"".join(
        struct.pack("<12fH", 0, 0, 0, *tetra_points[a], *tetra_points[b], *tetra_points[c], 0)
        for a, b, c in tetra_faces), ["claims 2000000000 triangles"]),
    # Broken XML: the parser inside VTK's reader reports it to nobody; it must not reach the
    # terminal in VTK's log format, next to the program's own line.
    "broken.vtp": (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n<PolyData><Piece Number',
                   ["broken.vtp"]),
}
for number, (name, (data, words)) in enumerate(sorted(sized.items())):
    with open(os.path.join(work, name), "wb") as f:
        f.write(data)
    expect_failure([name, hand, "-o", f"sized{number}"], [name, *words], [f"sized{number}"], timeout=120)
    expect_failure([name, hand, "-o", f"sized{number}", "--quiet"], [name, *words], [f"sized{number}"],
                   timeout=120)

# VTK's own messages (here a warning of the legacy reader, which nobody observes) become the
# program's one-line warnings, each once, and --quiet silences them.
with open(os.path.join(work, "newer.vtk"), "w") as f:
    f.write("# vtk DataFile Version 5.2\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n"
            "POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\nCONNECTIVITY vtktypeint64\n0 2 1 0 1 3 1 2 3 0 3 2\n")
code, _, err = run("newer.vtk", "newer.vtk", "-o", "newer", "--resolution", "16")
warned = [line for line in err.splitlines() if "Reading file version" in line]
check(code == 0 and len(warned) == 1 and warned[0].startswith("mobius-register: warning: VTK: Reading file version")
      and "\x1b" not in err and "Warning: In" not in err, f"VTK's warning as the program's: {code} {err!r}")
code, _, err = run("newer.vtk", "newer.vtk", "-o", "newer", "--resolution", "16", "--quiet", "--force")
check(code == 0 and err == "", f"--quiet silences VTK's warning: {code} {err!r}")

# Not a regular file: a directory says so; a device that never ends must not hang the reader.
os.makedirs(os.path.join(work, "folder.off"), exist_ok=True)
expect_failure(["folder.off", hand, "-o", "notfile1"], ["folder.off", "is a directory"], ["notfile1"])
os.symlink("/dev/zero", os.path.join(work, "zero.off"))
os.symlink("/dev/zero", os.path.join(work, "zero.ply"))
expect_failure(["zero.off", hand, "-o", "notfile2"], ["zero.off", "not a regular file"], ["notfile2"], timeout=60)
expect_failure([hand, "zero.ply", "-o", "notfile3"], ["zero.ply", "not a regular file"], ["notfile3"], timeout=60)
expect_failure(["/dev/zero", hand, "-o", "notfile4"], ["/dev/zero"], ["notfile4"], timeout=60)

# Option values: NaN, infinities and absurd sizes are usage errors naming the option.
for option, value in (("--smoothing", "nan"), ("--smoothing", "inf"), ("--smoothing", "1e308"),
                      ("--tolerance", "nan"), ("--tolerance", "-inf"), ("--resolution", "100000"),
                      ("--threads", "-1"), ("--threads", "1025"), ("--threads", "two")):
    expect_failure([hand, hand, "-o", "option", option, value], [option], ["option"], code_expected=2,
                   timeout=60)
code, _, err = run(hand, hand, "-o", "option", "--resolution", "100000")
check("fits" in err, f"--resolution 100000 says what would fit: {err!r}")
# Running out of memory part way (here a 700 MB address space for --resolution 4096, which the
# machine's memory would allow; it needs about 1.2 GB) is an error of the stage, exit status 1,
# not "terminate called". (--resolution 64 runs in 500 MB.)
# AddressSanitizer reserves terabytes of address space for its shadow memory, so a program
# built with it cannot start under an address-space limit: the sanitizer build skips this.
with open(program, "rb") as binary:
    sanitized = b"AddressSanitizer" in binary.read()
if sanitized:
    print("skipped under AddressSanitizer: out of memory in a 700 MB address space")
else:
    code, _, err = run(hand, hand, "-o", "starved", "--resolution", "4096", "--quiet", memory=700 * 2 ** 20)
    check(code == 1 and len(err.strip().splitlines()) == 1 and "out of memory" in err and "--resolution" in err
          and "terminate" not in err, f"out of memory: {code} {err!r}")
    check(not [f for f in os.listdir(work) if f.startswith("starved")], "out of memory: no output")
# The help files an existing output under status 1, as the program does.
code, out, _ = run("--help")
check("existing file without --force" in " ".join(out.split("Exit status:")[-1].split("2 for")[0].split()),
      "--help: exit status 1 covers existing outputs")

# Hints name the command-line options, not the filters' properties.
open_mesh = "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n"
with open(os.path.join(work, "open.off"), "w") as f:
    f.write(open_mesh)
expect_failure(["open.off", hand, "-o", "hint", "--no-repair"], ["open.off", "--fill-holes"], ["hint"])
code, _, err = run("open.off", hand, "-o", "hint", "--no-repair")
check("FillHoles" not in err, f"hint names a VTK property: {err!r}")

# A failed rename leaves nothing behind: OUT.vtp is a folder, so moving the VTP into place
# fails after OUT.csv (written and moved first) was; OUT.csv must not stay.
os.makedirs(os.path.join(work, "renamed.vtp", "inside"))
code, _, err = run(hand, hand, "-o", "renamed", "--resolution", "32", "--refine", "none", "--force")
check(code == 1 and "renamed.vtp" in err and len(err.strip().splitlines()) == 1,
      f"failed rename: {code} {err!r}")
check(not os.path.exists(os.path.join(work, "renamed.csv")), "failed rename left renamed.csv behind")
check(not [f for f in os.listdir(work) if ".partial-" in f or ".previous-" in f], "temporary files left")
# ...and an existing OUT.csv replaced with --force comes back when the VTP cannot follow.
with open(os.path.join(work, "renamed.csv"), "w") as f:
    f.write("old")
code, _, err = run(hand, hand, "-o", "renamed", "--resolution", "32", "--refine", "none", "--force")
with open(os.path.join(work, "renamed.csv")) as f:
    check(code == 1 and f.read() == "old", "failed rename restores the replaced OUT.csv")
check(not [f for f in os.listdir(work) if ".partial-" in f], "temporary files left after the restore")


# Degenerate maps fail (status 1, one line with the reason) unless --allow-poor-maps.
def write_mesh(name, points, faces):
    with open(os.path.join(work, name), "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


# A closed pentagonal prism: 10 vertices, caps fanned from a corner.
prism_points = [(math.cos(2 * math.pi * k / 5), math.sin(2 * math.pi * k / 5), z) for z in (0, 1) for k in range(5)]
prism_faces = [(0, 2, 1), (0, 3, 2), (0, 4, 3), (5, 6, 7), (5, 7, 8), (5, 8, 9)]
for k in range(5):
    a, b = k, (k + 1) % 5
    prism_faces += [(a, b, b + 5), (a, b + 5, a + 5)]
write_mesh("prism.off", prism_points, prism_faces)


# A 1:1:1000 needle ellipsoid (a UV sphere stretched along z).
def uv_ellipsoid(rings, segments, scale):
    points = [(0, 0, scale[2])]
    for i in range(1, rings):
        theta = math.pi * i / rings
        points += [(scale[0] * math.sin(theta) * math.cos(2 * math.pi * j / segments),
                    scale[1] * math.sin(theta) * math.sin(2 * math.pi * j / segments),
                    scale[2] * math.cos(theta)) for j in range(segments)]
    points.append((0, 0, -scale[2]))
    south = len(points) - 1
    faces = [(0, 1 + j, 1 + (j + 1) % segments) for j in range(segments)]
    for i in range(rings - 2):
        for j in range(segments):
            a, b = 1 + i * segments + j, 1 + i * segments + (j + 1) % segments
            faces += [(a, a + segments, b), (b, a + segments, b + segments)]
    last = 1 + (rings - 2) * segments
    faces += [(last + j, south, last + (j + 1) % segments) for j in range(segments)]
    return points, faces


write_mesh("needle.off", *uv_ellipsoid(40, 40, (1, 1, 1000)))
for name in ("prism.off", "needle.off"):
    expect_failure([name, hand, "-o", "poor"], [name, "degenerate", "--allow-poor-maps"], ["poor"])
    code, out, err = run(name, hand, "-o", "allowed-" + name[:-4], "--allow-poor-maps", "--resolution", "64",
                         "--json")
    check(code == 0 and os.path.exists(os.path.join(work, f"allowed-{name[:-4]}.csv")),
          f"{name} with --allow-poor-maps: {code} {err!r}")
    if code == 0:
        maps = json.loads(out)
        check("squashed" in (maps["source_map"]["degenerate"] or "") and maps["target_map"]["degenerate"] is None,
              f"{name}: the JSON summary names the degenerate map: {maps['source_map']}")

# A tiny valid mesh (an icosahedron, 12 vertices, fewer than twice the refinement's basis):
# the refinement is skipped with a warning, the Möbius map is the result.
golden = (1 + 5 ** 0.5) / 2
ico_points = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0), (0, -1, golden), (0, 1, golden),
              (0, -1, -golden), (0, 1, -golden), (golden, 0, -1), (golden, 0, 1), (-golden, 0, -1), (-golden, 0, 1)]
ico_faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
write_mesh("icosahedron.off", ico_points, ico_faces)
code, out, err = run("icosahedron.off", "icosahedron.off", "-o", "ico", "--resolution", "32", "--json")
check(code == 0 and "refinement skipped" in err, f"icosahedron: {code} {err!r}")
if code == 0:
    summary = json.loads(out)
    check(summary["refinement"] is None, "icosahedron: no refinement in the summary")
    with open(os.path.join(work, "ico.csv")) as f:
        check(len(f.readlines()) == 13, "icosahedron: 12 CSV rows")


# Vertex numbering: the CSV names the vertices by their number in the files, whatever the
# reader and the repairs did to the order.
def read_off(path):
    with open(path) as f:
        lines = [line for line in (raw.split("#")[0].strip() for raw in f) if line]
    n, m = map(int, lines[1].split()[:2])
    points = [line for line in lines[2:2 + n]]
    faces = [list(map(int, line.split()[1:4])) for line in lines[2 + n:2 + n + m]]
    return points, faces


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines(p + "\n" for p in points)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


registrations = itertools.count()


def correspondence(*arguments):
    """Runs a registration; returns (source_vertex, target vertex of the largest weight) pairs."""
    output = f"numbering{next(registrations)}"
    code, _, err = run(*arguments, "-o", output, "--resolution", "64", "--quiet")
    check(code == 0, f"{arguments}: exit code {code}: {err}")
    if code != 0:
        return []
    pairs = []
    with open(os.path.join(work, output + ".csv")) as f:
        f.readline()
        for row in f:
            fields = row.split(",")
            weights = [float(w) for w in fields[5:8]]
            pairs.append((int(fields[0]), int(fields[2 + weights.index(max(weights))])))
    return pairs


def expect_numbering(pairs, expected_source, counterpart, label, fraction=0.98):
    sources = [s for s, _ in pairs]
    check(sorted(sources) == sorted(expected_source), f"{label}: source_vertex is not the file's numbering")
    matched = sum(1 for s, t in pairs if s >= 0 and t == counterpart(s))
    check(matched >= fraction * len(pairs),
          f"{label}: {matched} of {len(pairs)} vertices map to their counterpart")


points, faces = read_off(hand)
n = len(points)
# A mirrored pair: no rotation aligns it, and the program says so (it said nothing, and the
# map came back wrong); the same pair registered by reflections gets no such warning, and the
# same way round by reflections gets the opposite hint. Both hints are --transform both,
# which searches either kind.
mirrored = [" ".join([repr(-float(p.split()[0]))] + p.split()[1:3]) for p in points]
write_off(os.path.join(work, "hand-mirrored.off"), mirrored, [[a, c, b] for a, b, c in faces])
for target, transform, hint in (("hand-mirrored.off", "rotation", "--transform both"),
                                ("hand-mirrored.off", "reflection", None),
                                (hand, "reflection", "--transform both"), (hand, "rotation", None)):
    code, _, err = run(hand, target, "-o", "mirror-check", "--resolution", "64", "--refine", "none",
                       "--transform", transform, "--force")
    hinted = "look mirrored" in err or "same way round" in err
    check(code == 0 and (hint in err if hint else not hinted),
          f"{os.path.basename(target)} by {transform}: expected {hint or 'no hint'}: {code} {err!r}")
# Refined, the mirrored pair by rotations: the refinement's candidates are all wrong, and its
# warning no longer suggests keeping another one (--candidate) as the fix.
code, _, err = run(hand, "hand-mirrored.off", "-o", "mirror-check", "--resolution", "64", "--force")
check(code == 0 and "--transform both" in err and "--candidate" not in err,
      f"mirrored pair refined: the warning should suggest --transform both, not --candidate: {err!r}")
# OBJ with texture coordinates and normals, faces listed backwards with rotated corners, so
# VTK's OBJ reader would number the vertices in an order unrelated to the `v` lines.
with open(os.path.join(work, "hand-vt.obj"), "w") as f:
    f.writelines(f"v {p}\n" for p in points)
    f.writelines(f"vt {i / n} 0.5\nvn 0 0 1\n" for i in range(n))
    f.writelines(f"f {b + 1}/{b + 1}/{b + 1} {c + 1}/{c + 1}/{c + 1} {a + 1}/{a + 1}/{a + 1}\n"
                 for a, b, c in reversed(faces))
expect_numbering(correspondence("hand-vt.obj", hand), range(n), lambda s: s, "OBJ with vt/vn as source")
expect_numbering(correspondence(hand, "hand-vt.obj"), range(n), lambda s: s, "OBJ with vt/vn as target")
# The CSV has a row for every vertex of the file, in its numbering, whatever the repair
# dropped or added. An unused vertex in front: file vertex s + 1 is hand vertex s.
write_off(os.path.join(work, "hand-unused.off"), ["5 5 5"] + points,
          [[a + 1, b + 1, c + 1] for a, b, c in faces])
expect_numbering(correspondence("hand-unused.off", hand), range(n + 1), lambda s: s - 1, "unused vertex")
# A small separate tetrahedron in front: a loose part, dropped (its rows map through the repair).
tetra = ["3 3 3", "3.1 3 3", "3 3.1 3", "3 3 3.1"]
write_off(os.path.join(work, "hand-tetra.off"), tetra + points,
          [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]] + [[a + 4, b + 4, c + 4] for a, b, c in faces])
for options in ((), ("--no-repair", "--keep-largest-component")):
    expect_numbering(correspondence("hand-tetra.off", hand, *options), range(n + 4), lambda s: s - 4,
                     f"loose tetrahedron {' '.join(options)}")
# Two neighbouring faces removed: the four-edge hole is closed, by default or by --fill-holes
# without the other repairs; the target vertices are always the hand's own.
first = set(faces[0])
neighbour = next(k for k in range(1, len(faces)) if len(first & set(faces[k])) == 2)
holed = [face for k, face in enumerate(faces) if k not in (0, neighbour)]
write_off(os.path.join(work, "hand-hole.off"), points, holed)
for options in ((), ("--no-repair", "--fill-holes")):
    expect_numbering(correspondence("hand-hole.off", hand, *options), range(n), lambda s: s,
                     f"hole {' '.join(options)}", fraction=0.95)
    expect_numbering(correspondence(hand, "hand-hole.off", *options), range(n), lambda s: s,
                     f"onto a hole {' '.join(options)}", fraction=0.95)

harness.finish()
