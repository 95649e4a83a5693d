"""mobius-register --degree as a user runs it: generalized centering (the paper's Section 5,
Figure 5) for both meshes of a registration. On CGAL's hand against a turned copy of itself,
--degree 2 reaches vtkMobiusCenter for both meshes (their centering reports degree 2 and its
advection steps, with the moments of degree 1 and 2 gone), and the Möbius map still finds the
copy's vertices; the default is the paper's centering (degree 1). A degree outside 1..8, and
--degree with --symmetry or --orbifold, are usage errors (status 2) naming the option."""
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
run, check, expect_failure = harness.run, harness.check, harness.expect_failure

code, out, _ = run("--help")
check(code == 0 and "--degree L" in out and "generalized centering" in out, "--help documents --degree")

# The hand and a copy turned about a skew axis: vertex i of the copy is the image of vertex i.
hand = os.path.join(mesh_dir, "hand.off")
with open(hand) as f:
    lines = [line for line in f.read().splitlines() if line.strip() and not line.startswith("#")]
vertex_count = int(lines[1].split()[0])
points = [tuple(float(v) for v in line.split()[:3]) for line in lines[2:2 + vertex_count]]
angle, axis = 1.1, (0.48, -0.6, 0.64)  # a unit axis
c, s = math.cos(angle), math.sin(angle)
cross = [[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]]
turn = [[c * (i == j) + s * cross[i][j] + (1 - c) * axis[i] * axis[j] for j in range(3)] for i in range(3)]
turned = [tuple(sum(turn[i][j] * p[j] for j in range(3)) for i in range(3)) for p in points]
copy = os.path.join(work, "hand-turned.off")
with open(copy, "w") as f:
    f.write("\n".join(lines[:2] + [" ".join(repr(x) for x in p) for p in turned] + lines[2 + vertex_count:]) + "\n")


def mean_error(stem):
    """Mean distance from each mapped point to its true image, over the diagonal of the
    copy's bounding box."""
    with open(os.path.join(work, stem + ".csv")) as table:
        rows = list(csv.DictReader(table))
    errors = [math.dist((float(r["mapped_x"]), float(r["mapped_y"]), float(r["mapped_z"])),
                        turned[int(r["source_vertex"])]) for r in rows]
    low = [min(p[k] for p in turned) for k in range(3)]
    high = [max(p[k] for p in turned) for k in range(3)]
    return sum(errors) / len(errors) / math.dist(low, high), len(rows)


results = {}
for degree in (None, 2):
    stem = f"degree-{degree or 'default'}"
    arguments = [hand, copy, "-o", stem, "--resolution", "64", "--refine", "none", "--json", "--quiet"]
    code, out, err = run(*arguments + ([] if degree is None else ["--degree", str(degree)]))
    check(code == 0, f"{stem}: exit {code}: {err}")
    if code != 0:
        continue
    summary = json.loads(out)
    for side in ("source_map", "target_map"):
        quality = summary[side]
        check(quality["centering_degree"] == (degree or 1), f"{stem} {side}: degree {quality['centering_degree']}")
        steps = quality["generalized_centering_iterations"]
        check(steps == 0 if degree is None else 0 < steps < 200, f"{stem} {side}: {steps} advection steps")
        check(quality["center_of_mass_norm"] <= 1e-9, f"{stem} {side}: moments left {quality['center_of_mass_norm']}")
    results[degree] = summary, mean_error(stem)
    print(f"{stem}: mean error {results[degree][1][0]:.4f} of the diagonal, "
          f"advection steps {summary['source_map']['generalized_centering_iterations']} / "
          f"{summary['target_map']['generalized_centering_iterations']}")
    check(results[degree][1][1] == vertex_count, f"{stem}: a CSV row per vertex")
    # The turned copy's map is the same up to the turn, so the rotation search finds it: the
    # Möbius map alone places vertices near their true images.
    check(results[degree][1][0] < 0.03, f"{stem}: mean error {results[degree][1][0]}")
if None in results and 2 in results:
    # Not the same centering: the two maps differ where the advection moved points.
    default_rows = open(os.path.join(work, "degree-default.csv")).read()
    check(default_rows != open(os.path.join(work, "degree-2.csv")).read(), "--degree 2 changed the map")

# Out of range: the range in the message; not an integer: the word it was given.
for value in ("0", "9", "-1"):
    expect_failure([hand, copy, "-o", "bad", "--degree", value], ["--degree", "1 to 8", value], ["bad"],
                   code_expected=2, timeout=60)
for value in ("2.5", "nan", "two"):
    expect_failure([hand, copy, "-o", "bad", "--degree", value], ["--degree", "integer", f"'{value}'"], ["bad"],
                   code_expected=2, timeout=60)
expect_failure([hand, copy, "-o", "bad", "--degree"], ["--degree"], ["bad"], code_expected=2, timeout=60)
expect_failure(["--symmetry", hand, "-o", "bad", "--degree", "2"], ["--degree", "--symmetry"], ["bad"],
               code_expected=2, timeout=60)
expect_failure(["--orbifold", "3", hand, "-o", "bad", "--degree", "3"], ["--degree", "--orbifold"], ["bad"],
               code_expected=2, timeout=60)
harness.finish()
