/**
 * @class   vtkMobiusRegistration
 * @brief   The whole Möbius registration of one mesh onto another, in one filter.
 *
 * Runs the pipeline mobius-register runs (MobiusPipeline.h): the repair and spherical
 * conformal map of each mesh (vtkSphericalConformalMap), its centering (vtkMobiusCenter),
 * the rotational alignment (vtkSO3Register), the dense map (vtkDenseCorrespondence) and its
 * spectral refinement (vtkCorrespondenceRefinement, when Refine is on and both maps have
 * at least 2 x BasisSize points). The stage filters stay for those who want the steps.
 *
 * Inputs: port 0 `Source`, port 1 `Target`: triangle meshes; one that is no closed genus-0
 * surface is repaired into a genus-0 proxy (Repair), and the outputs still have one row per
 * vertex of the mesh as given.
 *
 * Output: the correspondence, as the last stage gives it and mobius-register writes to
 * OUT.vtp: the source's connectivity (points on the target surface, or the source surface
 * with OutputGeometry SOURCE), point data `InputPointId`, `TargetCellId`,
 * `TargetBarycentric`, `TargetInputPointIds`, `MappedPoints` and the target's point arrays
 * transferred, and the last stage's field data. Besides, every stage's field data under
 * its stage's name: `SourceMap.`, `TargetMap.` (conformal maps, e.g.
 * `SourceMap.MeanQuasiConformalDistortion`), `SourceCentering.`, `TargetCentering.`,
 * `Registration.` (e.g. `Registration.Rotation`) and, when refined,
 * `MobiusCorrespondence.`.
 *
 * Two more outputs, for a view of the alignment: port 1, the source's centered spherical
 * map turned by the rotational alignment (vtkSO3Register's output, with the source's point
 * arrays); port 2, the target's centered spherical map (vtkMobiusCenter's output).
 *
 * Port 3 shows the map on the target's own mesh (the mesh as given, every vertex of it, when
 * a repair changed it), where the source placed by the map (port
 * 0) may fold over itself: the target's surface and point arrays, and per vertex where on
 * the source it comes from (its closest point on the placed source): `SourceCellId`,
 * `SourceBarycentric`, `SourcePoints`, `SourceInputPointIds` and the source's point arrays
 * carried back. Color it by a source array to see what the map carries over.
 *
 * Landmarks (AddLandmark): pairs of a source vertex and the target vertex it must go to,
 * for shapes too symmetric or too different for the automatic map. Every stage keeps them:
 * the rotational alignment chooses the transform that brings their sphere points together
 * (LandmarkMode 0) or a Möbius transform makes 3 of them meet (LandmarkMode 1); the
 * refinement maps each source landmark onto its target landmark and pins it in the polish.
 * Field data `LandmarkCount` and `LandmarkResidual` (one value per landmark: the
 * straight-line distance on the target between the image of the source landmark and the
 * target landmark, over sqrt(target area)).
 *
 * Errors: a mesh that cannot be mapped (the stage's message, naming the Source or the
 * Target), a degenerate conformal map unless AllowPoorMaps, a landmark naming a vertex the
 * mesh does not have or that its repair removed, a vertex in two landmarks, LandmarkMode 1
 * with fewer than 3 landmarks. Warnings: the stages'.
 *
 * Defaults are the core's (mobius::RegistrationParameters), the same as mobius-register's
 * and mobiusregistration.register()'s.
 *
 * @sa vtkSphericalConformalMap vtkMobiusCenter vtkSO3Register vtkDenseCorrespondence
 * vtkCorrespondenceRefinement
 */
#ifndef vtkMobiusRegistration_h
#define vtkMobiusRegistration_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusLandmarkPolyDataAlgorithm.h"

#include <string> // For the names

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkMobiusRegistration
  : public vtkMobiusLandmarkPolyDataAlgorithm
{
public:
  static vtkMobiusRegistration* New();
  vtkTypeMacro(vtkMobiusRegistration, vtkMobiusLandmarkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The mesh mapped (port 0) and the mesh it is mapped onto (port 1). */
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSourceData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetTargetData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

  ///@{
  /** Names of the meshes in messages (default "Source", "Target"), e.g. their files. */
  void SetSourceName(const char* name);
  const char* GetSourceName() const { return this->SourceName.c_str(); }
  void SetTargetName(const char* name);
  const char* GetTargetName() const { return this->TargetName.c_str(); }
  ///@}

  ///@{
  /**
   * The inputs are centered spherical maps already (vtkMobiusCenter outputs, as a collection
   * driver keeps one per shape, with a stored eigenbasis if it likes): the job starts at the
   * rotational alignment, and the output has no `SourceMap.`, `TargetMap.` or `*Centering.`
   * field data. Off by default: the inputs are meshes.
   */
  vtkSetMacro(InputsAreCenteredMaps, bool);
  vtkGetMacro(InputsAreCenteredMaps, bool);
  vtkBooleanMacro(InputsAreCenteredMaps, bool);

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
  ///@}

  ///@{
  /** Go on with a degenerate conformal map (DegenerateMap) instead of failing. */
  vtkSetMacro(AllowPoorMaps, bool);
  vtkGetMacro(AllowPoorMaps, bool);
  vtkBooleanMacro(AllowPoorMaps, bool);
  ///@}

  ///@{
  /** Conformal map: flow steps, convergence tolerance, centering between steps. */
  vtkSetMacro(MaximumNumberOfIterations, int);
  vtkGetMacro(MaximumNumberOfIterations, int);
  vtkSetMacro(ConvergenceTolerance, double);
  vtkGetMacro(ConvergenceTolerance, double);
  vtkSetMacro(CenterBetweenSteps, bool);
  vtkGetMacro(CenterBetweenSteps, bool);
  vtkBooleanMacro(CenterBetweenSteps, bool);
  ///@}

  ///@{
  /** Centering degree of both maps: 1 the Möbius centering, 2..8 generalized (vtkMobiusCenter). */
  vtkSetMacro(CenteringDegree, int);
  vtkGetMacro(CenteringDegree, int);
  ///@}

  ///@{
  /**
   * Rotational alignment (vtkSO3Register): grid size (even, >= 8), smoothing time,
   * transforms searched (0 rotations, 1 reflections, 2 both), correlation peaks, and the
   * smallest angle (degrees, 0-180) between two of them (vtkSO3Register::CandidateSeparation).
   */
  vtkSetMacro(Resolution, int);
  vtkGetMacro(Resolution, int);
  vtkSetMacro(SmoothingTime, double);
  vtkGetMacro(SmoothingTime, double);
  vtkSetMacro(TransformMode, int);
  vtkGetMacro(TransformMode, int);
  vtkSetMacro(NumberOfCandidates, int);
  vtkGetMacro(NumberOfCandidates, int);
  vtkSetMacro(CandidateSeparation, double);
  vtkGetMacro(CandidateSeparation, double);
  ///@}

  ///@{
  /**
   * Refinement (vtkCorrespondenceRefinement): on or off (the paper's Möbius map), basis
   * size, geometric polish (in both directions, averaged: BothDirections), and the
   * candidate to keep (-1: it chooses).
   */
  vtkSetMacro(Refine, bool);
  vtkGetMacro(Refine, bool);
  vtkBooleanMacro(Refine, bool);
  vtkSetMacro(BasisSize, int);
  vtkGetMacro(BasisSize, int);
  vtkSetMacro(GeometricPolish, bool);
  vtkGetMacro(GeometricPolish, bool);
  vtkBooleanMacro(GeometricPolish, bool);
  vtkSetMacro(BothDirections, bool);
  vtkGetMacro(BothDirections, bool);
  vtkBooleanMacro(BothDirections, bool);
  vtkSetMacro(Candidate, int);
  vtkGetMacro(Candidate, int);
  ///@}

  // Landmarks (AddLandmark(sourceVertex, targetVertex), RemoveAllLandmarks,
  // GetNumberOfLandmarks, from the base class): 0-based point ids of the two inputs, i.e. the
  // files' vertex numbers (with InputsAreCenteredMaps, the maps' `InputPointId` values). A
  // vertex the repair merged into a duplicate stands for that duplicate; one the repair
  // removed is an error, and so is a vertex in two landmarks. None by default.

  ///@{
  /**
   * How the landmarks steer the rotational alignment: 0 (default) the rotation search
   * chooses among the correlation's transforms, and with 3 or more landmarks their best-fit
   * rotation, the one that brings the landmarks' sphere points closest together; 1 a Möbius
   * transform of the source's sphere makes the first 3 landmarks meet exactly, in place of
   * the rotation (needs at least 3 landmarks). Checked as the other properties are (see
   * CheckParameters), not clamped.
   */
  vtkSetMacro(LandmarkMode, int);
  vtkGetMacro(LandmarkMode, int);
  ///@}

  ///@{
  /** Where the output's points are: 0 the target surface, 1 the source surface. */
  vtkSetMacro(OutputGeometry, int);
  vtkGetMacro(OutputGeometry, int);
  ///@}

  ///@{
  /**
   * The properties' allowed values are checked in one place for every interface
   * (mobius::CheckRegistrationParameters), not clamped: before it runs, the filter reports
   * the first property outside them as an error and gives no output. CheckParameters says
   * it beforehand, in the words of `names`: the properties' own (PROPERTY_NAMES),
   * mobiusregistration.register()'s keywords (PYTHON_NAMES) or mobius-register's options
   * (COMMAND_LINE_NAMES); "" when every value is allowed.
   */
  enum ParameterNames
  {
    PROPERTY_NAMES,
    PYTHON_NAMES,
    COMMAND_LINE_NAMES
  };
  std::string CheckParameters(int names = PROPERTY_NAMES);

  /** Threads of every threaded stage (see the base class); checked as above, not clamped. */
  void SetNumberOfThreads(int threads) override;

protected:
  vtkMobiusRegistration();
  ~vtkMobiusRegistration() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: mobius::RegistrationParameters (the constructor).
  std::string SourceName = "Source";
  std::string TargetName = "Target";
  bool InputsAreCenteredMaps;
  bool Repair;
  bool FillHoles;
  bool KeepLargestComponent;
  bool AllowPoorMaps;
  int MaximumNumberOfIterations;
  double ConvergenceTolerance;
  bool CenterBetweenSteps;
  int CenteringDegree;
  int Resolution;
  double SmoothingTime;
  int TransformMode;
  int NumberOfCandidates;
  double CandidateSeparation;
  bool Refine;
  int BasisSize;
  bool GeometricPolish;
  bool BothDirections;
  int Candidate;
  int OutputGeometry;
  int LandmarkMode;

private:
  vtkMobiusRegistration(const vtkMobiusRegistration&) = delete;
  void operator=(const vtkMobiusRegistration&) = delete;
};

#endif
