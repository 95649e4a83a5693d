/**
 * @class   vtkSphericalOrbifoldMap
 * @brief   Spherical orbifold map with cyclic symmetry of a closed genus-0 surface
 *          (Möbius Registration, Section 7.2).
 *
 * A map of the surface onto 1/n of the sphere, a sector between two poles whose two sides
 * are glued: the quotient of the sphere by the rotations through 2 pi k / n about z. The
 * surface's two cone vertices get n times their angle on the sphere, which spreads the
 * shape's ends over more of it than a plain spherical map does: less area distortion.
 *
 * The filter cuts the surface along the shortest edge path between the two cone vertices,
 * glues NumberOfCopies copies of the cut surface into the n-fold cyclic covering (the left
 * side of the cut on copy i to the right side on copy i + 1), maps the covering onto the
 * sphere with the conformal flow, centers it (Möbius centering with the covering's areas)
 * and turns it so that the cones lie on the z axis (cone 2 at the north pole). The map is
 * n-fold symmetric, rotating copy i by 2 pi / n about z gives copy i + 1, by construction:
 * the flow starts from the surface's own spherical map lifted to the covering, whose copies
 * are already placed symmetrically about the cones' axis, and the flow (which treats the
 * copies alike) and the centering keep that symmetry (to rounding). Centering makes the
 * result canonical: any conformal map of the covering, once centered, is this one up to a
 * rotation, hence symmetric as well.
 *
 * Input: a closed genus-0 triangle mesh (mapped and repaired by vtkSphericalConformalMap's
 * defaults), or a spherical map made by vtkSphericalConformalMap (points on the unit sphere
 * with `SurfacePoints` and `SurfaceArea`).
 *
 * Output: the orbifold map of one copy (default): the surface cut open along the path, its
 * points on the sphere (the cut's interior vertices appear twice, once per side), or with
 * OutputCovering the whole covering. Point data `SurfacePoints`, `InputPointId` (the input
 * point each point is a copy of, in the numbering of ConeIds) and `Copy` (the copy, -1 at the cones);
 * cell data `SurfaceArea` and `Copy`. Field data: `NumberOfCopies`, `ConeIds` (one tuple of
 * 2 input ids), `CutPathPointIds` (input ids, cone to cone), `SymmetryError` (the largest
 * distance on the unit sphere between a vertex of copy i rotated by 2 pi / n about z and
 * the same vertex of copy i + 1; rounding-level for a good map), `ConeAntipodality`
 * (|x(cone 1) + x(cone 2)|), `FlippedTriangles` (of the covering's map),
 * `StdLogAreaRatio` and `PlainStdLogAreaRatio` (area-weighted standard deviation of
 * log(mapped area share / surface area share) over the triangles, for this map and for the
 * plain centered spherical map), `ConformalFlowIterations`, `ConformalFlowConverged`.
 *
 * Errors (vtkErrorMacro, no output): NumberOfCopies outside 2..8, a cone id that is not a
 * point of the input, two equal cones, cones that share an edge (no path with an interior
 * vertex to cut along), and inputs the conformal map rejects.
 *
 * @sa vtkSphericalConformalMap vtkMobiusCenter
 */
#ifndef vtkSphericalOrbifoldMap_h
#define vtkSphericalOrbifoldMap_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkSphericalOrbifoldMap
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkSphericalOrbifoldMap* New();
  vtkTypeMacro(vtkSphericalOrbifoldMap, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * n, the order of the cyclic symmetry: copies in the covering, 2 to 8 (checked when the
   * filter runs). Default 2.
   */
  vtkSetMacro(NumberOfCopies, int);
  vtkGetMacro(NumberOfCopies, int);
  ///@}

  ///@{
  /**
   * The two cone vertices: point ids of this filter's input, or for a spherical map input
   * carrying `InputPointId` (vtkSphericalConformalMap's output), values of that array (the
   * mesh file's vertex numbers); -1 -1 (default) chooses two
   * far-apart vertices (the ends of a double sweep of shortest edge paths: on elongated
   * shapes, the extremities).
   */
  vtkSetVector2Macro(ConeIds, vtkIdType);
  vtkGetVector2Macro(ConeIds, vtkIdType);
  ///@}

  ///@{
  /**
   * Output the whole covering (all copies) instead of one copy. Default off.
   */
  vtkSetMacro(OutputCovering, vtkTypeBool);
  vtkGetMacro(OutputCovering, vtkTypeBool);
  vtkBooleanMacro(OutputCovering, vtkTypeBool);
  ///@}

protected:
  vtkSphericalOrbifoldMap();
  ~vtkSphericalOrbifoldMap() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfCopies = 2;
  vtkIdType ConeIds[2] = { -1, -1 };
  vtkTypeBool OutputCovering = false;

private:
  // The input's own spherical map (a map input as it is, a surface through the conformal
  // map); nullptr after reporting why there is none.
  vtkSmartPointer<vtkPolyData> SphericalMapOf(vtkPolyData* input, bool inputIsMap);

  vtkSphericalOrbifoldMap(const vtkSphericalOrbifoldMap&) = delete;
  void operator=(const vtkSphericalOrbifoldMap&) = delete;
};

#endif
