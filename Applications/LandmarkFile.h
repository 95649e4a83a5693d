// The landmarks file of mobius-register --landmarks: one landmark per line, the source
// vertex and the target vertex (0-based vertex numbers of the mesh files) separated by a
// comma or spaces; '#' starts a comment, empty lines are skipped. A UTF-8 byte-order mark
// and CR LF or CR line ends are read as the mesh readers read them.
#ifndef LandmarkFile_h
#define LandmarkFile_h

#include "RegistrationParameters.h"

#include <istream>
#include <string>
#include <vector>

/// Reads the landmarks of `stream` (named `fileName` in messages), each with its line
/// number. False with `error` ("FILE line 3: ...", quoting the line's start) for a line that
/// is not two non-negative integers, or a file without any landmark.
bool ReadLandmarks(std::istream& stream, const std::string& fileName,
  std::vector<mobius::Landmark>& landmarks, std::string& error);

/// The same from the file `fileName`; an error also when it cannot be read or is a folder.
bool ReadLandmarkFile(
  const std::string& fileName, std::vector<mobius::Landmark>& landmarks, std::string& error);

#endif
