#include "MobiusLaplaceBeltramiBasisData.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace mobius
{
namespace vtk
{
namespace
{
// FNV-1a, 64 bits: not cryptographic, only to tell meshes apart.
struct Fnv1a
{
  std::uint64_t Hash = 14695981039346656037ull;
  void Add(const void* data, size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i)
    {
      Hash = (Hash ^ p[i]) * 1099511628211ull;
    }
  }
  template <typename T>
  void AddValue(T value)
  {
    this->Add(&value, sizeof(value));
  }
};

// Names what was computed: the cotangent stiffness of the intrinsic Delaunay triangulation,
// the lumped mass, unit area. A new version makes every stored basis foreign.
constexpr const char* BasisKind = "LaplaceBeltramiBasis v1: intrinsic Delaunay, lumped mass";
}

void NormalizeSurfaceScale(Points& surface)
{
  if (surface.size() == 0)
  {
    return;
  }
  const double largest = surface.cwiseAbs().maxCoeff();
  if (largest > 0.0 && std::isfinite(largest))
  {
    surface *= std::ldexp(1.0, -std::ilogb(largest));
  }
}

void CenterSurface(Points& surface)
{
  if (surface.rows() > 0)
  {
    surface.rowwise() -= surface.colwise().mean();
    NormalizeSurfaceScale(surface);
  }
}

std::string SurfaceFingerprint(const Points& surface, const Triangles& triangles)
{
  Fnv1a hash;
  hash.Add(BasisKind, std::strlen(BasisKind));
  hash.AddValue<std::int64_t>(surface.rows());
  hash.AddValue<std::int64_t>(triangles.rows());
  for (Index i = 0; i < surface.rows(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      hash.AddValue<double>(surface(i, k));
    }
  }
  for (Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      hash.AddValue<std::int64_t>(triangles(t, k));
    }
  }
  std::ostringstream text;
  text << std::hex << hash.Hash;
  return text.str();
}

void AddBasisArrays(
  vtkPolyData* output, const LaplaceBeltramiBasis& basis, const std::string& fingerprint)
{
  const Index n = basis.Functions.rows();
  const int k = static_cast<int>(basis.Functions.cols());
  vtkNew<vtkDoubleArray> functions;
  functions->SetName(LaplaceBeltramiBasisArrayName);
  functions->SetNumberOfComponents(k);
  functions->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (Index i = 0; i < n; ++i)
  {
    for (int j = 0; j < k; ++j)
    {
      functions->SetTypedComponent(static_cast<vtkIdType>(i), j, basis.Functions(i, j));
    }
  }
  output->GetPointData()->AddArray(functions);

  vtkNew<vtkDoubleArray> eigenvalues;
  eigenvalues->SetName(LaplaceBeltramiEigenvaluesArrayName);
  eigenvalues->SetNumberOfTuples(k);
  for (int j = 0; j < k; ++j)
  {
    eigenvalues->SetValue(j, basis.Eigenvalues(j));
  }
  vtkNew<vtkStringArray> mesh;
  mesh->SetName(LaplaceBeltramiBasisMeshArrayName);
  mesh->InsertNextValue(fingerprint);
  vtkFieldData* fieldData = output->GetFieldData();
  fieldData->RemoveArray(LaplaceBeltramiEigenvaluesArrayName);
  fieldData->RemoveArray(LaplaceBeltramiBasisMeshArrayName);
  fieldData->AddArray(eigenvalues);
  fieldData->AddArray(mesh);
}

StoredBasis ReadBasisArrays(vtkPolyData* input, int size, const std::string& fingerprint,
  LaplaceBeltramiBasis& basis, std::string& error)
{
  vtkDataArray* functions = input->GetPointData()->GetArray(LaplaceBeltramiBasisArrayName);
  if (!functions)
  {
    return StoredBasis::None;
  }
  if (functions->GetNumberOfComponents() != size)
  {
    return StoredBasis::OtherSize;
  }
  vtkDataArray* eigenvalues =
    input->GetFieldData()->GetArray(LaplaceBeltramiEigenvaluesArrayName);
  vtkStringArray* mesh = vtkStringArray::SafeDownCast(
    input->GetFieldData()->GetAbstractArray(LaplaceBeltramiBasisMeshArrayName));
  std::ostringstream problem;
  if (!eigenvalues || eigenvalues->GetNumberOfValues() != size || !mesh ||
    mesh->GetNumberOfValues() != 1)
  {
    problem << "its " << LaplaceBeltramiBasisArrayName << " comes without the field data "
            << LaplaceBeltramiEigenvaluesArrayName << " (" << size << " values) and "
            << LaplaceBeltramiBasisMeshArrayName;
  }
  else if (functions->GetNumberOfTuples() != input->GetNumberOfPoints() ||
    mesh->GetValue(0) != fingerprint)
  {
    problem << "its " << LaplaceBeltramiBasisArrayName
            << " was computed for another surface (mesh fingerprint " << mesh->GetValue(0)
            << ", this surface's is " << fingerprint
            << "): recompute it with Laplace-Beltrami Basis on this mesh, or remove it";
  }
  if (problem.str().empty())
  {
    const Index n = input->GetNumberOfPoints();
    basis.Functions.resize(n, size);
    basis.Eigenvalues.resize(size);
    for (Index i = 0; i < n; ++i)
    {
      for (int j = 0; j < size; ++j)
      {
        basis.Functions(i, j) = functions->GetComponent(static_cast<vtkIdType>(i), j);
      }
    }
    for (int j = 0; j < size; ++j)
    {
      basis.Eigenvalues(j) = eigenvalues->GetComponent(j / eigenvalues->GetNumberOfComponents(),
        j % eigenvalues->GetNumberOfComponents());
    }
    if (!basis.Functions.allFinite() || !basis.Eigenvalues.allFinite())
    {
      problem << "its " << LaplaceBeltramiBasisArrayName << " has NaN or infinite values";
    }
  }
  error = problem.str();
  return StoredBasis::Found;
}

void RemoveBasisArrays(vtkPolyData* output)
{
  output->GetPointData()->RemoveArray(LaplaceBeltramiBasisArrayName);
  output->GetPointData()->RemoveArray(
    (std::string(LaplaceBeltramiBasisArrayName) + "_Target").c_str());
  output->GetFieldData()->RemoveArray(LaplaceBeltramiEigenvaluesArrayName);
  output->GetFieldData()->RemoveArray(LaplaceBeltramiBasisMeshArrayName);
}
}
}
