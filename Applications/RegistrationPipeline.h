// The whole registration job on two meshes, as the command-line program and the benchmark
// run it: conformal map and centering of each mesh, rotational alignment, dense
// correspondence, and its spectral refinement. Times each stage, reports progress, and turns the filters' error
// messages into one message naming the input they concern.
#ifndef RegistrationPipeline_h
#define RegistrationPipeline_h

#include "RegistrationParameters.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

// The job's options and their defaults: the core's, one place for every interface.
using PipelineOptions = mobius::RegistrationParameters;

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
  std::vector<StageTiming> Stages;
  /// The whole job's wall time, 0 if not measured: less than the sum of Stages, since
  /// some stages run side by side.
  double WallSeconds = 0;
  std::vector<std::string> Warnings;
};

/// Called with a stage name and its progress in [0, 1].
using StageProgress = std::function<void(const std::string& stage, double fraction)>;

/// Runs the job. On failure returns false and sets `error` to one line naming what failed
/// (with `sourceName` / `targetName` for the stage that concerns one input).
bool RunRegistration(vtkPolyData* source, vtkPolyData* target, const std::string& sourceName,
  const std::string& targetName, const PipelineOptions& options, PipelineResult& result,
  std::string& error, const StageProgress& progress = {});

/// Bilateral symmetry of one mesh (vtkSymmetryDetection on its conformal map): the map in
/// result.SourceMap, the symmetric map and the measures in result.Correspondence.
bool RunSymmetryDetection(vtkPolyData* mesh, const std::string& name,
  const PipelineOptions& options, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

/// Spherical orbifold map of one mesh (vtkSphericalOrbifoldMap on its conformal map, cones
/// named by file vertex numbers, -1 -1 for automatic ones): the map in result.SourceMap, the
/// orbifold map (one copy, or the covering) in result.Correspondence.
bool RunOrbifoldMap(vtkPolyData* mesh, const std::string& name, const PipelineOptions& options,
  int copies, const long long cones[2], bool covering, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

/// Value of component `component` of field-data array `name`, NaN if absent.
double FieldValue(vtkPolyData* data, const char* name, int component = 0);

#endif
