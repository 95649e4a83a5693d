/**
 * @class   vtkMobiusLandmarkPolyDataAlgorithm
 * @brief   A two-input filter of the module that keeps landmarks: pairs of a source point
 *          and the target point it must go to.
 *
 * The list is the same for every such filter; what a landmark's numbers name is the
 * filter's to say: vtkMobiusRegistration takes the meshes' vertex numbers, the stage filters
 * (vtkSO3Register, vtkCorrespondenceRefinement) the point ids of their input maps.
 */
#ifndef vtkMobiusLandmarkPolyDataAlgorithm_h
#define vtkMobiusLandmarkPolyDataAlgorithm_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusThreadedPolyDataAlgorithm.h"

#include <string>  // For SettingsError
#include <utility> // For the landmarks
#include <vector>  // For the landmarks

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkMobiusLandmarkPolyDataAlgorithm
  : public vtkMobiusThreadedPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMobiusLandmarkPolyDataAlgorithm, vtkMobiusThreadedPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Landmarks: the source's point `sourceVertex` goes to the target's point `targetVertex`
   * (0-based ids, see the filter for what they number). None by default.
   */
  void AddLandmark(vtkIdType sourceVertex, vtkIdType targetVertex);
  void RemoveAllLandmarks();
  /**
   * The landmarks as one list of values, source and target vertex in turn (ParaView's
   * Landmarks property): each second value completes a landmark. A list of odd length is the
   * filter's error when it runs (the last value has no partner), not dropped.
   */
  void AddLandmarkValue(vtkIdType value);
  vtkIdType GetNumberOfLandmarks();
  /** The source and target vertex of landmark `landmark` (-1 if there is no such landmark). */
  vtkIdType GetLandmarkSourceVertex(vtkIdType landmark);
  vtkIdType GetLandmarkTargetVertex(vtkIdType landmark);
  ///@}

protected:
  vtkMobiusLandmarkPolyDataAlgorithm() = default;
  ~vtkMobiusLandmarkPolyDataAlgorithm() override = default;

  std::vector<std::pair<vtkIdType, vtkIdType>> Landmarks;
  /// AddLandmarkValue's value still waiting for its partner.
  bool HasUnpairedValue = false;
  vtkIdType UnpairedValue = 0;

  std::string SettingsError() override;

private:
  vtkMobiusLandmarkPolyDataAlgorithm(const vtkMobiusLandmarkPolyDataAlgorithm&) = delete;
  void operator=(const vtkMobiusLandmarkPolyDataAlgorithm&) = delete;
};

#endif
