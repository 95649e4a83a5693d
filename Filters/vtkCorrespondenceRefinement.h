/**
 * @class   vtkCorrespondenceRefinement
 * @brief   Refines the Möbius map into an accurate dense correspondence (spectral, ZoomOut).
 *
 * The Möbius map is rigid on the sphere: limbs, which a conformal map squeezes into tiny
 * regions, land beside their counterparts (the paper, §1 and §7.4, calls it a start for a
 * finer correspondence). This filter refines it with ZoomOut (Melzi et al. 2019): the
 * pointwise map is converted to a functional map between the surfaces' Laplace-Beltrami
 * eigenbases and back, in a basis growing from `StartBasisSize` to `BasisSize` functions,
 * on `NumberOfSamples` evenly spread vertices of each surface; the result is then extended
 * to every vertex, refined `FullResolutionIterations` times on all vertices, and each
 * mapped point placed inside a target triangle by projection in the spectral embedding.
 *
 * Candidates: vtkSO3Register reports several well-separated transforms
 * (`CandidateTransforms`). Symmetric-looking shapes can make a wrong one score best (a
 * person's arms on the wrong side). With `SearchCandidates` on (default), the refinement
 * starts from each candidate up to `ScreeningBasisSize` functions, each held on the side
 * its rotation put it by the aligned sphere coordinates (`SphereAnchorWeight`), and
 * continues the one of the expected orientation whose images keep the source's smoothed
 * mean curvature best (eigenfunctions cannot tell a body's front from its back, so the map
 * of a body turned half a turn is as orthogonal as the right one; faces, toes and kneecaps
 * tell them apart). When the runner-up comes within 10%, both maps are finished and the one
 * with the lower product of curvature difference and mean edge stretch is kept (between
 * bodies of different proportions the curvatures differ for real; a turned map stays
 * stretched where the front and the back differ). `Candidate` keeps a given candidate instead.
 *
 * Inputs: port 0 `Source`, the output of vtkSO3Register (the source's spherical map,
 * aligned; its field data `Rotation` and `CandidateTransforms` are used when present);
 * port 1 `Target`, the target's centered spherical map. Both need `SurfacePoints`, and
 * each surface must be a closed manifold with at least 2 x `BasisSize` vertices.
 *
 * Output: exactly as vtkDenseCorrespondence (SOURCE_TO_TARGET): the source's connectivity
 * with points on the target surface (or the source surface, `OutputGeometry`); point
 * arrays `MappedPoints`, `TargetCellId`, `TargetBarycentric`, `TargetInputPointIds`, the
 * target's point arrays transferred, the source's passed through (with `InputPointId`). Field data (besides the source's):
 * - `RefinementCandidate`: which candidate (0 = vtkSO3Register's best) was kept;
 * - `CandidateOrthogonalityResiduals`, `CandidateTargetCoverage` (one value per candidate
 *   tried, in candidate order): |C^T C - I|_F / sqrt(k) of its sampled functional map and the
 *   share of target samples it reaches;
 * - `CandidateOrientationAgreement` (per candidate): the share of sampled triangles whose
 *   image keeps its orientation (near 1 for a rotation's map, near 0 for a mirror image);
 * - `CandidateCurvatureDifferences` (per candidate): the mean |H_source - H_target| of the
 *   smoothed mean curvatures at the samples and their images, what the choice compares
 *   first (-1 where a surface's curvature could not be computed);
 * - `CandidateLandmarkDistanceDifferences` (per candidate): with landmarks, how far its
 *   screened map moves the samples' distances to the landmarks (in units of sqrt(area); a
 *   candidate more than 20% above the lowest is not kept: a map can keep every landmark
 *   and still turn the body between them); 0 without landmarks;
 * - `CandidateMapStretch` (per candidate): the mean edge stretch of its finished map (as
 *   `RefinementMeanStretch`) for the kept candidate and, when the runner-up came within 10%
 *   by curvature, for the runner-up too, whose map is then finished as well and the one
 *   with the lower product of curvature difference and stretch kept; -1 for a map not
 *   finished;
 * - `RefinementChoice` (string): what decided, "curvature", "curvature and map stretch",
 *   "orthogonality" (a surface without curvature; "orthogonality and map stretch") or
 *   "given" (`Candidate`);
 * - `RefinementChoiceSummary` (string): the same in one sentence, with the runner-up and
 *   how close it came, and the advice to look at it when it is near-equal (ParaView's
 *   Information panel shows it);
 * - `RefinementConfidence` (3 values): the kept candidate's score by what decided (its
 *   curvature difference, the orthogonality residual where a surface has no curvature; when
 *   both finished maps were compared, that times its finished map's stretch), the
 *   runner-up (the best other candidate of the expected orientation whose map differs; -1
 *   if none) and the margin, (runner-up's score - kept's) / kept's (-1 without a runner-up
 *   or when the kept score is 0): below 0.05 the two are near-equal and the map may be the
 *   wrong one of two (check it, and keep the other with `Candidate`);
 * - `RefinementMeanStretch`: the area-weighted mean of the point array `MapStretch`, per
 *   vertex the mean |log| of how the map stretches the edges around it (0 for an isometry;
 *   color the map by it to see where it can be trusted);
 * - `RefinementOrthogonalityResidual`, `RefinementOrientationAgreement` of the final map,
 *   `RefinementOrientationRepaired` (1 if the kept candidate came out mirrored and was
 *   repaired), `RefinementBasisSize`;
 * - `RefinementStageSeconds` (4 values, only with RecordTimings): eigenbases, candidate
 *   search, extension to every vertex, geometric polish (0 when off);
 * - `RefinementStoredBasisUsed` (2 values, source and target): 1 where the input's stored
 *   basis was used;
 * - `NumberOfThreadsUsed`.
 *
 * Stored bases: an input carrying the Laplace-Beltrami basis of its surface
 * (vtkLaplaceBeltramiBasis: point data `LaplaceBeltramiBasis` of BasisSize components, its
 * eigenvalues and the surface's fingerprint in field data) is refined with it instead of a
 * newly computed one: the output is the same, bit for bit, without the cost of the
 * eigensolver. A stored basis of another size is ignored (a new one is computed); one
 * computed for another surface is an error. These arrays are not passed to the output.
 *
 * Landmarks (AddLandmark, point ids of the two input maps): every candidate maps each
 * source landmark onto its target landmark (a hard constraint of ZoomOut's pointwise step,
 * and a heavy row of its functional-map fit), the candidates whose rotation leaves the
 * landmarks' sphere points much farther apart than the closest one does are not kept, and
 * the geometric polish holds each landmark on its target vertex, where it ends.
 *
 * Errors: a landmark naming a point an input does not have, inputs that are not spherical maps with `SurfacePoints`, meshes too small for
 * the basis, a stored basis of another surface, a Laplacian that cannot be factorized or
 * an eigensolver that does not converge.
 *
 * @sa vtkSO3Register vtkDenseCorrespondence vtkLaplaceBeltramiBasis
 */
#ifndef vtkCorrespondenceRefinement_h
#define vtkCorrespondenceRefinement_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkCorrespondenceRefinement
  : public vtkMobiusLandmarkPolyDataAlgorithm
{
public:
  static vtkCorrespondenceRefinement* New();
  vtkTypeMacro(vtkCorrespondenceRefinement, vtkMobiusLandmarkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OutputGeometries
  {
    TARGET = 0,
    SOURCE = 1
  };

  enum CandidateCriteria
  {
    CURVATURE = 0,
    ORTHOGONALITY = 1
  };

  ///@{
  /**
   * The target map (port 1); the source (vtkSO3Register's output) is the input of port 0.
   */
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSourceData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetTargetData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

  ///@{
  /**
   * Number of Laplace-Beltrami eigenfunctions of the final functional map. Default 80.
   */
  vtkSetClampMacro(BasisSize, int, 2, 500);
  vtkGetMacro(BasisSize, int);
  ///@}

  /**
   * Whether a map of `numberOfPoints` points (the smaller of the two) can be refined with
   * `basisSize` eigenfunctions: it needs at least twice as many points. On a smaller one the
   * Möbius map (vtkDenseCorrespondence) is the answer.
   */
  static bool CanRefine(vtkIdType numberOfPoints, int basisSize);

  ///@{
  /**
   * Basis size of the first ZoomOut iteration (default 4), and the fraction by which the
   * basis grows per iteration (default 0.15, at least one function).
   */
  vtkSetClampMacro(StartBasisSize, int, 1, 500);
  vtkGetMacro(StartBasisSize, int);
  vtkSetClampMacro(BasisGrowth, double, 0.0, 10.0);
  vtkGetMacro(BasisGrowth, double);
  ///@}

  ///@{
  /**
   * Basis size up to which every candidate start is refined before they are compared; the
   * best one then continues to BasisSize. Default 30.
   */
  vtkSetClampMacro(ScreeningBasisSize, int, 1, 500);
  vtkGetMacro(ScreeningBasisSize, int);
  ///@}

  ///@{
  /**
   * Vertices of each surface the iterations run on (farthest-point samples). Default 1000.
   */
  vtkSetClampMacro(NumberOfSamples, int, 10, 1000000);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * ZoomOut iterations on all vertices after the sampled ones, each with the exact nearest
   * vertex in the spectral embedding. Default 1.
   */
  vtkSetClampMacro(FullResolutionIterations, int, 0, 100);
  vtkGetMacro(FullResolutionIterations, int);
  ///@}

  ///@{
  /**
   * Refine from every candidate transform of vtkSO3Register and keep the best (default on),
   * or only from the transform the source was aligned with.
   */
  vtkSetMacro(SearchCandidates, bool);
  vtkGetMacro(SearchCandidates, bool);
  vtkBooleanMacro(SearchCandidates, bool);
  ///@}

  ///@{
  /**
   * Keep the map's orientation that of the transform it started from: preserved for a
   * rotation, reversed for a reflection. A bilaterally symmetric shape can otherwise come
   * out mapped onto the target's mirror image: its first eigenfunctions are all symmetric,
   * so the first ZoomOut iterations scramble left and right, and the first antisymmetric
   * one enters with a sign that is a coin flip. With this on (default), a ZoomOut iteration
   * whose map comes out decisively of the wrong orientation (at most a quarter of the
   * sampled triangles on the expected side) is redone with the sign of one eigenfunction
   * flipped (the mirror symmetry negates the antisymmetric ones), and if the kept
   * candidate still has the wrong orientation, ZoomOut is retried from its low-frequency
   * functional map with one or two signs flipped and the best map of the right
   * orientation kept.
   */
  vtkSetMacro(RepairOrientation, bool);
  vtkGetMacro(RepairOrientation, bool);
  vtkBooleanMacro(RepairOrientation, bool);
  ///@}

  ///@{
  /**
   * Weight of the aligned unit-sphere coordinates beside the eigenfunction values in every
   * nearest-point search of ZoomOut (0: none). The rotation found on the sphere cannot
   * reflect, so these coordinates hold each candidate's map on the side its rotation put it,
   * where the eigenfunctions alone let a right start slide into a body's front-back mirror
   * image; the conformal map squeezes each limb into a small patch of the sphere, so they
   * still let the large moves along limbs happen. Clamped to 0..100.
   */
  vtkSetClampMacro(SphereAnchorWeight, double, 0.0, 100.0);
  vtkGetMacro(SphereAnchorWeight, double);
  ///@}

  ///@{
  /**
   * What tells the candidates of the expected orientation apart: CURVATURE (default), the
   * smoothed mean curvature kept by the map, for registering two surfaces; ORTHOGONALITY,
   * the functional map's orthogonality residual alone (intrinsic), for a surface's own
   * mirror symmetry, where a pose can make another reflection an exact extrinsic symmetry
   * (vtkSymmetryDetection uses it).
   */
  vtkSetClampMacro(CandidateCriterion, int, CURVATURE, ORTHOGONALITY);
  vtkGetMacro(CandidateCriterion, int);
  void SetCandidateCriterionToCurvature() { this->SetCandidateCriterion(CURVATURE); }
  void SetCandidateCriterionToOrthogonality() { this->SetCandidateCriterion(ORTHOGONALITY); }
  ///@}

  ///@{
  /**
   * The candidate to keep: -1 (default) chooses (see the class description); 0..K-1 keeps
   * candidate K of vtkSO3Register's `CandidateTransforms` (0 its best), for a map that came
   * out wrong with a near-equal runner-up. A number beyond the candidates is an error.
   */
  vtkSetClampMacro(Candidate, int, -1, 63);
  vtkGetMacro(Candidate, int);
  ///@}

  ///@{
  /**
   * Finish the spectral map geometrically (default on): the source mesh, scaled to the
   * target's area, is deformed as rigidly as possible (ARAP) onto the target, starting from
   * the mapped points, by a few non-rigid ICP iterations, and each vertex is projected onto
   * the target. The spectral map is right to about an edge length but slides in thin parts;
   * on near-isometric pairs the polish takes that slide out (see SurfacePolish.h and the
   * README's Accuracy section).
   */
  vtkSetMacro(GeometricPolish, bool);
  vtkGetMacro(GeometricPolish, bool);
  vtkBooleanMacro(GeometricPolish, bool);
  ///@}

  ///@{
  /**
   * With GeometricPolish, polish the map the other way (target onto source) too, on a
   * second thread, and end each point halfway between its polished image and the inverse
   * of the other direction's map (default on; InverseAveraging.h). The polish favours the
   * surface it deforms, and the average is nearer the truth than either direction: about
   * 3-4% lower errors on FAUST_r pairs, for a second extension and polish (docs/DEVELOPMENT.md,
   * "Both directions"). On surfaces of up to 10,000 vertices the two polishes also meet
   * every 10 iterations, each map moving towards the other's inverse: 5.6% lower than one
   * direction in all (FAUST_r set A 1.341 -> 1.266), about 0.07 s more per 5,000-vertex
   * pair than two whole polishes ("Meeting while polishing").
   */
  vtkSetMacro(BothDirections, bool);
  vtkGetMacro(BothDirections, bool);
  vtkBooleanMacro(BothDirections, bool);
  ///@}

  ///@{
  /**
   * Record the stages' wall-clock seconds in the field data (`RefinementStageSeconds`).
   * Off by default: timings differ from run to run, and the output would too.
   */
  vtkSetMacro(RecordTimings, bool);
  vtkGetMacro(RecordTimings, bool);
  vtkBooleanMacro(RecordTimings, bool);
  ///@}

  ///@{
  /**
   * Share of the consistent (finite-element) mass matrix blended with the lumped one in the
   * Laplace-Beltrami eigenproblem, 0..1 (0: lumped). See the README's Accuracy section.
   */
  vtkSetClampMacro(ConsistentMassShare, double, 0.0, 1.0);
  vtkGetMacro(ConsistentMassShare, double);
  ///@}

  ///@{
  /**
   * Where the output's points are: on the target surface (TARGET, default) or on the
   * source surface (SOURCE).
   */
  vtkSetClampMacro(OutputGeometry, int, TARGET, SOURCE);
  vtkGetMacro(OutputGeometry, int);
  void SetOutputGeometryToTarget() { this->SetOutputGeometry(TARGET); }
  void SetOutputGeometryToSource() { this->SetOutputGeometry(SOURCE); }
  ///@}

protected:
  vtkCorrespondenceRefinement();
  ~vtkCorrespondenceRefinement() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  int BasisSize;
  int StartBasisSize;
  double BasisGrowth = 0.15;
  int ScreeningBasisSize;
  int NumberOfSamples = 1000;
  int FullResolutionIterations;
  bool SearchCandidates = true;
  bool RepairOrientation = true;
  double ConsistentMassShare = 0.0;
  bool GeometricPolish;
  bool BothDirections;
  bool RecordTimings = false;
  double SphereAnchorWeight = 2.0;
  int CandidateCriterion = CURVATURE;
  int Candidate;
  int OutputGeometry;

private:
  vtkCorrespondenceRefinement(const vtkCorrespondenceRefinement&) = delete;
  void operator=(const vtkCorrespondenceRefinement&) = delete;
};

#endif
