"""mobius-score as a user runs it: mobius-register's map of CGAL's hand onto itself scores 0, its
map onto a stretched, rotated copy scores a little (and the Euclidean figures agree with a
computation done here from the CSV and the mesh), corrupted maps score badly by the expected
amount, and bad input gives one line and exit status 1 (2 for usage errors)."""
import json
import math
import os
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


def run(*arguments):
    result = subprocess.run([score, *arguments], cwd=work, capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


def figures(*arguments):
    code, out, err = run(*arguments, "--json")
    check(code == 0, f"{arguments}: exit code {code}: {err}")
    return json.loads(out) if code == 0 else None


def read_off(path):
    words = [w for line in open(path) for w in line.split("#")[0].split()]
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    values = words[4:]
    points = [tuple(float(v) for v in values[3 * i:3 * i + 3]) for i in range(nv)]
    rest, faces = values[3 * nv:], []
    for _ in range(nf):
        n = int(rest[0])
        faces.append([int(v) for v in rest[1:1 + n]])
        rest = rest[1 + n:]
    return points, faces


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def area(points, faces):
    total = 0.0
    for face in faces:
        for k in range(1, len(face) - 1):
            u, v = sub(points[face[k]], points[face[0]]), sub(points[face[k + 1]], points[face[0]])
            total += 0.5 * norm([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])
    return total


def write_csv(name, header, rows):
    with open(os.path.join(work, name), "w") as f:
        f.write(header)
        f.writelines(rows)
    return name


hand = os.path.join(mesh_dir, "hand.off")
points, faces = read_off(hand)
n = len(points)
scale = math.sqrt(area(points, faces))

# A copy stretched by 1.2 along x and rotated by 0.7 rad about z: not isometric, so the map
# onto it is close to, but not exactly, vertex i -> vertex i.
c, s = math.cos(0.7), math.sin(0.7)
stretched_points = [(c * 1.2 * x - s * y, s * 1.2 * x + c * y, z) for x, y, z in points]
stretched = os.path.join(work, "hand-stretched.off")
with open(stretched, "w") as f:
    f.write(f"OFF\n{n} {len(faces)} 0\n")
    f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in stretched_points)
    f.writelines(" ".join(str(v) for v in [len(face)] + face) + "\n" for face in faces)
stretched_scale = math.sqrt(area(stretched_points, faces))

code, out, _ = run("--help")
check(code == 0 and out.startswith("usage: mobius-score"), "--help")



def register_map(target, name):
    result = subprocess.run([register, hand, target, "-o", os.path.join(work, name), "--resolution", "64",
                             "--quiet"], capture_output=True, text=True)
    check(result.returncode == 0, f"mobius-register {name}: {result.stderr}")
    with open(os.path.join(work, name + ".csv")) as f:
        return f.readline(), f.readlines()


# The map of the hand onto itself is exact: every vertex lands on itself.
header, rows = register_map(hand, "hand")
check(len(rows) == n, f"{len(rows)} CSV rows, {n} vertices")
self_map = figures(hand, hand, "hand.csv")
if self_map:
    e, g = self_map["euclidean"], self_map["geodesic"]
    print(f"self-map of the hand: Euclidean mean {e['mean']}, geodesic mean {g['mean']}; {self_map['seconds']} s")
    check(self_map["source_vertices"] == n and e["count"] == n and g["count"] == n, "counts")
    check(abs(self_map["target_area"] - scale ** 2) < 1e-9 * scale ** 2, "target area")
    check(e["mean"] < 1e-9 and g["mean"] < 1e-9 and g["within"]["0.025"] == 1, "self-map scores 0")

# The map onto the stretched copy (measured with the refinement: Euclidean mean 0.0032, every
# vertex within 0.05; the Möbius map alone: 0.020 and 95%): small but not zero. The Euclidean errors are recomputed here from the CSV's mapped
# positions and the mesh.
header, stretched_rows = register_map(stretched, "stretched")
columns = header.strip().split(",")
mapped_column = columns.index("mapped_x")
euclidean = sorted(norm(sub([float(v) for v in row.split(",")[mapped_column:mapped_column + 3]],
                            stretched_points[i])) / stretched_scale for i, row in enumerate(stretched_rows))
own_mean = sum(euclidean) / n
own_median = euclidean[n // 2] if n % 2 else 0.5 * (euclidean[n // 2 - 1] + euclidean[n // 2])
own_within = sum(1 for x in euclidean if x <= 0.05) / n
near = figures(hand, stretched, "stretched.csv")
if near:
    e, g = near["euclidean"], near["geodesic"]
    print(f"hand onto its stretched copy: Euclidean mean {e['mean']}, median {e['median']}, p90 {e['p90']}; "
          f"geodesic mean {g['mean']}, median {g['median']}, within 0.05 {g['within']['0.05']}; {near['seconds']} s")
    check(abs(e["mean"] - own_mean) <= 1e-6 * own_mean, f"Euclidean mean {e['mean']} vs {own_mean}")
    check(abs(e["median"] - own_median) <= 1e-6 * own_median, f"Euclidean median {e['median']} vs {own_median}")
    check(abs(e["within"]["0.05"] - own_within) <= 1e-12, f"Euclidean within 0.05 {e['within']['0.05']}")
    check(0.0005 < e["mean"] < 0.05 and 0.0005 < g["mean"] < 0.05, f"stretched means {e['mean']} {g['mean']}")
    check(g["mean"] >= e["mean"] and g["median"] >= e["median"] and g["p90"] >= e["p90"], "geodesic >= Euclidean")
    check(g["mean"] < 1.3 * e["mean"], "edge paths: a few % (sub-edge distances: up to ~20%) above Euclidean")

# The Markdown table.
code, out, err = run(hand, hand, "hand.csv")
lines = out.splitlines()
check(code == 0 and lines[0].startswith("| error / √area | mean | median | p90 |")
      and lines[2].startswith("| Euclidean |") and lines[3].startswith("| geodesic |"), f"table: {out}{err}")

# The identity given as a truth file, and as triangle points, scores the same.
with open(os.path.join(work, "identity.txt"), "w") as f:
    f.write("# target vertex of each source vertex\n")
    f.writelines(f"{i}\n" for i in range(n))
explicit = figures(hand, hand, "hand.csv", "--truth", "identity.txt")
if self_map and explicit:
    check(explicit["euclidean"] == self_map["euclidean"] and explicit["geodesic"] == self_map["geodesic"],
          "identity truth file")

# The cap on geodesic queries, and per-vertex errors.
capped = figures(hand, hand, "hand.csv", "--max-geodesic", "100", "--errors", "errors.csv")
if capped:
    check(capped["geodesic"]["count"] == 100 and capped["euclidean"]["count"] == n, "--max-geodesic")
with open(os.path.join(work, "errors.csv")) as f:
    error_rows = f.read().splitlines()
check(len(error_rows) == n + 1 and error_rows[0] == "source_vertex,euclidean,geodesic"
      and sum(1 for r in error_rows[1:] if r.split(",")[2]) == 100, "--errors file")
# A file that cannot be written fully, and a standard output that cannot be written: exit
# status 1 and one line, never a silently short file (the final flush included).
code, _, err = run(hand, hand, "hand.csv", "--max-geodesic", "100", "--errors", "/dev/full")
check(code == 1 and len(err.strip().splitlines()) == 1 and "/dev/full: cannot write" in err,
      f"--errors /dev/full: {code} {err!r}")
with open("/dev/full", "w") as full:
    code = subprocess.run([score, hand, hand, "hand.csv", "--max-geodesic", "100"], cwd=work, stdout=full,
                          stderr=subprocess.PIPE, text=True)
    check(code.returncode == 1 and "standard output: cannot write" in code.stderr,
          f"standard output /dev/full: {code.returncode} {code.stderr!r}")

# Corrupted maps. Every 10th vertex sent where vertex (i + n/2) mod n goes: about 10% of the
# vertices leave the 0.025 band, and the mean grows accordingly.
corrupt = list(rows)
for i in range(0, n, 10):
    fields = rows[(i + n // 2) % n].split(",")
    corrupt[i] = ",".join([str(i)] + fields[1:])
write_csv("corrupt10.csv", header, corrupt)
bad = figures(hand, hand, "corrupt10.csv")
wrong = [i for i in range(0, n, 10) if norm(sub(points[i], points[(i + n // 2) % n])) / scale > 0.025]
if bad:
    e, g = bad["euclidean"], bad["geodesic"]
    print(f"10% corrupted: Euclidean mean {e['mean']}, geodesic mean {g['mean']}, "
          f"geodesic within 0.025 {g['within']['0.025']}")
    check(abs(g["within"]["0.025"] - (1 - len(wrong) / n)) <= 1e-12,
          f"10% corrupted: within 0.025 = {g['within']['0.025']}, {len(wrong)} of {n} moved far")
    own = sum(norm(sub(points[i], points[(i + n // 2) % n])) for i in range(0, n, 10)) / scale / n
    check(abs(e["mean"] - own) <= 1e-9 * own, f"10% corrupted: Euclidean mean {e['mean']} vs {own}")
    check(g["mean"] >= e["mean"], "10% corrupted: geodesic >= Euclidean")
# Every vertex sent where the vertex half-way around the list goes: a useless map.
shuffled = [",".join([str(i)] + rows[(i + n // 2) % n].split(",")[1:]) for i in range(n)]
write_csv("shuffled.csv", header, shuffled)
useless = figures(hand, hand, "shuffled.csv")
if useless:
    print(f"shuffled: geodesic mean {useless['geodesic']['mean']}, median {useless['geodesic']['median']}")
    check(useless["geodesic"]["mean"] > 0.2 and useless["geodesic"]["within"]["0.025"] < 0.1, "shuffled map")


def expect_failure(arguments, words, code_expected=1):
    code, out, err = run(*arguments)
    lines = err.strip().splitlines()
    check(code == code_expected, f"{arguments}: exit code {code}, expected {code_expected}")
    check(len(lines) == 1 and out == "" and all(w in err for w in words),
          f"{arguments}: message {err!r} lacks {words}")


write_csv("short.csv", header, rows[:-1])
expect_failure([hand, hand, "short.csv"], ["short.csv", f"{n - 1} rows", f"{n} vertices"])
out_of_range = list(rows)
fields = rows[5].split(",")
fields[2] = str(n + 7)
out_of_range[5] = ",".join(fields)
write_csv("range.csv", header, out_of_range)
expect_failure([hand, hand, "range.csv"], ["range.csv line 7", f"target vertex {n + 7}", "out of range"])
wrong_triangle = list(rows)
fields = rows[3].split(",")
fields[1] = str(len(faces) + 1)
fields[2], fields[3] = fields[3], fields[2]
wrong_triangle[3] = ",".join(fields)
write_csv("triangle.csv", header, wrong_triangle)
check(figures(hand, hand, "triangle.csv") is not None, "a triangle found by its vertices")
write_csv("garbage.csv", "a,b,c\n", rows)
expect_failure([hand, hand, "garbage.csv"], ["garbage.csv", "not a mobius-register CSV"])
with open(os.path.join(work, "truth-range.txt"), "w") as f:
    f.writelines(f"{i if i != 9 else n}\n" for i in range(n))
expect_failure([hand, hand, "hand.csv", "--truth", "truth-range.txt"],
               ["truth-range.txt line 10", f"target vertex {n}", "out of range"])
with open(os.path.join(work, "truth-short.txt"), "w") as f:
    f.writelines(f"{i}\n" for i in range(n - 2))
expect_failure([hand, hand, "hand.csv", "--truth", "truth-short.txt"], ["truth-short.txt", f"{n - 2} entries"])
cow = os.path.join(mesh_dir, "cow.off")
expect_failure([hand, cow, "hand.csv"], ["hand.csv", "not a triangle of TARGET"])
expect_failure([cow, cow, "hand.csv"], ["hand.csv"])
expect_failure(["missing.off", hand, "hand.csv"], ["missing.off"])
expect_failure([hand, hand, "missing.csv"], ["missing.csv", "cannot open"])
expect_failure([hand, hand, "hand.csv", "--truth", "missing.txt"], ["missing.txt", "cannot open"])
expect_failure([hand, hand], ["expected SOURCE TARGET MAP.csv"], code_expected=2)
expect_failure([hand, hand, "hand.csv", "--bogus"], ["unknown option --bogus"], code_expected=2)
expect_failure([hand, hand, "hand.csv", "--max-geodesic", "x"], ["--max-geodesic"], code_expected=2)
expect_failure([hand, hand, "hand.csv", "--truth"], ["--truth needs a file"], code_expected=2)

# Text as editors and other tools write it: a UTF-8 byte-order mark, CR LF or lone CR line
# ends, in the map and the truth (a byte-order mark was refused: "not a mobius-register CSV").
with open(os.path.join(work, "hand.csv"), "rb") as f:
    map_bytes = f.read()
with open(os.path.join(work, "identity.txt"), "rb") as f:
    truth_bytes = f.read()
for label, convert in (("a byte-order mark", lambda b: b"\xef\xbb\xbf" + b),
                       ("CR LF line ends", lambda b: b.replace(b"\n", b"\r\n")),
                       ("CR line ends", lambda b: b.replace(b"\n", b"\r"))):
    for name, data in (("bom-map.csv", convert(map_bytes)), ("bom-truth.txt", convert(truth_bytes))):
        with open(os.path.join(work, name), "wb") as f:
            f.write(data)
    read = figures(hand, hand, "bom-map.csv", "--truth", "bom-truth.txt")
    check(read is not None and self_map is not None and read["geodesic"] == self_map["geodesic"],
          f"map and truth with {label}: {read}")

# "--" ends the options: a file whose name starts with '-' is a file.
shutil.copyfile(os.path.join(work, "hand.csv"), os.path.join(work, "-hand.csv"))
code, out, err = run("--json", "--", hand, hand, "-hand.csv")
check(code == 0 and self_map is not None and json.loads(out)["geodesic"] == self_map["geodesic"],
      f"a map named -hand.csv after --: {code} {err!r}")
# --json stays JSON whatever a file name holds (a line break, a quote, a byte that is not UTF-8).
odd = 'truth "odd"\nname\\\x7f.txt'
shutil.copyfile(os.path.join(work, "identity.txt"), os.path.join(work, odd))
code, out, err = run(hand, hand, "hand.csv", "--truth", odd, "--json")
try:
    check(code == 0 and json.loads(out)["truth"] == odd, f"--json with a line break in a file name: {out!r}")
except ValueError:
    check(False, f"--json with a line break in a file name is not JSON: {out!r}")
# --errors never writes over one of the inputs (it replaced the map it was scoring), also
# through a link to it.
before = open(os.path.join(work, "hand.csv"), "rb").read()
os.symlink("hand.csv", os.path.join(work, "link-to-map.csv"))
for target in ("hand.csv", "link-to-map.csv", "identity.txt"):
    expect_failure([hand, hand, "hand.csv", "--truth", "identity.txt", "--errors", target],
                   [f"--errors {target} is the input", "would be overwritten"])
check(open(os.path.join(work, "hand.csv"), "rb").read() == before, "--errors wrote over the map")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
