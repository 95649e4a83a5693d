"""mobius-register --orbifold as a user runs it: on CGAL's hand the 3-fold orbifold map is
symmetric to rounding, reports its area distortion and the plain map's, and writes one copy (the
input's triangles) or, with --covering, all three; --cones picks the cones (file vertex
numbers, reported back); bad N, bad or equal cones and misplaced options exit with status 2,
cones outside the mesh with status 1 and the filter's reason."""
import json
import os
import shutil
import sys

from cli_harness import Harness

program, mesh_dir, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
harness = Harness(program, work)
run, check = harness.run, harness.check

hand = os.path.join(mesh_dir, "hand.off")
with open(hand) as f:
    f.readline()
    vertices, triangles = (int(x) for x in f.readline().split()[:2])


def vtp_counts(path):
    """NumberOfPoints and NumberOfPolys of the first Piece of a .vtp file."""
    with open(path, "rb") as f:
        head = f.read().decode("latin-1")
    piece = head[head.index("<Piece"):]
    value = lambda key: int(piece.split(key + '="')[1].split('"')[0])
    return value("NumberOfPoints"), value("NumberOfPolys")


code, out, err = run("--orbifold", "3", hand, "-o", "hand3", "--json")
check(code == 0, f"--orbifold 3 hand.off: exit {code}: {err}")
if code == 0:
    summary = json.loads(out)
    print("hand, n = 3:", {k: summary[k] for k in ("cones", "symmetry_error", "std_log_area_ratio",
                                                 "plain_std_log_area_ratio", "flipped_triangles")})
    check(summary["copies"] == 3, "copies reported")
    check(summary["symmetry_error"] < 1e-6, f"symmetric: {summary['symmetry_error']}")
    check(summary["flipped_triangles"] == 0, "no flipped triangles")
    check(0 < summary["std_log_area_ratio"] < 10 and 0 < summary["plain_std_log_area_ratio"] < 10,
          "area distortion of both maps reported")
    points, polys = vtp_counts(os.path.join(work, "hand3.vtp"))
    check(polys == triangles and vertices < points < vertices + 200, f"one copy: {points} points, {polys} triangles")
    cones = summary["cones"]

    code, out, err = run("--orbifold", "2", hand, "-o", "hand2", "--cones", f"{cones[1]},{cones[0]}",
                         "--covering", "--json")
    check(code == 0, f"--cones --covering: exit {code}: {err}")
    if code == 0:
        summary = json.loads(out)
        check(summary["cones"] == [cones[1], cones[0]], f"cones as given: {summary['cones']}")
        check(summary["symmetry_error"] < 1e-6, "n = 2 symmetric")
        points, polys = vtp_counts(os.path.join(work, "hand2.vtp"))
        check(points == 2 * (vertices - 2) + 2 and polys == 2 * triangles, f"covering: {points} {polys}")

code, out, err = run("--orbifold", "2", hand, "-o", "hand-text")
check(code == 0 and "orbifold map of" in out and "symmetry error" in out, f"plain output: {code} {out!r}")
# --orbifold writes no CSV: a file at OUT.csv is neither refused nor touched.
with open(os.path.join(work, "with-csv.csv"), "w") as f:
    f.write("mine\n")
code, out, err = run("--orbifold", "2", hand, "-o", "with-csv")
with open(os.path.join(work, "with-csv.csv")) as f:
    kept = f.read() == "mine\n"
check(code == 0 and kept, f"--orbifold with an unrelated OUT.csv: {code} {err!r}")

code, out, err = run("--orbifold", "2", hand, "-o", "far", "--cones", f"0,{vertices}")
check(code == 1 and "does not exist" in err, f"cone outside the mesh: {code} {err!r}")
for arguments, words in ((["--orbifold", "9", hand, "-o", "x"], "2 to 8"),
                         (["--orbifold", "two", hand, "-o", "x"], "2 to 8"),
                         (["--orbifold", "3", hand, "-o", "x", "--cones", "4,4"], "differ"),
                         (["--orbifold", "3", hand, "-o", "x", "--cones", "4"], "I,J"),
                         (["--orbifold", "3", hand], "-o"),
                         (["--orbifold", "3", hand, hand, "-o", "x"], "one mesh"),
                         ([hand, hand, "-o", "x", "--covering"], "--orbifold only")):
    code, out, err = run(*arguments)
    check(code == 2 and words in err, f"{arguments}: exit {code}, {err!r}")
check(not os.path.exists(os.path.join(work, "x.vtp")), "no output after a usage error")

harness.finish()
