"""Every mesh maps: the defect corpus (defect_corpus.py) made on a mesh in its rest pose,
mapped from a posed copy and back with mobius-register's defaults, and scored against the
ground truth the vertex numbers give, beside the map between the clean meshes.

CGAL's man at rest has his hands beside his thighs, where a scan fuses them: the `fused`
defects join a hand to the thigh and to the pelvis there. The posed copy (POSE, default
legs_apart, by Examples/pvbatch/posed_copies.py) is the other shape of the pair.

Asserts: no defective mesh is refused; each is repaired (the warning names the repair); and
outside the repaired region (the defect's zone) the mean geodesic error of the map onto
the defective mesh, and of the map from it, is within 20% of the clean pair's on the same
vertices (plus 0.001 sqrt(area): the clean pair is at the noise floor of the map there).

Usage: python3 test_defect_corpus.py MOBIUS_REGISTER MOBIUS_SCORE WORK_DIR MESH.off [POSE]
       (MESH: CGAL's man.off; any other closed mesh with POSE --bent: a bent copy is the
       other shape); prints the table. Exit status 1 when an assertion fails.
"""
import csv
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "Examples", "pvbatch"))
import defect_corpus  # noqa: E402

# How much worse than the clean pair a map may be outside the repaired region.
RELATIVE_TOLERANCE = 0.20
ABSOLUTE_TOLERANCE = 0.001


def register(program, source, target, output):
    run = subprocess.run([program, source, target, "-o", output, "--force", "--quiet"],
                         capture_output=True, text=True)
    return run.returncode, run.stderr.strip()


def repairs_of(program, source, target, output):
    """mobius-register's warnings (the repair's among them), without --quiet."""
    run = subprocess.run([program, source, target, "-o", output, "--force"], capture_output=True, text=True)
    return run.returncode, [line for line in run.stderr.splitlines() if "Repaired" in line]


def errors(scorer, source, target, map_csv, work):
    """Per source vertex, the geodesic error over sqrt(target area)."""
    path = os.path.join(work, "errors.csv")
    subprocess.run([scorer, source, target, map_csv, "--errors", path], check=True,
                   capture_output=True, text=True)
    with open(path) as f:
        return np.array([float(row["geodesic"]) for row in csv.DictReader(f)])


def onto_clean_triangles(map_csv, faces, points, count, output):
    """The map onto the defective target (`points`, the clean one's `count` first) as a map
    onto the clean one: a vertex the defect added at a clean vertex's place (a seam's copy)
    is that vertex, and an image on a triangle the defect added (a tube's) moves to its
    nearest corner."""
    at = {tuple(p): v for v, p in enumerate(points[:count].tolist())}
    original = [v if v < count else at.get(tuple(points[v]), -1) for v in range(len(points))]
    triangles = {tuple(sorted(t)) for t in faces.tolist()}
    around = {}
    for t in faces.tolist():
        for v in t:
            around.setdefault(v, t)
    with open(map_csv) as f, open(output, "w", newline="") as out:
        reader = csv.DictReader(f)
        writer = csv.DictWriter(out, fieldnames=reader.fieldnames)
        writer.writeheader()
        for row in reader:
            corners = [original[int(row[f"target_vertex_{k}"])] for k in range(3)]
            row.update({f"target_vertex_{k}": corners[k] for k in range(3)})
            if tuple(sorted(corners)) not in triangles:
                weights = [float(row[f"barycentric_{k}"]) for k in range(3)]
                nearest = corners[int(np.argmax(weights))]
                row.update({f"target_vertex_{k}": around[nearest][k] for k in range(3)})
                row.update({f"barycentric_{k}": float(around[nearest][k] == nearest) for k in range(3)})
            writer.writerow(row)


def first_rows(map_csv, count, output):
    """The rows of the first `count` source vertices (a defect's added vertices have no truth)."""
    with open(map_csv) as f, open(output, "w") as out:
        for k, line in enumerate(f):
            if k > count:
                break
            out.write(line)


def outside_mean(values, zone):
    keep = np.ones(len(values), bool)
    keep[list(zone)] = False
    return values[keep].mean()


def pair_errors(programs, other_path, mesh_path, points, clean_points, faces, work):
    """Per vertex of the clean mesh (`clean_points`, `faces`), the errors of the map from the
    other shape onto the mesh at `mesh_path` (whose first points are the clean mesh's,
    `points` all of them) and of the map from it back. None when a map is refused."""
    register_program, scorer = programs
    out = os.path.join(work, "map")
    clean_path = os.path.join(work, "clean.off")
    defect_corpus.write_off(clean_path, clean_points, faces)
    if register(register_program, other_path, mesh_path, out)[0] != 0:
        return None
    onto_clean_triangles(out + ".csv", faces, points, len(clean_points), out + "-clean.csv")
    onto = errors(scorer, other_path, clean_path, out + "-clean.csv", work)
    if register(register_program, mesh_path, other_path, out)[0] != 0:
        return None
    first_rows(out + ".csv", len(clean_points), out + "-first.csv")
    return onto, errors(scorer, clean_path, other_path, out + "-first.csv", work)


def main():
    register_program, scorer, work, mesh = sys.argv[1:5]
    pose = sys.argv[5] if len(sys.argv) > 5 else "legs_apart"
    programs = (register_program, scorer)
    os.makedirs(work, exist_ok=True)
    rest, faces = defect_corpus.read_off(mesh)
    facing = None  # holes at three places far apart
    if pose == "--bent":
        import make_test_collection
        other = make_test_collection.bent_copy(rest)
    else:
        import posed_copies
        other = posed_copies.Rig("man", rest, faces).pose(pose)[0]
        facing = ((0, 0, 1), (0, -1, 0))  # CGAL's man (skeletons.py): holes at his eyes and mouth
    rest_path, other_path = os.path.join(work, "rest.off"), os.path.join(work, "other.off")
    defect_corpus.write_off(rest_path, rest, faces)
    defect_corpus.write_off(other_path, other, faces)
    clean = pair_errors(programs, other_path, rest_path, rest, rest, faces, work)
    if clean is None:
        raise SystemExit("the clean pair failed")
    failures = []
    print("| defect | repairs | onto it: clean / defective (outside the zone) | from it: clean / defective | zone |")
    print("|---|---|---:|---:|---:|")
    for defect in defect_corpus.DEFECTS:
        points, defect_faces, zone = defect_corpus.make(defect, rest, faces, facing=facing)
        defective = os.path.join(work, defect + ".off")
        defect_corpus.write_off(defective, points, defect_faces)
        code, repairs = repairs_of(register_program, other_path, defective, os.path.join(work, "map"))
        reference = clean
        if defect == "scan":  # the noisy mesh without holes
            noisy = defect_corpus.make("noise", rest, faces)[0]
            noisy_path = os.path.join(work, "noisy.off")
            defect_corpus.write_off(noisy_path, noisy, faces)
            reference = pair_errors(programs, other_path, noisy_path, noisy, rest, faces, work)
        found = pair_errors(programs, other_path, defective, points, rest, faces, work) if code == 0 else None
        if found is None:
            failures.append(f"{defect}: refused (exit {code})")
            print(f"| {defect} | refused | | | |")
            continue
        if not repairs:
            failures.append(f"{defect}: mapped without a warning naming the repair")
        figures = [(outside_mean(r, zone), outside_mean(f, zone)) for r, f in zip(reference, found)]
        for (before, after), way in zip(figures, ("onto", "from")):
            if after > (1 + RELATIVE_TOLERANCE) * before + ABSOLUTE_TOLERANCE:
                failures.append(f"{defect}: the map {way} it has mean error {after:.4f} outside the "
                                f"repaired region, the clean pair {before:.4f}")
        repair_text = repairs[0].split("Repaired the mesh ", 1)[-1] if repairs else "(no warning)"
        print(f"| {defect} | {repair_text} | {figures[0][0]:.4f} / {figures[0][1]:.4f} | "
              f"{figures[1][0]:.4f} / {figures[1][1]:.4f} | {len(zone)} |")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
