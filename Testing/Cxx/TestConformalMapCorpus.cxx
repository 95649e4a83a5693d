// The conformal map on a corpus of meshes as users bring them (ConformalMapCorpus.h): CGAL's
// meshes re-triangulated at 3K-10K vertices and generated shapes with thin limbs, tails and
// fingers. Every one must map: no refusal (DegenerateMap 0), no triangle flipped, and the
// robust distortion figures within the bounds below.
//
// MOBIUS_CORPUS_DUMP=DIR also writes each mesh to DIR/NAME.off (to run other builds on them),
// MOBIUS_CORPUS_ONLY=TEXT maps only the meshes whose name contains TEXT, and
// MOBIUS_CORPUS_EXTRA=1 adds thinner shapes, for measurements (not checked).
#include "ConformalMapCorpus.h"
#include "IsotropicRemesher.h"
#include "MobiusTestUtilities.h"

#include "vtkSphericalConformalMap.h"
#include "vtkStringArray.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace
{
using mobius_corpus::CorpusMesh;

std::vector<CorpusMesh> Corpus(bool extra)
{
  std::vector<CorpusMesh> corpus;
  auto add = [&](const std::string& name, std::function<vtkSmartPointer<vtkPolyData>()> make) {
    corpus.push_back({ name, make });
  };
  // Generated shapes (after the CGAL meshes) are held to looser bounds: most of their surface
  // is thin parts.
#ifdef MOBIUS_MESH_DIR
  const std::string dir = MOBIUS_MESH_DIR;
  auto read = [dir](const std::string& name) { return mobius_corpus::ReadMesh(dir + "/" + name + ".off"); };
  // Isotropic remeshings: well-shaped triangles, as remeshing tools make them.
  for (const std::string name : { "cow", "bull", "camel", "man", "hand", "bear", "armadillo" })
  {
    for (int target : { 3000, 5000, 10000 })
    {
      add(name + "-remeshed-" + std::to_string(target / 1000) + "k",
        [=] { return mobius_corpus::IsotropicallyRemeshed(read(name), target); });
    }
  }
  // Quadric decimations: needles and obtuse triangles (non-Delaunay edges everywhere).
  for (const std::string name : { "bull", "camel", "man" })
  {
    add(name + "-decimated-3k", [=] { return mobius_corpus::Decimated(read(name), 3000); });
  }
  add("cow-subdivided-decimated-5k",
    [=] { return mobius_corpus::Decimated(mobius_corpus::LoopSubdivided(read("cow"), 1), 5000); });
  // Refused before as "squashed" (mean distortion 24.6, from the triangles of the tail).
  add("cow-subdivided2-decimated-5k",
    [=] { return mobius_corpus::Decimated(mobius_corpus::LoopSubdivided(read("cow"), 2), 5000); });
#endif
  // Generated shapes with thin parts; widths 0.2, body 1 wide.
  add("quadruped-legs10-tail10", [] { return mobius_corpus::Quadruped(10, 10, 0.95, 2); });
  add("quadruped-legs16-tail20", [] { return mobius_corpus::Quadruped(16, 20, 0.95, 2); });
  add("quadruped-legs20-tail30", [] { return mobius_corpus::Quadruped(20, 30, 0.97, 2); });
  add("hand-fingers8", [] { return mobius_corpus::Hand(8, 0.0, 2); });
  add("hand-fingers12-curled", [] { return mobius_corpus::Hand(12, 0.15, 2); });
  add("hand-fingers16", [] { return mobius_corpus::Hand(16, 0.05, 2); });
  add("urchin-6x10", [] { return mobius_corpus::Urchin(6, 10, 0.6, 2); });
  add("urchin-6x20", [] { return mobius_corpus::Urchin(6, 20, 0.6, 2); });
  add("urchin-2x40", [] { return mobius_corpus::Urchin(2, 40, 0.6, 2); });
  add("spike-60", [] { return mobius_corpus::Urchin(1, 60, 0.6, 2); });
  add("branches-20", [] { return mobius_corpus::Branches(20, 2); });
  add("branches-30", [] { return mobius_corpus::Branches(30, 2); });
  if (extra)
  {
    // Beyond the corpus: thinner and longer, for measurements (not checked).
    add("urchin-6x40", [] { return mobius_corpus::Urchin(6, 40, 0.6, 2); });
    add("urchin-6x60", [] { return mobius_corpus::Urchin(6, 60, 0.6, 2); });
    add("urchin-6x30-thin", [] { return mobius_corpus::Urchin(6, 30, 0.3, 2); });
    add("quadruped-legs30-tail50", [] { return mobius_corpus::Quadruped(30, 50, 0.98, 2); });
    add("hand-fingers24", [] { return mobius_corpus::Hand(24, 0.05, 2); });
    for (int length : { 10, 40, 50, 60 })
    {
      add("branches-" + std::to_string(length), [=] { return mobius_corpus::Branches(length, 2); });
    }
    for (int rings : { 10, 20, 30, 40, 50, 80, 100, 150 })
    {
      add("spike-" + std::to_string(rings), [=] { return mobius_corpus::Urchin(1, rings, 0.6, 2); });
    }
  }
  return corpus;
}

void WriteOff(vtkPolyData* mesh, const std::string& path)
{
  std::ofstream out(path);
  out << "OFF\n" << mesh->GetNumberOfPoints() << " " << mesh->GetNumberOfCells() << " 0\n";
  out << std::setprecision(17);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double* p = mesh->GetPoint(i);
    out << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    out << npts;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      out << " " << ids[k];
    }
    out << "\n";
  }
}

double Field(vtkPolyData* map, const char* name)
{
  return mobius_test::FieldValue(map, name);
}

// The bounds every corpus map is held to (measured: CGAL-derived median at most 1.41, p95 6.7,
// squashed 3.2%; generated median 3.1, p95 6.6, squashed 2.8%).
struct Bounds
{
  double Median, P95, SquashedShare;
};
constexpr Bounds CgalBounds{ 1.5, 8.0, 0.05 };
constexpr Bounds GeneratedBounds{ 3.5, 8.0, 0.05 };

// Checks one map; returns the failures (each printed).
int CheckMap(const std::string& name, vtkPolyData* out, const Bounds& bounds)
{
  int failures = 0;
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok)
    {
      std::cerr << name << ": " << what << "\n";
      ++failures;
    }
  };
  expect(Field(out, "DegenerateMap") == 0, "refused as degenerate");
  expect(Field(out, "FlippedTriangles") == 0, "triangles flipped");
  expect(Field(out, "MedianQuasiConformalDistortion") <= bounds.Median, "median distortion above bound");
  expect(Field(out, "P95QuasiConformalDistortion") <= bounds.P95, "95th percentile above bound");
  const double squashed = Field(out, "SquashedAreaShare");
  expect(squashed <= bounds.SquashedShare, "squashed share above bound");
  // Every triangle resolved on the sphere: no edge below about 1e-14.
  expect(Field(out, "SmallestSphereAreaShare") > 1e-32, "a triangle collapsed on the sphere");
  // The warning names the squashed share exactly when it is above 1%.
  auto warning = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("MapWarning"));
  const bool warned = warning && warning->GetNumberOfValues() == 1 && !warning->GetValue(0).empty();
  expect(warned == (squashed > 0.01), "warning and squashed share disagree");
  return failures;
}

// A mesh is mapped a second time, on the intrinsic Delaunay triangulation, only when the map
// with its own weights keeps folds after the repair: CGAL's man remeshed to 5K folds a few
// triangles with its own weights, which the repair undoes (it keeps its weights and is mapped
// once); the decimated camel is left with folds (mapped again). Returns the failures.
int CheckWeightsChoice(const std::string& name, vtkPolyData* out)
{
  const bool intrinsic = Field(out, "IntrinsicDelaunayUsed") == 1;
  if (name == "man-remeshed-5k" && (Field(out, "FlipRepairMovedVertices") == 0 || intrinsic))
  {
    std::cerr << name << ": expected repaired folds and the mesh's own weights\n";
    return 1;
  }
  if (name == "camel-decimated-3k" && !intrinsic)
  {
    std::cerr << name << ": expected the intrinsic Delaunay weights\n";
    return 1;
  }
  return 0;
}
}

int TestConformalMapCorpus(int, char*[])
{
  int failures = 0, mapped = 0;
  const char* dump = std::getenv("MOBIUS_CORPUS_DUMP");
  const char* only = std::getenv("MOBIUS_CORPUS_ONLY");
  const bool extra = std::getenv("MOBIUS_CORPUS_EXTRA") != nullptr;
  const auto started = std::chrono::steady_clock::now();
  std::cout << "| mesh | vertices | made in s | mapped in s | flips | mean QC | median | p95 | p99 | "
               "squashed % | smallest area / 4pi | degenerate |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::vector<CorpusMesh> corpus = Corpus(extra);
  const size_t checked = Corpus(false).size();
  for (size_t e = 0; e < corpus.size(); ++e)
  {
    const CorpusMesh& entry = corpus[e];
    if (only && entry.Name.find(only) == std::string::npos)
    {
      continue;
    }
    const auto made = std::chrono::steady_clock::now();
    vtkSmartPointer<vtkPolyData> mesh = entry.Make();
    const double making =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - made).count();
    if (dump)
    {
      WriteOff(mesh, std::string(dump) + "/" + entry.Name + ".off");
    }
    vtkNew<vtkSphericalConformalMap> map;
    mobius_test::MessageCatcher catcher(map);
    mobius_test::MessageCatcher executiveCatcher(map->GetExecutive());
    map->SetInputData(mesh);
    const auto start = std::chrono::steady_clock::now();
    map->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    vtkPolyData* out = map->GetOutput();
    if (!catcher.Error.empty() || out->GetNumberOfPoints() == 0)
    {
      std::cout << "| " << entry.Name << " | " << mesh->GetNumberOfPoints() << " | error: " << catcher.Error << " |\n";
      failures += e < checked ? 1 : 0;
      continue;
    }
    ++mapped;
    auto reason = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("DegenerateMapReason"));
    std::cout << "| " << entry.Name << " | " << out->GetNumberOfPoints() << " | " << std::setprecision(3)
              << making << " | " << seconds << " | " << Field(out, "FlippedTriangles") << " | "
              << Field(out, "MeanQuasiConformalDistortion") << " | "
              << Field(out, "MedianQuasiConformalDistortion") << " | "
              << Field(out, "P95QuasiConformalDistortion") << " | "
              << Field(out, "P99QuasiConformalDistortion") << " | "
              << 100 * Field(out, "SquashedAreaShare") << " | "
              << Field(out, "SmallestSphereAreaShare") << " | "
              << (reason ? reason->GetValue(0) : "") << " |" << std::endl;
    if (e < checked)
    {
      const bool generated = entry.Name.find("remeshed") == std::string::npos &&
        entry.Name.find("decimated") == std::string::npos;
      failures += CheckMap(entry.Name, out, generated ? GeneratedBounds : CgalBounds);
      failures += CheckWeightsChoice(entry.Name, out);
    }
  }
  std::cout << mapped << " meshes mapped in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()
            << " s; " << failures << " failures\n";
  // The corpus must be what the issue asks for: 30 meshes or more (unless narrowed).
  if (!only && checked < 30)
  {
    std::cerr << "the corpus has only " << checked << " meshes\n";
    ++failures;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
