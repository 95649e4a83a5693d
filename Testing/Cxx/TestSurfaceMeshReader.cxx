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

#include <fstream>

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
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
