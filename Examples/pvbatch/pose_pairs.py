"""The posed-pairs collection of make_test_collection.py (--poses): posed and remeshed copies
of CGAL's meshes, the pairs between them, and their ground truth, direct and mirrored.

Every copy (a version) is the original mesh or a remeshed copy of it, at rest or in one of
the mesh's poses, then turned and moved rigidly (a random rotation seeded by its name, so
the files are the same on every run). A version's vertices have known places on the rest
original (the vertex itself, or for a remeshed copy its closest surface point), which gives
the truth of any pair of versions of one mesh.
"""
import os
import zlib

import numpy as np

import posed_copies
from remeshed_copies import RemeshedCopy, Surface, interpolate

# Vertices of the remeshed copies "ra" and "rb", per vertex of the original. (Copies of the
# cow with 0.7, 1.0 or 1.1 times its vertices get a conformal map mobius-register refuses as
# degenerate, at 164a604; 0.8 and 1.2 map.)
REMESHED_SIZES = {"ra": 0.8, "rb": 1.2}
# A mirror truth is written only where the rest mesh is bilaterally symmetric: reflected
# across its fitted plane, its points lie within this (median, in sqrt(area)) of itself.
# The cow and camel fit within 0.0001, the bear 0.0035, the man 0.0093 (his legs and arms
# are not posed alike); the charging bull, 0.054, gets none.
MIRROR_RESIDUAL = 0.02


class Mesh:
    """One original mesh, its rig, remeshed copies and mirror plane, computed when needed."""

    def __init__(self, name, points, faces):
        self.name, self.points, self.faces = name, points, faces
        self.rig = posed_copies.Rig(name, points, faces)
        self.surface = Surface(points, faces)
        self.remeshed = {}
        self.posed = {}
        self.plane = mirror_plane(self.surface, posed_copies.MESHES[name][3])

    def remeshed_copy(self, label):
        if label not in self.remeshed:
            self.remeshed[label] = RemeshedCopy(self.points, self.faces,
                                                round(REMESHED_SIZES[label] * len(self.points)))
        return self.remeshed[label]

    def posed_original(self, pose):
        """The posed original and its rotations, checked for plausibility once."""
        if pose not in self.posed:
            points, rotations = self.rig.pose(pose)
            problems, measured = self.rig.check(points, rotations)
            if problems:
                raise ValueError(f"{self.name} {pose}: not plausible: {'; '.join(problems)}")
            print(f"{self.name} {pose}: {measured}")
            self.posed[pose] = (points, rotations)
        return self.posed[pose]


class Version:
    """The original (remesh None) or a remeshed copy, at rest (pose None) or posed."""

    def __init__(self, mesh, remesh, pose):
        self.mesh, self.remesh, self.pose = mesh, remesh, pose
        self.name = "_".join([mesh.name] + [part for part in (remesh, pose) if part] +
                             ([] if pose else ["rest"]))
        copy = mesh.remeshed_copy(remesh) if remesh else None
        self.faces = copy.faces if copy else mesh.faces
        # Rest positions, and the closest point on the rest original of each vertex.
        self.rest = copy.points if copy else mesh.points
        self.on_original = interpolate(mesh.points, mesh.faces, copy.triangles, copy.weights) if copy else mesh.points
        self.location = (copy.triangles, copy.weights) if copy else None

    def points(self):
        """The version's points as written: posed, then turned and moved rigidly."""
        points = self.rest
        if self.pose:
            posed, rotations = self.mesh.posed_original(self.pose)
            points = (self.mesh.remeshed[self.remesh].posed(self.mesh.faces, posed, rotations)
                      if self.remesh else posed)
        rng = np.random.default_rng(zlib.crc32(self.name.encode()))
        q, r = np.linalg.qr(rng.normal(size=(3, 3)))
        rotation = q * np.sign(np.diag(r))
        rotation *= np.linalg.det(rotation)
        return points @ rotation.T + rng.normal(scale=0.1, size=3)


def mirror_plane(surface, side_axis, samples=2000, iterations=8):
    """The plane of bilateral symmetry of a rest mesh, fitted from the given left-right axis:
    reflect, find the closest surface points, and refit the plane to the pairs (the 80% that
    fit best, so that an asymmetric pose of a limb does not tilt it). Returns (unit normal,
    offset, median residual in sqrt(area)) or None when the mesh is not symmetric enough."""
    points = surface.points[:: max(1, len(surface.points) // samples)]
    normal = np.asarray(side_axis, float) / np.linalg.norm(side_axis)
    offset = surface.points.mean(axis=0) @ normal
    for _ in range(iterations):
        reflected = points - 2 * ((points @ normal) - offset)[:, None] * normal
        partners = interpolate(surface.points, surface.faces, *surface.locate(reflected))
        residual = np.linalg.norm(reflected - partners, axis=1)
        best = residual <= np.percentile(residual, 80)
        across = points[best] - partners[best]
        _, vectors = np.linalg.eigh(across.T @ across)
        normal = vectors[:, 2] * np.sign(vectors[:, 2] @ normal)
        offset = ((points[best] + partners[best]) / 2 @ normal).mean()
    corners = surface.points[surface.faces]
    scale = np.sqrt(0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1).sum())
    fit = np.median(residual) / scale
    return (normal, offset, fit) if fit <= MIRROR_RESIDUAL else None


def truth_rows(source, target, mirrored=False):
    """The true image of each source vertex on the target, as mobius-score --truth lines: a
    target vertex where it is one, else a target triangle and barycentric weights. Mirrored:
    the image of the source vertex's mirror counterpart."""
    mesh = source.mesh
    places = source.on_original
    location = source.location
    if mirrored:
        normal, offset, _ = mesh.plane
        places = places - 2 * ((places @ normal) - offset)[:, None] * normal
        location = mesh.surface.locate(places)
        places = interpolate(mesh.points, mesh.faces, *location)
    if target.remesh is None and location is None:
        return [f"{i}\n" for i in range(len(places))]
    if target.remesh is not None:
        location = Surface(target.rest, target.faces).locate(places)
    triangles, weights = location
    return [f"{t} {w[0]:.9g} {w[1]:.9g} {w[2]:.9g}\n" for t, w in zip(triangles, weights)]


def pairs_of(mesh):
    """Rest -> first pose, each pose -> the next, remeshed copy ra at rest -> the last pose,
    and ra in the first pose -> remeshed copy rb in the last: ((remesh, pose), (remesh, pose))."""
    poses = list(mesh.rig.poses)
    specs = [((None, None), (None, poses[0]))]
    specs += [((None, a), (None, b)) for a, b in zip(poses, poses[1:])]
    return specs + [(("ra", None), (None, poses[-1])), (("ra", poses[0]), ("rb", poses[-1]))]


def write_pairs(output, mesh, specs, write_off):
    """Writes the versions and truths of the pairs `specs` of one mesh into `output`; returns
    their pairs.csv rows (source, target, truth, mirror_truth: file names in `output`)."""
    os.makedirs(os.path.join(output, "truth"), exist_ok=True)
    rows, written = [], set()
    for source, target in ((Version(mesh, *s), Version(mesh, *t)) for s, t in specs):
        for version in (source, target):
            if version.name not in written:
                write_off(os.path.join(output, version.name + ".off"), version.points(),
                          [[str(v) for v in face] for face in version.faces])
                written.add(version.name)
        stem = os.path.join("truth", f"{source.name}--{target.name}")
        with open(os.path.join(output, stem + ".txt"), "w") as f:
            f.writelines(truth_rows(source, target))
        mirror = ""
        if mesh.plane:
            mirror = stem + ".mirror.txt"
            with open(os.path.join(output, mirror), "w") as f:
                f.writelines(truth_rows(source, target, mirrored=True))
        rows.append({"source": source.name + ".off", "target": target.name + ".off",
                     "truth": stem + ".txt", "mirror_truth": mirror})
        print(f"  {source.name} -> {target.name}")
    return rows


def write_collection(output, mesh_files, read_off, write_off):
    """Every mesh's pairs_of, and OUTPUT/pairs.csv listing them all."""
    rows = []
    for mesh_file in mesh_files:
        name = os.path.splitext(os.path.basename(mesh_file))[0]
        points, polygons = read_off(mesh_file)
        mesh = Mesh(name, points, np.array(polygons, dtype=np.int64))
        print(f"{name}: mirror plane " + ("fits within %.4f sqrt(area)" % mesh.plane[2] if mesh.plane else "none"))
        rows += write_pairs(output, mesh, pairs_of(mesh), write_off)
    with open(os.path.join(output, "pairs.csv"), "w") as f:
        f.write("source,target,truth,mirror_truth\n")
        f.writelines(",".join(row.values()) + "\n" for row in rows)
