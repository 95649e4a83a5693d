// The whole registration job, assembled in one place: conformal map and centering of each
// mesh, rotational alignment, dense correspondence and its spectral refinement (and the
// one-mesh jobs, symmetry detection and the orbifold map). vtkMobiusRegistration wraps it
// for VTK and ParaView; mobius-register and mobius-score call it for the stages' outputs
// and timings. Not wrapped: plain C++ over the stage filters.
//
// Messages name the filters' properties (FillHoles, AllowPoorMaps, BasisSize); an
// interface with other names for them rewords the messages (MessageWording).
#ifndef MobiusPipeline_h
#define MobiusPipeline_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

namespace mobius
{
struct RegistrationParameters;
}

struct StageTiming
{
  std::string Name;
  double Seconds = 0;
};

struct PipelineResult
{
  vtkSmartPointer<vtkPolyData> SourceMap, TargetMap;           // conformal maps
  vtkSmartPointer<vtkPolyData> SourceCentered, TargetCentered; // centered maps
  vtkSmartPointer<vtkPolyData> Aligned;                        // source moved by vtkSO3Register
  vtkSmartPointer<vtkPolyData> MobiusCorrespondence; // vtkDenseCorrespondence output
  vtkSmartPointer<vtkPolyData> Correspondence; // the final map: refined, or the Möbius one
  /// The final map on the meshes as given (MobiusInputRows.h): one row per source vertex in
  /// its numbering, target triangles and vertices as given. The same object as
  /// Correspondence when no repair changed either mesh.
  vtkSmartPointer<vtkPolyData> InputCorrespondence;
  /// Per landmark, its source vertex and its target vertex as points of the maps (the
  /// user's vertex numbers found through the maps' `InputPointId`).
  std::vector<vtkIdType> SourceLandmarks, TargetLandmarks;
  std::vector<StageTiming> Stages;
  /// The whole job's wall time, 0 if not measured: less than the sum of Stages, since
  /// some stages run side by side.
  double WallSeconds = 0;
  std::vector<std::string> Warnings;
};

/// Called with a stage name and its progress in [0, 1] (from more than one thread while the
/// two meshes are mapped side by side; calls do not overlap).
using StageProgress = std::function<void(const std::string& stage, double fraction)>;

/// What a job leaves out of, or changes in, the first stages of one mesh (MapAndCenter).
struct OneMeshStages
{
  bool Map = true;         ///< false: the mesh is already its spherical map
  bool Center = true;      ///< false: the map stays uncentered (`centered` is the map)
  bool LinearStart = true; ///< vtkSphericalConformalMap::LinearStart
  std::string Which;       ///< appended to the stage names, e.g. " (source)"
  /// Asked at each progress step; true stops the running stage (a filter's AbortExecute).
  std::function<bool()> Abort;
};

/// The first stages of every job, for one mesh: its conformal map (a degenerate map is an
/// error unless AllowPoorMaps) and its centering (CenteringTolerance, CenteringDegree).
/// Messages start with `name`, or with the stage's name when `name` is empty. False (with
/// `error` set) on failure; `result` gets the stages' timings and warnings.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool MapAndCenter(vtkPolyData* mesh, const std::string& name,
  const mobius::RegistrationParameters& options, const OneMeshStages& stages,
  const StageProgress& progress, PipelineResult& result, vtkSmartPointer<vtkPolyData>& map,
  vtkSmartPointer<vtkPolyData>& centered, std::string& error);

/// Runs the registration job. On failure returns false and sets `error` to one line naming
/// what failed (with `sourceName` / `targetName` for the stage that concerns one input).
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool RunRegistrationPipeline(vtkPolyData* source,
  vtkPolyData* target, const std::string& sourceName, const std::string& targetName,
  const mobius::RegistrationParameters& options, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

/// Bilateral symmetry of one mesh (vtkSymmetryDetection on its conformal map): the map in
/// result.SourceMap, the symmetric map and the measures in result.Correspondence.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool RunSymmetryPipeline(vtkPolyData* mesh,
  const std::string& name, const mobius::RegistrationParameters& options, PipelineResult& result,
  std::string& error, const StageProgress& progress = {});

/// Spherical orbifold map of one mesh (vtkSphericalOrbifoldMap on its conformal map, cones
/// named by file vertex numbers, -1 -1 for automatic ones): the map in result.SourceMap, the
/// orbifold map (one copy, or the covering) in result.Correspondence.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool RunOrbifoldPipeline(vtkPolyData* mesh,
  const std::string& name, const mobius::RegistrationParameters& options, int copies,
  const long long cones[2], bool covering, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

/// Per landmark, the point of `map` (a spherical map of `mesh`) whose InputPointId is its
/// vertex on this side (`source`: the landmarks' source vertices, else their target
/// vertices); a vertex the repair merged into a duplicate (not in InputPointId) is found by
/// its position on the surface. False with `error` set, naming the mesh by `name`, when the
/// repair removed a landmark's vertex.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT bool FindLandmarkPoints(vtkPolyData* mesh, vtkPolyData* map,
  bool source, const mobius::RegistrationParameters& options, const std::string& name,
  std::vector<vtkIdType>& points, std::string& error);

/// Value of component `component` of field-data array `name`, NaN if absent.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT double FieldValue(
  vtkPolyData* data, const char* name, int component = 0);

#endif
