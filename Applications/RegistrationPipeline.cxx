#include "RegistrationPipeline.h"

#include "ParameterRules.h"

#include <utility>

namespace
{
// The filters' and the pipeline's hints name VTK properties; on the command line the options.
std::string InCommandLineWords(std::string text)
{
  static const std::pair<const char*, const char*> words[] = {
    { "Set FillHoles", "Use --fill-holes" },
    { "Set KeepLargestComponent", "Use --keep-largest-component" },
    { "a setting such as Resolution", "an option such as --resolution" },
    { "set AllowPoorMaps to write the result anyway", "--allow-poor-maps writes the result anyway" },
    { "(BasisSize)", "(--basis-size)" },
    { "set TransformMode to ROTATIONS_AND_REFLECTIONS", "try --transform both" },
    { "LandmarkMode 1", "--landmark-mode 1" },
  };
  for (const auto& [property, option] : words)
  {
    const auto at = text.find(property);
    if (at != std::string::npos)
    {
      text.replace(at, std::string(property).size(), option);
    }
  }
  return text;
}

bool InCommandLineWords(bool succeeded, PipelineResult& result, std::string& error)
{
  error = InCommandLineWords(error);
  for (auto& warning : result.Warnings)
  {
    warning = InCommandLineWords(warning);
  }
  return succeeded;
}
}

bool RunRegistration(vtkPolyData* source, vtkPolyData* target, const std::string& sourceName,
  const std::string& targetName, const PipelineOptions& options, PipelineResult& result,
  std::string& error, const StageProgress& progress)
{
  // The landmarks' vertex numbers against the meshes read, before any stage runs.
  error = mobius::CheckLandmarkVertices(options, source->GetNumberOfPoints(),
    target->GetNumberOfPoints(), mobius::ParameterNaming::CommandLine);
  if (!error.empty())
  {
    return false;
  }
  return InCommandLineWords(RunRegistrationPipeline(source, target, sourceName, targetName,
                              options, result, error, progress),
    result, error);
}

bool RunSymmetryDetection(vtkPolyData* mesh, const std::string& name,
  const PipelineOptions& options, PipelineResult& result, std::string& error,
  const StageProgress& progress)
{
  return InCommandLineWords(
    RunSymmetryPipeline(mesh, name, options, result, error, progress), result, error);
}

bool RunOrbifoldMap(vtkPolyData* mesh, const std::string& name, const PipelineOptions& options,
  int copies, const long long cones[2], bool covering, PipelineResult& result, std::string& error,
  const StageProgress& progress)
{
  return InCommandLineWords(
    RunOrbifoldPipeline(mesh, name, options, copies, cones, covering, result, error, progress),
    result, error);
}
