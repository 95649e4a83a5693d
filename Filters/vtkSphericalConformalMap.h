/**
 * @class   vtkSphericalConformalMap
 * @brief   Conformal map of a closed genus-0 triangle mesh onto the unit sphere.
 *
 * Conformalized mean curvature flow (Kazhdan, Solomon & Ben-Chen, SGP 2012): the cotangent
 * stiffness L is built once from the input (by default on its intrinsic Delaunay
 * triangulation, which keeps L well behaved on needle triangles), the mass matrix M_t from
 * the current shape, and each backward-Euler step solves (M_t + TimeStep L) x = M_t x_t,
 * then recenters and rescales to unit area. The flow stops when a step moves the shape by
 * less than ConvergenceTolerance (relative), or after MaximumNumberOfIterations steps; the
 * points are then projected radially onto the unit sphere. Optionally the map is Möbius
 * centered between steps (paper Section 7.1), which stops the drift of the flow toward a
 * point.
 *
 * Input: a vtkPolyData surface. Polygons with more than three points and triangle strips
 * are triangulated; points with exactly equal coordinates (a triangle soup, STL files) are
 * merged; an edge whose two ends are at one position is collapsed (its triangles, which have
 * no area, are dropped); triangles are reoriented consistently, and reversed if they face
 * inward. The mesh must then be a closed, edge- and vertex-manifold, connected surface of
 * genus 0 with finite coordinates; otherwise the filter fails with an
 * error naming every problem found (holes, non-manifold edges or vertices, components,
 * genus). By default (Repair) such a mesh is repaired into a genus-0 proxy instead
 * (mobius::RepairMesh: duplicate and degenerate triangles removed, non-manifold vertices
 * split, triangles oriented, small loose parts dropped, holes filled with faired patches,
 * handles cut), with a warning that names each repair and its size; field data
 * `MeshRepairs` holds the same phrases. With Repair off the filter is strict: it fails with
 * an error naming every problem, and only FillHoles (close boundary loops) and
 * KeepLargestComponent (drop all but the largest component) repair, on request.
 *
 * Output: the spherical map, i.e. the (repaired) mesh with points on the unit sphere,
 * carrying:
 * - point data `SurfacePoints` (3 doubles): the vertex on the original surface;
 * - cell data `SurfaceArea` (double): the triangle's area on the original surface;
 * - cell data `QuasiConformalDistortion` (the active cell scalars: ParaView's default
 *   coloring) and `LogAreaRatio`: each triangle's distortion (mobius::vtk::AddDistortionArrays);
 * - point data `InputPointId` (id type): the index of the point in this filter's input
 *   (for a mesh from vtkSurfaceMeshReader, the vertex number in the file), -1 for a point
 *   a repair created (a hole's patch). Repairs drop unused points, merge duplicates and
 *   split non-manifold vertices (the copies share their InputPointId), so output point i
 *   is in general not input point i; the later filters pass this array on, so results can
 *   name the input's vertices;
 * - cell data `InputCellId` (id type): the same for the triangles, the index of the
 *   triangle in the input with its polygons split into triangles, -1 for a triangle a
 *   repair created;
 * - every point and cell array of the input (points and triangles a repair created get
 *   zero values);
 * - field data: `ConformalFlowIterations`, `ConformalFlowRelativeChange`,
 *   `ConformalFlowConverged` (0/1), `ConformalFlowLinearStart` (0/1: the flow started from
 *   the linear conformal map), `ConformalFlowFactorizations` (numeric Cholesky
 *   factorizations made), `FlippedTriangles` (triangles with det(a,b,c) <= 0 on
 *   the sphere), `MeanQuasiConformalDistortion` (area-weighted mean over triangles of the
 *   ratio of the singular values of the linear map from the surface triangle to the
 *   spherical chord triangle; 1 is conformal), `MaxQuasiConformalDistortion`,
 *   `MedianQuasiConformalDistortion`, `P95QuasiConformalDistortion`,
 *   `P99QuasiConformalDistortion` (area-weighted quantiles: the distortion below which the
 *   triangles holding 50, 95, 99% of the surface lie), `SquashedAreaShare` (0 to 1: the
 *   share of the surface in triangles of distortion above 10), `SmallestSphereAreaShare`
 *   (the smallest spherical triangle's area over 4 pi),
 *   `AreaDistortionRange` (2 doubles: min and max of spherical share / surface share of
 *   area per triangle), `IntrinsicDelaunayUsed` (0/1), `IntrinsicDelaunayFlips`,
 *   `MergedDuplicatePoints`, `CollapsedEdges` (zero-length edges), `FilledHoles`,
 *   `ReversedTriangleOrientation` (0/1), `FlipRepairMovedVertices`,
 *   `SqueezedRegionRefinementFailed` (0/1), `DegenerateMap` (0/1),
 *   `DegenerateMapReason` (a string, empty for a good map) and `MapWarning` (a string, empty
 *   unless a usable map squashes more than 1% of the surface).
 *
 * A map is degenerate (output anyway, with a warning; the caller decides) when triangles
 * are still flipped after the repair, when its triangles collapsed to a small part of the
 * sphere, when they squash more than half the surface (distortion above 10), when the flow
 * did not converge, or when the refinement of squeezed regions failed
 * (mobius::JudgeConformalMap, MapVerdict.h, holds the rule). Such a map carries no
 * trustworthy correspondence. Thin parts (tails, fingers) are squeezed exponentially by any
 * conformal map and can be extreme without spoiling the rest: a map squashing more than 1%
 * of the surface is used, with a warning naming the share.
 *
 * @sa vtkMobiusCenter
 */
#ifndef vtkSphericalConformalMap_h
#define vtkSphericalConformalMap_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSphericalConformalMap
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkSphericalConformalMap* New();
  vtkTypeMacro(vtkSphericalConformalMap, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Backward-Euler step of the flow, for a surface scaled to unit area with the standard
   * cot/2 stiffness. Default 0.4.
   */
  vtkSetClampMacro(TimeStep, double, 1e-6, 1e6);
  vtkGetMacro(TimeStep, double);
  ///@}

  ///@{
  /**
   * Upper bound on flow steps. Default 100.
   */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /**
   * Stop when a step moves the shape (area-weighted RMS, relative to its size) by less
   * than this. Default 1e-4.
   */
  vtkSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /**
   * Möbius-center the map after every flow step (paper Section 7.1). Default on; off
   * reproduces plain CMCF, which drifts and typically needs many more steps.
   */
  vtkSetMacro(CenterBetweenSteps, vtkTypeBool);
  vtkGetMacro(CenterBetweenSteps, vtkTypeBool);
  vtkBooleanMacro(CenterBetweenSteps, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Start the flow from a linear conformal map (one sparse solve: the surface punctured in
   * a flat, well-shaped triangle, mapped to the plane and projected onto the sphere) instead
   * of from the surface, so that the flow only polishes it and converges in fewer steps to
   * the same map (up to a rotation). Default on (used only with CenterBetweenSteps); off
   * reproduces the published flow, which also keeps a mirror symmetry of the surface
   * exactly (vtkSymmetryDetection uses it). The field data
   * `ConformalFlowLinearStart` says whether the linear start was used (it falls back on the
   * surface if the linear map cannot be computed).
   */
  vtkSetMacro(LinearStart, vtkTypeBool);
  vtkGetMacro(LinearStart, vtkTypeBool);
  vtkBooleanMacro(LinearStart, vtkTypeBool);
  ///@}

  ///@{
  /**
   * On meshes of 50,000 vertices or more, solve each flow step after the first by
   * conjugate gradients preconditioned with the first step's Cholesky factorization
   * instead of factorizing again (a new factorization only when that does not converge in
   * 10 iterations): the same steps and map, at the cost of a few triangular solves per step
   * (smaller meshes' factorizations cost about as much). Default on; the field data
   * `ConformalFlowFactorizations` counts the factorizations made (the linear start's
   * included).
   */
  vtkSetMacro(ReuseFactorization, vtkTypeBool);
  vtkGetMacro(ReuseFactorization, vtkTypeBool);
  vtkBooleanMacro(ReuseFactorization, vtkTypeBool);
  ///@}

  enum IntrinsicDelaunayModes
  {
    INTRINSIC_DELAUNAY_OFF = 0,
    INTRINSIC_DELAUNAY_ON = 1,
    INTRINSIC_DELAUNAY_AUTOMATIC = 2
  };

  ///@{
  /**
   * Build the stiffness on the intrinsic Delaunay triangulation of the input, which keeps
   * cotangent weights bounded on needle triangles (cot of 1 degree is 57, of 0.01 degree
   * 5730: the flow then folds triangles). On well-shaped meshes the input's own cotangent
   * weights give a slightly lower quasi-conformal distortion measured on its triangles.
   * AUTOMATIC (default) uses it when the smallest triangle angle is below
   * IntrinsicDelaunayAngle, or when the map made with the input's own weights keeps folds
   * after the repair (negative weights across non-Delaunay edges fold squeezed limbs: a
   * decimated camel); the field data `IntrinsicDelaunayUsed` says which was used.
   */
  vtkSetClampMacro(IntrinsicDelaunay, int, INTRINSIC_DELAUNAY_OFF, INTRINSIC_DELAUNAY_AUTOMATIC);
  vtkGetMacro(IntrinsicDelaunay, int);
  ///@}

  ///@{
  /**
   * Smallest triangle angle, in degrees, below which AUTOMATIC uses the intrinsic Delaunay
   * triangulation. Default 1.
   */
  vtkSetClampMacro(IntrinsicDelaunayAngle, double, 0.0, 60.0);
  vtkGetMacro(IntrinsicDelaunayAngle, double);
  ///@}

  ///@{
  /**
   * Sweeps of local repair of triangles left flipped on the sphere by the flow (each
   * moves vertices of flipped triangles inside their neighbourhood; the sweep with the
   * fewest folds is kept, and the vertices of folds left are then moved into the kernel of
   * their star, which never adds a fold); 0 disables the repair. Default 100.
   */
  vtkSetClampMacro(FlipRepairPasses, int, 0, VTK_INT_MAX);
  vtkGetMacro(FlipRepairPasses, int);
  ///@}

  ///@{
  /**
   * Repair a mesh that is not a closed, connected, manifold, consistently oriented genus-0
   * surface into a genus-0 proxy of it instead of failing (see the class description).
   * Default on; off is the strict mode.
   */
  vtkSetMacro(Repair, vtkTypeBool);
  vtkGetMacro(Repair, vtkTypeBool);
  vtkBooleanMacro(Repair, vtkTypeBool);
  ///@}

  ///@{
  /**
   * With Repair off: close the input's holes (boundary loops) instead of failing. Default
   * off. (Repair closes them anyway.)
   */
  vtkSetMacro(FillHoles, vtkTypeBool);
  vtkGetMacro(FillHoles, vtkTypeBool);
  vtkBooleanMacro(FillHoles, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Keep only the largest connected component instead of failing when there are several
   * (with Repair: when another one is not small against it, see
   * mobius::kLooseComponentShare; smaller ones are dropped anyway). Default off.
   */
  vtkSetMacro(KeepLargestComponent, vtkTypeBool);
  vtkGetMacro(KeepLargestComponent, vtkTypeBool);
  vtkBooleanMacro(KeepLargestComponent, vtkTypeBool);
  ///@}

protected:
  vtkSphericalConformalMap();
  ~vtkSphericalConformalMap() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double TimeStep = 0.4;
  // Defaults: mobius::RegistrationParameters (the constructor).
  int MaximumNumberOfIterations;
  double ConvergenceTolerance;
  vtkTypeBool CenterBetweenSteps;
  vtkTypeBool LinearStart = true;
  vtkTypeBool ReuseFactorization = true;
  int IntrinsicDelaunay = INTRINSIC_DELAUNAY_AUTOMATIC;
  double IntrinsicDelaunayAngle = 1.0;
  int FlipRepairPasses = 100;
  vtkTypeBool Repair;
  vtkTypeBool FillHoles;
  vtkTypeBool KeepLargestComponent;

private:
  vtkSphericalConformalMap(const vtkSphericalConformalMap&) = delete;
  void operator=(const vtkSphericalConformalMap&) = delete;
};

#endif
