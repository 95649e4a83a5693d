#include "CandidateChoice.h"

#include "CotangentLaplacian.h"

#include <cmath>
#include <utility>

namespace mobius
{
namespace
{
// What the choice compares: the curvature difference when both surfaces have a curvature.
double Score(const SampleMap& map, bool useCurvature)
{
  return useCurvature ? map.CurvatureDifference : map.OrthogonalityResidual;
}

// (runner-up's score - kept's) / kept's score; infinite when the kept one's is 0.
double RelativeMargin(double kept, double runnerUp)
{
  return kept > 0 ? (runnerUp - kept) / kept : std::numeric_limits<double>::infinity();
}
}

double SampleMapDistance(const SampleMap& a, const SampleMap& b, const SpectralSurface& target)
{
  const double scale = std::sqrt(TriangleAreas(target.Positions, target.Faces).sum());
  if (a.TargetVertex.empty() || a.TargetVertex.size() != b.TargetVertex.size() || !(scale > 0))
  {
    return std::numeric_limits<double>::infinity();
  }
  double sum = 0;
  for (size_t s = 0; s < a.TargetVertex.size(); ++s)
  {
    sum += (target.Positions.row(a.TargetVertex[s]) - target.Positions.row(b.TargetVertex[s])).norm();
  }
  return sum / (static_cast<double>(a.TargetVertex.size()) * scale);
}

CandidateChoice ChooseCandidate(const std::vector<SampleMap>& screened,
  const std::vector<bool>& rightSide, const SpectralSurface& target,
  CandidateCriterion criterion)
{
  CandidateChoice choice;
  bool useCurvature = criterion == CandidateCriterion::Curvature;
  for (const SampleMap& map : screened)
  {
    useCurvature = useCurvature && std::isfinite(map.CurvatureDifference);
  }
  // The expected orientation first, then the lower score.
  auto better = [&](size_t c, size_t than) {
    if (rightSide[c] != rightSide[than])
    {
      return static_cast<bool>(rightSide[c]);
    }
    return Score(screened[c], useCurvature) < Score(screened[than], useCurvature);
  };
  for (size_t c = 1; c < screened.size(); ++c)
  {
    if (better(c, static_cast<size_t>(choice.Kept)))
    {
      choice.Kept = static_cast<int>(c);
    }
  }
  for (const SampleMap& map : screened)
  {
    choice.Score.push_back(Score(map, useCurvature));
  }
  const SampleMap& kept = screened[static_cast<size_t>(choice.Kept)];
  for (size_t c = 0; c < screened.size(); ++c)
  {
    if (static_cast<int>(c) == choice.Kept || !rightSide[c] ||
      SampleMapDistance(screened[c], kept, target) < kSameMapDistance)
    {
      continue;
    }
    if (choice.RunnerUp < 0 || better(c, static_cast<size_t>(choice.RunnerUp)))
    {
      choice.RunnerUp = static_cast<int>(c);
    }
  }
  if (choice.RunnerUp >= 0)
  {
    choice.Margin = RelativeMargin(choice.Score[static_cast<size_t>(choice.Kept)],
      choice.Score[static_cast<size_t>(choice.RunnerUp)]);
  }
  return choice;
}

void ChooseByFinishedMaps(
  CandidateChoice& choice, size_t candidates, double keptStretch, double runnerUpStretch)
{
  const size_t kept = static_cast<size_t>(choice.Kept);
  const size_t runnerUp = static_cast<size_t>(choice.RunnerUp);
  choice.Stretch.assign(candidates, std::numeric_limits<double>::quiet_NaN());
  choice.Stretch[kept] = keptStretch;
  choice.Stretch[runnerUp] = runnerUpStretch;
  choice.ByFinishedMaps = true;
  // The relative differences of the two measures add (to first order): a near tie in one
  // leaves the decision to the other.
  double keptProduct = choice.Score[kept] * keptStretch;
  double runnerUpProduct = choice.Score[runnerUp] * runnerUpStretch;
  if (runnerUpProduct < keptProduct)
  {
    std::swap(choice.Kept, choice.RunnerUp);
    std::swap(keptProduct, runnerUpProduct);
  }
  choice.Margin = RelativeMargin(keptProduct, runnerUpProduct);
}
}
