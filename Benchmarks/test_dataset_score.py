"""mobius-score --dataset as a researcher runs it, on a benchmark folder built here: CGAL's cow
(exactly mirror-symmetric about z = 0) and a re-triangulated (every third triangle split at its
centroid), rotated and renumbered copy, with .vts samples that follow the known correspondence
and .sym.vts samples that follow the mirror. The registration's map scores near 0 against the
truth and far from 0 against the mirror truth; the same map with the two truths swapped scores
the two figures swapped and is flagged as mirrored; the same map computed by mobius-register
and scored with --maps gives the same figures; pair lists and bad input."""
import csv
import math
import os
import random
import shutil
import subprocess
import sys

register, score, mesh_dir, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED:", message)


def read_off(path):
    words = [w for line in open(path) for w in line.split("#")[0].split()]
    nv, nf = int(words[1]), int(words[2])
    values = words[4:]
    points = [tuple(float(v) for v in values[3 * i:3 * i + 3]) for i in range(nv)]
    rest, faces = values[3 * nv:], []
    for _ in range(nf):
        n = int(rest[0])
        faces.append([int(v) for v in rest[1:1 + n]])
        rest = rest[1 + n:]
    return points, faces


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in points)
        f.writelines(" ".join(str(v) for v in [len(face)] + face) + "\n" for face in faces)


def write_vts(path, vertices):
    with open(path, "w") as f:
        f.writelines(f"{v + 1}\n" for v in vertices)


def nearest(points, q):
    return min(range(len(points)), key=lambda i: sum((a - b) ** 2 for a, b in zip(points[i], q)))


# The cow and its mirror-image vertex for 300 samples.
points, faces = read_off(os.path.join(mesh_dir, "cow.off"))
n = len(points)
rng = random.Random(25)
samples = rng.sample(range(n), 300)
mirror = [nearest(points, (points[s][0], points[s][1], -points[s][2])) for s in samples]
check(sum(1 for s, m in zip(samples, mirror) if s != m) > 250, "the mirror moves most samples")

# The copy: every third triangle split at its centroid (so its vertices are not the cow's),
# rotated about a tilted axis, vertices renumbered by a random permutation.
split_points, split_faces = list(points), []
for t, (a, b, c) in enumerate(faces):
    if t % 3:
        split_faces.append([a, b, c])
        continue
    centroid = tuple(sum(points[v][k] for v in (a, b, c)) / 3 for k in range(3))
    split_points.append(centroid)
    m = len(split_points) - 1
    split_faces += [[a, b, m], [b, c, m], [c, a, m]]
axis = [0.3, 0.8, 0.52]
length = math.sqrt(sum(x * x for x in axis))
ux, uy, uz = (x / length for x in axis)
c, s = math.cos(1.9), math.sin(1.9)
rotation = [[c + ux * ux * (1 - c), ux * uy * (1 - c) - uz * s, ux * uz * (1 - c) + uy * s],
            [uy * ux * (1 - c) + uz * s, c + uy * uy * (1 - c), uy * uz * (1 - c) - ux * s],
            [uz * ux * (1 - c) - uy * s, uz * uy * (1 - c) + ux * s, c + uz * uz * (1 - c)]]
rotated = [tuple(sum(rotation[i][k] * p[k] for k in range(3)) for i in range(3)) for p in split_points]
order = list(range(len(rotated)))
rng.shuffle(order)  # new vertex j is old vertex order[j]
new_index = {old: new for new, old in enumerate(order)}
copy_points = [rotated[old] for old in order]
copy_faces = [[new_index[v] for v in face] for face in split_faces]

data = os.path.join(work, "dataset")
os.makedirs(os.path.join(data, "off"))
os.makedirs(os.path.join(data, "corres"))
write_off(os.path.join(data, "off", "cow.off"), points, faces)
write_off(os.path.join(data, "off", "copy.off"), copy_points, copy_faces)
write_off(os.path.join(data, "off", "swapped.off"), copy_points, copy_faces)
write_vts(os.path.join(data, "corres", "cow.vts"), samples)
write_vts(os.path.join(data, "corres", "cow.sym.vts"), mirror)
write_vts(os.path.join(data, "corres", "copy.vts"), [new_index[v] for v in samples])
write_vts(os.path.join(data, "corres", "copy.sym.vts"), [new_index[v] for v in mirror])
# The deliberately mirrored truth: the copy's two ground truths swapped.
write_vts(os.path.join(data, "corres", "swapped.vts"), [new_index[v] for v in mirror])
write_vts(os.path.join(data, "corres", "swapped.sym.vts"), [new_index[v] for v in samples])
with open(os.path.join(work, "pairs.txt"), "w") as f:
    f.write("# source target\ncow copy\ncow,swapped.off\n")


def run(*arguments):
    result = subprocess.run([score, "--dataset", data, *arguments], cwd=work, capture_output=True,
                            text=True)
    return result.returncode, result.stdout, result.stderr


def rows(path):
    with open(path) as f:
        return {(r["source"], r["target"]): r for r in csv.DictReader(f)}


# The registration at mobius-register's defaults on both pairs.
code, out, err = run("--pairs", "pairs.txt", "--csv", "pipeline.csv", "--quiet")
print(out)
check(code == 0 and err == "", f"pipeline run: exit code {code}: {err}")
table = rows(os.path.join(work, "pipeline.csv")) if code == 0 else {}
direct, swapped = table.get(("cow", "copy")), table.get(("cow", "swapped"))
if direct and swapped:
    e, m = float(direct["error"]), float(direct["mirror_error"])
    print(f"cow -> copy: error {e}, mirror error {m}; {direct['seconds']} s + {direct['score_seconds']} s")
    check(e < 1.0, f"correct map: error {e} (x100) should be near 0")
    check(m > 15.0, f"correct map: mirror error {m} should be large")
    check(direct["mirrored"] == "0" and swapped["mirrored"] == "1", "mirrored flags")
    # The same map against swapped truths: the figures swap, but errors below 20 are
    # measured by shortened paths and mirror errors by edge paths (a few % longer).
    se, sm = float(swapped["error"]), float(swapped["mirror_error"])
    check(swapped["geodesics"] == "shortened" and 0.9 * m < se <= m and e <= sm < 1.2 * e + 0.01,
          f"swapped truths: {se} {sm} against {m} {e}")
    check(float(direct["euclidean_error"]) <= e + 1e-9, "Euclidean <= geodesic")
    check(direct["kept_candidate"] != "" and int(direct["candidates"]) >= 1
          and 0.5 < float(direct["orientation_agreement"]) <= 1, "refinement's candidate figures")
    check(float(direct["score_seconds"]) < 1.0, f"scoring took {direct['score_seconds']} s")
    check(direct["unmapped_samples"] == "0", "every sample mapped")
    check(direct["geodesics"] == "shortened", "a pair below 20: shortened geodesics")
check("| cow | copy |" in out and "| pairs | mean | median | > 10 |" in out
      and "edge paths" in out and "| 2 |" in out and "1 of 2" in out, "the tables")

# The map computed by mobius-register and scored from its CSV: the same figures.
maps = os.path.join(work, "maps")
os.makedirs(maps)
result = subprocess.run([register, os.path.join(data, "off", "cow.off"), os.path.join(data, "off", "copy.off"),
                         "-o", os.path.join(maps, "cow-copy"), "--quiet"], capture_output=True, text=True)
check(result.returncode == 0, f"mobius-register: {result.stderr}")
shutil.copy(os.path.join(maps, "cow-copy.csv"), os.path.join(maps, "cow-swapped.csv"))
code, out, err = run("--pairs", "pairs.txt", "--maps", maps, "--csv", "maps.csv")
check(code == 0, f"--maps: exit code {code}: {err}")
if code == 0 and direct:
    again = rows(os.path.join(work, "maps.csv"))[("cow", "copy")]
    check(again["error"] == direct["error"] and again["mirror_error"] == direct["mirror_error"],
          f"--maps scores {again['error']}, the pipeline run {direct['error']}")

# Options pass through to the pipeline: the Moebius map alone has no refinement figures and
# is less precise.
code, out, err = run("--pairs", "pairs.txt", "--refine", "none", "--csv", "mobius.csv", "--quiet")
check(code == 0, f"--refine none: exit code {code}: {err}")
if code == 0 and direct:
    mobius = rows(os.path.join(work, "mobius.csv"))[("cow", "copy")]
    print(f"--refine none: error {mobius['error']}")
    check(mobius["kept_candidate"] == "" and float(mobius["error"]) > float(direct["error"]),
          "--refine none reaches the pipeline")

# Generated pair lists (scored from maps: every pair needs its CSV). The copy onto its
# identical twin by the identity map: exactly 0 against the twin's (swapped) mirror truth.
star = {}
for t, face in enumerate(copy_faces):
    for k, v in enumerate(face):
        star[v] = (t, face, k)
with open(os.path.join(maps, "copy-swapped.csv"), "w") as f:
    f.write("source_vertex,target_triangle,target_vertex_0,target_vertex_1,target_vertex_2,"
            "barycentric_0,barycentric_1,barycentric_2\n")
    for v in range(len(copy_points)):
        t, face, k = star[v]
        f.write(",".join(str(x) for x in [v, t, *face, *[int(j == k) for j in range(3)]]) + "\n")
code, out, err = run("--all", "--shapes", "*p*", "--maps", maps, "--csv", "all.csv")
identity = rows(os.path.join(work, "all.csv")) if code == 0 else {}
check(list(identity) == [("copy", "swapped")], f"--all --shapes: {out}{err}")
if identity and direct:
    twin = identity[("copy", "swapped")]
    check(float(twin["mirror_error"]) == 0 and twin["mirrored"] == "1" and float(twin["error"]) > 15,
          f"identity map against swapped truths: {twin}")
    # Its error: the same distances as the correct map's mirror error, with the copy's
    # identity in place of the registration (near the identity): close, not equal.
    check(abs(float(twin["error"]) - float(swapped["error"])) < 0.5, "identity vs registration")


def random_pairs(seed):
    code, out, err = run("--random", "2", "--seed", seed, "--maps", maps, "--csv", "random.csv")
    return list(rows(os.path.join(work, "random.csv"))) if code in (0, 1) else None


first, again = random_pairs("7"), random_pairs("7")
check(first == again and len(first) == 2 and len(set(first)) == 2
      and all(a < b for a, b in first), f"--random 2: {first} then {again}")


def expect_failure(arguments, words, code_expected=1):
    code, out, err = run(*arguments)
    lines = err.strip().splitlines()
    check(code == code_expected, f"{arguments}: exit code {code}, expected {code_expected}: {err}")
    check(len(lines) == 1 and all(w in err for w in words), f"{arguments}: message {err!r} lacks {words}")
    return out


def write_pairs(name, text):
    with open(os.path.join(work, name), "w") as f:
        f.write(text)
    return name


expect_failure(["--pairs", write_pairs("missing.txt", "cow nothing\n")], ["nothing.off", "no such file"])
expect_failure(["--pairs", "absent.txt"], ["absent.txt", "cannot open"])
expect_failure(["--pairs", write_pairs("bad.txt", "cow copy swapped\n")], ["bad.txt line 1", "two shape names"])
expect_failure(["--random", "4"], ["--random 4", "only 3 pairs"])
expect_failure(["--pairs", "pairs.txt", "--bogus"], ["unknown option --bogus"], 2)
expect_failure(["--pairs", "pairs.txt", "--basis-size", "1"], ["--basis-size"], 2)
expect_failure([], ["--pairs FILE, --all or --random N"], 2)
expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--no-polish"], ["--no-polish has no effect with --maps"], 2)
os.remove(os.path.join(maps, "cow-swapped.csv"))
out = expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--quiet"], ["cow -> swapped", "cow-swapped.csv", "cannot open"])
check("| cow | swapped | FAILED |" in out and "1 of 2 pairs FAILED" in out, f"a failed pair: {out}")

# Text as editors write it: a byte-order mark and CR line ends in the pairs file and in a
# .vts file (a byte-order mark was refused as "expected one vertex number").
corres = os.path.join(data, "corres")
with open(os.path.join(corres, "swapped.vts"), "rb") as f:
    vts_bytes = f.read()
with open(os.path.join(corres, "swapped.vts"), "wb") as f:
    f.write(b"\xef\xbb\xbf" + vts_bytes.replace(b"\n", b"\r"))
shutil.copy(os.path.join(maps, "cow-copy.csv"), os.path.join(maps, "cow-swapped.csv"))
with open(os.path.join(work, "bom-pairs.txt"), "wb") as f:
    f.write(b"\xef\xbb\xbfcow copy\r\ncow swapped\r\n")
code, out, err = run("--pairs", "bom-pairs.txt", "--maps", maps, "--csv", "bom.csv")
check(code == 0 and list(rows(os.path.join(work, "bom.csv"))) == [("cow", "copy"), ("cow", "swapped")],
      f"a byte-order mark and CR line ends: {code} {err!r}")
with open(os.path.join(corres, "swapped.vts"), "wb") as f:
    f.write(vts_bytes)

# The files named after two shapes: two pairs whose files would be one (shapes a-b and c, a
# and b-c) are refused before any work, for --maps and --errors.
for name in ("a-b", "c", "a", "b-c"):
    shutil.copy(os.path.join(data, "off", "cow.off"), os.path.join(data, "off", name + ".off"))
    shutil.copy(os.path.join(corres, "cow.vts"), os.path.join(corres, name + ".vts"))
expect_failure(["--pairs", write_pairs("colliding.txt", "a-b c\na b-c\n"), "--errors", maps],
               ["the pairs a-b c and a b-c would both use", "a-b-c.csv"])
# --errors writes over neither a --maps file (the same folder) nor the --pairs file, and not
# through a link or a device it finds in its folder.
expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--errors", maps], ["--errors and --maps name the same folder"], 2)
expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--csv", "pairs.txt"], ["--csv pairs.txt is the --pairs file"], 2)
errors = os.path.join(work, "errors")
os.makedirs(errors)
planted = os.path.join(work, "planted.txt")
with open(planted, "w") as f:
    f.write("not for mobius-score\n")
os.symlink(planted, os.path.join(errors, "cow-copy.csv"))
out = expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--errors", errors, "--quiet"],
                     ["cow -> copy", "cow-copy.csv exists and is not a regular file", "not written"])
check(open(planted).read() == "not for mobius-score\n", "--errors wrote through a link")
for name in ("a-b", "c", "a", "b-c"):
    os.remove(os.path.join(data, "off", name + ".off"))
# A shape matching --shapes without its .vts is named, not silently left out.
shutil.copy(os.path.join(data, "off", "cow.off"), os.path.join(data, "off", "cox.off"))
code, out, err = run("--all", "--shapes", "co[pwx]*", "--maps", maps, "--quiet")
check("warning: 1 shape(s) matching 'co[pwx]*' have no" in err and "corres/NAME.vts and are left out: cox" in err,
      f"no warning of a shape without .vts: {err!r}")
os.remove(os.path.join(data, "off", "cox.off"))
# --csv quotes names that hold commas (two columns of the row became three).
shutil.copy(os.path.join(data, "off", "copy.off"), os.path.join(data, "off", "co,py.off"))
shutil.copy(os.path.join(corres, "copy.vts"), os.path.join(corres, "co,py.vts"))
shutil.copy(os.path.join(maps, "copy-swapped.csv"), os.path.join(maps, "co,py-swapped.csv"))
code, out, err = run("--all", "--shapes", "[cs][ow]*[ypd]", "--maps", maps, "--csv", "commas.csv", "--quiet")
table_rows = list(rows(os.path.join(work, "commas.csv"))) if os.path.exists(os.path.join(work, "commas.csv")) else []
check(("co,py", "swapped") in table_rows and ("co,py", "copy") in table_rows,
      f"--csv with a comma in a shape name: {table_rows} {err!r}")
# "--" ends the options (nothing may follow it here: no positional arguments).
expect_failure(["--pairs", "pairs.txt", "--maps", maps, "--", "extra"], ["unexpected argument extra"], 2)

# Broken sample files (each checked before any registration runs).
corres = os.path.join(data, "corres")
write_vts(os.path.join(corres, "swapped.vts"), [len(copy_points)] + [new_index[v] for v in mirror][1:])
expect_failure(["--pairs", "pairs.txt"], ["swapped.vts line 1", f"vertex {len(copy_points) + 1}", "out of range"])
write_vts(os.path.join(corres, "swapped.vts"), [new_index[v] for v in mirror][:-1])
write_vts(os.path.join(corres, "swapped.sym.vts"), [new_index[v] for v in samples][:-1])
expect_failure(["--pairs", "pairs.txt"], ["cow.vts has 300 samples", "swapped.vts 299"])
write_vts(os.path.join(corres, "swapped.vts"), [new_index[v] for v in mirror])
write_vts(os.path.join(corres, "swapped.sym.vts"), [new_index[v] for v in samples][:-5])
expect_failure(["--pairs", "pairs.txt"], ["swapped.sym.vts", "295 samples"])
with open(os.path.join(corres, "swapped.vts"), "w") as f:
    f.write("1\nseven\n")
expect_failure(["--pairs", "pairs.txt"], ["swapped.vts line 2", "one vertex number"])
os.remove(os.path.join(corres, "swapped.vts"))
expect_failure(["--pairs", "pairs.txt"], ["swapped.vts", "cannot open"])
expect_failure(["--pairs", "pairs.txt", "--dataset", work], ["not a dataset folder"])

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
