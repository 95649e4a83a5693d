/**
 * @class   vtkLaplaceBeltramiBasis
 * @brief   Computes a surface's Laplace-Beltrami eigenbasis once, for every refinement the
 *          surface takes part in.
 *
 * vtkCorrespondenceRefinement compares two surfaces in the bases of their first BasisSize
 * Laplace-Beltrami eigenfunctions; computing them (a sparse factorization and shift-invert
 * Lanczos, single-threaded) is most of the cost of refining one pair. In a collection every
 * surface takes part in many pairs: this filter computes the basis once and stores it on the
 * surface, and vtkCorrespondenceRefinement uses a stored basis that matches its input
 * instead of computing one (the refined map is the same, bit for bit).
 *
 * The eigenproblem is the refinement's: the cotangent stiffness of the intrinsic Delaunay
 * triangulation against the lumped mass, on the surface scaled to unit area.
 *
 * Input: a closed, manifold, consistently oriented triangle mesh with at least BasisSize + 1
 * points: a spherical map (then the surface is its point array `SurfacePoints`, as the
 * refinement reads it; e.g. the output of vtkMobiusCenter) or a surface (its points).
 *
 * Output: the input, with
 * - point data `LaplaceBeltramiBasis` (BasisSize components): the eigenfunctions, ascending
 *   eigenvalue, orthonormal in the mass matrix of the unit-area surface;
 * - field data `LaplaceBeltramiEigenvalues` (BasisSize values);
 * - field data `LaplaceBeltramiBasisMesh` (string): a fingerprint of the surface's
 *   coordinates and triangles and of the kind of basis. The refinement uses the basis only
 *   when the fingerprint and the point count match its input and the number of functions is
 *   its BasisSize; it computes its own for a basis of another size and refuses, with an
 *   error, one that belongs to another surface.
 * The refinement does not pass these arrays on to its output.
 *
 * Errors: no triangles, NaN or infinite coordinates, fewer than BasisSize + 1 points,
 * non-manifold or inconsistently oriented edges, a Laplacian that cannot be factorized or
 * an eigensolver that does not converge.
 *
 * @sa vtkCorrespondenceRefinement
 */
#ifndef vtkLaplaceBeltramiBasis_h
#define vtkLaplaceBeltramiBasis_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkMobiusPolyDataAlgorithm.h"

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkLaplaceBeltramiBasis
  : public vtkMobiusPolyDataAlgorithm
{
public:
  static vtkLaplaceBeltramiBasis* New();
  vtkTypeMacro(vtkLaplaceBeltramiBasis, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of eigenfunctions: the BasisSize of the refinements that will use them.
   * Default 80 (the refinement's default).
   */
  vtkSetClampMacro(BasisSize, int, 2, 500);
  vtkGetMacro(BasisSize, int);
  ///@}

protected:
  vtkLaplaceBeltramiBasis() = default;
  ~vtkLaplaceBeltramiBasis() override = default;

  int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int BasisSize = 80;

private:
  vtkLaplaceBeltramiBasis(const vtkLaplaceBeltramiBasis&) = delete;
  void operator=(const vtkLaplaceBeltramiBasis&) = delete;
};

#endif
