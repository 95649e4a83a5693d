// vtkSurfaceMeshReader: every supported format round-trips a mesh; bad files give an error
// naming the file and the reason.
#include "MobiusTestUtilities.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkExecutive.h"
#include "vtkPLYWriter.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLWriter.h"
#include "vtkSphereSource.h"
#include "vtkLogger.h"
#include "vtkTestUtilities.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace
{
int ExpectMesh(const std::string& fileName, vtkIdType points, vtkIdType polys)
{
  int failures = 0;
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPoints() != points ||
    reader->GetOutput()->GetNumberOfPolys() != polys)
  {
    std::cerr << fileName << ": read " << reader->GetOutput()->GetNumberOfPoints() << " points, "
              << reader->GetOutput()->GetNumberOfPolys() << " polygons; expected " << points
              << ", " << polys << "\n";
    ++failures;
  }
  return failures;
}

int ExpectError(const std::string& fileName, const std::string& words)
{
  int failures = 0;
  vtkNew<vtkSurfaceMeshReader> reader;
  mobius_test::MessageCatcher catcher(reader);
  mobius_test::MessageCatcher executiveCatcher(reader->GetExecutive());
  reader->SetFileName(fileName.c_str());
  reader->Update();
  if (catcher.Error.find(words) == std::string::npos ||
    catcher.Error.find(fileName) == std::string::npos)
  {
    std::cerr << "expected an error naming " << fileName << " and containing '" << words
              << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(reader->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

void WriteText(const std::string& fileName, const std::string& text)
{
  std::ofstream(fileName) << text;
}

const char* const TetraVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";

std::string AsciiPly(
  const std::string& faces, const std::string& vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
{
  return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
         "end_header\n" +
    vertices + faces;
}

// Files whose indices or coordinates VTK's readers would pass on unchecked (or crash on):
// each must be an error naming the problem, without touching memory out of bounds.
int TestHostileFiles(const std::string& dir)
{
  int failures = 0;
  WriteText(dir + "/zero.obj", std::string(TetraVertices) + "f 0 1 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  failures +=
    ExpectError(dir + "/zero.obj", "invalid vertex index '0' (OBJ numbers vertices from 1)");
  WriteText(
    dir + "/far.obj", std::string(TetraVertices) + "f 1 3 2\nf 1 2 99999\nf 2 3 4\nf 1 4 3\n");
  failures += ExpectError(dir + "/far.obj", "face 1 (line 6) refers to vertex 99999");
  WriteText(dir + "/before.obj", std::string(TetraVertices) + "f 1 3 2\nf -1 -2 -5\n");
  failures += ExpectError(dir + "/before.obj", "invalid vertex index '-5'");
  WriteText(dir + "/words.obj", std::string(TetraVertices) + "f 1 3 two\n");
  failures += ExpectError(dir + "/words.obj", "invalid vertex index 'two'");
  WriteText(dir + "/line.obj", std::string(TetraVertices) + "f 1 3\n");
  failures += ExpectError(dir + "/line.obj", "fewer than 3 vertices");
  WriteText(dir + "/nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n");
  failures +=
    ExpectError(dir + "/nan.obj", "vertex 2 (line 3) has a NaN or infinite coordinate 'nan'");
  WriteText(dir + "/inf.obj", "v 0 0 0\nv 1 0 -inf\nf 1 2 1\n");
  failures += ExpectError(dir + "/inf.obj", "vertex 1 (line 2) has a NaN or infinite coordinate");
  WriteText(dir + "/short.obj", "v 0 0\nf 1 1 1\n");
  failures += ExpectError(dir + "/short.obj", "vertex 0 (line 1) does not have three numeric");

  WriteText(dir + "/far.ply", AsciiPly("3 0 2 1\n3 0 1 1000000\n3 1 2 3\n3 0 3 2\n"));
  failures += ExpectError(dir + "/far.ply", "face 1 refers to vertex 1000000, but the file has 4");
  WriteText(dir + "/negative.ply", AsciiPly("3 0 2 1\n3 0 1 -5\n3 1 2 3\n3 0 3 2\n"));
  failures += ExpectError(dir + "/negative.ply", "face 1 refers to vertex -5");
  WriteText(dir + "/exponent.ply", AsciiPly("3 0 2 1\n3 0 1 1e6\n3 1 2 3\n3 0 3 2\n"));
  failures += ExpectError(dir + "/exponent.ply", "face 1 (property 'vertex_indices') is malformed");
  WriteText(dir + "/truncated.ply", AsciiPly("3 0 2 1\n3 0 1\n"));
  failures += ExpectError(dir + "/truncated.ply", "is missing");
  WriteText(dir + "/nan.ply",
    AsciiPly("3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n", "0 0 0\n1 0 0\n0 nan 0\n0 0 1\n"));
  failures += ExpectError(dir + "/nan.ply", "vertex 2 has a NaN or infinite coordinate y");

  // Binary, both byte orders: a tetrahedron whose last face has index `last`.
  for (const bool big : { false, true })
  {
    for (const int last : { 3, 4, -1 })
    {
      std::string bytes = std::string("ply\nformat ") +
        (big ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
      auto put = [&](const void* value, size_t size) {
        std::string word(static_cast<const char*>(value), size);
        if (big) // this test runs on little-endian machines only (x86-64, arm64)
        {
          std::reverse(word.begin(), word.end());
        }
        bytes += word;
      };
      const float coordinates[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
      for (float c : coordinates)
      {
        put(&c, sizeof c);
      }
      const int faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, last } };
      for (const auto& face : faces)
      {
        bytes += '\3';
        for (int index : face)
        {
          put(&index, sizeof index);
        }
      }
      const std::string name =
        dir + "/binary" + (big ? "-big" : "-little") + std::to_string(last) + ".ply";
      WriteText(name, bytes);
      failures += last == 3
        ? ExpectMesh(name, 4, 4)
        : ExpectError(
            name, "face 3 refers to vertex " + std::to_string(last) + ", but the file has 4");
    }
  }

  WriteText(dir + "/past.vtk", "# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\n"
                               "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n"
                               "3 0 2 1\n3 0 1 3\n3 1 2 7\n3 0 3 2\n");
  failures += ExpectError(dir + "/past.vtk", "polygon 2 refers to point 7, but there are 4 points");
  return failures;
}

// Headers claiming more than the file holds: VTK's readers (and a naive OFF reader) would
// allocate the claim before reading, gigabytes for a file of a few bytes.
int TestHostileSizes(const std::string& dir)
{
  int failures = 0;
  const std::string tetraOff = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  WriteText(dir + "/huge.off", "OFF\n2000000000 4 0\n" + tetraOff + "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  failures += ExpectError(dir + "/huge.off", "the header claims 2000000000 vertices");
  WriteText(dir + "/huge-faces.off", "OFF\n4 2000000000 0\n" + tetraOff + "3 0 2 1\n");
  failures += ExpectError(dir + "/huge-faces.off", "2000000000 faces");
  WriteText(dir + "/huge-face.off",
    "OFF\n4 4 0\n" + tetraOff + "2000000000 0 1 2\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  failures += ExpectError(dir + "/huge-face.off", "face 0 of 4 claims 2000000000 vertices");
  const std::string legacyHeader = "# vtk DataFile Version 3.0\nhostile\nASCII\nDATASET POLYDATA\n";
  WriteText(dir + "/huge.vtk", legacyHeader + "POINTS 2000000000 float\n0 0 0 1 0 0 0 1 0 0 0 1\n");
  failures += ExpectError(dir + "/huge.vtk", "the header claims 2000000000 points");
  WriteText(dir + "/huge-cells.vtk", legacyHeader +
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 3000000000\n3 0 2 1\n");
  failures += ExpectError(dir + "/huge-cells.vtk", "3000000000 values");
  WriteText(dir + "/huge-data.vtk", legacyHeader +
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 1 4\n3 0 2 1\nPOINT_DATA 2000000000\n");
  failures += ExpectError(dir + "/huge-data.vtk", "2000000000 point data tuples");
  WriteText(dir + "/huge.vtp",
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n"
    "<PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"2000000000\">\n"
    "</Piece></PolyData></VTKFile>\n");
  failures += ExpectError(dir + "/huge.vtp", "the header claims 2000000000 polygons");
  WriteText(dir + "/huge-field.vtk", legacyHeader +
      "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 1 4\n3 0 2 1\nPOINT_DATA 4\n"
      "FIELD FieldData 1\nbig 1000000000 4 float\n0 0 0 0\n");
  failures += ExpectError(dir + "/huge-field.vtk", "claims 1000000000 x 4 values");
  WriteText(dir + "/components.vtp",
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n"
    "<PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"1\">\n<Points><DataArray "
    "type=\"Float32\" NumberOfComponents=\"1000000000\" format=\"ascii\">0 0 0</DataArray>"
    "</Points></Piece></PolyData></VTKFile>\n");
  failures += ExpectError(dir + "/components.vtp", "claims 1000000000 components per tuple");
  // A binary STL whose count claims 2e9 triangles and holds one: VTK's reader would allocate
  // the claim (and end the program).
  std::string stl(80, 'x');
  const unsigned char count[4] = { 0x00, 0x94, 0x35, 0x77 }; // 2,000,000,000, little-endian
  stl.append(reinterpret_cast<const char*>(count), 4);
  stl.append(50, '\0');
  WriteText(dir + "/huge.stl", stl);
  failures += ExpectError(dir + "/huge.stl", "the header claims 2000000000 triangles");
  // Not regular files: a directory, and a device that never ends.
  const std::string folder = dir + "/folder.off";
  mkdir(folder.c_str(), 0755);
  failures += ExpectError(folder, "is a directory");
  const std::string zero = dir + "/zero.ply";
  std::remove(zero.c_str());
  if (symlink("/dev/zero", zero.c_str()) == 0)
  {
    failures += ExpectError(zero, "is not a regular file");
  }
  return failures;
}

// OBJ with texture coordinates and normals, faces in an order unrelated to the `v` order,
// polygons, relative indices and an unused vertex: point i must still be the file's i-th `v`.
int TestObjVertexOrder(const std::string& dir)
{
  int failures = 0;
  WriteText(dir + "/order.obj",
    "# a square pyramid whose faces list the apex (the last v) first\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 9 9 9\nv 0.5 0.5 1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
    "g side\nusemtl stone\ns 1\n"
    "f 6/1/1 1/2/1 2/3/1\nf -1/1 2/2 3/3\nf 6//1 3//1 4//1\nf 6 4 \\\n 1\n"
    "f 4/1/1 3/2/1 2/3/1 1/1/1\n");
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName((dir + "/order.obj").c_str());
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput();
  MOBIUS_EXPECT(mesh->GetNumberOfPoints() == 6);
  MOBIUS_EXPECT(mesh->GetNumberOfPolys() == 5);
  const double expected[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 9, 9, 9 },
    { 0.5, 0.5, 1 } };
  for (vtkIdType i = 0; i < std::min<vtkIdType>(6, mesh->GetNumberOfPoints()); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    MOBIUS_EXPECT(p[0] == expected[i][0] && p[1] == expected[i][1] && p[2] == expected[i][2]);
  }
  const std::vector<std::vector<vtkIdType>> faces = { { 5, 0, 1 }, { 5, 1, 2 }, { 5, 2, 3 },
    { 5, 3, 0 }, { 3, 2, 1, 0 } };
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  polys->InitTraversal();
  for (const auto& face : faces)
  {
    MOBIUS_EXPECT(polys->GetNextCell(npts, ids) &&
      std::vector<vtkIdType>(ids, ids + npts) == face);
  }
  return failures;
}

// Cases of the hostile-input suite (Testing/Applications/test_hostile_inputs.py) fixed in the
// reader, which ParaView uses without the command line.
int TestHostileText(const std::string& dir)
{
  int failures = 0;
  // Complete, but without the last line break: VTK's PLY reader failed an assertion (and
  // ended the program) at the end of the file.
  std::string ply = AsciiPly("3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2");
  WriteText(dir + "/unterminated.ply", ply);
  failures += ExpectMesh(dir + "/unterminated.ply", 4, 4);
  // Blank lines among the items (some with white space or a carriage return): VTK's parser
  // took each for an item, read past the end and failed an assertion (found by the fuzzer).
  ply = AsciiPly("3 0 2 1\n\n3 0 1 3\n3 1 2 3\n \t\n3 0 3 2\n", "0 0 0\n\n1 0 0\r\n\r\n0 1 0\n0 0 1\n\n");
  WriteText(dir + "/blank-lines.ply", ply);
  failures += ExpectMesh(dir + "/blank-lines.ply", 4, 4);
  // Faces first, the vertices last without a final line break: the rewrite puts the vertices
  // first, and no blank line may come between them and the faces.
  WriteText(dir + "/faces-first.ply",
    "ply\nformat ascii 1.0\nelement face 4\nproperty list uchar int vertex_indices\n"
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1");
  failures += ExpectMesh(dir + "/faces-first.ply", 4, 4);
  // NaN, infinite and overflowing coordinates are named as such (not "malformed", and not
  // VTK's "Unrecognized keyword: nan").
  WriteText(dir + "/nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 nan 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  failures += ExpectError(dir + "/nan.off", "vertex 2 has a NaN or infinite coordinate 'nan'");
  WriteText(dir + "/overflow.ply", AsciiPly("3 0 2 1\n", "0 0 0\n1 0 0\n0 1e999 0\n0 0 1\n"));
  failures += ExpectError(dir + "/overflow.ply", "vertex 2 has a NaN or infinite coordinate y");
  WriteText(dir + "/inf.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                              "0 0 0 1 0 0\n0 -inf 0 0 0 1\nPOLYGONS 1 4\n3 0 1 2\n");
  failures += ExpectError(dir + "/inf.vtk", "point 2 has a NaN or infinite coordinate '-inf'");
  // A cell count past the section's declared size: VTK's legacy reader read past its buffer.
  WriteText(dir + "/long-cell.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                                    "0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 3\n9 0 3 2\n");
  failures += ExpectError(dir + "/long-cell.vtk", "POLYGONS section: cell 3 claims 9 points");
  // VTK quotes the bytes it could not parse: the message stays one printable line.
  WriteText(dir + "/binary-garbage.vtk", std::string("\x1b[31m\n\x01\x02garbage\r\nmore\n", 21));
  {
    vtkNew<vtkSurfaceMeshReader> reader;
    mobius_test::MessageCatcher catcher(reader);
    mobius_test::MessageCatcher executiveCatcher(reader->GetExecutive());
    reader->SetFileName((dir + "/binary-garbage.vtk").c_str());
    reader->Update();
    const std::string reason = catcher.Error.substr(catcher.Error.find("binary-garbage.vtk"));
    const std::string body = reason.substr(0, reason.find_last_not_of('\n') + 1);
    MOBIUS_EXPECT(!catcher.Error.empty() && body.find('\n') == std::string::npos &&
      body.find('\x1b') == std::string::npos && body.find('\x01') == std::string::npos);
  }
  // Headers VTK's PLY reader crashed on: no z, no vertex_indices.
  const std::string tetra = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  std::string noZ = AsciiPly(tetra);
  noZ.replace(noZ.find("property float z"), 16, "property float w");
  WriteText(dir + "/no-z.ply", noZ);
  failures += ExpectError(dir + "/no-z.ply", "the PLY vertex element has no scalar property 'z'");
  std::string noIndices = AsciiPly(tetra);
  noIndices.replace(noIndices.find("vertex_indices"), 14, "corners");
  WriteText(dir + "/no-indices.ply", noIndices);
  failures += ExpectError(dir + "/no-indices.ply", "no list property 'vertex_indices'");
  WriteText(dir + "/faces-first.ply",
    "ply\nformat ascii 1.0\nelement face 4\nproperty list uchar int vertex_indices\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\nend_header\n" + tetra +
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  // Read by giving VTK's reader the vertices first (ReadablePLYText), as is an element it
  // does not know, which crashed it.
  failures += ExpectMesh(dir + "/faces-first.ply", 4, 4);
  WriteText(dir + "/material-first.ply",
    "ply\nformat ascii 1.0\nelement material 1\nproperty float shine\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\nelement face 4\n"
    "property list uchar int vertex_indices\nend_header\n0.5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
    tetra);
  failures += ExpectMesh(dir + "/material-first.ply", 4, 4);
  WriteText(dir + "/empty-binary.stl", std::string(80, 'x') + std::string(4, '\0'));
  failures += ExpectError(dir + "/empty-binary.stl", "holds no triangles");
  return failures;
}
}

int TestSurfaceMeshReader(int argc, char* argv[])
{
  int failures = 0;
  char* tempDir =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string dir = tempDir;
  delete[] tempDir;

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  const vtkIdType n = mesh->GetNumberOfPoints(), m = mesh->GetNumberOfPolys();

  vtkNew<vtkXMLPolyDataWriter> vtp;
  vtp->SetInputData(mesh);
  // Inline binary, not the default appended data: with Debian bookworm's expat
  // (2.5.0-1+deb12u5) VTK 9.2's XML parser rejects many files with appended data.
  vtp->SetDataModeToBinary();
  vtp->SetFileName((dir + "/reader.vtp").c_str());
  vtp->Write();
  failures += ExpectMesh(dir + "/reader.vtp", n, m);

  vtkNew<vtkPolyDataWriter> legacy;
  legacy->SetInputData(mesh);
  legacy->SetFileName((dir + "/reader.vtk").c_str());
  legacy->Write();
  failures += ExpectMesh(dir + "/reader.vtk", n, m);

  vtkNew<vtkPLYWriter> ply;
  ply->SetInputData(mesh);
  ply->SetFileName((dir + "/reader.ply").c_str());
  ply->Write();
  failures += ExpectMesh(dir + "/reader.ply", n, m);

  vtkNew<vtkSTLWriter> stl;
  stl->SetInputData(mesh);
  stl->SetFileName((dir + "/reader.STL").c_str()); // extensions are case-insensitive
  stl->Write();
  failures += ExpectMesh(dir + "/reader.STL", n, m); // the STL reader merges points again
  stl->SetFileTypeToBinary(); // its triangle count is checked against the file size
  stl->SetFileName((dir + "/reader-binary.stl").c_str());
  stl->Write();
  failures += ExpectMesh(dir + "/reader-binary.stl", n, m);

  // A tetrahedron in OFF with comments, counts on the header line and a face color; and
  // the same in OBJ.
  WriteText(dir + "/tetra.off", "OFF 4 4 6 # comment\n0 0 0\n1 0 0\n0 1 0\n# skip\n0 0 1\n"
                                "3 0 2 1\n3 0 1 3\n3 1 2 3 255 0 0\n3 0 3 2\n");
  failures += ExpectMesh(dir + "/tetra.off", 4, 4);
  WriteText(dir + "/tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  failures += ExpectMesh(dir + "/tetra.obj", 4, 4);
  MOBIUS_EXPECT(vtkSurfaceMeshReader::IsSupportedFile("a/b.Off"));
  MOBIUS_EXPECT(!vtkSurfaceMeshReader::IsSupportedFile("a/b.xyz"));

  failures += ExpectError(dir + "/does-not-exist.off", "cannot open");
  WriteText(dir + "/mesh.xyz", "1 2 3\n");
  failures += ExpectError(dir + "/mesh.xyz", "unknown mesh format");
  WriteText(dir + "/empty.off", "");
  failures += ExpectError(dir + "/empty.off", "empty");
  WriteText(dir + "/bad-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  failures += ExpectError(dir + "/bad-index.off", "out of range");
  WriteText(dir + "/short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  failures += ExpectError(dir + "/short.off", "vertex 2 of 3");
  {
    // VTK's XML parser prints its own complaint; keep it out of the test log.
    const auto verbosity = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    WriteText(dir + "/garbage.vtp", "this is not XML");
    failures += ExpectError(dir + "/garbage.vtp", "");
    vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(verbosity));
  }
  failures += TestHostileFiles(dir);
  failures += TestHostileSizes(dir);
  failures += TestObjVertexOrder(dir);
  failures += TestHostileText(dir);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
