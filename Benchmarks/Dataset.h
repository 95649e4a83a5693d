// A shape-correspondence benchmark folder laid out as FAUST_r, SCAPE_r, SHREC'19_r, TOSCA and
// DT4D-H are distributed: off/NAME.off (the mesh), corres/NAME.vts (line k: the 1-based
// vertex of NAME that stands for reference sample k) and, where the dataset has it,
// corres/NAME.sym.vts (the same for the left-right mirrored samples). Pair lists: read from
// a file, all pairs, or random pairs.
#ifndef Dataset_h
#define Dataset_h

#include "MeshTypes.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

struct DatasetShape
{
  std::string Name;
  std::string MeshPath;
  mobius::Points Points;
  mobius::Triangles Triangles;
  /// 0-based vertex of each reference sample (from NAME.vts).
  std::vector<mobius::Index> Samples;
  /// The mirror ground truth (NAME.sym.vts); empty when the dataset has none.
  std::vector<mobius::Index> MirrorSamples;
};

using ShapePair = std::pair<std::string, std::string>;

class Dataset
{
public:
  /// Fails unless `folder` holds off/ and corres/.
  bool Open(const std::string& folder, std::string& error);

  /// Names that have both off/NAME.off and corres/NAME.vts and match the shell pattern
  /// (fnmatch: * ? [...]), sorted; `withoutSamples` gets those that match but have no .vts.
  std::vector<std::string> ShapeNames(
    const std::string& pattern, std::vector<std::string>& withoutSamples) const;

  /// Reads NAME's mesh and sample files and checks them (every vertex in range, as many
  /// mirror samples as samples).
  bool Load(const std::string& name, DatasetShape& shape, std::string& error) const;

  std::string MeshPath(const std::string& name) const;
  std::string SamplesPath(const std::string& name) const;
  std::string MirrorSamplesPath(const std::string& name) const;

private:
  std::string Folder;
};

bool IsDirectory(const std::string& path);

/// Whether both paths name one existing file (links followed).
bool SameFile(const std::string& a, const std::string& b);

/// Whether something that is not a regular file (a symbolic link, a device, a folder) is at
/// `path`: a file the program names itself is never written through it.
bool IsNotRegularFile(const std::string& path);

/// Reads a .vts file: one 1-based vertex number per line (blank lines skipped), each in
/// 1..vertexCount; returns the 0-based vertices.
bool ReadVertexSamples(const std::string& path, mobius::Index vertexCount,
  std::vector<mobius::Index>& samples, std::string& error);

/// Reads pairs "X Y" or "X,Y", one per line; blank lines and lines starting with # are
/// skipped; a trailing ".off" on a name is dropped.
bool ReadPairList(const std::string& path, std::vector<ShapePair>& pairs, std::string& error);

/// Every pair (names[i], names[j]) with i < j, in order.
std::vector<ShapePair> AllPairs(const std::vector<std::string>& names);

/// `count` distinct pairs drawn at random from AllPairs(names), the same for the same seed
/// on every platform (std::mt19937_64 with rejection sampling), in the order drawn.
std::vector<ShapePair> RandomPairs(
  const std::vector<std::string>& names, std::size_t count, std::uint64_t seed);

#endif
