// The files mobius-register writes. Everything is written to temporary files first and
// renamed into place only when the whole job has succeeded, so a failure leaves no partial
// output behind; existing files are never replaced without --force.
#ifndef OutputFiles_h
#define OutputFiles_h

#include "vtkPolyData.h"

#include <string>
#include <vector>

class OutputFiles
{
public:
  ~OutputFiles();

  /// Decides the paths from -o (a prefix, or a .vtp path) and --png; fails if a file
  /// exists and `force` is off, if the folder does not exist, or if an output would
  /// replace one of `inputs` (never allowed, even with `force`).
  bool Plan(const std::string& output, const std::string& picture, bool force,
    const std::vector<std::string>& inputs, std::string& error);

  /// The correspondence output as VTP (inline binary: Debian bookworm's expat cannot read
  /// VTK 9.2's appended data back).
  bool WriteMesh(vtkPolyData* correspondence, std::string& error);
  /// Per source vertex: target triangle, its three vertices, barycentric coordinates and
  /// the mapped position. Vertices are numbered as in the mesh files (InputPointId,
  /// TargetInputPointIds); -1 is a vertex --fill-holes created.
  bool WriteCsv(vtkPolyData* correspondence, std::string& error);
  /// The picture, rendered by RenderCorrespondencePicture into a temporary file.
  bool WritePicture(vtkPolyData* alignedSource, vtkPolyData* correspondence, std::string& error);

  /// Moves the temporary files into place.
  bool Commit(std::string& error);

  std::string MeshPath, CsvPath, PicturePath;

private:
  std::string Temporary(const std::string& path) const;
  std::vector<std::string> Written; // final paths whose temporary file exists
};

#endif
