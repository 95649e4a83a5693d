// Joining the pieces of a surface split over ranks (MobiusMergePieces.h, which
// MobiusDistributedInputs uses on rank 0): a closed mesh cut in two comes back whole, in its
// own point and cell order when the pieces carry global ids, and two vertices of one
// piece at one position (CGAL's cow has such a pair) stay two; ghost copies of cells are
// dropped; a piece that refers to a point it lacks is an error, not a crash.
#include "MobiusTestUtilities.h"
#include "Private/MobiusMergePieces.h"

#include "vtkIdTypeArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace
{
using mobius_test::BumpyMesh;

struct PieceOptions
{
  bool GlobalIds = false;      // point and cell global ids: the whole mesh's numbers
  bool Shuffle = false;        // the piece's points in a scrambled order
  std::set<vtkIdType> Ghosts;  // cells of other pieces added as DUPLICATECELL ghosts
};

// The cells `cells` of `mesh` (in this order) as a piece with its own point numbering.
vtkSmartPointer<vtkPolyData> MakePiece(vtkPolyData* mesh, const std::vector<vtkIdType>& cells,
  const PieceOptions& options, unsigned seed)
{
  std::vector<vtkIdType> all(cells);
  all.insert(all.end(), options.Ghosts.begin(), options.Ghosts.end());
  std::vector<vtkIdType> used;
  for (vtkIdType c : all)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    used.insert(used.end(), ids, ids + npts);
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (options.Shuffle)
  {
    std::mt19937 random(seed);
    std::shuffle(used.begin(), used.end(), random);
  }
  std::map<vtkIdType, vtkIdType> local;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> pointIds;
  vtkNew<vtkDoubleArray> marker; // a point array to follow through the merge
  marker->SetName("Marker");
  for (vtkIdType id : used)
  {
    local[id] = points->InsertNextPoint(mesh->GetPoint(id));
    pointIds->InsertNextValue(id);
    marker->InsertNextValue(1000.0 + id);
  }
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> cellIds;
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  for (vtkIdType c : all)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    std::vector<vtkIdType> renumbered;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      renumbered.push_back(local[ids[k]]);
    }
    polys->InsertNextCell(npts, renumbered.data());
    cellIds->InsertNextValue(c);
    ghosts->InsertNextValue(options.Ghosts.count(c) ? vtkDataSetAttributes::DUPLICATECELL : 0);
  }
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  piece->SetPoints(points);
  piece->SetPolys(polys);
  piece->GetPointData()->AddArray(marker);
  if (options.GlobalIds)
  {
    pointIds->SetName("GlobalPointIds");
    piece->GetPointData()->SetGlobalIds(pointIds);
    cellIds->SetName("GlobalCellIds");
    piece->GetCellData()->SetGlobalIds(cellIds);
  }
  if (!options.Ghosts.empty())
  {
    piece->GetCellData()->AddArray(ghosts);
  }
  return piece;
}

// The mesh's cells split by the sign of their centroid's x (a plane cut, as
// RedistributeDataSet's k-d tree makes), the second half in reverse order.
std::vector<std::vector<vtkIdType>> SplitCells(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> halves(2);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    double x = 0;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      x += mesh->GetPoint(ids[k])[0] / npts;
    }
    halves[x < 0 ? 0 : 1].push_back(c);
  }
  std::reverse(halves[1].begin(), halves[1].end());
  return halves;
}

// Edges of the polygons used by one polygon only.
int OpenEdges(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      ++uses[std::minmax(ids[k], ids[(k + 1) % npts])];
    }
  }
  return static_cast<int>(
    std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second == 1; }));
}

// Every edge of the polygons is used by exactly two of them (a closed surface).
bool IsClosed(vtkPolyData* mesh)
{
  return OpenEdges(mesh) == 0;
}

// Same points (exactly, in order), same cells (in order) and the marker array in order.
int ExpectSameMesh(vtkPolyData* merged, vtkPolyData* mesh)
{
  int failures = 0;
  MOBIUS_EXPECT(merged->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  MOBIUS_EXPECT(merged->GetNumberOfCells() == mesh->GetNumberOfCells());
  if (failures)
  {
    return failures;
  }
  vtkDataArray* marker = merged->GetPointData()->GetArray("Marker");
  MOBIUS_EXPECT(marker != nullptr);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints() && failures == 0; ++i)
  {
    const double* p = mesh->GetPoint(i);
    const double* q = merged->GetPoint(i);
    MOBIUS_EXPECT(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
    MOBIUS_EXPECT(marker && marker->GetTuple1(i) == 1000.0 + i);
  }
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells() && failures == 0; ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *a, *b;
    mesh->GetCellPoints(c, n1, a);
    merged->GetCellPoints(c, n2, b);
    MOBIUS_EXPECT(n1 == n2 && std::equal(a, a + n1, b));
  }
  return failures;
}

int TestGlobalIdsRestoreTheOrder()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  const auto halves = SplitCells(mesh);
  PieceOptions options;
  options.GlobalIds = true;
  options.Shuffle = true;
  auto a = MakePiece(mesh, halves[1], options, 1);
  auto b = MakePiece(mesh, halves[0], options, 2);
  vtkNew<vtkPolyData> empty;
  const auto merged = mobius::vtk::MergePieces({ a, empty, b });
  MOBIUS_EXPECT(merged.Error.empty() && merged.GlobalIdsIgnored.empty());
  failures += ExpectSameMesh(merged.Surface, mesh);
  return failures;
}

int TestGhostCellsDropped()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  const auto halves = SplitCells(mesh);
  PieceOptions withGhosts;
  withGhosts.GlobalIds = true;
  // Piece a also holds copies of the first cells of piece b, marked as ghosts.
  withGhosts.Ghosts.insert(halves[0].begin(), halves[0].begin() + 40);
  PieceOptions plain;
  plain.GlobalIds = true;
  auto a = MakePiece(mesh, halves[1], withGhosts, 3);
  auto b = MakePiece(mesh, halves[0], plain, 4);
  const auto merged = mobius::vtk::MergePieces({ a, b });
  MOBIUS_EXPECT(merged.Error.empty());
  failures += ExpectSameMesh(merged.Surface, mesh);
  MOBIUS_EXPECT(!merged.Surface->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));

  // Without global ids, by position: still whole and closed, ghosts gone.
  withGhosts.GlobalIds = plain.GlobalIds = false;
  const auto byPosition = mobius::vtk::MergePieces(
    { MakePiece(mesh, halves[1], withGhosts, 3), MakePiece(mesh, halves[0], plain, 4) });
  MOBIUS_EXPECT(byPosition.Surface->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  MOBIUS_EXPECT(byPosition.Surface->GetNumberOfCells() == mesh->GetNumberOfCells());
  MOBIUS_EXPECT(IsClosed(byPosition.Surface));
  return failures;
}

int TestPositionsWithoutIds()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  const auto halves = SplitCells(mesh);
  PieceOptions options;
  options.Shuffle = true;
  const auto merged = mobius::vtk::MergePieces(
    { MakePiece(mesh, halves[0], options, 5), MakePiece(mesh, halves[1], options, 6) });
  MOBIUS_EXPECT(merged.Error.empty() && merged.GlobalIdsIgnored.empty());
  MOBIUS_EXPECT(merged.Surface->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  MOBIUS_EXPECT(merged.Surface->GetNumberOfCells() == mesh->GetNumberOfCells());
  MOBIUS_EXPECT(IsClosed(merged.Surface));
  // Each point keeps its own data: the marker names a mesh point at the same position.
  vtkDataArray* marker = merged.Surface->GetPointData()->GetArray("Marker");
  MOBIUS_EXPECT(marker != nullptr);
  for (vtkIdType i = 0; marker && i < merged.Surface->GetNumberOfPoints() && failures == 0; ++i)
  {
    const double* p = merged.Surface->GetPoint(i);
    const double* q = mesh->GetPoint(static_cast<vtkIdType>(marker->GetTuple1(i)) - 1000);
    MOBIUS_EXPECT(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
  }

  // Ids that name two positions are not trusted: joined by position, with the reason.
  options.GlobalIds = true;
  auto a = MakePiece(mesh, halves[0], options, 7);
  auto b = MakePiece(mesh, halves[1], options, 8);
  // Swap the ids of two points of b on the cut (ids that a also has).
  auto aIds = vtkIdTypeArray::SafeDownCast(a->GetPointData()->GetGlobalIds());
  auto bIds = vtkIdTypeArray::SafeDownCast(b->GetPointData()->GetGlobalIds());
  std::set<vtkIdType> inA;
  for (vtkIdType i = 0; i < aIds->GetNumberOfTuples(); ++i)
  {
    inA.insert(aIds->GetValue(i));
  }
  std::vector<vtkIdType> shared;
  for (vtkIdType i = 0; i < bIds->GetNumberOfTuples() && shared.size() < 2; ++i)
  {
    if (inA.count(bIds->GetValue(i)))
    {
      shared.push_back(i);
    }
  }
  MOBIUS_EXPECT(shared.size() == 2);
  if (shared.size() == 2)
  {
    const vtkIdType first = bIds->GetValue(shared[0]);
    bIds->SetValue(shared[0], bIds->GetValue(shared[1]));
    bIds->SetValue(shared[1], first);
  }
  const auto distrusted = mobius::vtk::MergePieces({ a, b });
  MOBIUS_EXPECT(!distrusted.GlobalIdsIgnored.empty());
  MOBIUS_EXPECT(distrusted.Surface->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  MOBIUS_EXPECT(IsClosed(distrusted.Surface));
  return failures;
}

// A closed mesh with two vertices at one position (as CGAL's cow): vertex `pinch` of
// `mesh` and a copy of it, which takes over the cells of its fan with a centroid above
// the vertex. Returns the copy's id.
vtkIdType AddCoincidentVertex(vtkPolyData* mesh, vtkIdType pinch)
{
  const vtkIdType copy = mesh->GetPoints()->InsertNextPoint(mesh->GetPoint(pinch));
  const double z = mesh->GetPoint(pinch)[2];
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, npts, ids);
    std::vector<vtkIdType> cell(ids, ids + npts);
    double centroidZ = 0;
    for (vtkIdType id : cell)
    {
      centroidZ += mesh->GetPoint(id)[2] / npts;
    }
    for (vtkIdType& id : cell)
    {
      id = (id == pinch && centroidZ > z) ? copy : id;
    }
    polys->InsertNextCell(npts, cell.data());
  }
  mesh->SetPolys(polys);
  mesh->DeleteCells();
  return copy;
}

int TestCoincidentVerticesOfOnePieceStayApart()
{
  int failures = 0;
  auto mesh = BumpyMesh(2);
  // A vertex far from the cut x = 0, so that its whole fan lies in one piece.
  vtkIdType pinch = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    pinch = mesh->GetPoint(i)[0] > mesh->GetPoint(pinch)[0] ? i : pinch;
  }
  AddCoincidentVertex(mesh, pinch);
  const auto halves = SplitCells(mesh);
  PieceOptions options;
  options.Shuffle = true;
  const auto merged = mobius::vtk::MergePieces(
    { MakePiece(mesh, halves[0], options, 9), MakePiece(mesh, halves[1], options, 10) });
  // The copy splits the vertex's fan: a slit of two edges, open on both sides, as in
  // the mesh; joining the two points would close it.
  MOBIUS_EXPECT(OpenEdges(mesh) == 4);
  MOBIUS_EXPECT(merged.Surface->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  MOBIUS_EXPECT(OpenEdges(merged.Surface) == 4);

  // A vertex on the cut, and its copy: the piece holding both fans keeps two points.
  auto cutMesh = BumpyMesh(2);
  vtkIdType onCut = 0;
  for (vtkIdType i = 0; i < cutMesh->GetNumberOfPoints(); ++i)
  {
    onCut = std::abs(cutMesh->GetPoint(i)[0]) < std::abs(cutMesh->GetPoint(onCut)[0]) ? i : onCut;
  }
  AddCoincidentVertex(cutMesh, onCut);
  const auto cutHalves = SplitCells(cutMesh);
  const auto cutMerged = mobius::vtk::MergePieces({ MakePiece(cutMesh, cutHalves[0], options, 11),
    MakePiece(cutMesh, cutHalves[1], options, 12) });
  MOBIUS_EXPECT(cutMerged.Surface->GetNumberOfPoints() == cutMesh->GetNumberOfPoints());
  MOBIUS_EXPECT(OpenEdges(cutMerged.Surface) == OpenEdges(cutMesh));
  return failures;
}

int TestTrivialAndBadPieces()
{
  int failures = 0;
  auto mesh = BumpyMesh(1);
  vtkNew<vtkPolyData> empty;
  // One non-empty piece is the surface itself, untouched.
  const auto single = mobius::vtk::MergePieces({ empty, mesh, nullptr });
  MOBIUS_EXPECT(single.Surface.Get() == mesh.Get());
  const auto none = mobius::vtk::MergePieces({ empty, nullptr });
  MOBIUS_EXPECT(none.Surface && none.Surface->GetNumberOfPoints() == 0);

  const auto halves = SplitCells(mesh);
  auto a = MakePiece(mesh, halves[0], PieceOptions(), 13);
  auto b = MakePiece(mesh, halves[1], PieceOptions(), 14);
  const vtkIdType bad[3] = { 0, 1, b->GetNumberOfPoints() + 5 };
  b->GetPolys()->InsertNextCell(3, bad);
  const auto broken = mobius::vtk::MergePieces({ a, b });
  MOBIUS_EXPECT(!broken.Error.empty() && !broken.Surface);
  MOBIUS_EXPECT(broken.Error.find("refers to point") != std::string::npos);
  return failures;
}
}

int TestMergePieces(int, char*[])
{
  int failures = 0;
  failures += TestGlobalIdsRestoreTheOrder();
  failures += TestGhostCellsDropped();
  failures += TestPositionsWithoutIds();
  failures += TestCoincidentVerticesOfOnePieceStayApart();
  failures += TestTrivialAndBadPieces();
  return failures == 0 ? 0 : 1;
}
