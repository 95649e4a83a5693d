"""Skinning a triangle mesh by a small hand-made skeleton: which bone moves each vertex, how
much (smooth weights), and where a pose puts it (dual-quaternion skinning). Plain numpy.

A skeleton is a list of Bone, parents before children. A bone rotates about its `head`
(the joint with its parent) and runs to its `tail`; both are points in the rest mesh's own
coordinates. A pose is {bone name: (axis, degrees)}: the bone's rotation about its head,
the axis given in rest coordinates, applied before the parent's motion (forward kinematics).
"""
import heapq
from dataclasses import dataclass
from typing import Optional

import numpy as np


@dataclass
class Bone:
    """A bone rotates about its `head` and runs to its `tail`. It owns the vertices on the far
    side of its cut (a plane through `cut_point`, default the head, with normal `cut_normal`,
    default head to tail) that are connected to its tail without crossing the cut, unless a
    bone further down the chain owns them. The default cut suits a limb sticking out; an arm
    hanging along the body needs a cut from the armpit to the shoulder's top. A tail lying
    against the rump, which no plane separates, is instead given by its `reach`: the vertices
    within that edge-path distance of its tail."""
    name: str
    parent: Optional[str]
    head: tuple
    tail: tuple
    cut_normal: Optional[tuple] = None
    cut_point: Optional[tuple] = None
    reach: Optional[float] = None

    def cut(self):
        head, tail = np.asarray(self.head, float), np.asarray(self.tail, float)
        normal = np.asarray(self.cut_normal if self.cut_normal is not None else tail - head, float)
        point = np.asarray(self.cut_point if self.cut_point is not None else head, float)
        return point, normal / np.linalg.norm(normal)


def mesh_graph(points, faces):
    """The edge graph as CSR arrays (start, neighbours, lengths)."""
    faces = np.asarray(faces)
    pairs = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    pairs = np.unique(np.sort(pairs, axis=1), axis=0)
    both = np.concatenate([pairs, pairs[:, ::-1]])
    both = both[np.argsort(both[:, 0], kind="stable")]
    start = np.searchsorted(both[:, 0], np.arange(len(points) + 1))
    lengths = np.linalg.norm(points[both[:, 0]] - points[both[:, 1]], axis=1)
    return start, both[:, 1], lengths


def components(members, graph):
    """Connected components of the vertices where `members` is true (label array, -1 outside)."""
    start, neighbours, _ = graph
    label = np.full(len(members), -1)
    count = 0
    for seed in np.flatnonzero(members):
        if label[seed] >= 0:
            continue
        label[seed] = count
        stack = [seed]
        while stack:
            v = stack.pop()
            for w in neighbours[start[v]:start[v + 1]]:
                if members[w] and label[w] < 0:
                    label[w] = count
                    stack.append(w)
        count += 1
    return label, count


def bone_labels(points, graph, bones):
    """Each vertex's bone (index into `bones`): the last bone, in skeleton order, whose cut
    region holds it; the root bone owns the rest. A bone whose region is empty is an error
    (its cut or tail is misplaced)."""
    labels = np.zeros(len(points), dtype=int)
    for b, bone in enumerate(bones[1:], start=1):
        if bone.reach is not None:
            tip = np.argmin(np.linalg.norm(points - bone.tail, axis=1))
            labels[np.isfinite(distances_from([tip], graph, bone.reach))] = b
            continue
        point, normal = bone.cut()
        side = (points - point) @ normal > 0
        if not side.any():
            raise ValueError(f"bone {bone.name}: no vertex beyond its cut")
        piece, _ = components(side, graph)
        candidates = np.flatnonzero(side)
        nearest = candidates[np.argmin(np.linalg.norm(points[candidates] - bone.tail, axis=1))]
        labels[piece == piece[nearest]] = b
    return labels


def distances_from(sources, graph, cutoff):
    """Edge-path distance from a set of vertices, up to `cutoff` (inf beyond)."""
    start, neighbours, lengths = graph
    distance = np.full(len(start) - 1, np.inf)
    distance[sources] = 0.0
    heap = [(0.0, v) for v in sources]
    while heap:
        d, v = heapq.heappop(heap)
        if d > distance[v]:
            continue
        for k in range(start[v], start[v + 1]):
            w, e = neighbours[k], d + lengths[k]
            if e < distance[w] and e < cutoff:
                distance[w] = e
                heapq.heappush(heap, (e, w))
    return distance


def skinning_weights(points, faces, bones, blend=1.0):
    """Smooth weights (n x bones, rows summing to 1) and the labels they blend. A vertex at
    edge-path distance d from a bone's region weighs that bone (1 - (d/s)^2)^2, where s is
    `blend` times the limb's radius at the joint between the two regions (the median distance
    of the child's border vertices to its head). Inside a region the weight is 1, on the
    border two regions share half-half, and the blend ends a limb radius away on each side:
    a joint bends over about the width of the limb."""
    graph = mesh_graph(points, faces)
    labels = bone_labels(points, graph, bones)
    start, neighbours, _ = graph
    owner = np.repeat(np.arange(len(points)), np.diff(start))
    border = labels[owner] != labels[neighbours]
    radius = np.full(len(bones), np.inf)
    for b, bone in enumerate(bones):
        ring = np.unique(owner[border & (labels[owner] == b)])
        if len(ring):
            radius[b] = np.median(np.linalg.norm(points[ring] - bone.head, axis=1))
    radius[0] = np.inf  # the root has no joint: a border takes the other bone's radius
    weights = np.zeros((len(points), len(bones)))
    weights[np.arange(len(points)), labels] = 1.0
    for b in range(len(bones)):
        region = labels == b
        if not region.any():
            continue
        reach = blend * (radius[b] if np.isfinite(radius[b]) else radius[np.isfinite(radius)].max())
        d = distances_from(np.flatnonzero(region), graph, reach)
        near = np.flatnonzero(~region & np.isfinite(d))
        s = d[near] / (blend * np.minimum(radius[b], radius[labels[near]]))
        weights[near, b] = np.where(s < 1, (1 - s ** 2) ** 2, 0.0)
    return weights / weights.sum(axis=1, keepdims=True), labels


def rotation(axis, degrees):
    axis = np.asarray(axis, float)
    axis = axis / np.linalg.norm(axis)
    angle = np.radians(degrees)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def bone_transforms(bones, pose):
    """Each bone's rigid motion (R, t), x -> R x + t, by forward kinematics. Unknown bone
    names in the pose are an error."""
    names = [bone.name for bone in bones]
    unknown = set(pose) - set(names)
    if unknown:
        raise ValueError(f"pose names bones the skeleton does not have: {sorted(unknown)}")
    transforms = {}
    for bone in bones:
        local = rotation(*pose[bone.name]) if bone.name in pose else np.eye(3)
        head = np.asarray(bone.head, float)
        R, t = local, head - local @ head
        if bone.parent is not None:
            P, s = transforms[bone.parent]
            R, t = P @ R, P @ t + s
        transforms[bone.name] = (R, t)
    return [transforms[name] for name in names]


def quaternion(R):
    """Unit quaternion (w, x, y, z) of a rotation matrix."""
    w = np.sqrt(max(0.0, 1 + np.trace(R))) / 2
    x = np.copysign(np.sqrt(max(0.0, 1 + R[0, 0] - R[1, 1] - R[2, 2])) / 2, R[2, 1] - R[1, 2])
    y = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] + R[1, 1] - R[2, 2])) / 2, R[0, 2] - R[2, 0])
    z = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] - R[1, 1] + R[2, 2])) / 2, R[1, 0] - R[0, 1])
    return np.array([w, x, y, z])


def multiply(a, b):
    """Quaternion products, row by row (arrays of shape (..., 4))."""
    aw, ax, ay, az = np.moveaxis(a, -1, 0)
    bw, bx, by, bz = np.moveaxis(b, -1, 0)
    return np.stack([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw], -1)


def blended_dual_quaternions(weights, transforms):
    """Each vertex's unit dual quaternion (real, dual parts): the normalized weighted sum of its
    bones' (Kavan et al. 2007), which keeps a twisted or bent joint's volume where linear
    blending collapses it."""
    real = np.array([quaternion(R) for R, _ in transforms])
    dual = np.array([0.5 * multiply(np.concatenate([[0.0], t]), q) for (_, t), q in zip(transforms, real)])
    # Every bone's quaternion on the hemisphere of the vertex's main bone: shortest blends.
    main = real[np.argmax(weights, axis=1)]
    signs = np.sign(main @ real.T)
    signs[signs == 0] = 1
    blend_real, blend_dual = (weights * signs) @ real, (weights * signs) @ dual
    norm = np.linalg.norm(blend_real, axis=1, keepdims=True)
    return blend_real / norm, blend_dual / norm


def rotate(quaternions, vectors):
    """Vectors rotated by unit quaternions, row by row."""
    conjugate = quaternions * np.array([1, -1, -1, -1])
    pure = np.concatenate([np.zeros((len(vectors), 1)), vectors], axis=1)
    return multiply(multiply(quaternions, pure), conjugate)[:, 1:]


def dual_quaternion_skinning(points, weights, transforms):
    """Posed points, and each vertex's blended rotation (unit quaternions)."""
    real, dual = blended_dual_quaternions(weights, transforms)
    translation = 2 * multiply(dual, real * np.array([1, -1, -1, -1]))[:, 1:]
    return rotate(real, points) + translation, real
