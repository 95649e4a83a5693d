"""mobius-register as a user runs it: the demo, two meshes, --json, and every kind of
failure (hostile files included) with its message, exit code and no partial or overwritten
output."""
import json
import os
import shutil
import subprocess
import sys

program, mesh_dir, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def run(*arguments, env=None, cwd=work):
    result = subprocess.run([program, *arguments], cwd=cwd, env=env, capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED:", message)


# --help and --version
code, out, _ = run("--help")
check(code == 0 and "usage: mobius-register" in out and "default 256" in out, "--help")
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
    check(summary["demo_mean_error_over_sqrt_area"] < 0.1,
          f"demo error {summary['demo_mean_error_over_sqrt_area']}")
    check(summary["source_map"]["flipped_triangles"] == 0, "demo source map has no flips")
    check([s["name"] for s in summary["stages"]][-1] == "dense correspondence", "demo stages")
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


def expect_failure(arguments, words, outputs, env=None, code_expected=1):
    code, _, err = run(*arguments, env=env)
    lines = err.strip().splitlines()
    check(code == code_expected, f"{arguments}: exit code {code}, expected {code_expected}")
    check(len(lines) == 1 and all(w in err for w in words), f"{arguments}: message {err!r} lacks {words}")
    for output in outputs:
        leftovers = [f for f in os.listdir(work) if f.startswith(output)]
        check(not leftovers, f"{arguments}: left {leftovers}")


missing = os.path.join(work, "no-such-mesh.off")
expect_failure([missing, hand, "-o", "out1"], [missing, "cannot open"], ["out1"])
with open(os.path.join(work, "mesh.xyz"), "w") as f:
    f.write("1 2 3\n")
expect_failure(["mesh.xyz", hand, "-o", "out2"], ["mesh.xyz", "unknown mesh format"], ["out2"])
eight = os.path.join(mesh_dir, "eight.off")
expect_failure([eight, hand, "-o", "out3"], [eight, "genus 2"], ["out3"])
expect_failure([hand, hand, "-o", "out4", "--resolution", "33"], ["--resolution"], ["out4"], code_expected=2)
expect_failure([hand, hand, "-o", "out5", "--bogus"], ["unknown option --bogus"], ["out5"], code_expected=2)
shutil.copy(hand, os.path.join(work, "mine.vtp.off"))
code, _, err = run(hand, "mine.vtp.off", "-o", "mine.vtp.off", "--png", "mine.vtp.off", "--force")
check(code == 1 and "is an input mesh" in err, f"output onto an input: {code} {err}")
check(os.path.getsize(os.path.join(work, "mine.vtp.off")) == os.path.getsize(hand), "input kept")
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

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
