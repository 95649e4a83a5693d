"""Runs mobius-register on pairs with known ground truth and scores each map with mobius-score
against the direct truth and, where there is one, the mirror truth (the image of each point's
left-right counterpart); tells maps that are mirrored or turned from maps that are right.

Used by the PosePairs test and on its own over a collection written by
`make_test_collection.py --poses OUT MESH...`:

    python3 pose_pair_scores.py BINARY_DIR COLLECTION_DIR [mobius-register options...]

(BINARY_DIR: the folder of mobius-register and mobius-score, or a build folder holding bin/)

prints one Markdown row per pair of COLLECTION_DIR/pairs.csv and a summary line.
"""
import csv
import json
import os
import subprocess
import sys
import time

import numpy as np

# A map is right when its geodesic mean error against the direct truth is at most this (in
# sqrt(target area)); docs/accuracy.md: the refined maps of bent copies score 0.004-0.02, those
# of FAUST_r pose pairs that work about 0.036.
RIGHT = 0.05
# Geodesic errors are computed for at most this many source vertices (an even subsample).
GEODESIC_SAMPLES = 2000


def read_off(path):
    words = open(path).read().split()
    vertices, faces = int(words[1]), int(words[2])
    points = np.array(words[4:4 + 3 * vertices], dtype=float).reshape(vertices, 3)
    cells = np.array(words[4 + 3 * vertices:4 + 3 * vertices + 4 * faces], dtype=np.int64)
    return points, cells.reshape(faces, 4)[:, 1:]


def orientation_agreement(source, target, map_csv):
    """Share of the source's area whose mapped triangles face the way the target's triangles
    under them do: near 1 for an orientation-preserving map (right or turned), near 0 for a
    mirror image."""
    source_points, source_faces = read_off(source)
    target_points, target_faces = read_off(target)
    columns = np.genfromtxt(map_csv, delimiter=",", names=True)
    mapped = np.stack([columns["mapped_x"], columns["mapped_y"], columns["mapped_z"]], axis=1)
    under = target_faces[columns["target_triangle"].astype(np.int64)[source_faces[:, 0]]]

    def normals(points, faces):
        return np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    agree = (normals(mapped, source_faces) * normals(target_points, under)).sum(axis=1) > 0
    area = np.linalg.norm(normals(source_points, source_faces), axis=1)
    return float(area[agree].sum() / area.sum())


def geodesic(score, source, target, map_csv, truth):
    result = subprocess.run([score, source, target, map_csv, "--truth", truth, "--json",
                             "--max-geodesic", str(GEODESIC_SAMPLES)], capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"mobius-score {source} {target}: {result.stderr.strip()}")
    figures = json.loads(result.stdout)["geodesic"]
    return {"mean": figures["mean"], "median": figures["median"],
            "within_0.05": figures["within"]["0.05"], "within_0.1": figures["within"]["0.1"]}


def verdict(direct, mirror, agreement):
    """right, mirrored (closer to the mirror truth, orientation reversed), turned (closer to
    the mirror truth, orientation kept: a half turn of a bilateral shape) or inaccurate (not
    within RIGHT, and nearer the direct truth, or without a mirror truth to tell)."""
    if direct["mean"] <= RIGHT:
        return "right"
    if mirror is not None and mirror["mean"] < direct["mean"]:
        return "mirrored" if agreement < 0.5 else "turned"
    return "inaccurate"


def run_pair(binary_dir, folder, row, work, options=()):
    """Maps one pair of the collection and scores it: a dict of the figures and the verdict
    (verdict 'refused' with the message when mobius-register declines the pair)."""
    source, target = (os.path.join(folder, row[k]) for k in ("source", "target"))
    output = os.path.join(work, os.path.splitext(row["source"])[0] + "--" + os.path.splitext(row["target"])[0])
    start = time.time()
    mapped = subprocess.run([os.path.join(binary_dir, "mobius-register"), source, target, "-o", output,
                             "--quiet", "--force", *options], capture_output=True, text=True)
    seconds = time.time() - start
    if mapped.returncode != 0:
        return {"pair": f"{row['source']} -> {row['target']}", "verdict": "refused",
                "message": mapped.stderr.strip(), "seconds": seconds}
    score = os.path.join(binary_dir, "mobius-score")
    direct = geodesic(score, source, target, output + ".csv", os.path.join(folder, row["truth"]))
    mirror = (geodesic(score, source, target, output + ".csv", os.path.join(folder, row["mirror_truth"]))
              if row.get("mirror_truth") else None)
    agreement = orientation_agreement(source, target, output + ".csv")
    return {"pair": f"{row['source']} -> {row['target']}", "direct": direct, "mirror": mirror,
            "orientation": agreement, "verdict": verdict(direct, mirror, agreement), "seconds": seconds}


def table_row(result):
    if result["verdict"] == "refused":
        return f"| {result['pair']} | refused: {result['message']} | | | | | | |"
    d, m = result["direct"], result["mirror"]
    mirror = f"{m['mean']:.3f}" if m else "-"
    return (f"| {result['pair']} | {d['mean']:.4f} | {d['median']:.4f} | {100 * d['within_0.05']:.1f} | "
            f"{100 * d['within_0.1']:.1f} | {mirror} | {result['orientation']:.2f} | {result['verdict']} | "
            f"{result['seconds']:.1f} |")


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    binary_dir, folder, options = sys.argv[1], sys.argv[2], sys.argv[3:]
    if not os.path.exists(os.path.join(binary_dir, "mobius-register")):
        binary_dir = os.path.join(binary_dir, "bin")  # a build folder
    work = os.path.join(folder, "maps")
    os.makedirs(work, exist_ok=True)
    print("| pair | geodesic mean | median | % within 0.05 | % within 0.1 | mean vs mirror truth | "
          "orientation kept | verdict | seconds |")
    print("|---|---:|---:|---:|---:|---:|---:|---|---:|")
    results = []
    with open(os.path.join(folder, "pairs.csv")) as f:
        for row in csv.DictReader(f):
            results.append(run_pair(binary_dir, folder, row, work, options))
            print(table_row(results[-1]), flush=True)
    means = [r["direct"]["mean"] for r in results if "direct" in r]
    counts = {v: sum(r["verdict"] == v for r in results) for v in ("right", "mirrored", "turned", "inaccurate", "refused")}
    print(f"\n{len(results)} pairs: " + ", ".join(f"{n} {v}" for v, n in counts.items()) +
          (f"; geodesic mean over pairs {np.mean(means):.4f}, median pair {np.median(means):.4f}" if means else ""))


if __name__ == "__main__":
    main()
