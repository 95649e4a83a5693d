"""Real-world mesh defects made on a clean closed mesh, with the ground truth kept: every
defect keeps the mesh's vertices first and in their order (it removes triangles, or adds
triangles and vertices after them), so vertex i of a defective copy is vertex i of the clean
mesh. Plain numpy; used by test_defect_corpus.py and to measure the repair on any mesh.

Each defect returns (points, faces, zone): the defective mesh and the vertices of the clean
mesh at and around the defect (the repaired region, where a map is not expected to be as
good as on the clean mesh).

    duplicate      one triangle listed twice (as in 11 of 37 public human meshes)
    fin            a non-manifold fan: three triangles hanging off one edge
    flipped        a patch of 300 triangles turned over
    holes          three holes of 0.1% of the area each (a body's mouth and eyes)
    loose          two small closed parts (eyeballs) and ten loose triangles beside the mesh
    seams          the mesh cut into three pieces whose seam vertices are duplicated
    scan           twenty small holes of 0.01% of the area each, and noise (`noise`: 0.1% of
                   sqrt(area) along each axis; the map of a scan is compared with that of
                   the noisy mesh without holes)
    fused          two near parts of the surface that face each other (a hand and a thigh)
                   pressed together and joined by a short tube from a contact 1.4% of
                   sqrt(area) across (2 cm on a body): genus 1. (The repair cuts a handle's
                   shortest loop: a contact wider than the wrist would be cut at the wrist.)
    fused_twice    two such places far apart: genus 2
"""
import heapq

import numpy as np

from landmark_pair_scores import read_off, surface_area, write_off  # noqa: F401 (read_off, write_off: for callers)

DEFECTS = ("duplicate", "fin", "flipped", "holes", "loose", "seams", "scan", "fused", "fused_twice")


def vertex_normals(points, faces):
    p = points[faces]
    normals = np.zeros_like(points)
    face_normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    for k in range(3):
        np.add.at(normals, faces[:, k], face_normals)
    return normals / np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)


def neighbours(count, faces):
    lists = [set() for _ in range(count)]
    for a, b, c in faces:
        lists[a].update((b, c))
        lists[b].update((a, c))
        lists[c].update((a, b))
    return lists


def grow(seeds, adjacency, rings):
    """The vertices within `rings` edges of the seeds."""
    region, front = set(seeds), set(seeds)
    for _ in range(rings):
        front = {w for v in front for w in adjacency[v]} - region
        region |= front
    return region


def disc(points, adjacency, centre, radius):
    """The vertices reached from `centre` along edges without leaving the ball of `radius`."""
    region, front = {centre}, [centre]
    while front:
        front = {w for v in front for w in adjacency[v]
                 if w not in region and np.linalg.norm(points[w] - points[centre]) <= radius}
        region |= front
    return region


def without_faces_at(faces, vertices):
    """The faces with no corner in `vertices`."""
    inside = np.zeros(faces.max() + 1, bool)
    inside[list(vertices)] = True
    return faces[~inside[faces].any(axis=1)]


def boundary_loops(faces):
    """Boundary loops of a manifold mesh, each in its triangles' direction."""
    directed = {(a, b) for a, b, c in faces for a, b in ((a, b), (b, c), (c, a))}
    following = {a: b for a, b in directed if (b, a) not in directed}
    loops = []
    while following:
        start, loop = next(iter(following)), []
        vertex = start
        while vertex in following:
            loop.append(vertex)
            vertex = following.pop(vertex)
        loops.append(loop)
    return loops


def spread_vertices(points, count, rng, away_from=()):
    """`count` vertices far apart (farthest points from a random start)."""
    chosen = [int(rng.integers(len(points)))] if not len(away_from) else []
    nearest = np.full(len(points), np.inf)
    for v in list(away_from) + chosen:
        nearest = np.minimum(nearest, np.linalg.norm(points - points[v], axis=1))
    while len(chosen) < count:
        chosen.append(int(np.argmax(nearest)))
        nearest = np.minimum(nearest, np.linalg.norm(points - points[chosen[-1]], axis=1))
    return chosen


def scale(points, faces):
    return np.sqrt(surface_area(points, faces))


def duplicate(points, faces, rng):
    t = int(rng.integers(len(faces)))
    return points, np.vstack([faces, faces[t][::-1]]), set(faces[t])


def fin(points, faces, rng):
    t = int(rng.integers(len(faces)))
    a, b, c = faces[t]
    normal = vertex_normals(points, faces)[[a, b]].mean(axis=0)
    size = np.linalg.norm(points[a] - points[b])
    tips = (points[a] + points[b]) / 2 + size * np.array([normal, normal + points[c] - points[a], 1.5 * normal])
    n = len(points)
    added = np.array([[b, a, n], [a, b, n + 1], [b, a, n + 2]])
    return np.vstack([points, tips]), np.vstack([faces, added]), {a, b}


def flipped(points, faces, rng):
    adjacency = neighbours(len(points), faces)
    patch = grow([int(rng.integers(len(points)))], adjacency, 6)
    inside = np.zeros(len(points), bool)
    inside[list(patch)] = True
    turned = faces.copy()
    chosen = np.flatnonzero(inside[faces].all(axis=1))[:300]
    turned[chosen] = turned[chosen][:, ::-1]
    return points, turned, set(faces[chosen].ravel())


def face_points(points, up, front):
    """Where a body's eyes and mouth are, given its up and front directions: on the head (the
    top 12% along `up`) the nose is the point farthest to the front; the eyes are above it
    and to its sides, the mouth below it."""
    up, front = (np.asarray(v, float) / np.linalg.norm(v) for v in (up, front))
    height = points @ up
    extent = height.max() - height.min()
    head = np.flatnonzero(height > height.max() - 0.12 * extent)
    nose = points[head[np.argmax(points[head] @ front)]]
    side = np.cross(up, front)
    targets = [nose + extent * (0.025 * up + 0.02 * side - 0.01 * front),
               nose + extent * (0.025 * up - 0.02 * side - 0.01 * front),
               nose - extent * (0.035 * up + 0.005 * front)]
    return [int(head[np.argmin(np.linalg.norm(points[head] - t, axis=1))]) for t in targets]


def holes(points, faces, rng, centres=None, share=0.001):
    """Holes of about `share` of the area each (a mouth or an eye of a scanned body: about
    0.1%), around `centres` (default: three vertices far apart)."""
    adjacency = neighbours(len(points), faces)
    radius = np.sqrt(share * surface_area(points, faces) / np.pi)
    removed = set()
    for centre in centres if centres is not None else spread_vertices(points, 3, rng):
        removed |= disc(points, adjacency, centre, radius)
    return points, without_faces_at(faces, removed), grow(removed, adjacency, 2)


def sphere(centre, radius, rings=6):
    """A small UV sphere: points and outward faces."""
    points = [centre + radius * np.array([0, 0, 1.0])]
    for i in range(1, rings):
        theta = np.pi * i / rings
        for j in range(2 * rings):
            phi = np.pi * j / rings
            points.append(centre + radius * np.array([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)]))
    points.append(centre - radius * np.array([0, 0, 1.0]))
    faces, around, last = [], 2 * rings, len(points) - 1
    for j in range(around):
        faces.append([0, 1 + j, 1 + (j + 1) % around])
        faces.append([last, 1 + (rings - 2) * around + (j + 1) % around, 1 + (rings - 2) * around + j])
    for i in range(rings - 2):
        for j in range(around):
            a, b = 1 + i * around + j, 1 + i * around + (j + 1) % around
            faces += [[a, a + around, b], [b, a + around, b + around]]
    return np.array(points), np.array(faces)


def loose(points, faces, rng):
    size = scale(points, faces)
    normals = vertex_normals(points, faces)
    parts_points, parts_faces, n = [points], [faces], len(points)
    zone = set()
    for v in spread_vertices(points, 2, rng):
        ball_points, ball_faces = sphere(points[v] + 0.03 * size * normals[v], 0.015 * size)
        parts_points.append(ball_points)
        parts_faces.append(ball_faces + n)
        n += len(ball_points)
        zone.add(v)
    for _ in range(10):
        v = int(rng.integers(len(points)))
        corner = points[v] + 0.02 * size * normals[v]
        parts_points.append(corner + 0.005 * size * rng.standard_normal((3, 3)))
        parts_faces.append(np.array([[n, n + 1, n + 2]]))
        n += 3
    return np.vstack(parts_points), np.vstack(parts_faces), zone


def seams(points, faces, rng):
    """Three pieces cut by two planes across the longest axis; each piece's seam vertices
    get copies of their own (appended), at the same positions."""
    centred = points - points.mean(axis=0)
    axis = np.linalg.eigh(centred.T @ centred)[1][:, 2]
    height = (points[faces].mean(axis=1) - points.mean(axis=0)) @ axis
    cuts = np.quantile(height, [0.35, 0.7])
    piece = np.searchsorted(cuts, height)
    faces = faces.copy()
    extra, zone = [], set()
    owner = {}
    for t in range(len(faces)):
        for k in range(3):
            v = faces[t, k]
            first = owner.setdefault(v, piece[t])
            if first != piece[t]:
                key = (v, piece[t])
                if key not in owner:
                    owner[key] = len(points) + len(extra)
                    extra.append(v)
                faces[t, k] = owner[key]
                zone.add(v)
    return np.vstack([points, points[extra]]), faces, zone


def noise(points, faces, rng):
    """The points moved at random by 0.1% of sqrt(area) along each axis (a scan's noise; not
    a defect the repair sees, the reference that `scan` is compared with)."""
    return points + 0.001 * scale(points, faces) * rng.standard_normal(points.shape), faces, set()


def scan(points, faces, rng):
    noisy = noise(points, faces, rng)[0]
    return holes(noisy, faces, rng, spread_vertices(points, 20, rng), share=0.0001)


def within(points, adjacency, source, reach):
    """The vertices within `reach` of `source` along edges (a bounded Dijkstra)."""
    distance, queue = {source: 0.0}, [(0.0, source)]
    while queue:
        d, v = heapq.heappop(queue)
        if d > distance[v]:
            continue
        for w in adjacency[v]:
            through = d + np.linalg.norm(points[v] - points[w])
            if through <= reach and through < distance.get(w, np.inf):
                distance[w] = through
                heapq.heappush(queue, (through, w))
    return distance


def facing_pairs(points, faces, count, rng, apart):
    """`count` pairs of vertices, each on two parts of the surface that face each other
    across a small gap (a hand beside a thigh): the nearest pairs of vertices whose normals
    are opposite, which lie in front of each other and are far apart along the surface;
    pairs `apart` from each other."""
    size = scale(points, faces)
    adjacency = neighbours(len(points), faces)
    normals = vertex_normals(points, faces)
    sample = rng.choice(len(points), size=min(len(points), 3000), replace=False)
    best = []
    for start in range(0, len(sample), 100):
        chunk = sample[start:start + 100]
        gap = points[None, :, :] - points[chunk, None, :]  # chunk x all
        distance = np.linalg.norm(gap, axis=2)
        facing = (normals[chunk] @ normals.T < -0.7)
        in_front = np.einsum("ijk,ik->ij", gap, normals[chunk]) > 0
        distance[~(facing & in_front)] = np.inf
        nearest = distance.argmin(axis=1)
        best += [(distance[i, nearest[i]], chunk[i], nearest[i]) for i in range(len(chunk))]
    best.sort()
    pairs, near = [], []  # near: the surroundings of candidates found too close along the surface
    for d, a, b in best:
        if not np.isfinite(d) or d < 0.01 * size:
            continue  # a place where the mesh touches or cuts through itself already
        if any(a in region and b in region for region in near) or \
                any(np.linalg.norm(points[a] - points[p]) <= apart for p, _ in pairs):
            continue
        region = within(points, adjacency, a, 0.3 * size)
        if b in region:
            near.append(region)
            continue
        pairs.append((int(a), int(b)))
        if len(pairs) == count:
            break
    return pairs


def zipped_band(loop_a, loop_b, points):
    """Triangles joining two boundary loops (each in its triangles' direction) into a tube
    that runs against both, its ends matched by the points nearest each other."""
    def shares(loop):
        lengths = np.linalg.norm(points[np.roll(loop, -1)] - points[loop], axis=1)
        return np.concatenate([[0], np.cumsum(lengths)[:-1]]) / lengths.sum()
    # The tube runs against both loops: along loop A forward, along loop B backward.
    loop_b = loop_b[::-1]
    start = int(np.argmin(np.linalg.norm(points[loop_b] - points[loop_a[0]], axis=1)))
    loop_b = np.roll(loop_b, -start)
    sa, sb = shares(np.asarray(loop_a)), shares(np.asarray(loop_b))
    i = j = 0
    band = []
    na, nb = len(loop_a), len(loop_b)
    while i < na or j < nb:
        next_a = sa[i + 1] if i + 1 < na else 1.0
        next_b = sb[j + 1] if j + 1 < nb else 1.0
        if j >= nb or (i < na and next_a <= next_b):
            band.append([loop_a[(i + 1) % na], loop_a[i], loop_b[j % nb]])
            i += 1
        else:
            band.append([loop_b[j % nb], loop_b[(j + 1) % nb], loop_a[i % na]])
            j += 1
    return np.array(band)


def pressed_together(points, adjacency, a, b, reach):
    """The points with the surfaces around a and b bent towards each other until a and b
    meet halfway (smoothly, within `reach` of each), as a hand pressed against a thigh; and
    the points moved."""
    moved = points.copy()
    middle, region = (points[a] + points[b]) / 2, set()
    for centre in (a, b):
        around = disc(points, adjacency, centre, reach)
        for v in around:
            t = np.linalg.norm(points[v] - points[centre]) / reach
            moved[v] += (middle - points[centre]) * (1 - t * t) ** 2
        region |= around
    return moved, region


def fuse(points, faces, rng, count):
    """`count` places where two facing parts of the surface are pressed together and joined by
    a short tube from a contact about 1% of sqrt(area) across."""
    size = scale(points, faces)
    adjacency = neighbours(len(points), faces)
    zone = set()
    for a, b in facing_pairs(points, faces, count, rng, apart=0.3 * size):
        points, moved = pressed_together(points, adjacency, a, b, 0.06 * size)
        removed = disc(points, adjacency, a, 0.007 * size) | disc(points, adjacency, b, 0.007 * size)
        kept = without_faces_at(faces, removed)
        new_loops = [loop for loop in boundary_loops(kept) if set(loop) & grow(removed, adjacency, 1)]
        if len(new_loops) != 2:
            continue  # the two discs met: not two places apart
        faces = np.vstack([kept, zipped_band(np.array(new_loops[0]), np.array(new_loops[1]), points)])
        zone |= grow(moved | removed, adjacency, 3)
    return points, faces, zone


def make(defect, points, faces, seed=1, facing=None):
    """The defective copy of the mesh; `facing`: a body's up and front directions, for holes
    at its face (without it the holes are at three vertices far apart)."""
    rng = np.random.default_rng(seed)
    if defect == "holes" and facing is not None:
        return holes(points, faces, rng, face_points(points, *facing))
    if defect == "fused":
        return fuse(points, faces, rng, 1)
    if defect == "fused_twice":
        return fuse(points, faces, rng, 2)
    return globals()[defect](points, faces, rng)
