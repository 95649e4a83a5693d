"""Small meshes generated in the tests (no downloads) and their bytes in every format
mobius-register reads: OFF, OBJ, PLY (ASCII, binary little and big endian), legacy VTK
(ASCII and binary), VTP (ASCII and inline binary), STL (ASCII and binary).

A mesh is (points, faces): points a list of (x, y, z), faces a list of vertex-index tuples
(triangles, or polygons where the format allows them), counter-clockwise seen from outside."""
import base64
import math
import struct


def icosphere(subdivisions):
    """The unit icosahedron, each triangle split in four `subdivisions` times (12, 42, 162, 642
    vertices)."""
    golden = (1 + 5 ** 0.5) / 2
    points = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0), (0, -1, golden),
              (0, 1, golden), (0, -1, -golden), (0, 1, -golden), (golden, 0, -1), (golden, 0, 1),
              (-golden, 0, -1), (-golden, 0, 1)]
    points = [tuple(c / math.sqrt(1 + golden ** 2) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                m = [(p + q) / 2 for p, q in zip(points[a], points[b])]
                norm = math.sqrt(sum(c * c for c in m))
                points.append(tuple(c / norm for c in m))
                midpoints[key] = len(points) - 1
            return midpoints[key]
        refined = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    return points, faces


def lumpy(points):
    """Moves the points of a unit sphere radially into a shape without symmetries (stretched
    unequally along the axes, with a bump off every axis), so that a registration of the
    shape with itself has one right answer: every vertex onto itself."""
    bump = (0.6, 0.5, 0.62)
    result = []
    for x, y, z in points:
        distance2 = (x - bump[0]) ** 2 + (y - bump[1]) ** 2 + (z - bump[2]) ** 2
        r = 1 + 0.5 * math.exp(-distance2 / 0.15) + 0.15 * x * y
        result.append((1.0 * r * x, 1.4 * r * y, 0.8 * r * z))
    return result


def lumpy_sphere(subdivisions=2):
    points, faces = icosphere(subdivisions)
    return lumpy(points), faces


def scaled(mesh, factor):
    points, faces = mesh
    return [tuple(factor * c for c in p) for p in points], faces


def holed_plate(holes):
    """The surface of a plate of unit cubes, 2 * holes + 1 long, 3 wide, 1 thick, with a
    square hole through every other cube of the middle row: a closed surface of genus
    `holes`, as quads split into triangles."""
    filled = {(i, j) for i in range(2 * holes + 1) for j in range(3)}
    filled -= {(2 * k + 1, 1) for k in range(holes)}
    index, points, faces = {}, [], []

    def vertex(p):
        if p not in index:
            index[p] = len(points)
            points.append(tuple(float(c) for c in p))
        return index[p]
    # A face of a cube is on the surface when the neighbour across it is empty; its corners go
    # counter-clockwise seen from that neighbour.
    for (i, j) in sorted(filled):
        for axis in range(3):
            for side in (0, 1):
                step = [0, 0, 0]
                step[axis] = 1 if side else -1
                if axis < 2 and ((i + step[0], j + step[1]) in filled):
                    continue
                base = [i, j, 0]
                base[axis] += side
                u, v = [0, 0, 0], [0, 0, 0]
                u[(axis + 1) % 3], v[(axis + 2) % 3] = 1, 1
                if not side:
                    u, v = v, u
                corners = [tuple(base[k] + a * u[k] + b * v[k] for k in range(3))
                           for a, b in ((0, 0), (1, 0), (1, 1), (0, 1))]
                a, b, c, d = (vertex(p) for p in corners)
                faces += [(a, b, c), (a, c, d)]
    return points, faces


def quad_box(divisions=3, jitter=0.0):
    """A 1 x 1.5 x 2 box of quads, `divisions` per edge, with corners moved by `jitter` times
    a fixed pseudo-random offset (no symmetry left)."""
    size = (1.0, 1.5, 2.0)
    index, points, faces = {}, [], []

    def vertex(g):
        if g not in index:
            index[g] = len(points)
            offset = math.sin(12.9898 * len(points) + 78.233) * 43758.5453 % 1 - 0.5
            points.append(tuple(size[k] * (g[k] / divisions) + jitter * offset * (k + 1) / 3
                                for k in range(3)))
        return index[g]
    for axis in range(3):
        for side in (0, divisions):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            if side == 0:
                u, v = v, u
            for a in range(divisions):
                for b in range(divisions):
                    quad = []
                    for da, db in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        g = [0, 0, 0]
                        g[axis], g[u], g[v] = side, a + da, b + db
                        quad.append(vertex(tuple(g)))
                    faces.append(tuple(quad))
    return points, faces


def polygon_prism(sides, height=1.0):
    """A prism over a regular polygon: `sides` quads around, one `sides`-gon on each end."""
    points = [(math.cos(2 * math.pi * k / sides), math.sin(2 * math.pi * k / sides), z)
              for z in (0.0, height) for k in range(sides)]
    faces = [tuple(reversed(range(sides))), tuple(range(sides, 2 * sides))]
    faces += [(k, (k + 1) % sides, (k + 1) % sides + sides, k + sides) for k in range(sides)]
    return points, faces


def triangulated(faces):
    """Polygons fanned into triangles."""
    return [(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)]


# --- Formats ---------------------------------------------------------------------------

def off_bytes(points, faces):
    lines = ["OFF", f"{len(points)} {len(faces)} 0"]
    lines += ["%.17g %.17g %.17g" % tuple(p) for p in points]
    lines += [" ".join(map(str, [len(f), *f])) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def obj_bytes(points, faces):
    lines = ["# generated by the hostile-input test"]
    lines += ["v %.17g %.17g %.17g" % tuple(p) for p in points]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def ply_header(encoding, vertices, faces):
    return ("ply\nformat %s 1.0\ncomment generated\nelement vertex %d\nproperty double x\n"
            "property double y\nproperty double z\nelement face %d\n"
            "property list uchar int vertex_indices\nend_header\n" % (encoding, vertices, faces)).encode()


def ply_ascii_bytes(points, faces):
    body = "".join("%.17g %.17g %.17g\n" % tuple(p) for p in points)
    body += "".join(" ".join(map(str, [len(f), *f])) + "\n" for f in faces)
    return ply_header("ascii", len(points), len(faces)) + body.encode()


def ply_binary_bytes(points, faces, byte_order="<"):
    encoding = "binary_little_endian" if byte_order == "<" else "binary_big_endian"
    data = b"".join(struct.pack(byte_order + "3d", *p) for p in points)
    data += b"".join(struct.pack(byte_order + "B%di" % len(f), len(f), *f) for f in faces)
    return ply_header(encoding, len(points), len(faces)) + data


def vtk_ascii_bytes(points, faces):
    size = sum(len(f) + 1 for f in faces)
    text = "# vtk DataFile Version 3.0\ngenerated\nASCII\nDATASET POLYDATA\n"
    text += f"POINTS {len(points)} double\n" + "".join("%.17g %.17g %.17g\n" % tuple(p) for p in points)
    text += f"POLYGONS {len(faces)} {size}\n" + "".join(" ".join(map(str, [len(f), *f])) + "\n" for f in faces)
    return text.encode()


def vtk_binary_bytes(points, faces):
    size = sum(len(f) + 1 for f in faces)
    data = b"# vtk DataFile Version 3.0\ngenerated\nBINARY\nDATASET POLYDATA\n"
    data += f"POINTS {len(points)} double\n".encode() + b"".join(struct.pack(">3d", *p) for p in points)
    data += f"\nPOLYGONS {len(faces)} {size}\n".encode()
    data += b"".join(struct.pack(">%di" % (len(f) + 1), len(f), *f) for f in faces) + b"\n"
    return data


def _vtp(points, faces, array):
    offsets, connectivity = [], []
    for f in faces:
        connectivity += f
        offsets.append(len(connectivity))
    return ('<?xml version="1.0"?>\n'
            '<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" header_type="UInt32">\n'
            '<PolyData>\n<Piece NumberOfPoints="%d" NumberOfVerts="0" NumberOfLines="0" '
            'NumberOfStrips="0" NumberOfPolys="%d">\n<Points>\n%s</Points>\n<Polys>\n%s%s</Polys>\n'
            '</Piece>\n</PolyData>\n</VTKFile>\n'
            % (len(points), len(faces), array("Float64", "Points", 3, [c for p in points for c in p]),
               array("Int64", "connectivity", 1, connectivity), array("Int64", "offsets", 1, offsets))).encode()


def vtp_ascii_bytes(points, faces):
    def array(kind, name, components, values):
        text = " ".join("%.17g" % v if kind == "Float64" else str(v) for v in values)
        return ('<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="ascii">\n%s\n</DataArray>\n'
                % (kind, name, components, text))
    return _vtp(points, faces, array)


def vtp_binary_bytes(points, faces):
    def array(kind, name, components, values):
        data = struct.pack("<%d%s" % (len(values), "d" if kind == "Float64" else "q"), *values)
        encoded = base64.b64encode(struct.pack("<I", len(data)) + data).decode()
        return ('<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="binary">\n%s\n</DataArray>\n'
                % (kind, name, components, encoded))
    return _vtp(points, faces, array)


def stl_ascii_bytes(points, faces):
    text = "solid generated\n"
    for f in triangulated(faces):
        text += "facet normal 0 0 0\nouter loop\n"
        text += "".join("vertex %.17g %.17g %.17g\n" % tuple(points[i]) for i in f)
        text += "endloop\nendfacet\n"
    return (text + "endsolid generated\n").encode()


def stl_binary_bytes(points, faces):
    triangles = triangulated(faces)
    data = b"binary STL generated by the hostile-input test".ljust(80, b" ")
    data += struct.pack("<I", len(triangles))
    for f in triangles:
        data += struct.pack("<12fH", 0, 0, 0, *points[f[0]], *points[f[1]], *points[f[2]], 0)
    return data


# Every format: name -> (file extension, writer). STL stores single-precision triangles.
FORMATS = {
    "off": ("off", off_bytes),
    "obj": ("obj", obj_bytes),
    "ply-ascii": ("ply", ply_ascii_bytes),
    "ply-little": ("ply", ply_binary_bytes),
    "ply-big": ("ply", lambda p, f: ply_binary_bytes(p, f, ">")),
    "vtk-ascii": ("vtk", vtk_ascii_bytes),
    "vtk-binary": ("vtk", vtk_binary_bytes),
    "vtp-ascii": ("vtp", vtp_ascii_bytes),
    "vtp-binary": ("vtp", vtp_binary_bytes),
    "stl-ascii": ("stl", stl_ascii_bytes),
    "stl-binary": ("stl", stl_binary_bytes),
}
