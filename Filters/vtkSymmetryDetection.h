/**
 * @class   vtkSymmetryDetection
 * @brief   Non-rigid bilateral symmetry of a genus-0 surface: its symmetry distance and
 *          symmetric (mirror) map (Möbius Registration, Section 7.3).
 *
 * A bilaterally symmetric shape, even bent non-rigidly, has an orientation-reversing map
 * onto itself that is close to an isometry. Centering makes the spherical map of a
 * symmetric surface symmetric (the paper, Section 7.3), so the mirror map is found as the
 * best orientation-reversing self-registration of the centered map: vtkMobiusCenter, then
 * vtkSO3Register with the map on both ports and only reflections (det T = -1), then the
 * dense map of the surface onto itself, refined by vtkCorrespondenceRefinement (default) or
 * read off the sphere by vtkDenseCorrespondence (the paper's map, `Refine` off).
 *
 * Input: a closed genus-0 triangle mesh, mapped to the sphere and centered here by the
 * pipeline's one-mesh stages (MapAndCenter, MobiusPipeline.h) with their defaults (the flow
 * from the surface; centering between flow steps only when `Centering` is on); or a
 * spherical map already made by vtkSphericalConformalMap (points on the unit
 * sphere with `SurfacePoints` and `SurfaceArea`), to choose the flow's settings.
 *
 * Output: the surface (points at `SurfacePoints`, the input's connectivity) with the
 * symmetric map m as point arrays, named as vtkDenseCorrespondence names a map (here of
 * the surface onto itself):
 * - `TargetCellId`, `TargetBarycentric`: the triangle (of this output) and barycentric
 *   coordinates of the vertex's mirror image m(v);
 * - `MappedPoints`: the position of m(v) on the surface;
 * - `TargetInputPointIds` (when the input had `InputPointId`): the triangle's corners in
 *   the input file's numbering;
 * - every other point array NAME of the input read at the mirror image, as NAME_Target
 *   (data mirrored across the shape);
 * - `Asymmetry`: |v - m(m(v))| / sqrt(surface area), 0 where m is an involution (exact
 *   symmetry), large where the two sides do not match.
 * Field data (besides the passed-through fields of the stages, e.g. `CandidateTransforms`,
 * `CandidateScores` and the refinement's `Candidate*` arrays):
 * - `SymmetryDistance` in [0, 1]: d = |f - f∘T^-1| / 2 for the conformal scale-factor
 *   signal f of vtkSO3Register (sqrt(area ratio), low-passed), made mean-free and of unit
 *   L2 norm, and the best reflection T; equivalently sqrt((1 - rho) / 2) with rho the
 *   correlation coefficient of f with f∘T^-1 (vtkSO3Register's `CorrelationCoefficient`).
 *   0: perfectly symmetric; about 0.71: no better than an unrelated signal; the quantity
 *   whose cumulative distribution the paper's Figure 8 plots;
 * - `CandidateSymmetryDistances`: the same for each candidate reflection, best first;
 * - `Reflection` (9 doubles, row-major, x' = T x on the sphere): the best reflection;
 * - `MirrorPlaneNormal` (3 doubles): the normal n of the mirror plane x . n = 0 on the
 *   sphere, `MirrorPlaneTwist`: the angle (radians) of the rotation about n that T adds to
 *   the pure reflection in that plane (0 for an exact mirror symmetry),
 *   `CandidateMirrorPlaneNormals` (one tuple per candidate);
 * - `MeanAsymmetry`, `MaximumAsymmetry` of `Asymmetry`;
 * - `SymmetryCentered` (1 if the map was centered), `SymmetryRefined` (1 if refined),
 *   `SnappedVertices` (how many images `SnapTolerance` put exactly on a vertex);
 * - `NumberOfThreadsUsed` (every stage runs with this count).
 *
 * Errors (vtkErrorMacro, no output): an input the stages reject (open, non-manifold,
 * genus > 0, ...), with the stage's reason. A mesh with fewer than 2 x `BasisSize` vertices
 * is not refined (warning).
 *
 * @sa vtkSO3Register vtkCorrespondenceRefinement vtkMobiusCenter
 */
#ifndef vtkSymmetryDetection_h
#define vtkSymmetryDetection_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusThreadedPolyDataAlgorithm.h"

class vtkPolyDataAlgorithm;

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSymmetryDetection
  : public vtkMobiusThreadedPolyDataAlgorithm
{
public:
  static vtkSymmetryDetection* New();
  vtkTypeMacro(vtkSymmetryDetection, vtkMobiusThreadedPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Center the spherical map before the registration (default on). Off gives the
   * paper's "uncentered" curve of Figure 8: arbitrary Möbius transformations do not
   * preserve reflective symmetry, so the distance is larger.
   */
  vtkSetMacro(Centering, bool);
  vtkGetMacro(Centering, bool);
  vtkBooleanMacro(Centering, bool);
  ///@}

  ///@{
  /**
   * Grid size N of the scale-factor signal (even, >= 4), as vtkSO3Register. Default 256.
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Heat-kernel time of the signal's low pass, as vtkSO3Register. Default 5e-4.
   */
  vtkSetClampMacro(SmoothingTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SmoothingTime, double);
  ///@}

  ///@{
  /**
   * Candidate reflections kept (well-separated correlation peaks). Default 4.
   */
  vtkSetClampMacro(NumberOfCandidates, int, 1, 64);
  vtkGetMacro(NumberOfCandidates, int);
  ///@}

  ///@{
  /**
   * Refine the symmetric map spectrally (vtkCorrespondenceRefinement, default on), or keep
   * the Möbius map read off the sphere (off).
   */
  vtkSetMacro(Refine, bool);
  vtkGetMacro(Refine, bool);
  vtkBooleanMacro(Refine, bool);
  ///@}

  ///@{
  /**
   * Eigenfunctions of the refinement's functional map. Default 80.
   */
  vtkSetClampMacro(BasisSize, int, 2, 500);
  vtkGetMacro(BasisSize, int);
  ///@}

  ///@{
  /**
   * End the refinement with its geometric polish (vtkCorrespondenceRefinement's
   * GeometricPolish, default on): the mirrored surface deformed as rigidly as possible onto
   * the surface.
   */
  vtkSetMacro(GeometricPolish, bool);
  vtkGetMacro(GeometricPolish, bool);
  vtkBooleanMacro(GeometricPolish, bool);
  ///@}

  ///@{
  /**
   * Exactness where the spherical map is exactly symmetric: a vertex whose reflected
   * sphere point lies within SnapTolerance x (the shortest sphere edge at a vertex w) of w
   * is mapped exactly onto w, whatever the refinement's interpolation made of it (an exactly
   * mirror-symmetric mesh then gets its exact mirror map). On other meshes this almost never
   * applies, and moves an image by less than the tolerance. Default 1e-3; 0 disables.
   */
  vtkSetClampMacro(SnapTolerance, double, 0.0, 0.5);
  vtkGetMacro(SnapTolerance, double);
  ///@}

protected:
  vtkSymmetryDetection();
  ~vtkSymmetryDetection() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  bool Centering;
  int Resolution;
  double SmoothingTime;
  int NumberOfCandidates;
  bool Refine;
  int BasisSize;
  bool GeometricPolish;
  double SnapTolerance = 1e-3;

private:
  // An internal stage's result, or nullptr after reporting its error as this filter's.
  vtkSmartPointer<vtkPolyData> RunStage(
    vtkPolyDataAlgorithm* filter, const char* stage, double begin, double end);
  // The input's centered spherical map (MapAndCenter), or nullptr after reporting why not.
  vtkSmartPointer<vtkPolyData> CenteredMapOf(vtkPolyData* input);
  // The centered map registered against itself over reflections only.
  vtkSmartPointer<vtkPolyData> SelfRegister(vtkPolyData* centered, int threads);
  // Whether Refine applies to the mesh; warns when it is on but the mesh is too small.
  bool RefinementApplies(vtkPolyData* centered);
  // The symmetric map: the refinement's, or the dense correspondence's without refinement.
  vtkSmartPointer<vtkPolyData> SymmetricMap(
    vtkPolyData* reflected, vtkPolyData* centered, int threads, bool refine);

  vtkSymmetryDetection(const vtkSymmetryDetection&) = delete;
  void operator=(const vtkSymmetryDetection&) = delete;
};

#endif
