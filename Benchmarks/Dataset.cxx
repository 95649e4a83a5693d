#include "Dataset.h"

#include "ScoreInput.h"
#include "TextFormats.h"

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <dirent.h>
#include <fnmatch.h>
#include <fstream>
#include <random>
#include <set>
#include <sys/stat.h>

namespace
{
bool IsFile(const std::string& path)
{
  struct stat status;
  return stat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

bool EndsWith(const std::string& text, const std::string& end)
{
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// A uniform integer in [0, bound), the same on every platform (std::uniform_int_distribution
// is not).
std::uint64_t Uniform(std::mt19937_64& generator, std::uint64_t bound)
{
  const std::uint64_t limit = generator.max() - (generator.max() % bound + 1) % bound;
  std::uint64_t draw;
  do
  {
    draw = generator();
  } while (draw > limit);
  return draw % bound;
}
}

bool IsDirectory(const std::string& path)
{
  struct stat status;
  return stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode);
}

bool SameFile(const std::string& a, const std::string& b)
{
  struct stat first, second;
  return stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0 &&
    first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

bool IsNotRegularFile(const std::string& path)
{
  struct stat status;
  return lstat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode);
}

bool Dataset::Open(const std::string& folder, std::string& error)
{
  this->Folder = folder;
  for (const char* sub : { "off", "corres" })
  {
    if (!IsDirectory(folder + "/" + sub))
    {
      error = folder + ": not a dataset folder (no " + sub +
        "/ folder in it; expected off/NAME.off and corres/NAME.vts)";
      return false;
    }
  }
  return true;
}

std::string Dataset::MeshPath(const std::string& name) const
{
  return this->Folder + "/off/" + name + ".off";
}

std::string Dataset::SamplesPath(const std::string& name) const
{
  return this->Folder + "/corres/" + name + ".vts";
}

std::string Dataset::MirrorSamplesPath(const std::string& name) const
{
  return this->Folder + "/corres/" + name + ".sym.vts";
}

std::vector<std::string> Dataset::ShapeNames(
  const std::string& pattern, std::vector<std::string>& withoutSamples) const
{
  std::vector<std::string> names;
  withoutSamples.clear();
  DIR* directory = opendir((this->Folder + "/off").c_str());
  if (!directory)
  {
    return names;
  }
  while (const dirent* entry = readdir(directory))
  {
    const std::string file = entry->d_name;
    if (!EndsWith(file, ".off"))
    {
      continue;
    }
    const std::string name = file.substr(0, file.size() - 4);
    if (fnmatch(pattern.c_str(), name.c_str(), 0) == 0)
    {
      (IsFile(this->SamplesPath(name)) ? names : withoutSamples).push_back(name);
    }
  }
  closedir(directory);
  std::sort(names.begin(), names.end());
  std::sort(withoutSamples.begin(), withoutSamples.end());
  return names;
}

bool Dataset::Load(const std::string& name, DatasetShape& shape, std::string& error) const
{
  shape = DatasetShape();
  shape.Name = name;
  shape.MeshPath = this->MeshPath(name);
  if (!IsFile(shape.MeshPath))
  {
    error = shape.MeshPath + ": no such file (shape " + name + ")";
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh;
  if (!ReadMesh(shape.MeshPath, mesh, error))
  {
    return false;
  }
  if (!ExtractTriangleMesh(mesh, shape.Points, shape.Triangles, error))
  {
    error = shape.MeshPath + ": " + error;
    return false;
  }
  const mobius::Index vertices = shape.Points.rows();
  if (!ReadVertexSamples(this->SamplesPath(name), vertices, shape.Samples, error))
  {
    return false;
  }
  const std::string mirror = this->MirrorSamplesPath(name);
  if (IsFile(mirror))
  {
    if (!ReadVertexSamples(mirror, vertices, shape.MirrorSamples, error))
    {
      return false;
    }
    if (shape.MirrorSamples.size() != shape.Samples.size())
    {
      error = mirror + ": " + std::to_string(shape.MirrorSamples.size()) + " samples, but " +
        this->SamplesPath(name) + " has " + std::to_string(shape.Samples.size());
      return false;
    }
  }
  return true;
}

bool ReadVertexSamples(const std::string& path, mobius::Index vertexCount,
  std::vector<mobius::Index>& samples, std::string& error)
{
  samples.clear();
  std::ifstream file(path);
  if (!file)
  {
    error = path + ": cannot open the file for reading";
    return false;
  }
  std::string line;
  TextLines lines(file);
  while (lines.Next(line))
  {
    const std::vector<std::string> fields = Fields(line);
    if (fields.empty())
    {
      continue;
    }
    mobius::Index vertex = 0;
    const std::string where = path + " line " + std::to_string(lines.Number()) + ": ";
    if (fields.size() != 1 || !ParseIndex(fields[0], vertex))
    {
      error = where + "expected one vertex number (1-based), found '" + Excerpt(line) + "'";
      return false;
    }
    if (vertex < 1 || vertex > vertexCount)
    {
      error = where + "vertex " + std::to_string(vertex) + " is out of range (1-based; the mesh has " +
        std::to_string(vertexCount) + " vertices)";
      return false;
    }
    samples.push_back(vertex - 1);
  }
  if (samples.empty())
  {
    error = path + ": no samples";
    return false;
  }
  return true;
}

bool ReadPairList(const std::string& path, std::vector<ShapePair>& pairs, std::string& error)
{
  std::ifstream file(path);
  if (!file)
  {
    error = path + ": cannot open the file for reading";
    return false;
  }
  std::string line;
  TextLines lines(file);
  while (lines.Next(line))
  {
    std::vector<std::string> fields = Fields(line);
    if (fields.empty() || fields[0][0] == '#')
    {
      continue;
    }
    if (fields.size() != 2)
    {
      error = path + " line " + std::to_string(lines.Number()) +
        ": expected two shape names, X Y or X,Y; found '" + Excerpt(line) + "'";
      return false;
    }
    for (std::string& name : fields)
    {
      name = EndsWith(name, ".off") ? name.substr(0, name.size() - 4) : name;
    }
    pairs.emplace_back(fields[0], fields[1]);
  }
  return true;
}

std::vector<ShapePair> AllPairs(const std::vector<std::string>& names)
{
  std::vector<ShapePair> pairs;
  for (size_t i = 0; i < names.size(); ++i)
  {
    for (size_t j = i + 1; j < names.size(); ++j)
    {
      pairs.emplace_back(names[i], names[j]);
    }
  }
  return pairs;
}

std::vector<ShapePair> RandomPairs(
  const std::vector<std::string>& names, std::size_t count, std::uint64_t seed)
{
  const std::uint64_t n = names.size();
  const std::uint64_t total = n < 2 ? 0 : n * (n - 1) / 2;
  count = static_cast<std::size_t>(std::min<std::uint64_t>(count, total));
  // Floyd's sampling of `count` distinct pair numbers, then pair number -> (i, j), i < j.
  std::mt19937_64 generator(seed);
  std::set<std::uint64_t> chosen;
  std::vector<std::uint64_t> order;
  for (std::uint64_t j = total - count; j < total; ++j)
  {
    const std::uint64_t draw = Uniform(generator, j + 1);
    const std::uint64_t pick = chosen.count(draw) ? j : draw;
    chosen.insert(pick);
    order.push_back(pick);
  }
  std::vector<ShapePair> pairs;
  for (std::uint64_t number : order)
  {
    std::uint64_t i = 0, rowLength = n - 1;
    while (number >= rowLength)
    {
      number -= rowLength;
      ++i;
      --rowLength;
    }
    pairs.emplace_back(names[i], names[i + 1 + number]);
  }
  return pairs;
}
