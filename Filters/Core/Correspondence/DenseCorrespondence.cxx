#include "DenseCorrespondence.h"

#include "LandmarkAlignment.h"
#include "MeshAdjacency.h"
#include "SphericalPointLocator.h"
#include "StopWatchingProgress.h"

#include <algorithm>

namespace mobius
{
namespace
{
// Every query point located (progress: 0.2 to 0.8 of the whole); false with the error, or
// stopped, if the location failed.
bool LocateQueryPoints(const SphericalPointLocator& locator, const Points& query,
  const DenseCorrespondenceParameters& parameters, std::vector<SphericalLocation>& locations,
  DenseCorrespondence& correspondence)
{
  StopWatchingProgress report{ parameters.Progress };
  auto progress = [&report](double fraction) { return report(0.2 + 0.6 * fraction); };
  if (locator.LocateAll(query, locations, parameters.NumberOfThreads, progress))
  {
    return true;
  }
  correspondence.Stopped = report.StopAsked;
  if (!report.StopAsked)
  {
    correspondence.Error = "Point location failed.";
  }
  return false;
}

// The locations as the map's triangles and coordinates, with the clamped points' figures.
void KeepLocations(
  const std::vector<SphericalLocation>& locations, DenseCorrespondence& correspondence)
{
  for (const auto& location : locations)
  {
    correspondence.Triangle.push_back(location.Triangle);
    correspondence.Barycentric.push_back(location.Barycentric);
    correspondence.ClampedPoints += location.Clamped ? 1 : 0;
    correspondence.MaximumClampDistance =
      std::max(correspondence.MaximumClampDistance, location.AngularDistance);
  }
}

// Each query landmark on its located landmark's vertex (a triangle's corner there); the
// problem with the landmarks, if one names a point its map does not have or a point in no
// triangle.
std::string PlaceLandmarks(const CorrespondenceMap maps[2], int query,
  const std::vector<std::pair<Index, Index>>& landmarks, DenseCorrespondence& correspondence)
{
  const Index counts[2] = { maps[0].Sphere.rows(), maps[1].Sphere.rows() };
  const std::string names[2] = { maps[0].Name, maps[1].Name };
  std::string error = CheckLandmarkIds(landmarks, counts, names);
  const int located = 1 - query;
  const Triangles& triangles = maps[located].Triangles;
  const VertexLists corners = VertexTriangles(maps[located].Sphere.rows(), triangles);
  for (size_t k = 0; error.empty() && k < landmarks.size(); ++k)
  {
    const Index ends[2] = { landmarks[k].first, landmarks[k].second };
    const Index from = ends[query], to = ends[located];
    if (corners.Begin(to) == corners.End(to))
    {
      return "landmark " + std::to_string(k) + " names point " + std::to_string(to) +
        ", which is in no triangle";
    }
    PlaceAtVertex(triangles, corners, to, correspondence.Triangle[from],
      correspondence.Barycentric[from]);
  }
  return error;
}
}

DenseCorrespondence CorrespondSphericalMaps(
  const CorrespondenceMap maps[2], const DenseCorrespondenceParameters& parameters)
{
  // The query map's points are located in the other one.
  const int query = parameters.TargetToSource ? 1 : 0;
  const CorrespondenceMap& located = maps[1 - query];
  DenseCorrespondence correspondence;
  SphericalPointLocator locator;
  std::string error;
  if (!locator.Build(located.Sphere, located.Triangles, error))
  {
    correspondence.Error = "Cannot map: the " + located.Name + ": " + error + ".";
    return correspondence;
  }
  if (parameters.Progress)
  {
    parameters.Progress(0.2);
  }
  std::vector<SphericalLocation> locations;
  if (!LocateQueryPoints(locator, maps[query].Sphere, parameters, locations, correspondence))
  {
    return correspondence;
  }
  KeepLocations(locations, correspondence);
  error = PlaceLandmarks(maps, query, parameters.Landmarks, correspondence);
  if (!error.empty())
  {
    correspondence.Error = "Cannot map: " + error + ".";
  }
  return correspondence;
}
}
