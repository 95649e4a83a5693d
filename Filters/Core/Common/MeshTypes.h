// Plain data types shared by the VTK-free core (namespace mobius).
//
// The core never sees VTK types: a mesh is an N x 3 row-major array of points and an
// M x 3 row-major array of triangle vertex indices. Row-major storage matches the
// memory layout of a 3-component vtkDoubleArray / vtkIdTypeArray, so the VTK classes can
// copy (or map) their arrays without reshuffling.
#ifndef mobius_MeshTypes_h
#define mobius_MeshTypes_h

#include <Eigen/Core>

#include <cstdint>
#include <functional>

namespace mobius
{
using Index = std::int64_t;
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Triangles = Eigen::Matrix<Index, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Vector = Eigen::VectorXd;

/// Progress report in [0, 1]; returning false asks the algorithm to stop early
/// (the VTK classes connect this to UpdateProgress and AbortExecute).
using ProgressCallback = std::function<bool(double)>;
}

#endif
