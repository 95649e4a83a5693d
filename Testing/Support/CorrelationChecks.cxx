#include "CorrelationChecks.h"

#include "ParallelFor.h"
#include "Rotation.h"
#include "SO3CorrelationTensor.h"

#include <algorithm>
#include <complex>
#include <memory>

namespace mobius
{
double EvaluateCorrelationDirectly(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform)
{
  SphericalHarmonicCoefficients rotated;
  SphericalHarmonicCoefficients truncated;
  const int B = std::min(source.Bandwidth, target.Bandwidth);
  truncated.Resize(B);
  for (int l = 0; l < B; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      truncated(l, m) = source(l, m);
    }
  }
  RotateCoefficients(truncated, transform, rotated);
  // ∫ (f∘T⁻¹) g = Σ (f∘T⁻¹)_lm conj(g_lm) for real g.
  std::complex<double> sum = 0;
  for (int l = 0; l < B; ++l)
  {
    for (int m = -l; m <= l; ++m)
    {
      sum += rotated(l, m) * std::conj(target(l, m));
    }
  }
  return sum.real();
}

std::vector<double> ComputeCorrelationGrid(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int correlationBandwidth, bool reflectSource,
  int numberOfThreads)
{
  const int threads = ResolveThreadCount(numberOfThreads);
  SO3CorrelationTensor tensor(source, target, correlationBandwidth, reflectSource, threads);
  tensor.TransformToBetaSamples();
  const int M = tensor.GetGridResolution();
  const std::size_t area = static_cast<std::size_t>(M) * M;
  std::vector<double> grid(area * (correlationBandwidth + 1));
  std::vector<std::unique_ptr<SO3CorrelationTensor::SliceWorkspace>> workspaces(threads);
  for (auto& w : workspaces)
  {
    w = tensor.NewSliceWorkspace();
  }
  ParallelFor(correlationBandwidth + 1, threads, [&](int j, int thread) {
    tensor.SynthesizeSlice(j, *workspaces[thread], grid.data() + area * j);
  });
  return grid;
}
}
