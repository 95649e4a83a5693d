#include "MobiusMergePieces.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace mobius
{
namespace vtk
{
namespace
{
using Position = std::array<double, 3>;

struct PositionHash
{
  size_t operator()(const Position& p) const
  {
    size_t hash = 0;
    for (double x : p)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      hash = hash * 0x9E3779B97F4A7C15ULL + std::hash<std::uint64_t>()(bits);
    }
    return hash;
  }
};

struct EdgeHash
{
  size_t operator()(const std::pair<vtkIdType, vtkIdType>& e) const
  {
    return std::hash<long long>()(static_cast<long long>(e.first) * 0x9E3779B97F4A7C15LL) ^
      std::hash<long long>()(static_cast<long long>(e.second));
  }
};

// A point's position, with -0 as +0 so that equal coordinates hash alike.
Position PositionOf(vtkPolyData* piece, vtkIdType point)
{
  double p[3];
  piece->GetPoint(point, p);
  return { p[0] + 0.0, p[1] + 0.0, p[2] + 0.0 };
}

// The cell arrays of a polydata in the order of its cell ids.
std::array<vtkCellArray*, 4> CellArraysOf(vtkPolyData* piece)
{
  return { piece->GetVerts(), piece->GetLines(), piece->GetPolys(), piece->GetStrips() };
}

// What the merge needs to know about one piece.
struct Piece
{
  vtkPolyData* Data = nullptr;
  std::vector<char> KeptCells;  // per cell id: not a copy of a cell another piece owns
  std::vector<char> KeptPoints; // used by a kept cell, or by no cell at all
  std::vector<char> OnCut;      // on an open edge of the kept polygons (or of another cell type)
  std::vector<std::pair<vtkIdType, vtkIdType>> OpenEdges; // of the kept polygons
};

// Reads one piece; fails on a cell referring to a point the piece does not have.
std::string AnalyzePiece(vtkPolyData* data, int number, Piece& piece)
{
  piece.Data = data;
  const vtkIdType points = data->GetNumberOfPoints();
  piece.KeptCells.assign(data->GetNumberOfCells(), 1);
  std::vector<char> usedByKept(points, 0), usedByDropped(points, 0);
  piece.OnCut.assign(points, 0);
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    data->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (ghosts && ghosts->GetNumberOfTuples() != data->GetNumberOfCells())
  {
    ghosts = nullptr;
  }
  std::unordered_map<std::pair<vtkIdType, vtkIdType>, int, EdgeHash> edgeUses;
  vtkIdType cellId = 0;
  const auto arrays = CellArraysOf(data);
  for (size_t type = 0; type < arrays.size(); ++type)
  {
    vtkCellArray* cells = arrays[type];
    const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
    for (vtkIdType c = 0; c < count; ++c, ++cellId)
    {
      vtkIdType size;
      const vtkIdType* ids;
      cells->GetCellAtId(c, size, ids);
      for (vtkIdType k = 0; k < size; ++k)
      {
        if (ids[k] < 0 || ids[k] >= points)
        {
          std::ostringstream error;
          error << "piece " << number << ": cell " << cellId << " refers to point " << ids[k]
                << " of " << points;
          return error.str();
        }
      }
      const bool kept = !ghosts || !(ghosts->GetValue(cellId) & vtkDataSetAttributes::DUPLICATECELL);
      piece.KeptCells[cellId] = kept ? 1 : 0;
      for (vtkIdType k = 0; k < size; ++k)
      {
        (kept ? usedByKept : usedByDropped)[ids[k]] = 1;
      }
      if (!kept)
      {
        continue;
      }
      if (type != 2) // vertices, lines and strips: joined wherever they meet another piece
      {
        for (vtkIdType k = 0; k < size; ++k)
        {
          piece.OnCut[ids[k]] = 1;
        }
        continue;
      }
      for (vtkIdType k = 0; k < size; ++k)
      {
        const vtkIdType a = ids[k], b = ids[(k + 1) % size];
        ++edgeUses[{ std::min(a, b), std::max(a, b) }];
      }
    }
  }
  for (const auto& edge : edgeUses)
  {
    if (edge.second == 1)
    {
      piece.OnCut[edge.first.first] = piece.OnCut[edge.first.second] = 1;
      piece.OpenEdges.push_back(edge.first);
    }
  }
  std::sort(piece.OpenEdges.begin(), piece.OpenEdges.end()); // the same joins on every run
  piece.KeptPoints.resize(points);
  for (vtkIdType i = 0; i < points; ++i)
  {
    piece.KeptPoints[i] = usedByKept[i] || !usedByDropped[i];
  }
  return {};
}

// Where each merged point comes from (its first piece and point there), and the merged
// number of every kept point of every piece (-1 for a dropped one).
struct PointMerge
{
  std::vector<std::pair<int, vtkIdType>> Sources;
  std::vector<std::vector<vtkIdType>> Numbers;
};

// Joins points of equal global id and numbers them by increasing id; fails (with the
// reason) when the ids are missing, repeated within a piece or name two positions.
std::string MergeByGlobalIds(const std::vector<Piece>& pieces, PointMerge& merge)
{
  std::unordered_map<long long, std::pair<int, vtkIdType>> first;
  for (size_t k = 0; k < pieces.size(); ++k)
  {
    vtkPolyData* data = pieces[k].Data;
    vtkDataArray* ids = data->GetPointData()->GetGlobalIds();
    if (!ids)
    {
      return "not every piece carries them";
    }
    if (ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != data->GetNumberOfPoints())
    {
      return "they are not one value per point";
    }
    std::unordered_set<long long> inPiece;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      if (!pieces[k].KeptPoints[i])
      {
        continue;
      }
      const long long id = static_cast<long long>(ids->GetTuple1(i));
      if (!inPiece.insert(id).second)
      {
        return "global id " + std::to_string(id) + " names two points of one piece";
      }
      const auto found = first.emplace(id, std::make_pair(static_cast<int>(k), i));
      if (!found.second &&
        PositionOf(pieces[found.first->second.first].Data, found.first->second.second) !=
          PositionOf(data, i))
      {
        return "global id " + std::to_string(id) + " names two positions";
      }
    }
  }
  std::vector<long long> sorted;
  sorted.reserve(first.size());
  for (const auto& entry : first)
  {
    sorted.push_back(entry.first);
  }
  std::sort(sorted.begin(), sorted.end());
  merge.Sources.resize(sorted.size());
  for (size_t m = 0; m < sorted.size(); ++m)
  {
    merge.Sources[m] = first[sorted[m]];
  }
  merge.Numbers.resize(pieces.size());
  for (size_t k = 0; k < pieces.size(); ++k)
  {
    vtkPolyData* data = pieces[k].Data;
    vtkDataArray* ids = data->GetPointData()->GetGlobalIds();
    merge.Numbers[k].assign(data->GetNumberOfPoints(), -1);
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      if (pieces[k].KeptPoints[i])
      {
        const long long id = static_cast<long long>(ids->GetTuple1(i));
        merge.Numbers[k][i] =
          std::lower_bound(sorted.begin(), sorted.end(), id) - sorted.begin();
      }
    }
  }
  return {};
}

// Position pairs of an edge, smaller position first.
using EdgePositions = std::pair<Position, Position>;

struct EdgePositionsHash
{
  size_t operator()(const EdgePositions& e) const
  {
    return PositionHash()(e.first) * 31 + PositionHash()(e.second);
  }
};

// The corners of each kept polygon of a piece, sorted by position (with their point ids);
// empty for a polygon with two corners at one position.
std::vector<std::vector<std::pair<Position, vtkIdType>>> SortedPolygonCorners(const Piece& piece)
{
  vtkPolyData* data = piece.Data;
  const vtkIdType first = data->GetNumberOfVerts() + data->GetNumberOfLines();
  vtkCellArray* polys = data->GetPolys();
  std::vector<std::vector<std::pair<Position, vtkIdType>>> result;
  for (vtkIdType c = 0; polys && c < polys->GetNumberOfCells(); ++c)
  {
    if (!piece.KeptCells[first + c])
    {
      continue;
    }
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCellAtId(c, size, ids);
    std::vector<std::pair<Position, vtkIdType>> corners;
    for (vtkIdType k = 0; k < size; ++k)
    {
      corners.emplace_back(PositionOf(data, ids[k]), ids[k]);
    }
    std::sort(corners.begin(), corners.end());
    for (size_t k = 1; k < corners.size(); ++k)
    {
      if (corners[k].first == corners[k - 1].first)
      {
        corners.clear();
        break;
      }
    }
    result.push_back(std::move(corners));
  }
  return result;
}

struct PositionsHash
{
  size_t operator()(const std::vector<Position>& positions) const
  {
    size_t hash = 0;
    for (const auto& p : positions)
    {
      hash = hash * 31 + PositionHash()(p);
    }
    return hash;
  }
};

// Joins the points of each piece with those of the pieces before it, never two points of
// one piece: first the corners of a polygon that an earlier piece has too (the same corner
// positions: Redistribute DataSet copies the cells on the cut into both pieces, unmarked
// when asked to assign them to all regions), then along the cut's edges (an open edge of
// this piece with the same end positions as an open edge of an earlier one). Both tell
// apart two vertices at one position, whose cells and edges lead to different places. Last
// a point on the cut that only touches another piece at a corner, by position. Numbers in
// the pieces' order.
void MergeByPosition(const std::vector<Piece>& pieces, PointMerge& merge)
{
  std::unordered_map<EdgePositions, std::vector<std::pair<vtkIdType, vtkIdType>>,
    EdgePositionsHash>
    cutEdges;
  std::unordered_map<Position, std::vector<vtkIdType>, PositionHash> cutPoints;
  std::unordered_map<std::vector<Position>, std::vector<std::vector<vtkIdType>>, PositionsHash>
    polygons; // merged corners of the earlier pieces' polygons, by sorted corner positions
  merge.Numbers.resize(pieces.size());
  for (size_t k = 0; k < pieces.size(); ++k)
  {
    vtkPolyData* data = pieces[k].Data;
    std::vector<vtkIdType>& numbers = merge.Numbers[k];
    numbers.assign(data->GetNumberOfPoints(), -1);
    std::unordered_set<vtkIdType> taken; // merged points this piece already joins
    auto canJoin = [&](vtkIdType local, vtkIdType merged) {
      return numbers[local] == merged || (numbers[local] < 0 && !taken.count(merged));
    };
    auto join = [&](vtkIdType local, vtkIdType merged) {
      if (numbers[local] < 0)
      {
        numbers[local] = merged;
        taken.insert(merged);
      }
    };
    // Both ends of an edge with the smaller position first.
    auto ordered = [&](const std::pair<vtkIdType, vtkIdType>& edge, EdgePositions& key) {
      const Position a = PositionOf(data, edge.first), b = PositionOf(data, edge.second);
      key = a < b ? EdgePositions(a, b) : EdgePositions(b, a);
      return a < b ? edge : std::make_pair(edge.second, edge.first);
    };
    const auto corners = SortedPolygonCorners(pieces[k]);
    std::vector<Position> key;
    for (const auto& polygon : corners)
    {
      key.clear();
      for (const auto& corner : polygon)
      {
        key.push_back(corner.first);
      }
      const auto found = polygon.empty() ? polygons.end() : polygons.find(key);
      if (found == polygons.end())
      {
        continue;
      }
      for (const auto& candidate : found->second)
      {
        bool all = true;
        for (size_t c = 0; c < polygon.size(); ++c)
        {
          all = all && canJoin(polygon[c].second, candidate[c]);
        }
        if (all)
        {
          for (size_t c = 0; c < polygon.size(); ++c)
          {
            join(polygon[c].second, candidate[c]);
          }
          break;
        }
      }
    }
    for (const auto& edge : pieces[k].OpenEdges)
    {
      EdgePositions key;
      const auto ends = ordered(edge, key);
      const auto found = key.first == key.second ? cutEdges.end() : cutEdges.find(key);
      if (found == cutEdges.end())
      {
        continue;
      }
      for (const auto& candidate : found->second)
      {
        if (canJoin(ends.first, candidate.first) && canJoin(ends.second, candidate.second))
        {
          join(ends.first, candidate.first);
          join(ends.second, candidate.second);
          break;
        }
      }
    }
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      if (!pieces[k].KeptPoints[i] || numbers[i] >= 0 || !pieces[k].OnCut[i])
      {
        continue;
      }
      const auto found = cutPoints.find(PositionOf(data, i));
      if (found == cutPoints.end())
      {
        continue;
      }
      for (vtkIdType candidate : found->second)
      {
        if (canJoin(i, candidate))
        {
          join(i, candidate);
          break;
        }
      }
    }
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      if (pieces[k].KeptPoints[i] && numbers[i] < 0)
      {
        numbers[i] = static_cast<vtkIdType>(merge.Sources.size());
        merge.Sources.emplace_back(static_cast<int>(k), i);
      }
    }
    // What the next pieces may join: this piece's polygons and cut, in merged numbers.
    for (const auto& polygon : corners)
    {
      if (polygon.empty())
      {
        continue;
      }
      key.clear();
      std::vector<vtkIdType> merged;
      for (const auto& corner : polygon)
      {
        key.push_back(corner.first);
        merged.push_back(numbers[corner.second]);
      }
      auto& known = polygons[key];
      if (std::find(known.begin(), known.end(), merged) == known.end())
      {
        known.push_back(merged);
      }
    }
    for (const auto& edge : pieces[k].OpenEdges)
    {
      EdgePositions key;
      const auto ends = ordered(edge, key);
      auto& known = cutEdges[key];
      const std::pair<vtkIdType, vtkIdType> merged(numbers[ends.first], numbers[ends.second]);
      if (std::find(known.begin(), known.end(), merged) == known.end())
      {
        known.push_back(merged);
      }
    }
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      if (pieces[k].KeptPoints[i] && pieces[k].OnCut[i])
      {
        auto& known = cutPoints[PositionOf(data, i)];
        if (std::find(known.begin(), known.end(), numbers[i]) == known.end())
        {
          known.push_back(numbers[i]);
        }
      }
    }
  }
}

// The kept cells of one cell type (0 vertices, 1 lines, 2 polygons, 3 strips) of all
// pieces: by increasing global cell id when every piece has unique ones, else in the
// pieces' order.
std::vector<std::pair<int, vtkIdType>> CellsOfType(const std::vector<Piece>& pieces, int type)
{
  struct Cell
  {
    int Piece;
    vtkIdType Id;
    long long GlobalId;
  };
  std::vector<Cell> cells;
  bool sortable = true;
  std::unordered_map<long long, int> pieceOfId; // the first piece holding each global id
  for (size_t k = 0; k < pieces.size(); ++k)
  {
    vtkPolyData* data = pieces[k].Data;
    vtkDataArray* ids = data->GetCellData()->GetGlobalIds();
    if (!ids || ids->GetNumberOfComponents() != 1 ||
      ids->GetNumberOfTuples() != data->GetNumberOfCells())
    {
      ids = nullptr;
      sortable = false;
    }
    const auto arrays = CellArraysOf(data);
    vtkIdType first = 0;
    for (int t = 0; t < type; ++t)
    {
      first += arrays[t] ? arrays[t]->GetNumberOfCells() : 0;
    }
    const vtkIdType count = arrays[type] ? arrays[type]->GetNumberOfCells() : 0;
    for (vtkIdType c = first; c < first + count; ++c)
    {
      if (!pieces[k].KeptCells[c])
      {
        continue;
      }
      const long long id = ids ? static_cast<long long>(ids->GetTuple1(c)) : 0;
      const auto seen = ids ? pieceOfId.emplace(id, static_cast<int>(k))
                            : std::make_pair(pieceOfId.end(), true);
      // Another piece's cell of the same id is a copy of it (Redistribute DataSet copies
      // the cut's cells, unmarked, when assigning them to all regions); MergePieces keeps
      // one of two cells with the same points. Two cells of one piece with one id: the ids
      // order nothing.
      if (!seen.second && seen.first->second == static_cast<int>(k))
      {
        sortable = false;
      }
      cells.push_back({ static_cast<int>(k), c, id });
    }
  }
  if (sortable)
  {
    std::stable_sort(cells.begin(), cells.end(),
      [](const Cell& a, const Cell& b) { return a.GlobalId < b.GlobalId; });
  }
  std::vector<std::pair<int, vtkIdType>> order;
  order.reserve(cells.size());
  for (const auto& cell : cells)
  {
    order.emplace_back(cell.Piece, cell.Id);
  }
  return order;
}

// The cell array of `type` in which cell `id` of `data` lies, and its index there.
std::pair<vtkCellArray*, vtkIdType> LocateCell(vtkPolyData* data, vtkIdType id)
{
  for (vtkCellArray* cells : CellArraysOf(data))
  {
    const vtkIdType count = cells ? cells->GetNumberOfCells() : 0;
    if (id < count)
    {
      return { cells, id };
    }
    id -= count;
  }
  return { nullptr, 0 };
}
}

//------------------------------------------------------------------------------
bool IsEmptyPiece(vtkPolyData* piece)
{
  return !piece || (piece->GetNumberOfPoints() == 0 && piece->GetNumberOfCells() == 0);
}

//------------------------------------------------------------------------------
MergedPieces MergePieces(const std::vector<vtkPolyData*>& pieces)
{
  MergedPieces result;
  std::vector<vtkPolyData*> nonEmpty;
  for (vtkPolyData* piece : pieces)
  {
    if (!IsEmptyPiece(piece))
    {
      nonEmpty.push_back(piece);
    }
  }
  if (nonEmpty.size() <= 1)
  {
    result.Surface = nonEmpty.empty() ? vtkSmartPointer<vtkPolyData>::New()
                                      : vtkSmartPointer<vtkPolyData>(nonEmpty[0]);
    return result;
  }

  std::vector<Piece> analyzed(nonEmpty.size());
  for (size_t k = 0; k < nonEmpty.size(); ++k)
  {
    result.Error = AnalyzePiece(nonEmpty[k], static_cast<int>(k), analyzed[k]);
    if (!result.Error.empty())
    {
      return result;
    }
  }
  PointMerge points;
  bool anyGlobalIds = false;
  for (vtkPolyData* piece : nonEmpty)
  {
    anyGlobalIds = anyGlobalIds || piece->GetPointData()->GetGlobalIds();
  }
  if (anyGlobalIds)
  {
    result.GlobalIdsIgnored = MergeByGlobalIds(analyzed, points);
  }
  if (!anyGlobalIds || !result.GlobalIdsIgnored.empty())
  {
    points = PointMerge();
    MergeByPosition(analyzed, points);
  }

  auto surface = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataType(
    nonEmpty[0]->GetPoints() ? nonEmpty[0]->GetPoints()->GetDataType() : VTK_DOUBLE);
  coordinates->SetNumberOfPoints(static_cast<vtkIdType>(points.Sources.size()));
  vtkDataSetAttributes::FieldList pointFields(static_cast<int>(nonEmpty.size()));
  vtkDataSetAttributes::FieldList cellFields(static_cast<int>(nonEmpty.size()));
  for (vtkPolyData* piece : nonEmpty)
  {
    pointFields.IntersectFieldList(piece->GetPointData());
    cellFields.IntersectFieldList(piece->GetCellData());
  }
  vtkPointData* pointData = surface->GetPointData();
  pointData->CopyAllocate(pointFields, static_cast<vtkIdType>(points.Sources.size()));
  for (size_t m = 0; m < points.Sources.size(); ++m)
  {
    const auto& source = points.Sources[m];
    coordinates->SetPoint(static_cast<vtkIdType>(m), nonEmpty[source.first]->GetPoint(source.second));
    pointData->CopyData(pointFields, nonEmpty[source.first]->GetPointData(), source.first,
      source.second, static_cast<vtkIdType>(m));
  }
  surface->SetPoints(coordinates);

  vtkCellData* cellData = surface->GetCellData();
  vtkIdType totalCells = 0;
  for (const auto& piece : analyzed)
  {
    totalCells += static_cast<vtkIdType>(std::count(piece.KeptCells.begin(), piece.KeptCells.end(), 1));
  }
  cellData->CopyAllocate(cellFields, totalCells);
  vtkIdType outputCell = 0;
  std::vector<vtkIdType> renumbered, corners;
  // A cell of one piece with the same points as a cell of another is the same cell, copied
  // into both (Redistribute DataSet does so on the cut unless it marks ghosts): kept once.
  // Two such cells of one piece are both kept, as a serial run would.
  std::map<std::vector<vtkIdType>, int> firstPieceOf;
  for (int type = 0; type < 4; ++type)
  {
    const auto order = CellsOfType(analyzed, type);
    if (order.empty())
    {
      continue;
    }
    vtkNew<vtkCellArray> cells;
    for (const auto& cell : order)
    {
      vtkPolyData* data = nonEmpty[cell.first];
      const auto located = LocateCell(data, cell.second);
      vtkIdType size;
      const vtkIdType* ids;
      located.first->GetCellAtId(located.second, size, ids);
      renumbered.resize(size);
      for (vtkIdType k = 0; k < size; ++k)
      {
        renumbered[k] = points.Numbers[cell.first][ids[k]];
      }
      corners = renumbered;
      std::sort(corners.begin(), corners.end());
      corners.push_back(type); // a vertex cell is not a polygon
      const auto first = firstPieceOf.emplace(corners, cell.first);
      if (!first.second && first.first->second != cell.first)
      {
        continue;
      }
      cells->InsertNextCell(size, renumbered.data());
      cellData->CopyData(cellFields, data->GetCellData(), cell.first, cell.second, outputCell++);
    }
    switch (type)
    {
      case 0:
        surface->SetVerts(cells);
        break;
      case 1:
        surface->SetLines(cells);
        break;
      case 2:
        surface->SetPolys(cells);
        break;
      default:
        surface->SetStrips(cells);
        break;
    }
  }
  // Every point and cell is now the only one of its kind: nothing is a ghost any more.
  pointData->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  cellData->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  surface->GetFieldData()->ShallowCopy(nonEmpty[0]->GetFieldData());
  result.Surface = surface;
  return result;
}
}
}
