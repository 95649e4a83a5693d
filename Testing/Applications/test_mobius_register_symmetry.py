"""mobius-register --symmetry as a user runs it: on a generated, exactly mirror-symmetric
egg (mirror partners known) the symmetry distance is about 0 and every vertex's mirror image
in the CSV is its partner to 1e-6 sqrt(area); on CGAL's cow without centering and
refinement it runs and says so; usage errors exit with status 2."""
import csv
import json
import math
import os
import shutil
import sys

from cli_harness import Harness

program, mesh_dir, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
harness = Harness(program, work)
run, check = harness.run, harness.check


# A UV sphere whose rings i and R - i are exact mirror images under z -> -z, bent into an egg
# by a map that keeps that symmetry and no other (x and y are mixed, z only scaled).
RINGS, SEGMENTS = 24, 32


def egg():
    heights = {}
    for i in range(1, RINGS):
        low = min(i, RINGS - i)
        theta = math.pi * low / RINGS
        sign = 1 if i <= RINGS // 2 else -1
        heights[i] = (math.sin(theta), sign * math.cos(theta) if i != RINGS // 2 else 0.0)
    points = [(0.0, 0.0, 1.0)]
    for i in range(1, RINGS):
        radius, z = heights[i]
        points += [(radius * math.cos(2 * math.pi * j / SEGMENTS), radius * math.sin(2 * math.pi * j / SEGMENTS), z)
                   for j in range(SEGMENTS)]
    points.append((0.0, 0.0, -1.0))
    shaped = [(1.6 * x * (1 + 0.3 * y) + 0.3 * y * y, 0.9 * y + 0.2 * x * x, 0.7 * z) for x, y, z in points]
    south = len(points) - 1
    faces = [(0, 1 + j, 1 + (j + 1) % SEGMENTS) for j in range(SEGMENTS)]
    # Quads split along opposite diagonals in the two halves, so that the mirror image of
    # every triangle is a triangle.
    for i in range(RINGS - 2):
        for j in range(SEGMENTS):
            a, b = 1 + i * SEGMENTS + j, 1 + i * SEGMENTS + (j + 1) % SEGMENTS
            if i < (RINGS - 2) // 2:
                faces += [(a, a + SEGMENTS, b), (b, a + SEGMENTS, b + SEGMENTS)]
            else:
                faces += [(a, a + SEGMENTS, b + SEGMENTS), (a, b + SEGMENTS, b)]
    last = 1 + (RINGS - 2) * SEGMENTS
    faces += [(last + j, south, last + (j + 1) % SEGMENTS) for j in range(SEGMENTS)]

    def partner(v):
        if v in (0, south):
            return south - v
        ring, segment = divmod(v - 1, SEGMENTS)
        return 1 + (RINGS - 2 - ring) * SEGMENTS + segment
    return shaped, faces, partner


points, faces, partner = egg()
assert all(points[partner(v)][2] == -points[v][2] and points[partner(v)][:2] == points[v][:2]
           for v in range(len(points)))
assert {tuple(sorted(map(partner, face))) for face in faces} == {tuple(sorted(face)) for face in faces}
with open(os.path.join(work, "egg.off"), "w") as f:
    f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
    f.writelines("%.17g %.17g %.17g\n" % p for p in points)
    f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)


def area():
    total = 0.0
    for a, b, c in faces:
        u = [points[b][k] - points[a][k] for k in range(3)]
        w = [points[c][k] - points[a][k] for k in range(3)]
        cross = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        total += 0.5 * math.sqrt(sum(x * x for x in cross))
    return total


code, out, err = run("--symmetry", "egg.off", "-o", "egg", "--resolution", "64", "--json")
check(code == 0, f"--symmetry egg.off: exit {code}: {err}")
if code == 0:
    summary = json.loads(out)
    print("egg: symmetry distance", summary["symmetry_distance"], "max asymmetry", summary["max_asymmetry"])
    check(summary["centered"] is True and summary["refinement"] is not None, "egg: centered and refined")
    check(0 <= summary["symmetry_distance"] < 0.01, f"egg: distance {summary['symmetry_distance']}")
    check(len(summary["candidates"]) >= 1 and len(summary["mirror_plane_normal"]) == 3, "egg: plane and candidates")
    scale = math.sqrt(area())
    worst = 0.0
    with open(os.path.join(work, "egg.csv")) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == len(points), f"egg: {len(rows)} CSV rows")
    for row in rows:
        v = int(row["source_vertex"])
        mapped = [float(row[f"mapped_{axis}"]) for axis in "xyz"]
        worst = max(worst, math.dist(mapped, points[partner(v)]) / scale)
    print(f"egg: largest distance of a mirror image from the partner vertex {worst:.3g} sqrt(area)")
    check(worst < 1e-6, f"egg: the symmetric map is exact: {worst}")
    check(os.path.exists(os.path.join(work, "egg.vtp")), "egg: egg.vtp written")

cow = os.path.join(mesh_dir, "cow.off")
# Without centering the flow drifts and does not converge on the cow (the paper's Section 7.1):
# the map is degenerate, written only with --allow-poor-maps.
code, out, err = run("--symmetry", cow, "-o", "cow", "--resolution", "64", "--no-centering", "--refine", "none")
check(code == 1 and "degenerate" in err, f"--no-centering without --allow-poor-maps: {code} {err!r}")
code, out, err = run("--symmetry", cow, "-o", "cow", "--resolution", "64", "--no-centering", "--refine", "none",
                     "--allow-poor-maps", "--json")
check(code == 0, f"--symmetry cow.off --no-centering: exit {code}: {err}")
if code == 0:
    summary = json.loads(out)
    print("cow, uncentered, Moebius map: symmetry distance", summary["symmetry_distance"])
    check(summary["centered"] is False and summary["refinement"] is None, "cow: uncentered, not refined")
    check(0 < summary["symmetry_distance"] <= 1, "cow: a distance in (0, 1]")
code, out, err = run("--symmetry", cow, "-o", "cow-text", "--resolution", "64", "--refine", "none")
check(code == 0 and "Symmetry of" in out and "distance" in out, f"plain output: {code} {out!r} {err!r}")

for arguments, words in ((["--symmetry", "egg.off", "egg.off", "-o", "x"], "one mesh"),
                         (["--symmetry", "egg.off", "-o", "x", "--png", "x.png"], "--png"),
                         (["--symmetry", "egg.off"], "-o"),
                         (["egg.off", "egg.off", "-o", "x", "--no-centering"], "--symmetry")):
    code, out, err = run(*arguments)
    check(code == 2 and words in err, f"{arguments}: exit {code}, {err!r}")
check(not os.path.exists(os.path.join(work, "x.vtp")), "no output after a usage error")

harness.finish()
