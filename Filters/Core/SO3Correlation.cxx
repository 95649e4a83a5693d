#include "SO3Correlation.h"

#include "ParallelFor.h"
#include "Rotation.h"
#include "SO3CorrelationTensor.h"
#include "WignerD.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <functional>
#include <memory>

namespace mobius
{
namespace
{
double Energy(const SphericalHarmonicCoefficients& c)
{
  double sum = 0;
  for (const std::complex<double>& v : c.Values)
  {
    sum += std::norm(v);
  }
  return sum;
}

bool IsSmooth(int n)
{
  for (int p : { 2, 3, 5 })
  {
    while (n % p == 0)
    {
      n /= p;
    }
  }
  return n == 1;
}

struct GridPeak
{
  double Value;
  Eigen::Vector3d Euler;
};

// Scans slices j = first .. last - 1 for local maxima over the 26 neighbours (α and γ wrap
// around; below β = 0 and above β = π the grid continues as C(α, -β, γ) = C(α+π, β, γ+π)).
// At β = 0 and π only γ = 0 is scanned: there C depends on α ± γ alone.
void ScanSlices(const SO3CorrelationTensor& tensor, int first, int last, int keep,
  std::vector<GridPeak>& peaks)
{
  const int B = tensor.GetBandwidth();
  const int M = tensor.GetGridResolution();
  const std::size_t area = static_cast<std::size_t>(M) * M;
  std::unique_ptr<SO3CorrelationTensor::SliceWorkspace> workspace = tensor.NewSliceWorkspace();
  std::vector<double> storage(3 * area), mirror(area);
  double* window[3] = { storage.data(), storage.data() + area, storage.data() + 2 * area };
  auto load = [&](int j, double* slice) {
    if (j >= 0 && j <= B)
    {
      tensor.SynthesizeSlice(j, *workspace, slice);
      return;
    }
    tensor.SynthesizeSlice(j < 0 ? -j : 2 * B - j, *workspace, mirror.data());
    for (int c = 0; c < M; ++c)
    {
      for (int a = 0; a < M; ++a)
      {
        slice[static_cast<std::size_t>(c) * M + a] =
          mirror[static_cast<std::size_t>((c + M / 2) % M) * M + (a + M / 2) % M];
      }
    }
  };
  load(first - 1, window[0]);
  load(first, window[1]);
  // Min-heap of the best `keep` local maxima.
  auto worse = [](const GridPeak& x, const GridPeak& y) { return x.Value > y.Value; };
  std::vector<GridPeak> heap;
  for (int j = first; j < last; ++j)
  {
    load(j + 1, window[2]);
    const double* below = window[0];
    const double* here = window[1];
    const double* above = window[2];
    const int cCount = (j == 0 || j == B) ? 1 : M;
    for (int c = 0; c < cCount; ++c)
    {
      const int cm = (c + M - 1) % M;
      const int cp = (c + 1) % M;
      for (int a = 0; a < M; ++a)
      {
        const double v = here[static_cast<std::size_t>(c) * M + a];
        if (static_cast<int>(heap.size()) == keep && v <= heap.front().Value)
        {
          continue;
        }
        const int am = (a + M - 1) % M;
        const int ap = (a + 1) % M;
        bool isMaximum = true;
        for (const double* slice : { here, below, above })
        {
          for (int cc : { cm, c, cp })
          {
            const double* row = slice + static_cast<std::size_t>(cc) * M;
            if (row[am] > v || row[a] > v || row[ap] > v)
            {
              isMaximum = false;
              break;
            }
          }
          if (!isMaximum)
          {
            break;
          }
        }
        if (!isMaximum)
        {
          continue;
        }
        GridPeak peak{ v, Eigen::Vector3d(2.0 * M_PI * a / M, M_PI * j / B, 2.0 * M_PI * c / M) };
        if (static_cast<int>(heap.size()) < keep)
        {
          heap.push_back(peak);
          std::push_heap(heap.begin(), heap.end(), worse);
        }
        else
        {
          std::pop_heap(heap.begin(), heap.end(), worse);
          heap.back() = peak;
          std::push_heap(heap.begin(), heap.end(), worse);
        }
      }
    }
    std::rotate(window, window + 1, window + 3);
  }
  peaks.insert(peaks.end(), heap.begin(), heap.end());
}

// Maximizes C from a grid point by Newton's method with the Hessian's eigenvalues forced
// negative (a maximizer even where Euler angles degenerate) and steps capped at one grid
// cell and halved until C does not decrease.
double RefinePeak(const SO3CorrelationTensor& tensor, Eigen::Vector3d& euler)
{
  const double maximumStep = M_PI / tensor.GetBandwidth();
  Eigen::Vector3d gradient;
  Eigen::Matrix3d hessian;
  double value = tensor.Evaluate(euler, &gradient, &hessian);
  for (int iteration = 0; iteration < 20; ++iteration)
  {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(hessian);
    Eigen::Vector3d lambda = eigen.eigenvalues();
    const double scale = std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
    for (int i = 0; i < 3; ++i)
    {
      lambda[i] = std::min(lambda[i], -1e-8 * scale);
    }
    Eigen::Vector3d step =
      -eigen.eigenvectors() * (eigen.eigenvectors().transpose() * gradient).cwiseQuotient(lambda);
    if (step.norm() < 1e-10)
    {
      break; // converged (quadratically): one more evaluation would not change anything
    }
    if (step.norm() > maximumStep)
    {
      step *= maximumStep / step.norm();
    }
    bool accepted = false;
    for (int halving = 0; halving < 30 && !accepted; ++halving, step *= 0.5)
    {
      Eigen::Vector3d trialGradient;
      Eigen::Matrix3d trialHessian;
      const Eigen::Vector3d trial = euler + step;
      const double trialValue = tensor.Evaluate(trial, &trialGradient, &trialHessian);
      if (trialValue >= value - 1e-14 * std::abs(value))
      {
        accepted = true;
        euler = trial;
        value = trialValue;
        gradient = trialGradient;
        hessian = trialHessian;
      }
    }
    if (!accepted)
    {
      break;
    }
  }
  return value;
}

// Best well-separated peaks of one determinant class.
std::vector<SO3Candidate> FindCandidates(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int bandwidth, bool reflect,
  const SO3CorrelationOptions& options, int threads, double energySum)
{
  SO3CorrelationTensor tensor(source, target, bandwidth, reflect, threads);
  tensor.TransformToBetaSamples();
  const int wanted = std::max(1, options.NumberOfCandidates);
  const int keep = 8 * wanted + 8;
  const int slices = bandwidth + 1;
  const int chunks = std::min(slices, threads);
  std::vector<std::vector<GridPeak>> found(chunks);
  ParallelFor(chunks, threads, [&](int chunk, int) {
    const int first = static_cast<int>(static_cast<long long>(slices) * chunk / chunks);
    const int last = static_cast<int>(static_cast<long long>(slices) * (chunk + 1) / chunks);
    ScanSlices(tensor, first, last, keep, found[chunk]);
  });
  std::vector<GridPeak> peaks;
  for (const auto& f : found)
  {
    peaks.insert(peaks.end(), f.begin(), f.end());
  }
  std::sort(peaks.begin(), peaks.end(),
    [](const GridPeak& x, const GridPeak& y) { return x.Value > y.Value; });
  if (options.RefinePeaks)
  {
    tensor.TransformToFourier();
  }
  const double sign = reflect ? -1.0 : 1.0;
  std::vector<SO3Candidate> accepted;
  auto separated = [&](const Eigen::Matrix3d& rotation) {
    for (const SO3Candidate& c : accepted)
    {
      if (RotationAngleBetween(sign * c.Transform, rotation) < options.MinimumCandidateSeparation)
      {
        return false;
      }
    }
    return true;
  };
  for (const GridPeak& peak : peaks)
  {
    if (static_cast<int>(accepted.size()) >= wanted)
    {
      break;
    }
    Eigen::Vector3d euler = peak.Euler;
    if (!separated(EulerZYZToMatrix(euler[0], euler[1], euler[2])))
    {
      continue;
    }
    double score = peak.Value;
    if (options.RefinePeaks)
    {
      score = RefinePeak(tensor, euler);
    }
    const Eigen::Matrix3d rotation = EulerZYZToMatrix(euler[0], euler[1], euler[2]);
    if (!separated(rotation))
    {
      continue; // climbed onto a peak we already have
    }
    SO3Candidate candidate;
    candidate.Transform = sign * rotation;
    candidate.Determinant = sign;
    candidate.EulerAngles = MatrixToEulerZYZ(rotation);
    candidate.Score = score;
    candidate.RegistrationError = energySum > 0 ? (energySum - 2.0 * score) / energySum : 0.0;
    accepted.push_back(candidate);
  }
  return accepted;
}
}

int ChooseCorrelationBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance, int minimum, int maximum)
{
  const int B = std::min(source.Bandwidth, target.Bandwidth);
  std::vector<double> product(B);
  double total = 0;
  for (int l = 0; l < B; ++l)
  {
    double f = 0;
    double g = 0;
    for (int m = -l; m <= l; ++m)
    {
      f += std::norm(source(l, m));
      g += std::norm(target(l, m));
    }
    product[l] = std::sqrt(f * g);
    total += product[l];
  }
  int bandwidth = B;
  double tail = 0;
  while (bandwidth > 1 && tail + product[bandwidth - 1] <= tolerance * total)
  {
    tail += product[--bandwidth];
  }
  const int upper = maximum > 0 ? std::min(maximum, B) : B;
  bandwidth = std::max(bandwidth, std::min(minimum, B));
  bandwidth = std::max(2, std::min(bandwidth, upper));
  int smooth = bandwidth;
  while (smooth < upper && !IsSmooth(smooth))
  {
    ++smooth;
  }
  return IsSmooth(smooth) ? smooth : bandwidth;
}

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

SO3CorrelationResult CorrelateOverRotations(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const SO3CorrelationOptions& options)
{
  SO3CorrelationResult result;
  result.SourceEnergy = Energy(source);
  result.TargetEnergy = Energy(target);
  const int threads = ResolveThreadCount(options.NumberOfThreads);
  const int bandwidth = ChooseCorrelationBandwidth(source, target, options.BandwidthTolerance,
    options.MinimumCorrelationBandwidth, options.MaximumCorrelationBandwidth);
  result.CorrelationBandwidth = bandwidth;
  result.GridResolution = 2 * bandwidth;
  const double energySum = result.SourceEnergy + result.TargetEnergy;
  // The two determinant classes run one after the other so only one tensor is alive.
  if (options.Reflections != SO3ReflectionMode::ReflectionsOnly)
  {
    auto found = FindCandidates(source, target, bandwidth, false, options, threads, energySum);
    result.Candidates.insert(result.Candidates.end(), found.begin(), found.end());
  }
  if (options.Reflections != SO3ReflectionMode::RotationsOnly)
  {
    auto found = FindCandidates(source, target, bandwidth, true, options, threads, energySum);
    result.Candidates.insert(result.Candidates.end(), found.begin(), found.end());
  }
  std::stable_sort(result.Candidates.begin(), result.Candidates.end(),
    [](const SO3Candidate& x, const SO3Candidate& y) { return x.Score > y.Score; });
  if (static_cast<int>(result.Candidates.size()) > std::max(1, options.NumberOfCandidates))
  {
    result.Candidates.resize(std::max(1, options.NumberOfCandidates));
  }
  if (!result.Candidates.empty())
  {
    const SO3Candidate& best = result.Candidates.front();
    result.Transform = best.Transform;
    result.Determinant = best.Determinant;
    result.EulerAngles = best.EulerAngles;
    result.Score = best.Score;
    result.RegistrationError = best.RegistrationError;
  }
  return result;
}
}
