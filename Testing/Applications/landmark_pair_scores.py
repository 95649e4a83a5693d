"""Non-isometric pairs with exact ground truth and 5 landmarks, and what the landmarks do to
the map: each mesh against a copy stretched along its length, squashed across and inflated
around one end (vertex i of the copy is the truth for vertex i), mapped by mobius-register
without landmarks and with 5 in each landmark mode, scored by mobius-score (geodesic mean
over sqrt(target area)). The table of docs/landmarks.md ("Measured"):

    python3 landmark_pair_scores.py BINARY_DIR WORK_DIR MESH.off [MESH.off ...]

(BINARY_DIR: the folder of mobius-register and mobius-score, or a build folder holding bin/;
WORK_DIR: where the pairs and maps are written.) test_landmarks.py makes its pair with
stretched_copy().
"""
import json
import os
import subprocess
import sys

import numpy as np

# (stretch along the length, squash across, inflation, end: +1 the front, -1 the back)
VARIANTS = {"a": (1.35, 0.8, 0.6, 1), "b": (1.2, 0.9, 0.8, -1)}
LANDMARKS = 5


def read_off(path):
    with open(path) as stream:
        words = [line.split("#")[0].split() for line in stream]
    words = [w for w in words if w]
    counts = [int(x) for x in words[1][:2]] if words[0] == ["OFF"] else [int(x) for x in words[0][3:5]]
    rows = words[2:] if words[0] == ["OFF"] else words[1:]
    vertices = np.array(rows[:counts[0]], dtype=float)
    faces = np.array([row[1:4] for row in rows[counts[0]:counts[0] + counts[1]]], dtype=np.int64)
    return vertices, faces


def write_off(path, vertices, faces):
    with open(path, "w") as stream:
        stream.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        stream.writelines("%.9g %.9g %.9g\n" % tuple(p) for p in vertices)
        stream.writelines("3 %d %d %d\n" % tuple(t) for t in faces)


def surface_area(vertices, faces):
    corners = vertices[faces]
    return 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum()


def stretched_copy(vertices, variant="a"):
    """The mesh in its principal axes, a copy stretched along the first, squashed along the
    second and blown up around one end (a Gaussian bulge): not isometric, and the automatic
    map misplaces the bulge. Returns (mesh, copy, landmarks): the landmarks are `LANDMARKS`
    vertices in farthest-point order from that end, each its own image."""
    stretch, squash, inflation, end = VARIANTS[variant]
    centered = vertices - vertices.mean(axis=0)
    local = centered @ np.linalg.svd(centered, full_matrices=False)[2].T
    tip = int(np.argmax(end * local[:, 0]))
    distance = np.linalg.norm(local - local[tip], axis=1)
    radius = 0.35 * np.ptp(local[:, 0])
    copy = local * np.array([stretch, squash, 1.0]) + \
        inflation * (local - local[tip]) * np.exp(-(distance / radius) ** 2)[:, None]
    chosen = [tip]
    while len(chosen) < LANDMARKS:
        nearest = np.min(np.linalg.norm(local[:, None] - local[chosen][None], axis=2), axis=1)
        chosen.append(int(np.argmax(nearest)))
    return local, copy, [(v, v) for v in chosen]


def geodesic_mean(binary_dir, source, target, options, out):
    register = [os.path.join(binary_dir, "mobius-register"), source, target, "-o", out,
                "--force", "--quiet", *options]
    result = subprocess.run(register, capture_output=True, text=True)
    if result.returncode != 0:
        return float("nan")
    score = subprocess.run([os.path.join(binary_dir, "mobius-score"), source, target, out + ".csv",
                            "--json"], capture_output=True, text=True, check=True)
    return json.loads(score.stdout)["geodesic"]["mean"]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    binary_dir, work, meshes = sys.argv[1], sys.argv[2], sys.argv[3:]
    if os.path.isdir(os.path.join(binary_dir, "bin")):
        binary_dir = os.path.join(binary_dir, "bin")
    os.makedirs(work, exist_ok=True)
    print("| pair | no landmarks | mode 0 | mode 1 |\n|---|---:|---:|---:|")
    rows = []
    for mesh in meshes:
        vertices, faces = read_off(mesh)
        for variant in VARIANTS:
            name = f"{os.path.splitext(os.path.basename(mesh))[0]}_{variant}"
            local, copy, landmarks = stretched_copy(vertices, variant)
            source, target, marks = (os.path.join(work, name + suffix) for suffix in ("_src.off", "_tgt.off", ".csv"))
            write_off(source, local, faces)
            write_off(target, copy, faces)
            with open(marks, "w") as stream:
                stream.writelines(f"{i},{j}\n" for i, j in landmarks)
            out = os.path.join(work, name + "_map")
            row = [geodesic_mean(binary_dir, source, target, options, out) for options in
                   ([], ["--landmarks", marks, "--landmark-mode", "0"],
                    ["--landmarks", marks, "--landmark-mode", "1"])]
            rows.append(row)
            print(f"| {name} | {row[0]:.4f} | {row[1]:.4f} | {row[2]:.4f} |", flush=True)
    table = np.array(rows)
    print(f"mean over pairs: {table[:, 0].mean():.4f} | {table[:, 1].mean():.4f} | "
          f"{table[:, 2].mean():.4f}; worse with landmarks than without: mode 0 "
          f"{int((table[:, 1] > table[:, 0]).sum())}, mode 1 {int((table[:, 2] > table[:, 0]).sum())} "
          f"of {len(table)}")


if __name__ == "__main__":
    main()
