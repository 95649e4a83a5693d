// The landmarks file of mobius-register --landmarks: one landmark per line, the source
// vertex and the target vertex (0-based vertex numbers of the mesh files) separated by a
// comma or spaces; '#' starts a comment, empty lines are skipped.
#ifndef LandmarkFile_h
#define LandmarkFile_h

#include "RegistrationParameters.h"

#include <istream>
#include <string>
#include <vector>

/// Reads the landmarks of `stream` (named `fileName` in messages), each with its line
/// number. False with `error` ("FILE line 3: ...") for a line that is not two non-negative
/// integers, or a file without any landmark.
bool ReadLandmarks(std::istream& stream, const std::string& fileName,
  std::vector<mobius::Landmark>& landmarks, std::string& error);

/// The same from the file `fileName`; an error also when it cannot be read.
bool ReadLandmarkFile(
  const std::string& fileName, std::vector<mobius::Landmark>& landmarks, std::string& error);

#endif
