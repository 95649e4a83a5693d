/**
 * @file MobiusLaplaceBeltramiBasisData.h
 * @brief A surface's Laplace-Beltrami eigenbasis stored on a vtkPolyData, so that it is
 * computed once per surface and reused by every refinement it takes part in (private to the
 * module).
 *
 * vtkLaplaceBeltramiBasis writes, and vtkCorrespondenceRefinement reads:
 * - point data `LaplaceBeltramiBasis` (k components, double): the k eigenfunctions;
 * - field data `LaplaceBeltramiEigenvalues` (k values, ascending);
 * - field data `LaplaceBeltramiBasisMesh` (a string): a fingerprint of the exact surface
 *   coordinates (after the power-of-two scaling below), triangles and kind of basis the
 *   functions were computed for, so that a basis carried over to another mesh of the same
 *   size, or computed differently, is recognized as foreign.
 */
#ifndef MobiusLaplaceBeltramiBasisData_h
#define MobiusLaplaceBeltramiBasisData_h

#include "LaplaceBeltramiBasis.h"
#include "MeshTypes.h"

#include <string>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
constexpr const char* LaplaceBeltramiBasisArrayName = "LaplaceBeltramiBasis";
constexpr const char* LaplaceBeltramiEigenvaluesArrayName = "LaplaceBeltramiEigenvalues";
constexpr const char* LaplaceBeltramiBasisMeshArrayName = "LaplaceBeltramiBasisMesh";

/// Multiplies the coordinates by the power of two that puts the largest magnitude in [1, 2):
/// the unit-area basis does not depend on the scale, but lengths enter it squared twice and
/// coordinates of 1e-100 or 1e100 would underflow or overflow. Exact (a power of two).
void NormalizeSurfaceScale(Points& surface);

/// Moves the surface to its mean and normalizes its scale again, before its basis and the
/// refinement's geometry are computed: a translation changes neither, but coordinates far
/// from the origin cost their precision (a unit-size mesh at 1e12 was refined 0.008 off,
/// its coordinates' rounding being 0.0001). Fingerprints are of the surface before.
void CenterSurface(Points& surface);

/// A 64-bit hash (hexadecimal) of the point count, coordinates and triangles, and of the
/// kind of basis (bump its version when ComputeLaplaceBeltramiBasis changes).
std::string SurfaceFingerprint(const Points& surface, const Triangles& triangles);

/// Adds the basis arrays to `output` (one tuple of the basis per point of `output`).
void AddBasisArrays(
  vtkPolyData* output, const LaplaceBeltramiBasis& basis, const std::string& fingerprint);

enum class StoredBasis
{
  None,      ///< no `LaplaceBeltramiBasis` point array
  OtherSize, ///< one of another number of functions: of no use, compute a new one
  Found      ///< `basis` holds its Functions and Eigenvalues (not the Mass)
};

/// Reads a stored basis of `size` functions for the surface of `fingerprint`. A basis of
/// the right size that does not belong to the surface (another fingerprint, another point
/// count), or is incomplete or not finite, sets `error` (the caller refuses it: using it
/// would give a silently wrong map).
StoredBasis ReadBasisArrays(vtkPolyData* input, int size, const std::string& fingerprint,
  LaplaceBeltramiBasis& basis, std::string& error);

/// Removes the basis arrays (and a transferred `LaplaceBeltramiBasis_Target`) from a
/// filter's output, where they would be stale and large.
void RemoveBasisArrays(vtkPolyData* output);
}
}

#endif
