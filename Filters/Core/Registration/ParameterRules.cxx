#include "ParameterRules.h"

#include <functional>
#include <limits>
#include <sstream>
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
    const std::string value = rule.Value(parameters);
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
}
