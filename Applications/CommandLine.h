// Options of mobius-register and their parsing.
#ifndef CommandLine_h
#define CommandLine_h

#include "RegistrationPipeline.h"

#include <string>

struct CommandLine
{
  std::string Source, Target;
  std::string Output;   // path prefix or .vtp file; outputs are <stem>.vtp and <stem>.csv
  std::string Picture;  // --png
  bool Demo = false;    // no input meshes given
  bool Symmetry = false; // --symmetry MESH: bilateral symmetry of Source
  int OrbifoldCopies = 0; // --orbifold N MESH: n-fold orbifold map of Source (0: not asked)
  long long Cones[2] = { -1, -1 }; // --cones I,J (file vertex numbers; -1: automatic)
  bool Covering = false;  // --covering: write the whole covering
  bool Force = false;
  bool Quiet = false;
  bool Json = false;
  bool Help = false;
  bool Version = false;
  PipelineOptions Pipeline;
};

/// Parses argv. Returns false with `error` for unknown options, missing values or values
/// out of range (mobius::CheckRegistrationParameters).
bool ParseCommandLine(int argc, char* argv[], CommandLine& commandLine, std::string& error);

/// Parses the pipeline option at argv[i] (conformal map, centering degree, registration,
/// refinement, --threads), advancing i past its value: the options mobius-register and
/// mobius-score's dataset mode share. `recognized` is false for any other argument (then
/// nothing is read). Returns false with `error` for a missing value or one that is not a
/// number; the caller checks the ranges once every option is read
/// (mobius::CheckRegistrationParameters).
bool ParsePipelineOption(
  int argc, char* argv[], int& i, PipelineOptions& pipeline, bool& recognized, std::string& error);

/// The --help text, with the defaults.
std::string UsageText();

#endif
