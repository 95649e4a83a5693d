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
}

#endif
