/**
 * @class   vtkSO3Register
 * @brief   The rotation (or reflection) that best aligns two centered spherical maps.
 *
 * Rotational alignment of Möbius Registration (Section 6.2). Both inputs are sampled as in
 * vtkSphericalScaleGrid (exact area rasterization onto an N x N cell-centered grid, our own
 * spherical harmonic transform, heat-kernel low pass), and the correlation
 * C(T) = integral of f(T^-1 x) g(x) over the sphere of the source's signal f with the
 * target's g is maximized over orthogonal transformations T: on a grid of Euler angles
 * (an FFT over SO(3) of the coefficient products, through the factorization of Wigner's d
 * by d(pi/2)), then refined below grid resolution by Newton's method on the band-limited
 * C. The best few well-separated peaks are kept: near-symmetric shapes have several.
 *
 * Inputs: port 0 `Source` and port 1 `Target`, centered spherical maps (points on the unit
 * sphere, triangles, cell array `SurfaceArea`), e.g. outputs of vtkMobiusCenter.
 *
 * Output: the source map with every point x moved to T x; connectivity and all arrays pass
 * through. (With a reflection, det T = -1, the output's triangles face inward.) Field data:
 * - `Rotation` (9 doubles, row-major 3x3 T, x' = T x; named for the common case, it is a
 *   reflection when `Determinant` is -1);
 * - `Determinant` (+1 or -1);
 * - `EulerAngles` (3 doubles, ZYZ (alpha, beta, gamma) in radians of the rotation part R,
 *   R = Rz(alpha) Ry(beta) Rz(gamma); T = R for rotations, T = -R for reflections);
 * - `CorrelationScore` C(T) and `RegistrationError` (|f|^2 + |g|^2 - 2 C(T)) / (|f|^2 + |g|^2),
 *   0 for a perfect match;
 * - `CorrelationCoefficient`: the correlation coefficient (Pearson, over the sphere) of
 *   f(T^-1 x) with g(x), in [-1, 1]; the signals' means and sizes do not count
 *   (vtkSymmetryDetection's symmetry distance is made of it);
 * - `CandidateTransforms` (K tuples of 9), `CandidateScores`, `CandidateRegistrationErrors`,
 *   `CandidateCorrelationCoefficients` (K tuples each), best first;
 * - `Resolution`, `CorrelationBandwidth` (the bands used by the grid search);
 * - `NumberOfThreadsUsed`;
 * - with landmarks, `CandidateLandmarkAngles` (per candidate, the root mean square angle in
 *   radians between the landmarks' source points moved by it and their target points).
 *
 * Landmarks (AddLandmark, point ids of the two input maps): with LandmarkMode 0 (default)
 * the candidates are put in the order of their landmark angles, the best first, and from 3
 * landmarks on the landmarks' best-fit transform (of the kinds TransformMode allows, by
 * orthogonal Procrustes) is a candidate too: 3 landmarks tell a symmetric shape from its
 * mirror image or its half-turned copy, which correlate equally well. With LandmarkMode 1
 * the source map is moved by the Möbius transformation that sends the first 3 landmarks
 * exactly onto their targets (after a reflection with TransformMode REFLECTIONS, or with
 * ROTATIONS_AND_REFLECTIONS when the 3 go round the other way on the target); `Rotation` and
 * the only candidate are then the identity (or the reflection y -> -y).
 *
 * Errors: an input that is not a spherical map (or has a triangle referring to a point id
 * out of range), missing or invalid `SurfaceArea`, Resolution odd or below 4, a Resolution
 * whose estimated memory (EstimateMemory) exceeds the machine's, running out of memory.
 *
 * @sa vtkSphericalScaleGrid vtkDenseCorrespondence
 */
#ifndef vtkSO3Register_h
#define vtkSO3Register_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSO3Register
  : public vtkMobiusLandmarkPolyDataAlgorithm
{
public:
  static vtkSO3Register* New();
  vtkTypeMacro(vtkSO3Register, vtkMobiusLandmarkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum TransformModes
  {
    ROTATIONS = 0,
    REFLECTIONS = 1,
    ROTATIONS_AND_REFLECTIONS = 2
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
   * Grid size N of the scale-factor signals (even, >= 4); bandwidth N / 2. Default 256.
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  /**
   * Estimated peak memory in bytes of a registration at `resolution`: the two meshes'
   * scale-factor grids, their transforms and the correlation grow as N^2; the estimate,
   * 160 bytes per cell and 50 MB, is about twice what a registration was measured to use,
   * so it errs on the safe side. RequestData refuses a Resolution whose estimate exceeds
   * the machine's physical memory, instead of failing part way through the allocations.
   */
  static double EstimateMemory(int resolution);

  /**
   * The largest even Resolution whose EstimateMemory fits in `bytes` (by default, 0, the
   * machine's physical memory).
   */
  static int LargestResolution(double bytes = 0);

  ///@{
  /**
   * Heat-kernel time of the low pass; 0 disables it. Default 5e-4.
   */
  vtkSetClampMacro(SmoothingTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SmoothingTime, double);
  ///@}

  ///@{
  /**
   * What the signals hold, as in vtkSphericalScaleGrid: 0 lambda, 1 sqrt(lambda)
   * (default).
   */
  vtkSetClampMacro(ValueMode, int, 0, 1);
  vtkGetMacro(ValueMode, int);
  ///@}

  ///@{
  /**
   * Which transformations to search: ROTATIONS (default), REFLECTIONS (det -1: mirror
   * images, bilateral symmetry) or ROTATIONS_AND_REFLECTIONS (the better of the two).
   */
  vtkSetClampMacro(TransformMode, int, ROTATIONS, ROTATIONS_AND_REFLECTIONS);
  vtkGetMacro(TransformMode, int);
  void SetTransformModeToRotations() { this->SetTransformMode(ROTATIONS); }
  void SetTransformModeToReflections() { this->SetTransformMode(REFLECTIONS); }
  void SetTransformModeToRotationsAndReflections()
  {
    this->SetTransformMode(ROTATIONS_AND_REFLECTIONS);
  }
  ///@}

  ///@{
  /**
   * How many well-separated correlation peaks to report (best first). Default 4.
   */
  vtkSetClampMacro(NumberOfCandidates, int, 1, 64);
  vtkGetMacro(NumberOfCandidates, int);
  ///@}

  ///@{
  /**
   * Smallest angle (degrees) between two candidates of the same determinant: peaks closer
   * to a better one are not reported. Default 60: a correlation peak has neighbours 10-45
   * degrees away that refine to the same map, while a shape's ambiguities (a body turned
   * half a turn, or upside down) are far apart.
   */
  vtkSetClampMacro(CandidateSeparation, double, 0.0, 180.0);
  vtkGetMacro(CandidateSeparation, double);
  ///@}

  ///@{
  /**
   * With TransformMode ROTATIONS or REFLECTIONS, also find the best transform of the other
   * kind by a cheap coarse search (`MirrorCheckErrors` in the field data),
   * and warn when it aligns the shapes far better: a mirrored pair registered by rotations
   * (or the same way round by reflections) gives a wrong map otherwise without a word. On by
   * default; off for a mesh registered with itself on purpose (symmetry detection).
   */
  vtkSetMacro(CheckMirroring, bool);
  vtkGetMacro(CheckMirroring, bool);
  vtkBooleanMacro(CheckMirroring, bool);
  ///@}

  ///@{
  /**
   * What the landmarks do (see the class description): 0 (default) order the candidates by
   * them, 1 fit a Möbius transformation to the first 3 (an error with fewer).
   */
  vtkSetClampMacro(LandmarkMode, int, 0, 1);
  vtkGetMacro(LandmarkMode, int);
  ///@}

protected:
  vtkSO3Register();
  ~vtkSO3Register() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  int Resolution;
  double SmoothingTime;
  int ValueMode = 1;
  int TransformMode;
  int NumberOfCandidates;
  double CandidateSeparation;
  bool CheckMirroring = true;
  int LandmarkMode;

private:
  vtkSO3Register(const vtkSO3Register&) = delete;
  void operator=(const vtkSO3Register&) = delete;
};

#endif
