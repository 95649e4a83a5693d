// The --json summary of a registration: transformation, scores, per-stage seconds and the
// quality figures of each stage, as one JSON object.
#ifndef JsonSummary_h
#define JsonSummary_h

#include "OutputFiles.h"
#include "RegistrationPipeline.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"

#include <string>

std::string JsonSummary(const std::string& source, const std::string& target,
  const PipelineOptions& options, const PipelineResult& result, const OutputFiles& outputs,
  double demoError);

/// The --symmetry summary: symmetry distance, mirror plane, candidate reflections, the
/// map's quality, the refinement, stages and outputs.
std::string SymmetryJsonSummary(
  const std::string& mesh, const PipelineResult& result, const OutputFiles& outputs);

/// The --orbifold summary: cones, symmetry error, area distortion of the orbifold and the
/// plain map, the covering flow, stages and outputs.
std::string OrbifoldJsonSummary(
  const std::string& mesh, const PipelineResult& result, const OutputFiles& outputs);

#endif
