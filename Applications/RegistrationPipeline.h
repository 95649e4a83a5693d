// The registration job as mobius-register and mobius-score run it: the module's one
// pipeline (MobiusPipeline.h), with its messages in the command line's words (--fill-holes
// where the filters say FillHoles).
#ifndef RegistrationPipeline_h
#define RegistrationPipeline_h

#include "MobiusPipeline.h"
#include "RegistrationParameters.h"

#include <string>

// The job's options and their defaults: the core's, one place for every interface.
using PipelineOptions = mobius::RegistrationParameters;

/// RunRegistrationPipeline, its messages in the command line's words.
bool RunRegistration(vtkPolyData* source, vtkPolyData* target, const std::string& sourceName,
  const std::string& targetName, const PipelineOptions& options, PipelineResult& result,
  std::string& error, const StageProgress& progress = {});

/// RunSymmetryPipeline, its messages in the command line's words.
bool RunSymmetryDetection(vtkPolyData* mesh, const std::string& name,
  const PipelineOptions& options, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

/// RunOrbifoldPipeline, its messages in the command line's words.
bool RunOrbifoldMap(vtkPolyData* mesh, const std::string& name, const PipelineOptions& options,
  int copies, const long long cones[2], bool covering, PipelineResult& result, std::string& error,
  const StageProgress& progress = {});

#endif
