"""A hostile-input suite for mobius-register, every file generated here: truncated and garbage
files of every format, absurd counts, NaN and infinite coordinates, bad indices, and the
meshes a surface-mapping tool meets in the wild (duplicate and zero-area faces,
non-manifold edges and vertices, holes, several components, handles, a single triangle, a
tetrahedron, scales of 1e-12 and 1e+12, collinear and coplanar points, quads and polygons,
unreferenced vertices).

Each case must end in one of two ways: exit status 1 with exactly one line on standard error
that names the file and the problem, and no output file; or exit status 0 with both outputs
and no NaN or infinity anywhere in them (and, for a mesh registered with itself, every
vertex mapped onto itself). Never a signal, a hang, a NaN or a partial output.

Usage: test_hostile_inputs.py MOBIUS_REGISTER WORK_FOLDER [TIMEOUT_SECONDS]"""
import base64
import itertools
import math
import os
import random
import re
import shutil
import struct
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import mesh_files
from cli_harness import Harness
from mesh_files import FORMATS

program, work = sys.argv[1], sys.argv[2]
# Per run: a hang is what takes longer than this (a run takes well under a second in Release;
# sanitizer builds are several times slower).
timeout = float(sys.argv[3]) if len(sys.argv) > 3 else 60
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
harness = Harness(program, work)
check = harness.check
# The fast settings: small grid, the Möbius map only (the refinement has its own cases).
FAST = ["--resolution", "32", "--refine", "none"]
outcomes = []  # (case, outcome) for the summary table
outputs = itertools.count()


def write(name, data):
    with open(os.path.join(work, name), "wb") as f:
        f.write(data)
    return name


def register(name, options):
    """Registers the mesh file `name` with itself."""
    output = f"out{next(outputs)}"
    arguments = [name, name, "-o", output, *options]
    code, _, err = harness.run(*arguments, timeout=timeout)
    return arguments, output, code, err


# Messages that name no problem: a user learns nothing from them.
VAGUE = ("cannot read the mesh", "produced no output", "an unknown exception", "unexpected error")


def check_error(label, arguments, output, code, err, name, words):
    harness.check_one_line_error(arguments, code, err, [name, *words], [output])
    reason = err.strip().split(name, 1)[-1].lstrip(": ")
    check(len(reason.split()) >= 3 and not any(v in err for v in VAGUE),
          f"{label}: the message names no problem: {err!r}")
    # A figure of the program's own printed as nan or inf (quoting the file is fine).
    own = re.sub(r"'[^']*'", "", reason).replace("NaN or infinite", "")
    check(not re.search(r"\b(nan|inf)\b", own, re.IGNORECASE), f"{label}: a NaN in the message: {err!r}")
    outcomes.append((label, "error: " + reason[:90]))


def finite_vtp(path):
    """Every point coordinate and every numeric point, cell and field array value is finite."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        return False, "no points"
    if not numpy.isfinite(vtk_to_numpy(data.GetPoints().GetData())).all():
        return False, "points"
    for attributes in (data.GetPointData(), data.GetCellData(), data.GetFieldData()):
        for k in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(k)
            if array is not None and array.GetNumberOfTuples() > 0 and \
                    not numpy.isfinite(vtk_to_numpy(array).astype(float)).all():
                return False, array.GetName()
    return True, ""


def check_result(label, output, points=None, self_map=False, sources=None, off_surface=()):
    """Both outputs, all finite; for a registration of a mesh with itself every source vertex
    maps onto itself: the target vertex of its largest barycentric weight is its own number
    (or, when `points`, the file's vertices, are given, one at its position, as a duplicate
    the repair merged) and the mapped point is its position. `sources`: the file's vertex
    numbers the CSV must list; `off_surface`: vertices on no triangle of the surface mapped
    (unused, or in a part the repair dropped), which map to their closest point instead."""
    vtp, csv = (os.path.join(work, output + ext) for ext in (".vtp", ".csv"))
    if not check(os.path.exists(vtp) and os.path.exists(csv), f"{label}: outputs missing"):
        return
    check(not [f for f in os.listdir(work) if ".partial-" in f], f"{label}: temporary files left")
    finite, where = finite_vtp(vtp)
    check(finite, f"{label}: NaN or infinity in {output}.vtp ({where})")
    with open(csv) as f:
        header = f.readline().strip().split(",")
        rows = [line.strip().split(",") for line in f]
    check(header[:5] == ["source_vertex", "target_triangle", "target_vertex_0", "target_vertex_1",
                         "target_vertex_2"] and len(header) == 11, f"{label}: CSV header {header}")
    values = numpy.array([[float(v) for v in row] for row in rows]) if rows else numpy.zeros((0, 11))
    check(len(rows) > 0 and values.shape[1] == 11 and numpy.isfinite(values).all(),
          f"{label}: NaN, infinity or a short row in {output}.csv")
    if sources is not None:
        check(sorted(int(row[0]) for row in values) == sorted(sources),
              f"{label}: the CSV's source vertices are not the file's {len(sources)} expected")
    if not self_map or len(rows) == 0:
        return
    scale = 1.0
    if points is not None:
        scale = float(numpy.ptp(numpy.array(points), axis=0).max())
    wrong = []
    for row in values:
        source = int(row[0])
        if source < 0 or source in off_surface:
            continue  # a vertex a repair created, or one not on the surface
        target = int(row[2 + int(numpy.argmax(row[5:8]))])
        moved = numpy.linalg.norm(row[8:11] - points[source]) / scale if points is not None else 0.0
        same_place = points is not None and numpy.linalg.norm(
            numpy.subtract(points[target], points[source])) <= 1e-12 * scale
        # The corner of largest weight names the vertex unless the image is the source's own
        # position to the last digit: then a tie in the weights (a corner of several
        # triangles, coincident points) may name another corner, and which one the CPU's
        # last bits decide (glibc's FMA or SSE2 routines).
        exact = moved <= 1e-12
        if (target != source and not same_place and not exact) or moved > 1e-3:
            wrong.append((source, target, moved))
    check(not wrong, f"{label}: {len(wrong)} of {len(rows)} vertices not mapped onto themselves: {wrong[:3]}")


def expect_error(label, name, words, options=()):
    """Exit status 1, one line naming `name` and holding `words`, no output."""
    arguments, output, code, err = register(name, [*FAST, *options])
    check_error(label, arguments, output, code, err, name, words)


def expect_result(label, name, points=None, options=(), self_map=True, sources=None, off_surface=()):
    """Exit status 0 and a correct result of the mesh registered with itself (see
    check_result)."""
    arguments, output, code, err = register(name, [*FAST, "--quiet", *options])
    if check(code == 0, f"{label}: {arguments}: exit code {code}: {err!r}"):
        check_result(label, output, points, self_map, sources, off_surface)
        outcomes.append((label, "result"))
    else:
        outcomes.append((label, f"FAILED (exit {code})"))


def expect_error_or_result(label, name, words=(), options=()):
    """Either outcome, each held to its rule (used where a cut or garbage may leave a valid
    mesh). A self-registration when it succeeds: vertices onto themselves."""
    arguments, output, code, err = register(name, [*FAST, *options])
    if code == 0:
        check_result(label, output, None, self_map=True)
        outcomes.append((label, "result"))
    else:
        check_error(label, arguments, output, code, err, name, words)


def bytes_of(fmt, mesh):
    return FORMATS[fmt][1](*mesh)


def file_name(stem, fmt):
    return f"{stem}-{fmt}.{FORMATS[fmt][0]}"


lumpy = mesh_files.lumpy_sphere(2)  # 162 vertices, no symmetry

# --- 1. Every format, valid: the baseline the broken files are cut from. ------------------
for fmt in FORMATS:
    name = write(file_name("valid", fmt), bytes_of(fmt, lumpy))
    # STL stores triangles without shared vertices: its vertex numbers are the reader's.
    expect_result(f"valid {fmt}", name, None if fmt.startswith("stl") else lumpy[0])


# --- 2. Truncated files: cut at several points, header only, empty. ------------------------
def header_length(fmt, data):
    """Bytes before the data of the first vertex."""
    if fmt == "stl-binary":
        return 84
    marker = {"ply-little": b"end_header\n", "ply-big": b"end_header\n", "vtk-binary": b" double\n",
              "vtp-binary": b'format="binary">\n', "stl-ascii": b"\n"}.get(fmt)
    if marker:
        return data.index(marker) + len(marker)
    return data.index(b"%.17g" % lumpy[0][0][0])  # the text formats


for fmt in FORMATS:
    data = bytes_of(fmt, lumpy)
    header = header_length(fmt, data)
    cuts = {"empty": 0, "header only": header, "1 byte": 1}
    cuts.update({f"{int(100 * share)}%": int(share * len(data)) for share in (0.1, 0.35, 0.6, 0.85)})
    cuts["all but 1 byte"] = len(data) - 1
    for what, cut in cuts.items():
        name = write(f"cut{cut}-{file_name('lumpy', fmt)}", data[:cut])
        expect_error_or_result(f"{fmt} cut: {what}", name)

# --- 3. Garbage: random bytes, random text, a valid header followed by garbage. ----------
generator = random.Random(20261130)
words = ["v", "f", "3", "0", "1e9", "-1", "nan", "facet", "vertex", "<DataArray", "POINTS", "end_header",
         "element", "#", "/", "1/2/3", "endloop", "\n", "\n\n", "\t"]
for fmt in FORMATS:
    data = bytes_of(fmt, lumpy)
    header = header_length(fmt, data)
    noise = bytes(generator.randrange(256) for _ in range(3000))
    text = " ".join(generator.choice(words) for _ in range(800)).encode()
    for number, (what, garbage) in enumerate((("random bytes", noise), ("random words", text),
                          ("header + random bytes", data[:header] + noise),
                          ("header + random words", data[:header] + text),
                          ("valid + random bytes", data + noise))):
        name = write(f"garbage{number}-{file_name('lumpy', fmt)}", garbage)
        expect_error_or_result(f"{fmt} garbage: {what}", name)


# --- 4. NaN and infinite coordinates, in every format. --------------------------------------
def with_point(mesh, index, point):
    points = list(mesh[0])
    points[index] = point
    return points, mesh[1]


for fmt in FORMATS:
    for what, value in (("NaN", math.nan), ("+inf", math.inf), ("-inf", -math.inf)):
        name = write(f"{what.strip('+-')}{'m' if what[0] == '-' else ''}-{file_name('lumpy', fmt)}",
                     bytes_of(fmt, with_point(lumpy, 5, (0.1, value, 0.2))))
        expect_error(f"{fmt}: a {what} coordinate", name, ["NaN or infinite"])
# Text that overflows a double is infinite too (VTK's XML reader calls the array short).
for fmt in ("off", "obj", "ply-ascii", "vtk-ascii", "vtp-ascii", "stl-ascii"):
    data = bytes_of(fmt, with_point(lumpy, 5, (0.1, 12345.0, 0.2)))
    name = write(file_name("overflow", fmt), data.replace(b"12345", b"1e999", 1))
    expect_error(f"{fmt}: coordinate 1e999", name, ["Points"] if fmt == "vtp-ascii" else ["NaN or infinite"])

# --- 5. Absurd counts and indices not covered by test_mobius_register. --------------------
tetra = ([(0, 0, 0), (1, 0, 0), (0, 2, 0), (0, 0, 3)], [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)])
off_tetra = bytes_of("off", tetra).decode()
ply_tetra = bytes_of("ply-ascii", tetra).decode()
vtk_tetra = bytes_of("vtk-ascii", tetra).decode()
vtp_tetra = bytes_of("vtp-ascii", tetra).decode()
counts = {
    "off face count 2e9": ("c1.off", off_tetra.replace("4 4 0", "4 2000000000 0"), ["2000000000"]),
    "off negative vertex count": ("c2.off", off_tetra.replace("4 4 0", "-4 4 0"), ["count"]),
    "off count past 64 bits": ("c3.off", off_tetra.replace("4 4 0", "99999999999999999999 4 0"), ["count"]),
    "off face index 1.5": ("c4.off", off_tetra.replace("3 0 2 1", "3 0 1.5 2"), ["face 0"]),
    "off face index past 64 bits": ("c5.off", off_tetra.replace("3 0 2 1", "3 0 2 99999999999999999999"),
                                    ["face 0"]),
    "ply face count 1e9": ("c6.ply", ply_tetra.replace("element face 4", "element face 1000000000"),
                           ["face 4 of 1000000000"]),
    "ply negative vertex count": ("c7.ply", ply_tetra.replace("element vertex 4", "element vertex -4"),
                                  ["header"]),
    "ply list count 255 on a short line": ("c8.ply", ply_tetra.replace("3 0 2 1", "255 0 2 1"), ["face 0"]),
    "ply face before the vertices it names": ("c9.ply", ply_tetra.replace("3 1 2 3", "3 1 2 4"),
                                              ["refers to vertex 4"]),
    # Headers VTK's PLY reader crashed on (it reads x, y, z and vertex_indices, in that order).
    "ply vertex without z": ("c25.ply", ply_tetra.replace("property double z", "property double w"),
                             ["no scalar property 'z'"]),
    "ply face without vertex_indices": ("c26.ply", ply_tetra.replace("vertex_indices", "corners"),
                                        ["no list property 'vertex_indices'"]),
    "ply no vertex element": ("c27.ply", ply_tetra.replace("element vertex", "element point"),
                              ["no 'vertex' element"]),
    "ply vertices only": ("c29.ply", ply_tetra.replace("element face 4", "element face 0").split("3 0 2 1")[0],
                          ["no triangles"]),
    "vtk negative index": ("c10.vtk", vtk_tetra.replace("3 0 2 1", "3 0 2 -1"), ["-1"]),
    "vtk cell longer than the connectivity": ("c11.vtk", vtk_tetra.replace("3 0 3 2", "9 0 3 2"),
                                              ["cell 3 claims 9 points"]),
    "vtk cells short of the declared size": ("c11b.vtk", vtk_tetra.replace("POLYGONS 4 16", "POLYGONS 3 16"),
                                             ["declares 16 values", "hold 12"]),
    "vtk negative points": ("c12.vtk", vtk_tetra.replace("POINTS 4", "POINTS -4"), ["-4"]),
    "vtk polygon size past 64 bits": ("c13.vtk", vtk_tetra.replace("POLYGONS 4 16", "POLYGONS 4 99999999999999999999"),
                                      ["polygons"]),
    "vtp 2e9 polygons": ("c14.vtp", vtp_tetra.replace('NumberOfPolys="4"', 'NumberOfPolys="2000000000"'),
                         ["2000000000"]),
    "vtp connectivity past the points": ("c15.vtp", vtp_tetra.replace("0 2 1 0 1 3", "0 2 1 0 1 30"),
                                         ["refers to point 30"]),
    "vtp negative connectivity": ("c16.vtp", vtp_tetra.replace("0 2 1 0 1 3", "0 2 1 0 1 -3"),
                                  ["refers to point -3"]),
    "vtp offsets past the connectivity": ("c17.vtp", vtp_tetra.replace("3 6 9 12", "3 6 9 40"), ["connectivity"]),
    "vtp offsets decreasing": ("c18.vtp", vtp_tetra.replace("3 6 9 12", "3 9 6 12"), ["offset"]),
    "vtp a billion components": ("c19.vtp", vtp_tetra.replace('NumberOfComponents="3"', 'NumberOfComponents="1000000000"'),
                                 ["components"]),
    "vtp points with 1 component": ("c40.vtp", vtp_tetra.replace('NumberOfComponents="3"', 'NumberOfComponents="1"'),
                                    ["1 component per point", "not 3"]),
    # Found by the fuzzer: a search of the text for NumberOfComponents="3" matched here.
    "vtp points' components inside a longer attribute": (
        "c41.vtp", vtp_tetra.replace('NumberOfComponents="3"', 'ComponentName0NumberOfComponents="3"'),
        ["1 component per point", "not 3"]),
    "stl no triangles": ("c20.stl", (b"x" * 80 + struct.pack("<I", 0)).decode(), ["no triangles"]),
    "obj no faces": ("c21.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", ["no triangles"]),
    "off no faces": ("c22.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", ["no triangles"]),
    "obj lines only": ("c23.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3 1\n", ["no triangles"]),
}
for label, (name, text, expected) in counts.items():
    expect_error(label, write(name, text.encode()), expected)
# XML allows spaces around '=' and single quotes: the points' component count is read as VTK
# reads it, so this spelling is not refused.
vtp_lumpy = bytes_of("vtp-ascii", lumpy).decode()
expect_result("vtp NumberOfComponents = '3'",
              write("c42.vtp", vtp_lumpy.replace('NumberOfComponents="3"', "NumberOfComponents = '3'").encode()),
              lumpy[0])
expect_error("ply float vertex indices",
             write("c30.ply", ply_tetra.replace("list uchar int vertex_indices", "list uchar float vertex_indices")
                   .encode()), ["floating-point", "integer type"])


# Valid PLY files that VTK 9.2's reader crashed on (an element other than vertex and face,
# in ASCII) or misread (the same in binary: "holes"), or refused (faces before vertices):
# elements in any order, every encoding, each read as the vertices and faces it holds.
def ply_elements(fmt, mesh, order):
    """A PLY file of `mesh` with its elements in `order`, a string of v (vertex), f (face)
    and m (a material element with a list property)."""
    encoding = {"ply-ascii": "ascii", "ply-little": "binary_little_endian", "ply-big": "binary_big_endian"}[fmt]
    points, faces = mesh
    header = {"v": "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n" % len(points),
              "f": "element face %d\nproperty list uchar int vertex_indices\n" % len(faces),
              "m": "element material 2\nproperty float shine\nproperty list uchar int ids\n"}
    if fmt == "ply-ascii":
        data = {"v": "".join("%.17g %.17g %.17g\n" % tuple(p) for p in points).encode(),
                "f": "".join(" ".join(map(str, [len(f), *f])) + "\n" for f in faces).encode(),
                "m": b"0.5 2 7 8\n0.25 1 9\n"}
    else:
        order_char = "<" if fmt == "ply-little" else ">"
        data = {"v": b"".join(struct.pack(order_char + "3d", *p) for p in points),
                "f": b"".join(struct.pack(order_char + "B%di" % len(f), len(f), *f) for f in faces),
                "m": struct.pack(order_char + "fB2i", 0.5, 2, 7, 8) + struct.pack(order_char + "fBi", 0.25, 1, 9)}
    text = "ply\nformat %s 1.0\n" % encoding + "".join(header[e] for e in order) + "end_header\n"
    return text.encode() + b"".join(data[e] for e in order)


for fmt in ("ply-ascii", "ply-little", "ply-big"):
    for order, what in (("mvf", "an element before the vertices"), ("vmf", "an element between vertices and faces"),
                        ("vfm", "an element after the faces"), ("fv", "faces before vertices"),
                        ("fmv", "faces, an element, vertices")):
        name = write(f"elements-{order}-{fmt}.ply", ply_elements(fmt, lumpy, order))
        expect_result(f"{fmt}: {what}", name, lumpy[0])
# The same without the final line break (ASCII): VTK's parser failed an assertion on it.
expect_result("ply-ascii: an element before the vertices, no final line break",
              write("elements-nobreak.ply", ply_elements("ply-ascii", lumpy, "mvf").rstrip(b"\n")), lumpy[0])

# The same in a binary legacy file: the first cell's count (big-endian) past the section.
binary = bytes_of("vtk-binary", tetra)
at = binary.index(b"POLYGONS 4 16\n") + len(b"POLYGONS 4 16\n")
expect_error("vtk binary cell longer than the connectivity",
             write("c24.vtk", binary[:at] + struct.pack(">i", 200) + binary[at + 4:]), ["cell 0 claims 200 points"])

# Text files as editors and other tools write them: each read as what it holds (they were
# taken for binary STL, lost OBJ vertex 1, or were refused with a misleading message).
stl_text = bytes_of("stl-ascii", lumpy).decode()
obj_text = bytes_of("obj", lumpy).decode()
off_text = bytes_of("off", lumpy).decode()
points = lumpy[0]
written_as = {
    "stl: a byte-order mark": ("bom.stl", "\ufeff" + stl_text, None),
    "stl: blank lines and spaces first": ("blank-first.stl", "\n\n   " + stl_text, None),
    "stl: upper-case keywords": ("upper.stl", stl_text.upper(), None),
    "stl: a UTF-8 solid name": ("utf8-name.stl", stl_text.replace("solid generated", "solid Würfel ü"), None),
    "stl: a 300-character solid name": ("long-name.stl", stl_text.replace("solid generated", "solid " + "n" * 300), None),
    "stl: CR LF line endings": ("crlf.stl", stl_text.replace("\n", "\r\n"), None),
    "obj: a byte-order mark": ("bom.obj", "\ufeff" + obj_text.split("\n", 1)[1], points),
    "obj: a comment ending in a backslash": ("comment-backslash.obj", "# a comment \\\n" + obj_text.split("\n", 1)[1], points),
    "obj: CR line endings": ("cr.obj", obj_text.replace("\n", "\r"), points),
    "off: a byte-order mark": ("bom.off", "\ufeff" + off_text, points),
    "off: CR line endings": ("cr.off", off_text.replace("\n", "\r"), points),
    "off: free format (counts and coordinates over lines)": (
        "free.off", off_text.replace(" ", "\n", 2 + 3 * len(points)), points),
    "off: free format (a face's indices on the next line)": (
        "free-faces.off", off_text.replace("\n3 ", "\n3\n"), points),
    "off: counts on the keyword's line": ("one-line-header.off", off_text.replace("OFF\n", "OFF ", 1), points),
    # OFF is free-format: all of a file on one line, or several vertices to a line (refused:
    # "vertex 1 of 162 is missing or malformed").
    "off: everything on one line": ("one-line.off", " ".join(off_text.split()) + "\n", points),
    "off: three vertices to a line": ("three-per-line.off", "\n".join(
        off_text.split("\n")[:2] + [" ".join(off_text.split("\n")[2 + k:5 + k]) for k in range(0, len(points), 3)]
        + off_text.split("\n")[2 + len(points):]), points),
    "off: counts joined to the keyword (OFF162)": ("joined-header.off", off_text.replace("OFF\n", "OFF", 1), points),
    "off: unannounced colors after the coordinates": ("colors-unannounced.off", "\n".join(
        line + (" 0.5 0.5 0.5" if 1 < k < 2 + len(points) else "")
        for k, line in enumerate(off_text.split("\n"))), points),
    "off: nOFF of dimension 3": ("noff.off", off_text.replace("OFF\n", "nOFF\n3\n", 1), points),
    "off: 4OFF (homogeneous)": ("4off.off", "4OFF\n" + off_text.split("\n", 1)[1].replace(
        "\n", " 2\n", len(points) + 1).replace(" 0 2\n", " 0\n", 1), [tuple(c / 2 for c in p) for p in points]),
    "off: COFF, colors after the coordinates and the faces": ("coff.off", "COFF\n" + "\n".join(
        line + (" 0.5 0.5 0.5 1" if k > 0 else "") for k, line in enumerate(off_text.split("\n")[1:-1])) + "\n", points),
}
for label, (name, text, truth) in written_as.items():
    expect_result(label, write(name, text.encode()), truth)
expect_error("off: nOFF of dimension 2", write("noff2.off", off_text.replace("OFF\n", "nOFF\n2\n", 1).encode()),
             ["2 coordinates", "3 dimensions"])
expect_error("off: OFF BINARY", write("binary.off", b"OFF BINARY\n" + struct.pack(">3i", 4, 4, 0)),
             ["binary OFF", "ASCII OFF"])


# --- 6. Meshes a surface mapper meets in the wild. ------------------------------------------
def off(name, mesh):
    return write(name + ".off", bytes_of("off", mesh))


def shifted(mesh, offset, by=(0, 0, 0)):
    points, faces = mesh
    return [tuple(c + d for c, d in zip(p, by)) for p in points], [tuple(i + offset for i in f) for f in faces]


def joined(*meshes):
    points, faces = [], []
    for mesh in meshes:
        points, faces = points + list(mesh[0]), faces + shifted(mesh, len(points))[1]
    return points, faces


points, faces = lumpy
STRICT = ["--no-repair"]
# Each defect is repaired by default (a result with every vertex of the file, mapped onto
# itself), and refused with today's message in strict mode (--no-repair).
for label, name in (("duplicate face", off("duplicate-face", (points, faces + [faces[7]]))),
                    ("duplicate face, reversed", off("duplicate-reversed", (points, faces + [faces[7][::-1]])))):
    expect_result(label, name, points, sources=range(len(points)))
    expect_error(label + ", strict", name, ["1 duplicate triangle"], STRICT)
# A zero-area face in a closed mesh: a new point m on the edge (a, b), the triangle (a, b, c)
# split at m and the sliver (a, b, m) closing the other side. The surface is fine (exporters
# write such slivers to close T-junctions): it maps, m included.
a, b, c = faces[0]
m = len(points)
sliver = (points + [tuple((p + q) / 2 for p, q in zip(points[a], points[b]))],
          faces[1:] + [(a, m, c), (m, b, c), (a, b, m)])
expect_result("zero-area face", off("zero-area", sliver), sliver[0], sources=range(len(sliver[0])))
# The same with m at a's position: the edge (a, m) has no length; it is collapsed (m merged
# into a, the two faces on it dropped); m's row is a's image.
coincident = (points + [points[a]], sliver[1])
expect_result("zero-length edge", off("zero-length-edge", coincident), coincident[0],
              sources=range(len(coincident[0])))
repeated = off("repeated-vertex", (points, faces + [(3, 3, 4)]))
expect_result("face naming a vertex twice", repeated, points, sources=range(len(points)))
expect_error("face naming a vertex twice, strict", repeated, ["same point twice"], STRICT)
# Three faces on one edge: a fin on the edge (a, b); its tip, dropped with it, is off the surface.
fin = off("fin", (points + [(3, 3, 3)], faces + [(a, b, m)]))
expect_result("non-manifold edge", fin, points + [(3, 3, 3)], sources=range(m + 1), off_surface={m})
expect_error("non-manifold edge, strict", fin, ["non-manifold edge"], STRICT)
# Two closed surfaces of one size touching at a vertex (the second's vertex 0 is the first's
# vertex 0): split there, two parts of comparable size, which to map is the user's choice.
touching_points = points + [tuple(-c for c in p) for p in points[1:]]
rename = lambda i: 0 if i == 0 else i + len(points) - 1
touching = off("touching", (touching_points, faces + [tuple(rename(i) for i in f) for f in faces]))
expect_error("two surfaces touching at a vertex", touching, ["comparable size", "--keep-largest-component"])
expect_error("non-manifold vertex, strict", touching, ["non-manifold vertex"], STRICT)
# Open: the triangles around vertex 0 removed; vertex 0 is then on no triangle.
open_mesh = off("open", (points, [f for f in faces if 0 not in f]))
expect_result("open mesh", open_mesh, points, sources=range(len(points)), off_surface={0})
expect_error("open mesh, strict", open_mesh, ["hole", "--fill-holes"], STRICT)
expect_result("open mesh, strict --fill-holes", open_mesh, points, [*STRICT, "--fill-holes"],
              sources=range(len(points)), off_surface={0})
# A small part beside the surface (9% of its area): a loose part, dropped; strict refuses it.
two_parts = joined(lumpy, mesh_files.scaled(shifted(lumpy, 0, (5, 0, 0)), 0.3))
two = off("two", two_parts)
small = set(range(len(points), len(two_parts[0])))
expect_result("a small loose part", two, two_parts[0], sources=range(len(two_parts[0])), off_surface=small)
expect_error("two components, strict", two, ["2 connected components", "--keep-largest-component"], STRICT)
expect_result("two components, strict --keep-largest-component", two, two_parts[0],
              [*STRICT, "--keep-largest-component"], sources=range(len(two_parts[0])), off_surface=small)
# A closed surface with no orientation: the projective plane in 6 vertices. Cut open and
# closed again it is a sphere of a few triangles, too coarse for the flow (degenerate).
projective_plane = off("projective-plane", (
    [(0.1, 0.2, 0.9), (0.8, 0.1, 0.3), (0.4, 0.9, 0.2), (0.7, 0.6, 0.9), (0.2, 0.8, 0.6), (0.9, 0.4, 0.5)],
    [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5), (0, 5, 1), (1, 2, 4), (2, 3, 5), (3, 4, 1), (4, 5, 2), (5, 1, 3)]))
expect_error_or_result("non-orientable closed surface", projective_plane, ["degenerate"])
expect_error("non-orientable closed surface, strict", projective_plane, ["not orientable"], STRICT)
# Plates with 1 to 3 holes: their handles are cut (the result is a thin plate, which the flow
# may squeeze: then degenerate); strict refuses the genus.
for genus in (1, 2, 3):
    plate = off(f"genus{genus}", mesh_files.holed_plate(genus))
    expect_error_or_result(f"genus {genus}", plate, ["degenerate"])
    expect_error(f"genus {genus}, strict", plate, [f"genus {genus}"], STRICT)
triangle = off("triangle", ([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]))
expect_error("single triangle", triangle, ["no closed surface"])
expect_error("single triangle, strict", triangle, ["hole"], STRICT)
# Closing the one hole leaves two triangles on the same three points: no inside to map.
expect_error("single triangle, strict --fill-holes", triangle, ["duplicate triangle"], [*STRICT, "--fill-holes"])
# Too coarse for the conformal flow: degenerate (the flow does not settle), with the option
# that writes the result anyway; that result holds no NaN.
for label, mesh in (("tetrahedron", tetra), ("tetrahedron inside out", (tetra[0], [f[::-1] for f in tetra[1]])),
                    ("quad cube (8 vertices)", mesh_files.quad_box(1, 0.15))):
    name = off(label.split()[0] + str(len(outcomes)), mesh)
    expect_error(label, name, ["degenerate", "--allow-poor-maps"])
    expect_result(label + ", --allow-poor-maps", name, options=["--allow-poor-maps"], self_map=False)
# Scale must not matter: the same mesh at 1e-150 to 1e+150, refinement included; beyond,
# the triangles' areas are not double-precision numbers.
for factor in (1e-150, 1e-12, 1e12, 1e150):
    small = mesh_files.scaled(lumpy, factor)
    expect_result(f"scaled {factor:g}", off(f"scaled{factor:g}", small), small[0])
    expect_result(f"scaled {factor:g}, refined", off(f"scaled{factor:g}", small), small[0],
                  ["--refine", "spectral", "--basis-size", "20"])
# Nor position: a target 1e3 to 1e12 from the origin, the source at it, maps vertex i onto
# vertex i, never onto its mirror image (the inside-out test of vtkSphericalConformalMap
# summed signed volumes in absolute coordinates: at 1e6 the map came back mirrored).
for offset in (1e3, 1e6, 1e9, 1e12):
    far = shifted(lumpy, 0, (offset, 0.5 * offset, -offset))
    for label, options in (("", FAST), (", refined", [*FAST, "--refine", "spectral", "--basis-size", "20"])):
        output = f"far{offset:g}{label.strip(', ')}"
        arguments = [off("lumpy", lumpy), off(f"far{offset:g}", far), "-o", output, *options, "--quiet"]
        code, _, err = harness.run(*arguments, timeout=timeout)
        if check(code == 0, f"{arguments}: exit code {code}: {err!r}"):
            check_result(f"target at {offset:g}{label}", output, far[0], self_map=True)
for factor in (1e-200, 1e200):
    expect_error(f"scaled {factor:g}", off(f"scaled{factor:g}", mesh_files.scaled(lumpy, factor)),
                 ["areas", "beyond what double precision represents", "rescale"])
expect_result("lumpy, refined", off("lumpy", lumpy), points, ["--refine", "spectral", "--basis-size", "20"])
collinear = ([(t, 2 * t, 3 * t) for t in range(4)], tetra[1])
expect_error("collinear points", off("collinear", collinear), ["every triangle has zero area"])
expect_error("all points equal", off("equal", ([(1, 1, 1)] * 4, tetra[1])), ["every triangle has zero area"])
# A flat closed surface: two disks glued at the rim, each with its own centre (both at the
# origin), no volume inside.
rim = [(math.cos(2 * math.pi * k / 12), math.sin(2 * math.pi * k / 12), 0.0) for k in range(12)]
flat = ([(0.0, 0.0, 0.0)] + rim + [(0.0, 0.0, 0.0)],
        [(0, 1 + k, 1 + (k + 1) % 12) for k in range(12)] + [(13, 1 + (k + 1) % 12, 1 + k) for k in range(12)])
expect_error_or_result("flat closed surface", off("flat", flat), ["degenerate"])
# Quads and polygons: triangulated, as VTK's filters do; the file's vertex numbers stay.
box = mesh_files.quad_box(3, 0.15)
for fmt in ("off", "obj", "ply-ascii", "ply-little", "vtk-ascii", "vtp-binary"):
    name = write(file_name("quad-box", fmt), bytes_of(fmt, box))
    expect_result(f"quad box {fmt}", name, box[0])
prism = mesh_files.polygon_prism(8, 1.0)
for fmt in ("off", "obj", "ply-ascii", "vtp-ascii"):
    name = write(file_name("octagonal-prism", fmt), bytes_of(fmt, prism))
    expect_error_or_result(f"octagonal prism {fmt}", name, ["degenerate"])
    expect_result(f"octagonal prism {fmt}, --allow-poor-maps", name, prism[0], ["--allow-poor-maps"])
# Unreferenced vertices, one far away and one at the front: the numbers kept, and their rows
# (every vertex of the file has one) at their closest points on the surface.
far = ([(1e30, -1e30, 0), *points, (7, 7, 7)], [tuple(i + 1 for i in f) for f in faces])
for fmt in ("off", "obj", "ply-little", "vtp-ascii"):
    name = write(file_name("unreferenced", fmt), bytes_of(fmt, far))
    expect_result(f"unreferenced vertices {fmt}", name, far[0], sources=range(len(far[0])),
                  off_surface={0, len(far[0]) - 1})
# One unused vertex near the largest doubles: it sets neither the scale (the surface's areas
# would underflow: "every triangle has zero area") nor a distance the locator could hold.
for far_away in (1e100, 1e300):
    stray = ([*points, (far_away, 0, 0)], faces)
    expect_result(f"an unused vertex at {far_away:g}", off(f"stray{far_away:g}", stray), stray[0],
                  sources=range(len(stray[0])), off_surface={len(points)})
# A vertex of a triangle at 1e300: the areas cannot be computed over that range; the error
# names the point (it said "every triangle has zero area").
spike = ([*points[:-1], (1e300, 0, 0)], faces)
expect_error("a vertex at 1e300", off("spike", spike), [f"point {len(points) - 1} is 1e+300 from the origin"])

# NaN in a point array of the user's own: carried into the output (the user's data, not
# ours to change), with a warning that says so.
values = [0.5] * len(lumpy[0])
values[7] = math.nan
encoded = base64.b64encode(struct.pack("<I", 8 * len(values)) + struct.pack("<%dd" % len(values), *values)).decode()
with_nan = bytes_of("vtp-ascii", lumpy).replace(
    b"<Points>", b'<PointData>\n<DataArray type="Float64" Name="temperature" format="binary">\n' +
    encoded.encode() + b"\n</DataArray>\n</PointData>\n<Points>", 1)
name = write("nan-array.vtp", with_nan)
arguments, output, code, err = register(name, FAST)
if check(code == 0, f"{arguments}: exit code {code}: {err!r}"):
    check("'temperature' holds 1 NaN or infinite values" in err and "warning" in err,
          f"a NaN in the user's point array: no warning: {err!r}")
    outcomes.append(("NaN in the user's own point array", "result, warning"))


# --- 7. The process's limits. ----------------------------------------------------------------
# AddressSanitizer reserves terabytes of address space and more stack per frame: the
# sanitizer build skips the runs under limits.
with open(program, "rb") as binary:
    sanitized = b"AddressSanitizer" in binary.read()
# Bytes after a binary STL's triangles are not triangles: ignored, with a warning. VTK's reader
# read them as triangles to the end of the file (here one far away: a second component) and
# sized its arrays by the file's length (512 MB of zeros, sparse here, ended the program in
# vtkPoints::Allocate under a 1 GB address space).
stl = bytes_of("stl-binary", lumpy)
far_triangle = struct.pack("<12fH", 0, 0, 1, 10, 10, 10, 11, 10, 10, 10, 11, 10, 0)
padded = write("padded.stl", stl + far_triangle + b"\0" * 7)
arguments, output, code, err = register(padded, FAST)
if check(code == 0, f"{arguments}: exit code {code}: {err!r}"):
    check("57 bytes after the 320 triangles" in err, f"padded STL: no warning of the bytes ignored: {err!r}")
    check_result("binary STL with bytes after its triangles", output, self_map=True)
    outcomes.append(("binary STL with bytes after its triangles", "result, warning"))
sparse = write("zero-padded.stl", stl)
with open(os.path.join(work, sparse), "r+b") as f:
    f.truncate(len(stl) + 512 * 2 ** 20)
if not sanitized:
    code, _, err = harness.run(sparse, sparse, "-o", "zero-padded", *FAST, "--quiet", timeout=timeout,
                               memory=2 ** 30)
    if check(code == 0, f"binary STL with 512 MB of zeros after it, 1 GB address space: exit code {code}: {err!r}"):
        check_result("binary STL with 512 MB of zeros after it", "zero-padded", self_map=True)
        outcomes.append(("binary STL with 512 MB of zeros after it, 1 GB address space", "result"))
    # A small stack (256 KB): the worker threads get stacks of their own size; they
    # overflowed inside Eigen (from about 2,500 vertices on). The refinement included.
    fine = off("lumpy2562", mesh_files.lumpy_sphere(4))
    code, _, err = harness.run(fine, fine, "-o", "small-stack", "--resolution", "32", "--threads", "2",
                               "--basis-size", "20", "--quiet", timeout=timeout, stack=256 * 2 ** 10)
    if check(code == 0, f"a 256 KB stack: exit code {code}: {err!r}"):
        check_result("a 256 KB stack, two threads", "small-stack", self_map=True)
        outcomes.append(("a 256 KB stack, two threads", "result"))
    # 200 KB with the default basis: the refinement's matrix products put their 128 KB
    # temporaries on the stack (SIGSEGV in FitFunctionalMap); they come from the heap now.
    code, _, err = harness.run(fine, fine, "-o", "smaller-stack", "--resolution", "32", "--threads", "2",
                               "--quiet", timeout=timeout, stack=200 * 2 ** 10)
    if check(code == 0, f"a 200 KB stack: exit code {code}: {err!r}"):
        check_result("a 200 KB stack, two threads, refined", "smaller-stack", self_map=True)
        outcomes.append(("a 200 KB stack, two threads, refined", "result"))
    # Too small for the program: one line that says so, before any work, not a crash.
    arguments = [fine, fine, "-o", "tiny-stack", *FAST]
    code, _, err = harness.run(*arguments, timeout=timeout, stack=64 * 2 ** 10)
    harness.check_one_line_error(arguments, code, err, ["the stack limit is 64 KB (ulimit -s)", "at least 128 KB"],
                                 ["tiny-stack"])
    outcomes.append(("a 64 KB stack", "error: " + err.strip()[:60]))
os.remove(os.path.join(work, sparse))

# --- 8. Random mutations (fixed seed): bytes changed, inserted, deleted in valid files. ----
mutator = random.Random(7)
for fmt in FORMATS:
    original = bytes_of(fmt, lumpy)
    for trial in range(5):
        data = bytearray(original)
        for _ in range(mutator.choice([1, 3, 10])):
            at, choice = mutator.randrange(len(data)), mutator.random()
            if choice < 0.5:
                data[at] = mutator.randrange(256)
            elif choice < 0.75:
                data[at:at] = bytes([mutator.choice(b"0123456789-.e \n")])
            else:
                del data[at:at + mutator.randrange(1, 8)]
        name = write(f"mutated{trial}-{file_name('lumpy', fmt)}", bytes(data))
        expect_error_or_result(f"{fmt} mutation {trial}", name)

width = max(len(label) for label, _ in outcomes)
print("\n".join(f"{label:<{width}}  {outcome}" for label, outcome in outcomes))
harness.finish()
