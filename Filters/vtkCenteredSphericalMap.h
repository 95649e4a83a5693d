/**
 * @class   vtkCenteredSphericalMap
 * @brief   One mesh's centered spherical conformal map, as vtkMobiusRegistration makes it.
 *
 * The first stages of the registration job for one mesh (MobiusPipeline.h, MapAndCenter):
 * the repair and spherical conformal map (vtkSphericalConformalMap) and its centering
 * (vtkMobiusCenter), with the same defaults and rules as vtkMobiusRegistration. For
 * collections, which map each shape once and register the pairs from the stored maps
 * (vtkMobiusRegistration with InputsAreCenteredMaps on).
 *
 * Output: the centered map (vtkMobiusCenter's output: the map's field data and the
 * centering's). Errors: a mesh that cannot be mapped (named by MeshName), a degenerate
 * conformal map unless AllowPoorMaps.
 *
 * @sa vtkMobiusRegistration vtkSphericalConformalMap vtkMobiusCenter
 */
#ifndef vtkCenteredSphericalMap_h
#define vtkCenteredSphericalMap_h

#include "vtkMobiusPolyDataAlgorithm.h"
#include "vtkMobiusRegistrationFiltersModule.h" // For export macro

#include <string> // For the name

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkCenteredSphericalMap
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkCenteredSphericalMap* New();
  vtkTypeMacro(vtkCenteredSphericalMap, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Name of the mesh in messages (default "Mesh"), e.g. its file. */
  void SetMeshName(const char* name);
  const char* GetMeshName() const { return this->MeshName.c_str(); }

  /**
   * The meshes' repair (vtkSphericalConformalMap): Repair (default on) builds a genus-0
   * proxy of a mesh that is none; with it off, FillHoles and KeepLargestComponent repair
   * on request.
   */
  vtkSetMacro(Repair, bool);
  vtkGetMacro(Repair, bool);
  vtkBooleanMacro(Repair, bool);
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  vtkSetMacro(KeepLargestComponent, bool);
  vtkGetMacro(KeepLargestComponent, bool);
  vtkBooleanMacro(KeepLargestComponent, bool);

  /** Go on with a degenerate conformal map (DegenerateMap) instead of failing. */
  vtkSetMacro(AllowPoorMaps, bool);
  vtkGetMacro(AllowPoorMaps, bool);
  vtkBooleanMacro(AllowPoorMaps, bool);

  /** Conformal map: flow steps, convergence tolerance, centering between steps. */
  vtkSetMacro(MaximumNumberOfIterations, int);
  vtkGetMacro(MaximumNumberOfIterations, int);
  vtkSetMacro(ConvergenceTolerance, double);
  vtkGetMacro(ConvergenceTolerance, double);
  vtkSetMacro(CenterBetweenSteps, bool);
  vtkGetMacro(CenterBetweenSteps, bool);
  vtkBooleanMacro(CenterBetweenSteps, bool);

  /** Centering degree: 1 the Möbius centering, 2..8 generalized (vtkMobiusCenter). */
  vtkSetMacro(CenteringDegree, int);
  vtkGetMacro(CenteringDegree, int);

protected:
  vtkCenteredSphericalMap();
  ~vtkCenteredSphericalMap() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCenteredSphericalMap(const vtkCenteredSphericalMap&) = delete;
  void operator=(const vtkCenteredSphericalMap&) = delete;

  std::string MeshName = "Mesh";
  bool Repair;
  bool FillHoles;
  bool KeepLargestComponent;
  bool AllowPoorMaps;
  int MaximumNumberOfIterations;
  double ConvergenceTolerance;
  bool CenterBetweenSteps;
  int CenteringDegree;
};

#endif
