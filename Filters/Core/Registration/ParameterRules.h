// The allowed values of the registration's parameters, checked in one place for every
// interface: mobius-register and mobius-score (once their options are read), Python's
// register() and vtkMobiusRegistration (before they run). Each interface reads the values
// its own way (a command-line word, a Python object, a VTK property) and names them in its
// own words; which values are allowed, and why, is said only here.
#ifndef mobius_ParameterRules_h
#define mobius_ParameterRules_h

#include "RegistrationParameters.h"

#include <string>

namespace mobius
{
/// Whose names a message uses: the VTK properties ("BasisSize"), the keywords of Python's
/// register() ("basis_size") or the command line's options ("--basis-size").
enum class ParameterNaming
{
  Filter,
  Python,
  CommandLine
};

/// The first parameter outside its allowed values, with the value it has, e.g.
/// "--basis-size needs an integer from 2 to 500, not 0" (CommandLine),
/// "basis_size must be an integer from 2 to 500, got 0" (Python),
/// "BasisSize must be an integer from 2 to 500 (it is 0)" (Filter); empty when every
/// parameter is allowed. The memory a Resolution needs is the registration's to check.
std::string CheckRegistrationParameters(
  const RegistrationParameters& parameters, ParameterNaming naming);

/// Landmark number `k` as the interface shows it: "landmark 2" (Filter), "landmarks[2]"
/// (Python), "FILE line 7" or "pair 2" (CommandLine).
std::string LandmarkName(const RegistrationParameters& parameters, size_t k, ParameterNaming naming);

/// Landmark number `k` as the user gave it: its file and line when it was read from a file
/// ("FILE line 7"), else its number ("landmark 2").
std::string LandmarkLabel(const RegistrationParameters& parameters, size_t k);

/// The first landmark that names a vertex the meshes do not have (the source has
/// `sourceVertices` vertices, the target `targetVertices`), e.g. "landmarks[2] names source
/// vertex 5000, which does not exist: the source mesh has 4000 vertices, numbered from 0 to
/// 3999" (Python); empty when every landmark names existing vertices. Checked once the
/// meshes are read; the rest of the landmarks' rules are CheckRegistrationParameters'.
std::string CheckLandmarkVertices(const RegistrationParameters& parameters, Index sourceVertices,
  Index targetVertices, ParameterNaming naming);
}

#endif
