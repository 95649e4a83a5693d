#include "RepairMesh.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mobius
{
namespace
{
std::string Counted(Index count, const char* singular, const char* plural)
{
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

// "0.4%", with two significant digits for small shares.
std::string Percent(double part, double whole)
{
  const double share = whole > 0 ? 100 * part / whole : 0;
  std::ostringstream text;
  text << std::setprecision(share >= 10 ? 3 : 2) << share << "%";
  return text.str();
}
}

bool MeshRepairLog::Any() const
{
  return this->MergedDuplicatePoints > 0 || this->CollapsedEdges > 0 ||
    this->RemovedRepeatedVertexTriangles > 0 || this->RemovedNonFiniteTriangles > 0 ||
    this->RemovedDuplicateTriangles > 0 || this->SplitVertices > 0 ||
    this->ReversedTriangles > 0 || this->OrientationCutEdges > 0 ||
    this->DroppedComponents > 0 || this->FilledHoles > 0 || !this->HandleLoopLengths.empty() ||
    this->DroppedUnusedPoints > 0;
}

std::vector<std::string> MeshRepairLog::Describe() const
{
  std::vector<std::string> phrases;
  auto add = [&](Index count, const char* singular, const char* plural, const std::string& detail) {
    if (count > 0)
    {
      phrases.push_back(Counted(count, singular, plural) + detail);
    }
  };
  add(this->MergedDuplicatePoints, "duplicate point merged", "duplicate points merged", "");
  add(this->CollapsedEdges, "zero-length edge collapsed", "zero-length edges collapsed", "");
  add(this->RemovedRepeatedVertexTriangles, "triangle naming a point twice removed",
    "triangles naming a point twice removed", "");
  add(this->RemovedNonFiniteTriangles, "triangle with a NaN or infinite point removed",
    "triangles with NaN or infinite points removed", "");
  add(this->RemovedDuplicateTriangles, "duplicate triangle removed", "duplicate triangles removed", "");
  add(this->SplitVertices, "non-manifold vertex split", "non-manifold vertices split",
    " (one copy per fan of its triangles)");
  add(this->ReversedTriangles, "triangle reversed", "triangles reversed",
    " to agree with their neighbours");
  add(this->OrientationCutEdges, "edge cut open", "edges cut open",
    " where no orientation of the triangles agrees");
  add(this->DroppedComponents, "loose part dropped", "loose parts dropped",
    " (" + Counted(this->DroppedComponentTriangles, "triangle", "triangles") + ", " +
      Percent(this->DroppedComponentArea, this->InputArea) + " of the area)");
  add(this->FilledHoles, "hole filled", "holes filled",
    " (" + Counted(this->FilledBoundaryEdges, "boundary edge", "boundary edges") + ", " +
      Percent(this->FilledArea, this->ProxyArea) + " of the area)");
  if (!this->HandleLoopLengths.empty())
  {
    std::ostringstream lengths;
    lengths << std::setprecision(2);
    const double unit = this->ProxyArea > 0 ? std::sqrt(this->ProxyArea) : 1.0;
    for (size_t k = 0; k < this->HandleLoopLengths.size(); ++k)
    {
      lengths << (k == 0 ? "" : ", ") << this->HandleLoopLengths[k] / unit;
    }
    const Index handles = static_cast<Index>(this->HandleLoopLengths.size());
    add(handles, "handle cut", "handles cut",
      std::string(" (loop length") + (handles == 1 ? " " : "s ") + lengths.str() + " sqrt(area))");
  }
  add(this->DroppedUnusedPoints, "unused point dropped", "unused points dropped", "");
  return phrases;
}
}
