/**
 * @class   vtkSurfaceMeshReader
 * @brief   Reads a surface mesh from OBJ, OFF, PLY, STL, VTP or legacy VTK, by extension.
 *
 * One reader for the formats geometry-processing users keep their meshes in. PLY, STL,
 * VTP and legacy .vtk go through VTK's own readers, whose cells are then checked to refer
 * only to existing points (VTK's readers do not check). OFF (with optional COFF/NOFF
 * header variants, comments and per-element colors, which are skipped) is parsed here
 * since VTK has no OFF reader, and so is OBJ (positions and faces; texture coordinates,
 * normals, groups and materials are skipped), since VTK's OBJ reader renumbers the points
 * of files with texture coordinates or normals and does not check indices or coordinates.
 *
 * Output point i is the file's vertex i (for OBJ, the i-th `v` line), also for vertices
 * no face uses. Polygons are kept as they are (vtkSphericalConformalMap triangulates them).
 * An unreadable, empty or malformed file (including a face index out of range and, for
 * OBJ, a NaN or infinite coordinate) is an error that names the file and the reason, and
 * the output is left empty.
 */
#ifndef vtkSurfaceMeshReader_h
#define vtkSurfaceMeshReader_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusPolyDataAlgorithm.h"

#include <string>

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSurfaceMeshReader
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkSurfaceMeshReader* New();
  vtkTypeMacro(vtkSurfaceMeshReader, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read; its extension (case-insensitive) picks the format:
   * .obj, .off, .ply, .stl, .vtp, .vtk.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * True if the extension of `fileName` is one this reader handles.
   */
  static bool IsSupportedFile(const char* fileName);

protected:
  vtkSurfaceMeshReader();
  ~vtkSurfaceMeshReader() override;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // An exception's message names the file.
  std::string ExceptionSubject() override { return this->FileName ? this->FileName : ""; }

  char* FileName = nullptr;

private:
  vtkSurfaceMeshReader(const vtkSurfaceMeshReader&) = delete;
  void operator=(const vtkSurfaceMeshReader&) = delete;
};

#endif
