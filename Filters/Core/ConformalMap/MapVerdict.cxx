#include "MapVerdict.h"

#include <sstream>

namespace mobius
{
std::string MapVerdict::Reason() const
{
  std::string reason;
  for (const auto& problem : this->Problems)
  {
    reason += (reason.empty() ? "" : "; ") + problem;
  }
  return reason;
}

MapVerdict JudgeConformalMap(const ConformalMapResult& result, double convergenceTolerance)
{
  MapVerdict verdict;
  const MapDistortion& d = result.Distortion;
  if (!result.Converged)
  {
    std::ostringstream problem;
    problem << "the flow stopped after " << result.Iterations << " steps with relative change "
            << result.RelativeChange << " above the tolerance " << convergenceTolerance;
    verdict.Problems.push_back(problem.str());
  }
  if (d.FlippedTriangles > 0)
  {
    std::ostringstream problem;
    problem << d.FlippedTriangles << " triangles are flipped on the sphere after the repair";
    verdict.Problems.push_back(problem.str());
  }
  if (!(d.MappedAreaShare >= MinimumMappedAreaShare))
  {
    std::ostringstream problem;
    problem << "the map collapsed: its triangles span " << 100 * d.MappedAreaShare
            << "% of the sphere";
    verdict.Problems.push_back(problem.str());
  }
  std::ostringstream share;
  share << 100 * d.SquashedAreaShare << "% of the surface (quasi-conformal distortion above "
        << SquashedQuasiConformalDistortion << "; median " << d.MedianQuasiConformal << ")";
  if (d.SquashedAreaShare > MaximumSquashedAreaShare)
  {
    verdict.Problems.push_back("its triangles are squashed: " + share.str() + ", more than " +
      std::to_string(static_cast<int>(100 * MaximumSquashedAreaShare)) + "%");
  }
  else if (d.SquashedAreaShare > WarningSquashedAreaShare)
  {
    verdict.Warning = "the map squashes " + share.str() +
      ": thin parts squeezed on the sphere; the Möbius correspondence there is rough (the "
      "refinement corrects it)";
  }
  if (!result.Refinement.Success)
  {
    verdict.Problems.push_back(
      "the refinement of squeezed regions failed, which keep the flow's positions");
  }
  return verdict;
}
}
