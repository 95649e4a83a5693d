"""Writes test collections: pairs of meshes whose true correspondence is known, to try the
collection driver or the refinement on and score with mobius-score. Plain python3 with numpy;
reads and writes OFF.

Bent copies (the default): a bent, rotated copy of each mesh given (vertex i of a copy is
vertex i of its original). The bend: the mesh is bent into an arc along its longest principal
axis, of radius 5 times the spread along that axis (lengths across the axis change by a few
percent), then rotated.

Posed pairs (--poses; needs VTK's Python modules for the remeshed copies): large pose changes
of CGAL's man, cow, bull, camel and bear (Debian's libcgal-demo, data/meshes), skinned by the
hand-made skeletons of skeletons.py and checked for plausibility (posed_copies.py), each copy
turned and moved rigidly; and independently remeshed copies (remeshed_copies.py) posed the
same way. Per mesh: rest -> first pose, each pose -> the next, a remeshed copy -> the last
pose, and a remeshed copy in the first pose -> another remeshed copy in the last. Writes
OUTPUT_DIR/NAME*.off, OUTPUT_DIR/truth/SOURCE--TARGET.txt (the true image of each source
vertex, as mobius-score --truth reads it), SOURCE--TARGET.mirror.txt (the image under the
mesh's left-right mirror symmetry, where the rest mesh has one: a map that swaps left and
right scores well against it) and OUTPUT_DIR/pairs.csv listing them.

Usage: python3 make_test_collection.py OUTPUT_DIR MESH.off...
       (writes OUTPUT_DIR/NAME.off, a copy, and OUTPUT_DIR/NAME_bent.off for each mesh)
       python3 make_test_collection.py --poses OUTPUT_DIR MESH.off...
"""
import os
import shutil
import sys

import numpy as np


def read_off(path):
    with open(path) as f:
        tokens = f.read().split()
    if not tokens or tokens[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    vertices, faces = int(tokens[1]), int(tokens[2])
    position = 4
    points = np.array(tokens[position:position + 3 * vertices], dtype=float).reshape(vertices, 3)
    position += 3 * vertices
    polygons = []
    for _ in range(faces):
        count = int(tokens[position])
        polygons.append(tokens[position + 1:position + 1 + count])
        position += 1 + count
    return points, polygons


def bent_copy(points):
    centered = points - points.mean(axis=0)
    spreads, frame = np.linalg.eigh(centered.T @ centered / len(points))  # ascending
    radius = 5 * np.sqrt(spreads[2])
    y = centered @ frame
    angle = y[:, 2] / radius
    arc = np.stack([y[:, 0], (radius + y[:, 1]) * np.cos(angle) - radius,
                    (radius + y[:, 1]) * np.sin(angle)], axis=1)
    c, s = np.cos(0.7), np.sin(0.7)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    return (arc @ frame.T) @ rotation.T


def write_off(path, points, polygons):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(polygons)} 0\n")
        f.writelines("%.9g %.9g %.9g\n" % tuple(p) for p in points)
        f.writelines(f"{len(p)} {' '.join(p)}\n" for p in polygons)


def bent_collection(output, meshes):
    for mesh in meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        points, polygons = read_off(mesh)
        shutil.copyfile(mesh, os.path.join(output, name + ".off"))
        write_off(os.path.join(output, name + "_bent.off"), bent_copy(points), polygons)
        print(f"{name}: {len(points)} vertices, bent copy written")


def main():
    arguments = sys.argv[1:]
    poses = "--poses" in arguments
    arguments = [a for a in arguments if a != "--poses"]
    if len(arguments) < 2:
        raise SystemExit(__doc__)
    output = arguments[0]
    os.makedirs(output, exist_ok=True)
    if poses:
        import pose_pairs  # VTK's Python modules only when asked for
        try:
            pose_pairs.write_collection(output, arguments[1:], read_off, write_off)
        except ValueError as error:  # no skeleton for the mesh, an implausible pose, ...
            raise SystemExit(f"make_test_collection.py: {error}")
    else:
        bent_collection(output, arguments[1:])


if __name__ == "__main__":
    main()
