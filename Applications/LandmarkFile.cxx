#include "LandmarkFile.h"

#include "TextFormats.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace
{
// A vertex number: digits only (no sign, no fraction), within range of an Index.
bool ParseVertex(const std::string& word, mobius::Index& vertex)
{
  if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  errno = 0;
  const long long value = std::strtoll(word.c_str(), nullptr, 10);
  vertex = static_cast<mobius::Index>(value);
  return errno == 0;
}

// The line's fields, split at commas and white space, its comment left out.
std::vector<std::string> Fields(std::string line)
{
  line = line.substr(0, line.find('#'));
  for (char& c : line)
  {
    c = c == ',' ? ' ' : c;
  }
  std::istringstream words(line);
  std::vector<std::string> fields;
  for (std::string word; words >> word;)
  {
    fields.push_back(word);
  }
  return fields;
}
}

bool ReadLandmarks(std::istream& stream, const std::string& fileName,
  std::vector<mobius::Landmark>& landmarks, std::string& error)
{
  landmarks.clear();
  std::string line;
  TextLines lines(stream);
  while (lines.Next(line))
  {
    const std::vector<std::string> fields = Fields(line);
    if (fields.empty())
    {
      continue;
    }
    mobius::Landmark landmark;
    landmark.Line = static_cast<int>(lines.Number());
    if (fields.size() != 2 || !ParseVertex(fields[0], landmark.Source) ||
      !ParseVertex(fields[1], landmark.Target))
    {
      error = fileName + " line " + std::to_string(lines.Number()) +
        ": a landmark is two vertex numbers (source, target; 0-based non-negative integers, "
        "separated by a comma or spaces), not '" +
        Excerpt(line) + "'";
      return false;
    }
    landmarks.push_back(landmark);
  }
  if (stream.bad())
  {
    error = fileName + ": cannot read the landmarks file (" + std::strerror(errno) + ")";
    return false;
  }
  if (landmarks.empty())
  {
    error = fileName + ": no landmarks in the file (one 'source,target' pair of vertex numbers per line)";
    return false;
  }
  return true;
}

bool ReadLandmarkFile(
  const std::string& fileName, std::vector<mobius::Landmark>& landmarks, std::string& error)
{
  // A folder opens as a stream that reads nothing: it would be "no landmarks in the file".
  struct stat status;
  if (stat(fileName.c_str(), &status) == 0 && S_ISDIR(status.st_mode))
  {
    error = fileName + ": a folder, not a landmarks file";
    return false;
  }
  std::ifstream file(fileName, std::ios::binary);
  if (!file)
  {
    error = fileName + ": cannot read the landmarks file (" + std::strerror(errno) + ")";
    return false;
  }
  return ReadLandmarks(file, fileName, landmarks, error);
}
