#include "JsonSummary.h"

#include "TextFormats.h"

#include "vtkFieldData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace
{
// JSON has no NaN: absent figures are null.
std::string Number(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

std::string Array(vtkPolyData* data, const char* name, int components)
{
  std::string out = "[";
  for (int k = 0; k < components; ++k)
  {
    out += (k ? ", " : "") + Number(FieldValue(data, name, k));
  }
  return out + "]";
}

// A figure the refinement stores as -1 when it could not measure it: null.
std::string Measured(double value)
{
  return value >= 0 ? Number(value) : "null";
}

// A one-value string field array's value; empty if there is none.
std::string FieldString(vtkPolyData* data, const char* name)
{
  auto array = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() > 0 ? array->GetValue(0) : std::string();
}

// How sure the refinement is of its choice (RefinementConfidence, RefinementChoice): what
// decided, the kept map's curvature difference, its finished map's stretch, the runner-up
// (null if none) and the margin to it by what decided (null if none).
std::string Confidence(vtkPolyData* refined)
{
  vtkDataArray* confidence = refined->GetFieldData()->GetArray("RefinementConfidence");
  vtkDataArray* curvature = refined->GetFieldData()->GetArray("CandidateCurvatureDifferences");
  vtkDataArray* stretch = refined->GetFieldData()->GetArray("CandidateMapStretch");
  const vtkIdType kept = static_cast<vtkIdType>(FieldValue(refined, "RefinementCandidate"));
  if (!confidence || confidence->GetNumberOfComponents() * confidence->GetNumberOfTuples() < 3 ||
    !curvature || !stretch || kept < 0 || kept >= curvature->GetNumberOfTuples() ||
    kept >= stretch->GetNumberOfTuples())
  {
    return "null";
  }
  const std::string choice = FieldString(refined, "RefinementChoice");
  const bool runnerUp = confidence->GetComponent(0, 1) >= 0;
  std::ostringstream out;
  out << "{\"decided_by\": " << (choice.empty() ? std::string("null") : JsonString(choice))
      << ", \"curvature_difference\": " << Measured(curvature->GetComponent(kept, 0))
      << ", \"map_stretch\": " << Measured(stretch->GetComponent(kept, 0))
      << ", \"runner_up\": " << (runnerUp ? Number(confidence->GetComponent(0, 1)) : "null")
      << ", \"margin\": " << (runnerUp ? Number(confidence->GetComponent(0, 2)) : "null") << "}";
  return out.str();
}

// A per-candidate figure, or null where the array is missing or short.
std::string CandidateFigure(vtkPolyData* refined, const char* name, vtkIdType c, bool measured)
{
  vtkDataArray* array = refined->GetFieldData()->GetArray(name);
  if (!array || c >= array->GetNumberOfTuples())
  {
    return "null";
  }
  return measured ? Measured(array->GetComponent(c, 0)) : Number(array->GetComponent(c, 0));
}

// What the refinement chose and why: every candidate's score, the kept one's index.
std::string Refinement(vtkPolyData* refined, bool done)
{
  if (!done)
  {
    return "null";
  }
  std::ostringstream out;
  out << "{\"method\": \"spectral\", \"basis_size\": " << Number(FieldValue(refined, "RefinementBasisSize"))
      << ", \"kept_candidate\": " << Number(FieldValue(refined, "RefinementCandidate"))
      << ", \"orthogonality_residual\": " << Number(FieldValue(refined, "RefinementOrthogonalityResidual"))
      << ", \"orientation_agreement\": " << Number(FieldValue(refined, "RefinementOrientationAgreement"))
      << ", \"orientation_repaired\": " << (FieldValue(refined, "RefinementOrientationRepaired") == 1 ? "true" : "false")
      << ", \"mean_stretch\": " << Number(FieldValue(refined, "RefinementMeanStretch"))
      << ", \"confidence\": " << Confidence(refined)
      << ", \"candidates\": [";
  vtkDataArray* residuals = refined->GetFieldData()->GetArray("CandidateOrthogonalityResiduals");
  for (vtkIdType c = 0; residuals && c < residuals->GetNumberOfTuples(); ++c)
  {
    out << (c ? ", " : "") << "{\"orthogonality_residual\": " << Number(residuals->GetComponent(c, 0))
        << ", \"target_coverage\": "
        << CandidateFigure(refined, "CandidateTargetCoverage", c, false)
        << ", \"orientation_agreement\": "
        << CandidateFigure(refined, "CandidateOrientationAgreement", c, false)
        << ", \"curvature_difference\": "
        << CandidateFigure(refined, "CandidateCurvatureDifferences", c, true)
        << ", \"landmark_distance_difference\": "
        << CandidateFigure(refined, "CandidateLandmarkDistanceDifferences", c, false)
        << ", \"map_stretch\": " << CandidateFigure(refined, "CandidateMapStretch", c, true) << "}";
  }
  out << "]}";
  return out.str();
}

// The landmarks: how many, the mode, and each one's residual (LandmarkResidual).
std::string Landmarks(const PipelineOptions& options, vtkPolyData* map)
{
  std::ostringstream out;
  out << "{\"count\": " << options.Landmarks.size() << ", \"mode\": " << options.LandmarkMode
      << ", \"residuals\": [";
  vtkDataArray* residuals = map->GetFieldData()->GetArray("LandmarkResidual");
  for (vtkIdType k = 0; residuals && k < residuals->GetNumberOfTuples(); ++k)
  {
    out << (k ? ", " : "") << Number(residuals->GetComponent(k, 0));
  }
  out << "]}";
  return out.str();
}

// "stages": [{"name", "seconds"}...], "total_seconds": the job's wall time (less than the
// stages' sum where stages ran side by side), or their sum where it was not measured.
std::string StageTimes(const PipelineResult& result)
{
  const std::vector<StageTiming>& stages = result.Stages;
  std::ostringstream json;
  json << "\"stages\": [";
  double total = 0;
  for (size_t s = 0; s < stages.size(); ++s)
  {
    json << (s ? ", " : "") << "{\"name\": " << JsonString(stages[s].Name)
         << ", \"seconds\": " << Number(stages[s].Seconds) << "}";
    total += stages[s].Seconds;
  }
  json << "],\n  \"total_seconds\": " << Number(result.WallSeconds > 0 ? result.WallSeconds : total);
  return json.str();
}

// What the repair did to a mesh (vtkSphericalConformalMap's field data): the warning's
// phrases and the figures behind them.
std::string Repairs(vtkPolyData* map)
{
  std::ostringstream out;
  out << "{\"done\": [";
  auto phrases = vtkStringArray::SafeDownCast(map->GetFieldData()->GetAbstractArray("MeshRepairs"));
  for (vtkIdType k = 0; phrases && k < phrases->GetNumberOfValues(); ++k)
  {
    out << (k ? ", " : "") << JsonString(phrases->GetValue(k));
  }
  out << "], \"removed_triangles\": " << Number(FieldValue(map, "RemovedTriangles"))
      << ", \"split_vertices\": " << Number(FieldValue(map, "SplitNonManifoldVertices"))
      << ", \"reversed_triangles\": " << Number(FieldValue(map, "ReversedTriangles"))
      << ", \"dropped_components\": " << Number(FieldValue(map, "DroppedComponents"))
      << ", \"dropped_area_share\": " << Number(FieldValue(map, "DroppedComponentAreaShare"))
      << ", \"filled_holes\": " << Number(FieldValue(map, "FilledHoles"))
      << ", \"filled_area_share\": " << Number(FieldValue(map, "FilledAreaShare"))
      << ", \"cut_handle_loop_lengths\": [";
  vtkDataArray* loops = map->GetFieldData()->GetArray("CutHandleLoopLengths");
  for (vtkIdType k = 0; loops && k < loops->GetNumberOfTuples(); ++k)
  {
    out << (k ? ", " : "") << Number(loops->GetComponent(k, 0));
  }
  out << "]}";
  return out.str();
}

std::string MapQuality(vtkPolyData* map, vtkPolyData* centered)
{
  std::ostringstream out;
  out << "{\"points\": " << map->GetNumberOfPoints() << ", \"repairs\": " << Repairs(map)
      << ", \"flow_iterations\": " << Number(FieldValue(map, "ConformalFlowIterations"))
      << ", \"flow_converged\": " << (FieldValue(map, "ConformalFlowConverged") == 1 ? "true" : "false")
      << ", \"flipped_triangles\": " << Number(FieldValue(map, "FlippedTriangles"))
      << ", \"mean_quasi_conformal_distortion\": " << Number(FieldValue(map, "MeanQuasiConformalDistortion"))
      << ", \"max_quasi_conformal_distortion\": " << Number(FieldValue(map, "MaxQuasiConformalDistortion"))
      << ", \"median_quasi_conformal_distortion\": " << Number(FieldValue(map, "MedianQuasiConformalDistortion"))
      << ", \"p95_quasi_conformal_distortion\": " << Number(FieldValue(map, "P95QuasiConformalDistortion"))
      << ", \"p99_quasi_conformal_distortion\": " << Number(FieldValue(map, "P99QuasiConformalDistortion"))
      << ", \"squashed_area_share\": " << Number(FieldValue(map, "SquashedAreaShare"))
      << ", \"smallest_sphere_area_share\": " << Number(FieldValue(map, "SmallestSphereAreaShare"))
      << ", \"centering_iterations\": " << Number(FieldValue(centered, "CenteringIterations"))
      << ", \"centering_degree\": " << Number(FieldValue(centered, "CenteringDegree"))
      << ", \"generalized_centering_iterations\": "
      << Number(FieldValue(centered, "GeneralizedCenteringIterations"))
      << ", \"center_of_mass_norm\": " << Number(FieldValue(centered, "CenterOfMassNorm"));
  // null for a good map; the reason for one written with --allow-poor-maps.
  auto reason =
    vtkStringArray::SafeDownCast(map->GetFieldData()->GetAbstractArray("DegenerateMapReason"));
  out << ", \"degenerate\": "
      << (FieldValue(map, "DegenerateMap") == 1 && reason && reason->GetNumberOfValues() > 0
             ? JsonString(reason->GetValue(0))
             : std::string("null"));
  // null, or what the user should know about a usable map (a squashed share of the surface).
  auto warning = vtkStringArray::SafeDownCast(map->GetFieldData()->GetAbstractArray("MapWarning"));
  out << ", \"warning\": "
      << (warning && warning->GetNumberOfValues() > 0 && !warning->GetValue(0).empty()
             ? JsonString(warning->GetValue(0))
             : std::string("null"))
      << "}";
  return out.str();
}
}

std::string JsonSummary(const std::string& source, const std::string& target,
  const PipelineOptions& options, const PipelineResult& result, const OutputFiles& outputs,
  double demoError)
{
  std::ostringstream json;
  json << "{\n  \"source\": " << JsonString(source) << ",\n  \"target\": " << JsonString(target)
       << ",\n  \"rotation\": " << Array(result.Aligned, "Rotation", 9)
       << ",\n  \"determinant\": " << Number(FieldValue(result.Aligned, "Determinant"))
       << ",\n  \"euler_angles_zyz\": " << Array(result.Aligned, "EulerAngles", 3)
       << ",\n  \"correlation_score\": " << Number(FieldValue(result.Aligned, "CorrelationScore"))
       << ",\n  \"registration_error\": " << Number(FieldValue(result.Aligned, "RegistrationError"))
       << ",\n  \"threads\": " << Number(FieldValue(result.Aligned, "NumberOfThreadsUsed"))
       << ",\n  \"candidates\": [";
  vtkDataArray* transforms = result.Aligned->GetFieldData()->GetArray("CandidateTransforms");
  vtkDataArray* scores = result.Aligned->GetFieldData()->GetArray("CandidateScores");
  for (vtkIdType c = 0; transforms && scores && c < transforms->GetNumberOfTuples(); ++c)
  {
    json << (c ? ", " : "") << "{\"score\": " << Number(scores->GetComponent(c, 0))
         << ", \"transform\": [";
    for (int k = 0; k < 9; ++k)
    {
      json << (k ? ", " : "") << Number(transforms->GetComponent(c, k));
    }
    json << "]}";
  }
  json << "],\n  \"source_map\": " << MapQuality(result.SourceMap, result.SourceCentered)
       << ",\n  \"target_map\": " << MapQuality(result.TargetMap, result.TargetCentered)
       << ",\n  \"clamped_points\": " << Number(FieldValue(result.MobiusCorrespondence, "ClampedPoints"))
       << ",\n  \"refinement\": " << Refinement(result.Correspondence, result.Correspondence != result.MobiusCorrespondence)
       << ",\n  \"landmarks\": " << Landmarks(options, result.Correspondence)
       << ",\n  " << StageTimes(result) << ",\n  \"outputs\": {\"mesh\": "
       << JsonString(outputs.MeshPath) << ", \"csv\": " << JsonString(outputs.CsvPath)
       << ", \"picture\": " << (outputs.PicturePath.empty() ? "null" : JsonString(outputs.PicturePath))
       << "}";
  if (std::isfinite(demoError))
  {
    json << ",\n  \"demo_mean_error_over_sqrt_area\": " << Number(demoError);
  }
  json << "\n}\n";
  return json.str();
}

std::string SymmetryJsonSummary(
  const std::string& mesh, const PipelineResult& result, const OutputFiles& outputs)
{
  vtkPolyData* symmetry = result.Correspondence;
  std::ostringstream json;
  json << "{\n  \"mesh\": " << JsonString(mesh)
       << ",\n  \"symmetry_distance\": " << Number(FieldValue(symmetry, "SymmetryDistance"))
       << ",\n  \"centered\": " << (FieldValue(symmetry, "SymmetryCentered") == 1 ? "true" : "false")
       << ",\n  \"reflection\": " << Array(symmetry, "Reflection", 9)
       << ",\n  \"mirror_plane_normal\": " << Array(symmetry, "MirrorPlaneNormal", 3)
       << ",\n  \"mirror_plane_twist\": " << Number(FieldValue(symmetry, "MirrorPlaneTwist"))
       << ",\n  \"mean_asymmetry\": " << Number(FieldValue(symmetry, "MeanAsymmetry"))
       << ",\n  \"max_asymmetry\": " << Number(FieldValue(symmetry, "MaximumAsymmetry"))
       << ",\n  \"threads\": " << Number(FieldValue(symmetry, "NumberOfThreadsUsed"))
       << ",\n  \"candidates\": [";
  vtkFieldData* fields = symmetry->GetFieldData();
  vtkDataArray* transforms = fields->GetArray("CandidateTransforms");
  vtkDataArray* scores = fields->GetArray("CandidateScores");
  vtkDataArray* distances = fields->GetArray("CandidateSymmetryDistances");
  vtkDataArray* normals = fields->GetArray("CandidateMirrorPlaneNormals");
  for (vtkIdType c = 0; transforms && scores && distances && normals &&
       c < transforms->GetNumberOfTuples() && c < distances->GetNumberOfTuples();
       ++c)
  {
    json << (c ? ", " : "") << "{\"symmetry_distance\": " << Number(distances->GetComponent(c, 0))
         << ", \"score\": " << Number(scores->GetComponent(c, 0)) << ", \"mirror_plane_normal\": ["
         << Number(normals->GetComponent(c, 0)) << ", " << Number(normals->GetComponent(c, 1))
         << ", " << Number(normals->GetComponent(c, 2)) << "], \"transform\": [";
    for (int k = 0; k < 9; ++k)
    {
      json << (k ? ", " : "") << Number(transforms->GetComponent(c, k));
    }
    json << "]}";
  }
  json << "],\n  \"map\": " << MapQuality(result.SourceMap, symmetry)
       << ",\n  \"refinement\": " << Refinement(symmetry, FieldValue(symmetry, "SymmetryRefined") == 1)
       << ",\n  " << StageTimes(result) << ",\n  \"outputs\": {\"mesh\": "
       << JsonString(outputs.MeshPath) << ", \"csv\": " << JsonString(outputs.CsvPath) << "}\n}\n";
  return json.str();
}

std::string OrbifoldJsonSummary(
  const std::string& mesh, const PipelineResult& result, const OutputFiles& outputs)
{
  vtkPolyData* map = result.Correspondence;
  std::ostringstream json;
  json << "{\n  \"mesh\": " << JsonString(mesh)
       << ",\n  \"copies\": " << Number(FieldValue(map, "NumberOfCopies"))
       << ",\n  \"cones\": " << Array(map, "ConeIds", 2)
       << ",\n  \"symmetry_error\": " << Number(FieldValue(map, "SymmetryError"))
       << ",\n  \"cone_antipodality\": " << Number(FieldValue(map, "ConeAntipodality"))
       << ",\n  \"flipped_triangles\": " << Number(FieldValue(map, "FlippedTriangles"))
       << ",\n  \"std_log_area_ratio\": " << Number(FieldValue(map, "StdLogAreaRatio"))
       << ",\n  \"plain_std_log_area_ratio\": " << Number(FieldValue(map, "PlainStdLogAreaRatio"))
       << ",\n  \"covering_flow_iterations\": " << Number(FieldValue(map, "ConformalFlowIterations"))
       << ",\n  \"covering_flow_converged\": "
       << (FieldValue(map, "ConformalFlowConverged") == 1 ? "true" : "false")
       << ",\n  " << StageTimes(result) << ",\n  \"outputs\": {\"mesh\": "
       << JsonString(outputs.MeshPath) << "}\n}\n";
  return json.str();
}
