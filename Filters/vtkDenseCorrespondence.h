/**
 * @class   vtkDenseCorrespondence
 * @brief   Dense point-to-point map between two registered surfaces, and data transfer.
 *
 * The last stage of Möbius Registration (Section 7.4). Every vertex of the Source spherical
 * map (already aligned with the target by vtkSO3Register) is located in the Target's
 * spherical triangulation: the containing triangle and the projective barycentric
 * coordinates of the point in it (alpha a + beta b + gamma c, normalized, is the point).
 * The same combination of the target triangle's `SurfacePoints` is the corresponding point
 * on the target surface, and of its point arrays the transferred data.
 *
 * Point location uses a hierarchy of spherical caps built once per target; points on
 * edges, vertices, poles and the azimuth seam are found, and a point that floating point
 * puts in no triangle (or that falls in a hole) takes the nearest point of the nearest
 * triangle; the field-data count `ClampedPoints` says how many did.
 *
 * Inputs: port 0 `Source` (the aligned source map), port 1 `Target` (the target's
 * centered map); both spherical maps with point array `SurfacePoints`.
 *
 * Direction: SOURCE_TO_TARGET (default) maps the source's vertices onto the target;
 * TARGET_TO_SOURCE maps the target's vertices onto the source (the inverse map), and then
 * "target" below means the source. Run the filter twice to get both directions.
 *
 * Output (`OutputGeometry`): TARGET (default) is the source's connectivity with each point
 * at its corresponding position on the target surface (the paper's Figure 10); SOURCE is
 * the source surface itself (its `SurfacePoints`). Point data: every array of the source
 * passed through; `MappedPoints` (3 doubles, the corresponding target-surface positions);
 * `TargetCellId` (id type); `TargetBarycentric` (3 doubles); `TargetInputPointIds` (3 ids,
 * when the target has vtkSphericalConformalMap's `InputPointId`: the target triangle's
 * vertices in the target's input, i.e. file, numbering); every target point array
 * transferred: floating-point arrays interpolated with the barycentric coordinates,
 * integer, string and other arrays (categorical data) take the value of the nearest target
 * vertex. A transferred array whose name the source already uses is renamed
 * `<name>_Target`: the source's `InputPointId` (its input vertex numbers) passes through,
 * and `InputPointId_Target` (always so named) is the input number of the nearest target
 * vertex. Field data: `ClampedPoints`, `MaximumClampDistance` (radians),
 * `NumberOfThreadsUsed`, and the source's field data.
 *
 * Landmarks (AddLandmark, point ids of the two input maps): each source landmark is placed
 * on its target landmark's vertex itself (with TARGET_TO_SOURCE, each target landmark on its
 * source vertex); the other points as located.
 *
 * Errors: an input missing, empty, not on the unit sphere or without `SurfacePoints`, or
 * with a triangle that refers to a point id out of range; a landmark naming a point an
 * input does not have.
 *
 * @sa vtkSO3Register
 */
#ifndef vtkDenseCorrespondence_h
#define vtkDenseCorrespondence_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkDenseCorrespondence
  : public vtkMobiusLandmarkPolyDataAlgorithm
{
public:
  static vtkDenseCorrespondence* New();
  vtkTypeMacro(vtkDenseCorrespondence, vtkMobiusLandmarkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OutputGeometries
  {
    TARGET = 0,
    SOURCE = 1
  };
  enum Directions
  {
    SOURCE_TO_TARGET = 0,
    TARGET_TO_SOURCE = 1
  };

  ///@{
  /**
   * The target map (port 1); the source is the input of port 0.
   */
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSourceData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetTargetData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

  ///@{
  /**
   * Where the output's points are: on the target surface (TARGET, default) or on the
   * source surface (SOURCE), carrying the transferred arrays.
   */
  vtkSetClampMacro(OutputGeometry, int, TARGET, SOURCE);
  vtkGetMacro(OutputGeometry, int);
  void SetOutputGeometryToTarget() { this->SetOutputGeometry(TARGET); }
  void SetOutputGeometryToSource() { this->SetOutputGeometry(SOURCE); }
  ///@}

  ///@{
  /**
   * SOURCE_TO_TARGET (default) or TARGET_TO_SOURCE (the inverse map).
   */
  vtkSetClampMacro(Direction, int, SOURCE_TO_TARGET, TARGET_TO_SOURCE);
  vtkGetMacro(Direction, int);
  void SetDirectionToSourceToTarget() { this->SetDirection(SOURCE_TO_TARGET); }
  void SetDirectionToTargetToSource() { this->SetDirection(TARGET_TO_SOURCE); }
  ///@}

protected:
  vtkDenseCorrespondence();
  ~vtkDenseCorrespondence() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  int OutputGeometry;
  int Direction = SOURCE_TO_TARGET;

private:
  vtkDenseCorrespondence(const vtkDenseCorrespondence&) = delete;
  void operator=(const vtkDenseCorrespondence&) = delete;
};

#endif
