/**
 * @class   vtkSphericalScaleGrid
 * @brief   Conformal scale factors of a spherical map on an equirectangular grid.
 *
 * The signal that rotational alignment correlates (Möbius Registration, Section 6.2 and
 * Figure 6). Each triangle's original-surface area (cell array `SurfaceArea`) is split
 * exactly among the cells of an N x N equirectangular grid that its spherical image
 * covers; a cell's value is that area divided by the cell's spherical area: the mean
 * conformal factor lambda over the cell (or its square root, see ValueMode). Samples
 * belong to cell centers, theta = pi (j + 1/2) / N, phi = 2 pi (i + 1/2) / N. The grid is
 * then expanded in spherical harmonics (bandwidth B = N / 2, our own transform with
 * Driscoll-Healy-type quadrature) and low-passed with the heat kernel exp(-t l(l+1)).
 *
 * Input: a spherical map (points on the unit sphere within 1e-6, triangles, cell array
 * `SurfaceArea`), normally Möbius-centered by vtkMobiusCenter.
 *
 * Output: a sphere of N x N cells (rows from the north pole, triangles at the poles, quads
 * elsewhere; cell j*N + i is grid cell (j, i)) with cell data `ConformalFactor` (the cell
 * values) and `ConformalFactorSmoothed` (the low-passed signal at the cell centers), and
 * field data `Resolution`, `Bandwidth`, `TotalArea` (the surface area, equal to the sum of
 * lambda times cell area), `SmoothingTime`, `ValueMode` (0: lambda, 1: sqrt(lambda)),
 * `NumberOfThreadsUsed` and
 * `DegreeEnergies` (B values: the smoothed signal's energy in each spherical-harmonic
 * degree l, the sum over m of |f_lm|^2; unchanged by rotating or mirroring the map, so
 * shapes can be compared by it before any alignment). With
 * DisplaceByValue each point is moved radially to |smoothed value| / max |smoothed value|
 * (the corner value being the mean of the adjacent cells), the picture of Figure 6.
 *
 * Errors: input not a spherical map (or with a triangle referring to a point id out of
 * range), missing or invalid `SurfaceArea`, Resolution odd or below 4, running out of
 * memory.
 *
 * @sa vtkMobiusCenter vtkSO3Register
 */
#ifndef vtkSphericalScaleGrid_h
#define vtkSphericalScaleGrid_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusThreadedPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSphericalScaleGrid
  : public vtkMobiusThreadedPolyDataAlgorithm
{
public:
  static vtkSphericalScaleGrid* New();
  vtkTypeMacro(vtkSphericalScaleGrid, vtkMobiusThreadedPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ValueModes
  {
    AREA_RATIO = 0,
    SQUARE_ROOT_AREA_RATIO = 1
  };

  ///@{
  /**
   * Grid size N: N x N cells, bandwidth N / 2. Must be even and at least 4. Default 256.
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Heat-kernel time t of the low pass exp(-t l(l+1)); 0 turns smoothing off.
   * Default 5e-4.
   */
  vtkSetClampMacro(SmoothingTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SmoothingTime, double);
  ///@}

  ///@{
  /**
   * What a cell holds: the area ratio lambda (AREA_RATIO) or sqrt(lambda)
   * (SQUARE_ROOT_AREA_RATIO, the default). With sqrt(lambda) the signal's squared L2 norm
   * is the surface area, and the huge ratios of squeezed limbs weigh less in the
   * correlation. Measured with vtkSO3Register at N = 256: a rotated copy of a real map
   * comes back within 0.008 / 0.19 / 0.22 / 0.07 degrees (hand, camel, man, armadillo;
   * worst of 4 rotations) with sqrt(lambda) against 0.06 / 0.50 / 0.76 / 0.26 degrees with
   * lambda, and on the SMPL man -> woman pair 51% of the vertices land within
   * 0.1 sqrt(area) of their counterpart against 37%.
   */
  vtkSetClampMacro(ValueMode, int, AREA_RATIO, SQUARE_ROOT_AREA_RATIO);
  vtkGetMacro(ValueMode, int);
  void SetValueModeToAreaRatio() { this->SetValueMode(AREA_RATIO); }
  void SetValueModeToSquareRootAreaRatio() { this->SetValueMode(SQUARE_ROOT_AREA_RATIO); }
  ///@}

  ///@{
  /**
   * Move each grid point radially by the smoothed value (normalized to a maximum radius
   * of 1), as in the paper's Figure 6. Default off.
   */
  vtkSetMacro(DisplaceByValue, vtkTypeBool);
  vtkGetMacro(DisplaceByValue, vtkTypeBool);
  vtkBooleanMacro(DisplaceByValue, vtkTypeBool);
  ///@}

protected:
  vtkSphericalScaleGrid();
  ~vtkSphericalScaleGrid() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution = 256;
  double SmoothingTime = 5e-4;
  int ValueMode = SQUARE_ROOT_AREA_RATIO;
  vtkTypeBool DisplaceByValue = false;

private:
  vtkSphericalScaleGrid(const vtkSphericalScaleGrid&) = delete;
  void operator=(const vtkSphericalScaleGrid&) = delete;
};

#endif
