/**
 * @class   vtkMobiusCenter
 * @brief   Canonical Möbius centering of a spherical map (Algorithm 1 of Möbius Registration).
 *
 * A conformal map of a genus-0 surface onto the sphere is unique only up to Möbius
 * transformations. vtkMobiusCenter removes the non-rotational part: it applies the
 * inversions eta_c(v) = (1-|c|^2)(v+c)/|v+c|^2 + c that move the area-weighted center of
 * mass mu = sum_t A(t) C(t) to the origin (C(t): the normalized centroid of spherical
 * triangle t; A(t): its original-surface area from cell array `SurfaceArea`, normalized to
 * sum 1). The result is unique up to a rotation. Each step is Gauss-Newton, c = -J^-1 mu
 * with J = 2 sum_t A(t)(I - C C^T), followed by a line search that keeps |c| < 1 and makes
 * |mu| decrease, so it converges on hard inputs too (typically in 3-7 steps).
 *
 * Input: a spherical map, i.e. a vtkPolyData of triangles with every point on the unit
 * sphere (radius within 1e-6 of 1) and the cell array `SurfaceArea` (finite, not negative,
 * not all 0), as made by vtkSphericalConformalMap. An input with no polygons is treated as a
 * point set on the sphere with unit weights (mu is then the mean of the points).
 *
 * Output: the input with its points moved by the centering transformation; connectivity and
 * every point, cell and field array are passed through. Cell data recomputed for the centered
 * map when the input has `SurfacePoints`: `LogAreaRatio` (the active cell scalars: ParaView's
 * default coloring) and `QuasiConformalDistortion` (mobius::vtk::AddDistortionArrays).
 * Field data added:
 * - `CenterOfMassNorm` (1 double): |mu| after centering;
 * - `InitialCenterOfMassNorm` (1 double): |mu| of the input;
 * - `CenteringIterations` (1 double): number of inversions applied;
 * - `MobiusTransform` (16 doubles, one tuple): the composed transformation as a 4x4
 *   row-major Lorentz matrix L acting on the light cone: for a point x on the sphere,
 *   [X, W] = L [x, 1] and the centered point is X / W. Apply it to any other point of the
 *   input sphere to move it the same way; L is a proper Lorentz matrix (det 1), so the
 *   inverse transformation is diag(1,1,1,-1) L^T diag(1,1,1,-1).
 * - `InversionCenters` (k tuples of 3 doubles): the centers c of the inversions, in order.
 *
 * Generalized centering (paper Sections 5 and 6.1): with Degree L > 1 the Möbius-centered
 * map is then advected along gradients of spherical harmonics until the area has no
 * component along the harmonics of degree 1 to L. The map is no longer conformal but its
 * area is spread more evenly (the paper's Figure 5); no triangle is allowed to flip.
 * `CenterOfMassNorm` is then the norm of all those moments, `GeneralizedCenteringIterations`
 * counts the advection steps, and `MobiusTransform` / `InversionCenters` describe only the
 * Möbius part.
 *
 * Errors (vtkErrorMacro, no output): empty input, NaN/Inf coordinates, points off the unit
 * sphere, lines/strips/non-triangle polygons, triangles referring to a point id out of
 * range, missing or invalid `SurfaceArea`, running out of memory. If the
 * tolerance is not reached within MaximumNumberOfIterations the result is still produced
 * and a warning gives the |mu| reached.
 *
 * Reference: A. Baden, K. Crane, M. Kazhdan, "Möbius Registration", Computer Graphics
 * Forum 37(5), SGP 2018, Section 4 and Algorithm 1.
 *
 * @sa vtkSphericalConformalMap
 */
#ifndef vtkMobiusCenter_h
#define vtkMobiusCenter_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkMobiusCenter
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkMobiusCenter* New();
  vtkTypeMacro(vtkMobiusCenter, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Stop when the area-weighted center of mass |mu| (weights summing to 1) is at most
   * this. Default 1e-10.
   */
  vtkSetClampMacro(Tolerance, double, 0.0, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Upper bound on the number of Gauss-Newton inversions. Default 100.
   */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /**
   * Highest spherical-harmonic degree centered against: 1 (default) is the Möbius
   * centering; 2 to 8 add the generalized centering. Needs triangles when above 1.
   */
  vtkSetClampMacro(Degree, int, 1, 8);
  vtkGetMacro(Degree, int);
  ///@}

  ///@{
  /**
   * Generalized centering (Degree > 1) has its own stopping rule, since its advection steps
   * converge differently from the Möbius inversions: stop when the norm of all moments of
   * degree 1 to Degree is at most GeneralizedTolerance (default 1e-10), or after
   * GeneralizedMaximumNumberOfIterations advection steps (default 200; each step moves no
   * vertex by more than 0.05 radians, so a strongly off-center map needs many).
   */
  vtkSetClampMacro(GeneralizedTolerance, double, 0.0, 1.0);
  vtkGetMacro(GeneralizedTolerance, double);
  vtkSetClampMacro(GeneralizedMaximumNumberOfIterations, int, 1, VTK_INT_MAX);
  vtkGetMacro(GeneralizedMaximumNumberOfIterations, int);
  ///@}

protected:
  vtkMobiusCenter();
  ~vtkMobiusCenter() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  double Tolerance;
  int MaximumNumberOfIterations = 100;
  int Degree;
  double GeneralizedTolerance;
  int GeneralizedMaximumNumberOfIterations = 200;

private:
  vtkMobiusCenter(const vtkMobiusCenter&) = delete;
  void operator=(const vtkMobiusCenter&) = delete;
};

#endif
