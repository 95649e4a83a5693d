// The files mobius-register writes. Everything is written to temporary files first
// (SafeOutputFile) and moved into place only when the whole job has succeeded
// (PublishOutputs), so a failure, a full disk or a signal leaves no partial output behind;
// existing files are never replaced without --force, not even those that appear while the
// program runs.
#ifndef OutputFiles_h
#define OutputFiles_h

#include "SafeOutputFile.h"

#include "vtkPolyData.h"

#include <memory>
#include <string>
#include <vector>

class OutputFiles
{
public:
  /// Decides the paths from -o (a prefix, or a .vtp path) and --png; fails if -o names a
  /// folder rather than files in it, if a file exists and `force` is off, if the folder
  /// does not exist, or if an output would replace one of `inputs` (never allowed, even
  /// with `force`). `writesCsv` false: a job without the CSV (--orbifold) plans none.
  bool Plan(const std::string& output, const std::string& picture, bool force,
    const std::vector<std::string>& inputs, std::string& error, bool writesCsv = true);

  /// The correspondence output as VTP (inline binary: Debian bookworm's expat cannot read
  /// VTK 9.2's appended data back).
  bool WriteMesh(vtkPolyData* correspondence, std::string& error);
  /// Per source vertex: target triangle, its three vertices, barycentric coordinates and
  /// the mapped position. Vertices are numbered as in the mesh files (InputPointId,
  /// TargetInputPointIds); -1 is a vertex --fill-holes created.
  bool WriteCsv(vtkPolyData* correspondence, std::string& error);
  /// The picture, rendered in memory by RenderCorrespondencePicture.
  bool WritePicture(vtkPolyData* alignedSource, vtkPolyData* targetMap,
    vtkPolyData* correspondence, std::string& error);

  /// Moves the finished files into place, all of them or none.
  bool Commit(std::string& error);

  std::string MeshPath, CsvPath, PicturePath;

private:
  /// A finished temporary file holding `bytes`, ready for Commit.
  bool WriteFile(const std::string& path, const std::string& bytes, std::string& error);

  bool Force = false;
  std::vector<std::unique_ptr<SafeOutputFile>> Written;
};

#endif
