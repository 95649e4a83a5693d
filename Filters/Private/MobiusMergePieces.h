/**
 * @file MobiusMergePieces.h
 * @brief Joins the pieces of a surface that was split over processes back into the whole
 * surface (private to the module; MobiusDistributedInputs gathers the pieces).
 *
 * Points that several pieces share (where the surface was cut apart) become one point:
 * - by point global ids (`vtkPointData::GetGlobalIds()`, as ParaView's Generate Global Ids
 *   makes them) when every piece has them, they are unique within each piece and one id
 *   names one position everywhere. The whole surface then lists its points by increasing
 *   global id, which is the undivided input's order when the ids number its points.
 * - otherwise by exact position: the corners of a polygon that an earlier piece has too
 *   (a cell copied into both pieces at the cut), the ends of matching open edges (the cut),
 *   and last a point on the cut alone. Two points of one piece are never joined (a closed
 *   mesh may have two vertices at one position, CGAL's cow does, and joining them would
 *   pinch it), nor a point inside a piece; matching cells and edges tells such a pair
 *   apart where the cut runs through it. Points come in the pieces' order.
 * Cells keep their pieces' order, or increasing global cell id when every piece carries
 * unique ones. Ghost cells marked DUPLICATECELL (copies of a cell another piece owns) are
 * dropped, and the ghost arrays with them; so is a cell with the same points as a cell of
 * another piece (a copy left unmarked).
 */
#ifndef MobiusMergePieces_h
#define MobiusMergePieces_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
struct MergedPieces
{
  /// The whole surface; a single non-empty piece is returned as it is, no piece as an
  /// empty vtkPolyData.
  vtkSmartPointer<vtkPolyData> Surface;
  /// Why point global ids that the pieces carry were not used (empty if they were, or if
  /// there were none): the caller warns, since the points then follow the pieces' order.
  std::string GlobalIdsIgnored;
  /// Why the pieces could not be joined (a cell refers to a point its piece does not
  /// have); Surface is then null.
  std::string Error;
};

/// True for nothing at all: no points and no cells.
bool IsEmptyPiece(vtkPolyData* piece);

/// Joins `pieces` (in rank order; null or empty pieces are skipped) into one surface.
MergedPieces MergePieces(const std::vector<vtkPolyData*>& pieces);
}
}

#endif
