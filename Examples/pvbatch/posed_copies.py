"""Large pose changes of CGAL's CC0 meshes with the vertex numbering kept (exact ground truth):
skinning by the hand-made skeletons of skeletons.py, and a check that a pose stays plausible.
Plain numpy.

A pose is plausible when the skinned mesh does not cut through itself anywhere except in
small folds on the inside of a bent joint: every mesh edge that crosses a triangle (not
touching it) in the posed mesh but not in the rest mesh must join surface points that are
near each other on the rest mesh, within FOLD times the square root of its area along its
edges, and the triangles turned over in such folds must cover at most FOLDED_AREA of the
surface. A limb pushed into the body, or two legs through each other, join points far apart
and fail. (Some of CGAL's meshes cut through themselves a little at rest already: the man
818 times, the cow 84; those crossings are not counted.) Connectivity is untouched, so a
closed manifold stays one.
"""
import numpy as np

import skeletons
import skinning

# Blend width of the skinning weights, in limb radii at each joint (skinning.skinning_weights):
# wider blends fold less on the inside of a bend but web more across an armpit.
BLEND = 1.0
# Largest rest-surface distance, in sqrt(area), between two sides of a fold at a joint.
FOLD = 0.15
# Largest share of the surface turned over in folds.
FOLDED_AREA = 0.005

# Each mesh's vertex count (the skeleton is in its coordinates), bones, poses, and the axis
# from its right side to its left (the normal of its plane of bilateral symmetry).
MESHES = {
    "man": (17495, skeletons.MAN, skeletons.MAN_POSES, (-1, 0, 0)),
    "cow": (2904, skeletons.COW, skeletons.COW_POSES, (0, 0, -1)),
    "bull": (6200, skeletons.BULL, skeletons.BULL_POSES, (0, 0, 1)),
    "camel": (9770, skeletons.CAMEL, skeletons.CAMEL_POSES, (1, 0, 0)),
    "bear": (13826, skeletons.BEAR, skeletons.BEAR_POSES, (1, 0, 0)),
}


def skeleton(name, points):
    """The bones and poses of the mesh `name`; an error when the mesh is not the one the
    skeleton was made for (its joints would be meaningless)."""
    if name not in MESHES:
        raise ValueError(f"{name}: no skeleton (there are: {', '.join(MESHES)})")
    count, bones, poses, _ = MESHES[name]
    if len(points) != count:
        raise ValueError(f"{name}: {len(points)} vertices, but its skeleton was made for CGAL's "
                         f"{name}.off with {count}")
    return bones, poses


class Rig:
    """A mesh with its skeleton and skinning weights, ready to pose."""

    def __init__(self, name, points, faces):
        self.points, self.faces = np.asarray(points, float), np.asarray(faces)
        self.bones, self.poses = skeleton(name, self.points)
        self.weights, self.labels = skinning.skinning_weights(self.points, self.faces, self.bones, BLEND)
        self.rest_crossings = None

    def pose(self, pose_name):
        """The posed points, and each vertex's rotation (unit quaternions)."""
        transforms = skinning.bone_transforms(self.bones, self.poses[pose_name])
        return skinning.dual_quaternion_skinning(self.points, self.weights, transforms)

    def check(self, posed, rotations):
        """Why the posed mesh is not plausible (empty when it is), and what was measured."""
        far, new = self.penetrations(posed)
        flipped = flipped_triangles(self.points, posed, self.faces, rotations)
        folded = triangle_areas(self.points, self.faces)[flipped].sum() / area(self.points, self.faces)
        problems = []
        if far:
            parts = sorted({(self.bones[self.labels[v]].name, self.bones[self.labels[self.faces[t, 0]]].name)
                            for v, t in far})
            problems.append(f"{len(far)} crossings between parts far apart ({parts[:4]})")
        if folded > FOLDED_AREA:
            problems.append(f"{flipped.sum()} triangles turned over, {100 * folded:.2f}% of the area")
        return problems, {"far_crossings": len(far), "new_crossings": new, "flipped": int(flipped.sum()),
                          "folded_area": round(float(folded), 5)}

    def penetrations(self, posed):
        """New crossings of the posed mesh whose two sides are more than FOLD sqrt(area)
        apart on the rest surface, as (edge vertex, triangle) pairs; and the count of new
        crossings in all (folds included)."""
        if self.rest_crossings is None:
            self.rest_crossings = set(zip(*crossings(self.points, self.faces)[:2]))
        edges_hit, triangles_hit, edges = crossings(posed, self.faces)
        new = [(e, t) for e, t in zip(edges_hit, triangles_hit) if (e, t) not in self.rest_crossings]
        reach = FOLD * np.sqrt(area(self.points, self.faces))
        graph = skinning.mesh_graph(self.points, self.faces)
        far = []
        for vertex in sorted({edges[e, 0] for e, _ in new}):
            near = np.isfinite(skinning.distances_from([vertex], graph, reach))
            far += [(vertex, t) for e, t in new if edges[e, 0] == vertex and not near[self.faces[t]].any()]
        return far, len(new)


def triangle_areas(points, faces):
    p = points[faces]
    return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def area(points, faces):
    return triangle_areas(points, faces).sum()


def unique_edges(faces):
    pairs = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    return np.unique(np.sort(pairs, axis=1), axis=0)


def grid_cells(lo, hi, size):
    """(cell key, item) for every cell of a grid of spacing `size` that box `item` overlaps."""
    first = np.floor(lo / size).astype(np.int64)
    span = np.floor(hi / size).astype(np.int64) - first + 1
    keys, items = [], []
    for offset in np.ndindex(*span.max(axis=0)):
        inside = np.flatnonzero((np.array(offset) < span).all(axis=1))
        cell = first[inside] + offset
        keys.append((cell[:, 0] * 2 ** 21 + cell[:, 1]) * 2 ** 21 + cell[:, 2])
        items.append(inside)
    return np.concatenate(keys), np.concatenate(items)


def overlapping_boxes(a_lo, a_hi, b_lo, b_hi, size):
    """Pairs (i, j) of boxes of list a and list b that overlap, found through a grid."""
    a_key, a_item = grid_cells(a_lo, a_hi, size)
    b_key, b_item = grid_cells(b_lo, b_hi, size)
    order = np.argsort(b_key, kind="stable")
    b_key, b_item = b_key[order], b_item[order]
    start, stop = np.searchsorted(b_key, a_key, "left"), np.searchsorted(b_key, a_key, "right")
    count = stop - start
    i = np.repeat(a_item, count)
    j = b_item[np.repeat(start - np.cumsum(count) + count, count) + np.arange(count.sum())]
    pair = np.unique(i * len(b_lo) + j)
    i, j = pair // len(b_lo), pair % len(b_lo)
    keep = (a_lo[i] <= b_hi[j]).all(axis=1) & (b_lo[j] <= a_hi[i]).all(axis=1)
    return i[keep], j[keep]


def crossings(points, faces):
    """Where the mesh cuts through itself: (edge indices, triangle indices, edges) of every
    edge that crosses the inside of a triangle it has no vertex in common with."""
    faces = np.asarray(faces)
    edges = unique_edges(faces)
    ends = points[edges]
    corners = points[faces]
    size = np.median(np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1))
    e, t = overlapping_boxes(ends.min(axis=1), ends.max(axis=1), corners.min(axis=1),
                             corners.max(axis=1), size)
    touching = (faces[t] == edges[e, :1]).any(axis=1) | (faces[t] == edges[e, 1:]).any(axis=1)
    e, t = e[~touching], t[~touching]
    # Segment against triangle (Moeller-Trumbore), strictly inside both.
    origin, direction = points[edges[e, 0]], points[edges[e, 1]] - points[edges[e, 0]]
    v0, e1, e2 = corners[t, 0], corners[t, 1] - corners[t, 0], corners[t, 2] - corners[t, 0]
    h = np.cross(direction, e2)
    det = (e1 * h).sum(axis=1)
    valid = np.abs(det) > 1e-300
    inverse = np.where(valid, 1 / np.where(valid, det, 1), 0)
    s = origin - v0
    u = inverse * (s * h).sum(axis=1)
    q = np.cross(s, e1)
    v = inverse * (direction * q).sum(axis=1)
    w = inverse * (e2 * q).sum(axis=1)
    hit = valid & (u > 0) & (v > 0) & (u + v < 1) & (w > 0) & (w < 1)
    return e[hit], t[hit], edges


def flipped_triangles(rest, posed, faces, rotations):
    """The triangles turned over (mask): their normal against their rest normal turned by the
    skinning's rotation at their first corner (a fold on the inside of a bent joint)."""
    def normals(p):
        return np.cross(p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]])
    expected = skinning.rotate(rotations[faces[:, 0]], normals(rest))
    return (expected * normals(posed)).sum(axis=1) <= 0
