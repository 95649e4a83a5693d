#include "ParameterRules.h"

#include <functional>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace mobius
{
namespace
{
// A parameter's name in each interface (Python's register() and the command line lack some:
// then the property's name stands in; their defaults always pass).
struct ParameterNames
{
  const char* Filter;
  const char* Python;
  const char* CommandLine;

  const char* In(ParameterNaming naming) const
  {
    const char* name = naming == ParameterNaming::Python ? Python
      : naming == ParameterNaming::CommandLine           ? CommandLine
                                                          : Filter;
    return name ? name : Filter;
  }
};

// One rule: whether the parameters pass it, and else what the parameter must be and what it is.
struct Rule
{
  ParameterNames Names;
  std::function<bool(const RegistrationParameters&)> Passes;
  std::function<std::string(const RegistrationParameters&, ParameterNaming)> Requirement;
  std::function<std::string(const RegistrationParameters&)> Value;
};

template <typename T>
std::string Text(T value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string Words(const IntegerRange& range)
{
  return "an integer from " + Text(range.Minimum) + " to " + Text(range.Maximum);
}

std::string Words(const NumberRange& range)
{
  return "a number from " + Text(range.Minimum) + " to " + Text(range.Maximum);
}

// A rule for the integer `member`, allowed in `range`.
Rule IntegerRule(ParameterNames names, int RegistrationParameters::*member, IntegerRange range)
{
  return { names, [=](const RegistrationParameters& p) { return range.Contains(p.*member); },
    [=](const RegistrationParameters&, ParameterNaming) { return Words(range); },
    [=](const RegistrationParameters& p) { return Text(p.*member); } };
}

// A rule for the real `member`, allowed in `range` (NaN never is).
Rule NumberRule(ParameterNames names, double RegistrationParameters::*member, NumberRange range)
{
  return { names, [=](const RegistrationParameters& p) { return range.Contains(p.*member); },
    [=](const RegistrationParameters&, ParameterNaming) { return Words(range); },
    [=](const RegistrationParameters& p) { return Text(p.*member); } };
}

const ParameterNames CandidatesNames{ "NumberOfCandidates", "candidates", "--candidates" };
const ParameterNames LandmarksNames{ "Landmarks", "landmarks", "--landmarks" };
}

std::string LandmarkName(const RegistrationParameters& p, size_t k, ParameterNaming naming)
{
  switch (naming)
  {
    case ParameterNaming::Python:
      return "landmarks[" + Text(k) + "]";
    case ParameterNaming::CommandLine:
      return p.Landmarks[k].Line > 0
        ? (p.LandmarksFile.empty() ? "" : p.LandmarksFile + " ") + "line " + Text(p.Landmarks[k].Line)
        : "pair " + Text(k);
    case ParameterNaming::Filter:
      break;
  }
  return "landmark " + Text(k);
}

std::string LandmarkLabel(const RegistrationParameters& p, size_t k)
{
  return LandmarkName(
    p, k, p.Landmarks[k].Line > 0 ? ParameterNaming::CommandLine : ParameterNaming::Filter);
}

namespace
{
// The first vertex given twice on one side ("source vertex 5 in landmark 0 and landmark 2");
// empty if none is. Two source vertices sent to one target vertex fold the map, and one
// source vertex sent to two places cannot be kept. One pass with the landmark where each
// vertex was first seen (a file of 200,000 lines was checked pair by pair: 20 s).
std::string RepeatedLandmarkVertex(const RegistrationParameters& p, ParameterNaming naming)
{
  std::unordered_map<Index, size_t> firstSource, firstTarget;
  for (size_t k = 0; k < p.Landmarks.size(); ++k)
  {
    const auto source = firstSource.emplace(p.Landmarks[k].Source, k).first;
    const auto target = firstTarget.emplace(p.Landmarks[k].Target, k).first;
    // The earlier landmark that shares a vertex with this one; the source side first.
    const bool sourceRepeated = source->second != k;
    const bool targetRepeated = target->second != k;
    if (!sourceRepeated && !targetRepeated)
    {
      continue;
    }
    const bool sourceSide = sourceRepeated && (!targetRepeated || source->second <= target->second);
    const size_t j = sourceSide ? source->second : target->second;
    const Index vertex = sourceSide ? p.Landmarks[k].Source : p.Landmarks[k].Target;
    return std::string(sourceSide ? "source" : "target") + " vertex " + Text(vertex) + " in " +
      LandmarkName(p, j, naming) + " and " + LandmarkName(p, k, naming);
  }
  return {};
}

const std::vector<Rule>& Rules()
{
  static const std::vector<Rule> rules = {
    IntegerRule({ "MaximumNumberOfIterations", "iterations", "--iterations" },
      &RegistrationParameters::FlowIterations, { 1, std::numeric_limits<int>::max() }),
    NumberRule({ "ConvergenceTolerance", "tolerance", "--tolerance" },
      &RegistrationParameters::FlowTolerance, FlowToleranceRange),
    IntegerRule({ "CenteringDegree", nullptr, "--degree" }, &RegistrationParameters::CenteringDegree,
      CenteringDegreeRange),
    // A coarser grid maps real shapes wrongly, and the grid's samples come in pairs.
    { { "Resolution", "resolution", "--resolution" },
      [](const RegistrationParameters& p) {
        return p.Resolution >= MinimumResolution && p.Resolution % 2 == 0;
      },
      [](const RegistrationParameters&, ParameterNaming) {
        return "an even integer, at least " + Text(MinimumResolution);
      },
      [](const RegistrationParameters& p) { return Text(p.Resolution); } },
    NumberRule({ "SmoothingTime", "smoothing", "--smoothing" }, &RegistrationParameters::SmoothingTime,
      SmoothingTimeRange),
    { { "TransformMode", "transform", "--transform" },
      [](const RegistrationParameters& p) { return p.TransformMode >= 0 && p.TransformMode <= 2; },
      [](const RegistrationParameters&, ParameterNaming) {
        return std::string("0 (rotations), 1 (reflections) or 2 (both)");
      },
      [](const RegistrationParameters& p) { return Text(p.TransformMode); } },
    IntegerRule(CandidatesNames, &RegistrationParameters::NumberOfCandidates, CandidateCountRange),
    NumberRule({ "CandidateSeparation", "candidate_separation", "--candidate-separation" },
      &RegistrationParameters::CandidateSeparation, CandidateSeparationRange),
    // The candidate kept must be one of those found (-1: the refinement chooses).
    { { "Candidate", "candidate", "--candidate" },
      [](const RegistrationParameters& p) {
        return p.Candidate == -1 || (p.Candidate >= 0 && p.Candidate < p.NumberOfCandidates);
      },
      [](const RegistrationParameters& p, ParameterNaming naming) {
        const std::string chooses = naming == ParameterNaming::Python ? "None" : "-1";
        return chooses + " (the refinement chooses) or one of the " +
          Text(p.NumberOfCandidates) + " candidates (" + CandidatesNames.In(naming) +
          "), numbered from 0";
      },
      [](const RegistrationParameters& p) { return Text(p.Candidate); } },
    IntegerRule({ "BasisSize", "basis_size", "--basis-size" }, &RegistrationParameters::BasisSize,
      BasisSizeRange),
    IntegerRule({ "OutputGeometry", nullptr, "--output-geometry" },
      &RegistrationParameters::OutputGeometry, { 0, 1 }),
    IntegerRule({ "NumberOfThreads", "threads", "--threads" },
      &RegistrationParameters::NumberOfThreads, ThreadCountRange),
    // Fitting a Möbius transform needs its 3 points; choosing a rotation works with any.
    { { "LandmarkMode", "landmark_mode", "--landmark-mode" },
      [](const RegistrationParameters& p) {
        return p.LandmarkMode == static_cast<int>(LandmarkMode::ChooseRotation) ||
          (p.LandmarkMode == static_cast<int>(LandmarkMode::FitMobius) &&
            p.Landmarks.size() >= static_cast<size_t>(FittedLandmarkCount));
      },
      [](const RegistrationParameters&, ParameterNaming naming) {
        return "0 (the rotation search chooses by the landmarks) or 1 (a Moebius transform "
               "fitted to " +
          Text(FittedLandmarkCount) + " landmarks, which needs at least " +
          Text(FittedLandmarkCount) + " " + LandmarksNames.In(naming) + ")";
      },
      [](const RegistrationParameters& p) {
        return Text(p.LandmarkMode) + " with " + Text(p.Landmarks.size()) + " landmarks";
      } },
    { LandmarksNames,
      [](const RegistrationParameters& p) {
        return RepeatedLandmarkVertex(p, ParameterNaming::Filter).empty();
      },
      [](const RegistrationParameters&, ParameterNaming) {
        return std::string("pairs of distinct source vertices and distinct target vertices");
      },
      nullptr },
  };
  return rules;
}
}

std::string CheckRegistrationParameters(
  const RegistrationParameters& parameters, ParameterNaming naming)
{
  for (const Rule& rule : Rules())
  {
    if (rule.Passes(parameters))
    {
      continue;
    }
    const std::string name = rule.Names.In(naming);
    const std::string requirement = rule.Requirement(parameters, naming);
    // A rule about a list names the offending entry in the interface's words.
    const std::string value = rule.Value ? rule.Value(parameters)
                                         : RepeatedLandmarkVertex(parameters, naming) + " (given twice)";
    switch (naming)
    {
      case ParameterNaming::CommandLine:
        return name + " needs " + requirement + ", not " + value;
      case ParameterNaming::Python:
        return name + " must be " + requirement + ", got " + value;
      case ParameterNaming::Filter:
        break;
    }
    return name + " must be " + requirement + " (it is " + value + ")";
  }
  return {};
}

std::string CheckLandmarkVertices(const RegistrationParameters& parameters, Index sourceVertices,
  Index targetVertices, ParameterNaming naming)
{
  const Index counts[2] = { sourceVertices, targetVertices };
  const char* sides[2] = { "source", "target" };
  for (size_t k = 0; k < parameters.Landmarks.size(); ++k)
  {
    const Index vertices[2] = { parameters.Landmarks[k].Source, parameters.Landmarks[k].Target };
    for (int side = 0; side < 2; ++side)
    {
      if (vertices[side] >= 0 && vertices[side] < counts[side])
      {
        continue;
      }
      const std::string where = LandmarkName(parameters, k, naming);
      const std::string range = "the " + std::string(sides[side]) + " mesh has " +
        Text(counts[side]) + " vertices, numbered from 0 to " + Text(counts[side] - 1);
      const std::string vertex = std::string(sides[side]) + " vertex " + Text(vertices[side]);
      switch (naming)
      {
        case ParameterNaming::CommandLine:
          return LandmarksNames.CommandLine + std::string(" ") + where + ": no " + vertex + ": " +
            range;
        case ParameterNaming::Python:
          return where + " names " + vertex + ", which does not exist: " + range;
        case ParameterNaming::Filter:
          break;
      }
      return "Landmarks: " + where + " names " + vertex + ", which does not exist: " + range;
    }
  }
  return {};
}
}
