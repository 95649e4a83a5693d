#include "SO3Correlation.h"

#include "ParallelFor.h"
#include "Rotation.h"
#include "SO3CorrelationTensor.h"
#include "WignerD.h"

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
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

// A strict total order on grid peaks, best first: by value, ties broken by position. Each
// chunk of slices keeps its best peaks in this order, so the best of all chunks together are
// the same however the slices were split among threads.
bool IsBetter(const GridPeak& x, const GridPeak& y)
{
  if (x.Value != y.Value)
  {
    return x.Value > y.Value;
  }
  return std::lexicographical_compare(
    x.Euler.data(), x.Euler.data() + 3, y.Euler.data(), y.Euler.data() + 3);
}

// Slice j of the grid into `slice`. Below β = 0 and above β = π the grid continues as
// C(α, -β, γ) = C(α+π, β, γ+π): such a slice is the mirrored slice (in `mirror`) shifted by
// half a turn in α and γ.
void LoadSlice(const SO3CorrelationTensor& tensor, SO3CorrelationTensor::SliceWorkspace& workspace,
  int j, std::vector<double>& mirror, double* slice)
{
  const int B = tensor.GetBandwidth();
  const int M = tensor.GetGridResolution();
  if (j >= 0 && j <= B)
  {
    tensor.SynthesizeSlice(j, workspace, slice);
    return;
  }
  tensor.SynthesizeSlice(j < 0 ? -j : 2 * B - j, workspace, mirror.data());
  for (int c = 0; c < M; ++c)
  {
    for (int a = 0; a < M; ++a)
    {
      slice[static_cast<std::size_t>(c) * M + a] =
        mirror[static_cast<std::size_t>((c + M / 2) % M) * M + (a + M / 2) % M];
    }
  }
}

// Whether the value at row c, column a of `here` is at least each of its 26 neighbours in
// the slices below, here and above (α and γ wrap around; M samples per row).
bool IsLocalMaximum(const double* below, const double* here, const double* above, int c, int a,
  int M, bool poleSlice)
{
  const double v = here[static_cast<std::size_t>(c) * M + a];
  const int cm = (c + M - 1) % M, cp = (c + 1) % M;
  const int am = (a + M - 1) % M, ap = (a + 1) % M;
  for (const double* slice : { here, below, above })
  {
    for (int cc : { cm, c, cp })
    {
      if (poleSlice && slice == here && cc != c)
      {
        // On a pole slice the rows c ± 1 repeat row c shifted by one sample (C depends
        // on α ± γ only), so one neighbour there equals v up to round-off, which must
        // not decide whether v is a maximum. Row c's own a ± 1 cover them.
        continue;
      }
      const double* row = slice + static_cast<std::size_t>(cc) * M;
      if (row[am] > v || row[a] > v || row[ap] > v)
      {
        return false;
      }
    }
  }
  return true;
}

// Adds `peak` to the heap of the best `keep` peaks (the worst of them at the front).
void KeepIfBest(const GridPeak& peak, int keep, std::vector<GridPeak>& heap)
{
  if (static_cast<int>(heap.size()) < keep)
  {
    heap.push_back(peak);
    std::push_heap(heap.begin(), heap.end(), IsBetter);
  }
  else if (IsBetter(peak, heap.front()))
  {
    std::pop_heap(heap.begin(), heap.end(), IsBetter);
    heap.back() = peak;
    std::push_heap(heap.begin(), heap.end(), IsBetter);
  }
}

// The local maxima of slice j (window: slices j - 1, j, j + 1) into the heap of the best
// `keep`. At β = 0 and π only γ = 0 is scanned: there C depends on α ± γ alone.
void ScanSlice(int j, int B, int M, const double* const window[3], int keep,
  std::vector<GridPeak>& heap)
{
  const bool poleSlice = j == 0 || j == B;
  const int cCount = poleSlice ? 1 : M;
  for (int c = 0; c < cCount; ++c)
  {
    for (int a = 0; a < M; ++a)
    {
      const double v = window[1][static_cast<std::size_t>(c) * M + a];
      if ((static_cast<int>(heap.size()) == keep && v < heap.front().Value) ||
        !IsLocalMaximum(window[0], window[1], window[2], c, a, M, poleSlice))
      {
        continue;
      }
      KeepIfBest(
        { v, Eigen::Vector3d(2.0 * M_PI * a / M, M_PI * j / B, 2.0 * M_PI * c / M) }, keep, heap);
    }
  }
}

// Scans slices j = first .. last - 1 for local maxima over the 26 neighbours, keeping the
// best `keep` in `peaks`. `next` is called after each slice; false from it ends the scan
// early.
void ScanSlices(const SO3CorrelationTensor& tensor, int first, int last, int keep,
  std::vector<GridPeak>& peaks, const std::function<bool()>& next)
{
  const int B = tensor.GetBandwidth();
  const int M = tensor.GetGridResolution();
  const std::size_t area = static_cast<std::size_t>(M) * M;
  std::unique_ptr<SO3CorrelationTensor::SliceWorkspace> workspace = tensor.NewSliceWorkspace();
  std::vector<double> storage(3 * area), mirror(area);
  double* window[3] = { storage.data(), storage.data() + area, storage.data() + 2 * area };
  LoadSlice(tensor, *workspace, first - 1, mirror, window[0]);
  LoadSlice(tensor, *workspace, first, mirror, window[1]);
  std::vector<GridPeak> heap;
  for (int j = first; j < last; ++j)
  {
    LoadSlice(tensor, *workspace, j + 1, mirror, window[2]);
    ScanSlice(j, B, M, window, keep, heap);
    std::rotate(window, window + 1, window + 3);
    if (!next())
    {
      break;
    }
  }
  peaks.insert(peaks.end(), heap.begin(), heap.end());
}

// Newton step for maximizing a function with gradient g and Hessian H: the Hessian's
// eigenvalues are forced negative, so the step is uphill even where H is indefinite or where
// Euler angles degenerate (β = 0, π: one direction has no curvature and no gradient).
Eigen::Vector3d MaximizingNewtonStep(const Eigen::Vector3d& gradient, const Eigen::Matrix3d& hessian)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(hessian);
  Eigen::Vector3d lambda = eigen.eigenvalues();
  const double scale = std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
  for (int i = 0; i < 3; ++i)
  {
    lambda[i] = std::min(lambda[i], -1e-8 * scale);
  }
  return -eigen.eigenvectors() * (eigen.eigenvectors().transpose() * gradient).cwiseQuotient(lambda);
}

// Maximizes C from a grid point by Newton's method on the tensor, steps capped at one grid
// cell and halved until C does not decrease. A true peak converges from its grid point in 4-7
// steps; grid maxima on ridges of C would crawl along them, so the iterations are capped.
// Single-threaded (peaks run in parallel).
double RefinePeak(const SO3CorrelationTensor& tensor, Eigen::Vector3d& euler)
{
  const double maximumStep = M_PI / tensor.GetBandwidth();
  Eigen::Vector3d gradient;
  Eigen::Matrix3d hessian;
  double value = tensor.Evaluate(euler, &gradient, &hessian, 1);
  for (int iteration = 0; iteration < 12; ++iteration)
  {
    Eigen::Vector3d step = MaximizingNewtonStep(gradient, hessian);
    if (step.norm() < 1e-10)
    {
      break; // converged (quadratically): one more evaluation would not change anything
    }
    if (step.norm() > maximumStep)
    {
      step *= maximumStep / step.norm();
    }
    bool accepted = false;
    for (int halving = 0; halving < 20 && !accepted; ++halving, step *= 0.5)
    {
      Eigen::Vector3d trialGradient;
      Eigen::Matrix3d trialHessian;
      const Eigen::Vector3d trial = euler + step;
      const double trialValue = tensor.Evaluate(trial, &trialGradient, &trialHessian, 1);
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

// A peak T = ±R(α,β,γ) · Q, with Q = I, or Q = Ry(π/2) when R itself would sit near the
// singular β = 0, π of the Euler chart (see PolishPeaks).
struct Peak
{
  Eigen::Vector3d Euler;
  double Score;
  bool Reflect;
  bool QuarterTurnChart = false;
};

Eigen::Matrix3d PeakRotation(const Peak& peak)
{
  const Eigen::Matrix3d rotation = EulerZYZToMatrix(peak.Euler[0], peak.Euler[1], peak.Euler[2]);
  return peak.QuarterTurnChart ? Eigen::Matrix3d(rotation * RotationAboutY(M_PI / 2)) : rotation;
}

Eigen::Matrix3d PeakTransform(const Peak& peak)
{
  const Eigen::Matrix3d rotation = PeakRotation(peak);
  return peak.Reflect ? Eigen::Matrix3d(-rotation) : rotation;
}

// Coefficients of f∘Q⁻¹ for Q = Ry(π/2): D^l(0, π/2, 0) = Δ^l, so f'_lm = Σ_n Δ^l_mn f_ln.
// Computed for m >= 0; f' is real, so f'_{l,-m} = (-1)^m conj(f'_lm).
SphericalHarmonicCoefficients RotateQuarterTurnAboutY(
  const SphericalHarmonicCoefficients& f, int bandwidth, int threads)
{
  SphericalHarmonicCoefficients rotated;
  rotated.Resize(bandwidth);
  ParallelFor(bandwidth, threads, [&](int task, int) {
    const int l = bandwidth - 1 - task;
    std::vector<double> quadrant(static_cast<std::size_t>(l + 1) * (l + 1));
    ComputeWignerDeltaQuadrant(l, quadrant.data());
    for (int m = 0; m <= l; ++m)
    {
      // Δ_{m,-n} = (-1)^(l+m) Δ_mn.
      const double* row = quadrant.data() + static_cast<std::size_t>(m) * (l + 1);
      const double sign = ((l + m) & 1) ? -1.0 : 1.0;
      std::complex<double> sum = row[0] * f(l, 0);
      for (int n = 1; n <= l; ++n)
      {
        sum += row[n] * (f(l, n) + sign * f(l, -n));
      }
      rotated(l, m) = sum;
      if (m > 0)
      {
        rotated(l, -m) = ((m & 1) ? -1.0 : 1.0) * std::conj(sum);
      }
    }
  });
  return rotated;
}

// Keeps peaks (already sorted best first) that are at least `separation` away from every
// better kept peak of the same determinant, up to `wanted` of them.
std::vector<Peak> SelectSeparated(const std::vector<Peak>& peaks, double separation, int wanted)
{
  std::vector<Peak> kept;
  for (const Peak& peak : peaks)
  {
    if (static_cast<int>(kept.size()) >= wanted)
    {
      break;
    }
    const Eigen::Matrix3d transform = PeakTransform(peak);
    bool separated = true;
    for (const Peak& other : kept)
    {
      if (other.Reflect == peak.Reflect &&
        RotationAngleBetween(PeakTransform(other), transform) < separation)
      {
        separated = false;
        break;
      }
    }
    if (separated)
    {
      kept.push_back(peak);
    }
  }
  return kept;
}

// The best `keep` local maxima of the tensor's grid (sampled in β), best first, the same
// for any thread count. `progress` (0.2 to 0.9 of the search) runs on the calling thread;
// false from it stops the scan (`aborted`, no peaks).
std::vector<GridPeak> ScanGrid(const SO3CorrelationTensor& tensor, int keep, int threads,
  const std::function<bool(double)>& progress, bool& aborted)
{
  const int slices = tensor.GetBandwidth() + 1;
  const int chunks = std::min(slices, threads);
  std::vector<std::vector<GridPeak>> found(chunks);
  // Progress is reported (and an abort heard) after each slice by the calling thread, the
  // pool's thread 0; the other threads only count their slices and look at the stop flag.
  std::atomic<int> scanned(0);
  std::atomic<bool> stop(false);
  ParallelFor(chunks, threads, [&](int chunk, int thread) {
    const int first = static_cast<int>(static_cast<long long>(slices) * chunk / chunks);
    const int last = static_cast<int>(static_cast<long long>(slices) * (chunk + 1) / chunks);
    ScanSlices(tensor, first, last, keep, found[chunk], [&] {
      const int done = ++scanned;
      if (thread == 0 && !progress(0.2 + 0.7 * done / slices))
      {
        stop = true;
      }
      return !stop;
    });
  });
  if (stop)
  {
    aborted = true;
    return {};
  }
  std::vector<GridPeak> gridPeaks;
  for (const auto& f : found)
  {
    gridPeaks.insert(gridPeaks.end(), f.begin(), f.end());
  }
  // Ties broken by position so the order does not depend on how the slices were split.
  std::sort(gridPeaks.begin(), gridPeaks.end(), IsBetter);
  if (static_cast<int>(gridPeaks.size()) > keep)
  {
    gridPeaks.resize(keep); // the best `keep` of all slices, whatever the split
  }
  return gridPeaks;
}

// Whether `peak` is at least `separation` from each of `others` (all of one determinant).
bool SeparatedFromAll(const Peak& peak, const std::vector<Peak>& others, double separation)
{
  const Eigen::Matrix3d transform = PeakTransform(peak);
  for (const Peak& other : others)
  {
    if (RotationAngleBetween(PeakTransform(other), transform) < separation)
    {
      return false;
    }
  }
  return true;
}

// The next grid peaks (from `next` on) to refine together, up to one per thread: those
// separated from the accepted peaks are taken as long as each is separated from the batch's
// earlier members (otherwise the batch ends there).
std::vector<Peak> NextBatch(const std::vector<GridPeak>& gridPeaks, bool reflect,
  const std::vector<Peak>& accepted, double separation, int threads, std::size_t& next)
{
  std::vector<Peak> batch;
  while (next < gridPeaks.size() && static_cast<int>(batch.size()) < threads)
  {
    const Peak candidate{ gridPeaks[next].Euler, gridPeaks[next].Value, reflect };
    if (!SeparatedFromAll(candidate, accepted, separation))
    {
      ++next;
      continue;
    }
    if (!SeparatedFromAll(candidate, batch, separation))
    {
      break;
    }
    batch.push_back(candidate);
    ++next;
  }
  return batch;
}

// Refines the batch's peaks on the coarse tensor (when asked) and accepts them peak by peak,
// up to `wanted`: one is skipped if it, or its refinement, comes near an accepted peak.
void RefineAndAccept(std::vector<Peak> batch, const SO3CorrelationTensor& tensor, bool refine,
  double separation, int threads, int wanted, std::vector<Peak>& accepted)
{
  const std::vector<Peak> unrefined = batch;
  if (refine)
  {
    ParallelFor(static_cast<int>(batch.size()), threads,
      [&](int i, int) { batch[i].Score = RefinePeak(tensor, batch[i].Euler); });
  }
  for (std::size_t i = 0; i < batch.size(); ++i)
  {
    if (static_cast<int>(accepted.size()) < wanted &&
      SeparatedFromAll(unrefined[i], accepted, separation) &&
      SeparatedFromAll(batch[i], accepted, separation))
    {
      accepted.push_back(batch[i]);
    }
  }
}

// Stage 1 for one determinant class: grid search at the coarse bandwidth, Newton on the
// coarse tensor, and up to `wanted` well-separated peaks, best first.
// `progress` (fraction of this search) runs on the calling thread; false from it stops the
// search (`aborted`, no peaks).
std::vector<Peak> SearchGrid(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int bandwidth, bool reflect,
  const SO3CorrelationOptions& options, int threads, int wanted,
  const std::function<bool(double)>& progress, bool& aborted)
{
  SO3CorrelationTensor tensor(source, target, bandwidth, reflect, threads);
  tensor.TransformToBetaSamples();
  if (!progress(0.2))
  {
    aborted = true;
    return {};
  }
  const std::vector<GridPeak> gridPeaks =
    ScanGrid(tensor, 8 * wanted + 8, threads, progress, aborted);
  if (gridPeaks.empty())
  {
    return {};
  }
  if (options.RefinePeaks)
  {
    tensor.TransformToFourier();
  }
  // Grid peaks are taken in order: one not separated from an accepted (refined) peak is
  // skipped, otherwise it is refined and accepted unless it climbed near an accepted peak.
  // For parallelism a batch of upcoming peaks is refined ahead (NextBatch); the batch is then
  // accepted peak by peak with exactly the rule above, so a refinement made ahead for a peak
  // that the rule skips is dropped, and the result is the one-thread result.
  std::vector<Peak> accepted;
  std::size_t next = 0;
  while (next < gridPeaks.size() && static_cast<int>(accepted.size()) < wanted)
  {
    RefineAndAccept(NextBatch(gridPeaks, reflect, accepted, options.MinimumCandidateSeparation,
                      threads, next),
      tensor, options.RefinePeaks, options.MinimumCandidateSeparation, threads, wanted, accepted);
  }
  return accepted;
}

// A peak's Newton iteration in PolishPeaks: the last accepted point and the step tried
// from it.
struct PolishState
{
  Eigen::Vector3d Base; // last accepted point
  double BaseValue = 0;
  bool HasBase = false;
  Eigen::Vector3d Step = Eigen::Vector3d::Zero();
  int Halvings = 0;
  bool Done = false;
};

// Near β = 0 or π the Euler chart is singular (only α ± γ is defined, and one direction of
// rotation is missing to first order), and Newton's method there stalls. Such peaks move to
// the chart T = R · Ry(π/2): C(R · Q) is the correlation of the rotated source f∘Q⁻¹ at R,
// and R's β is near π/2. Returns that rotated source (empty if no peak moved).
SphericalHarmonicCoefficients MoveOffSingularChart(const SphericalHarmonicCoefficients& source,
  int bandwidth, int threads, std::vector<Peak>& peaks)
{
  SphericalHarmonicCoefficients quarterTurnSource;
  for (Peak& peak : peaks)
  {
    if (!peak.QuarterTurnChart && std::abs(std::sin(peak.Euler[1])) < 0.5)
    {
      const Eigen::Matrix3d rotation = PeakRotation(peak);
      peak.Euler = MatrixToEulerZYZ(rotation * RotationAboutY(-M_PI / 2));
      peak.QuarterTurnChart = true;
      if (quarterTurnSource.Bandwidth == 0)
      {
        quarterTurnSource = RotateQuarterTurnAboutY(source, bandwidth, threads);
      }
    }
  }
  return quarterTurnSource;
}

// The correlation and its derivatives at the trial point of every peak still polishing, the
// ordinary chart's peaks first, then the quarter-turned ones; `owner[s]` is sample s's peak.
std::vector<SO3CorrelationSample> EvaluateTrialPoints(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& quarterTurnSource,
  const SphericalHarmonicCoefficients& target, int bandwidth, int threads,
  const std::vector<Peak>& peaks, const std::vector<PolishState>& states,
  std::vector<std::size_t>& owner)
{
  std::vector<SO3CorrelationSample> samples;
  for (int chart = 0; chart < 2; ++chart)
  {
    std::vector<SO3CorrelationSample> group;
    for (std::size_t i = 0; i < peaks.size(); ++i)
    {
      if (!states[i].Done && peaks[i].QuarterTurnChart == (chart == 1))
      {
        SO3CorrelationSample sample;
        sample.EulerAngles = states[i].HasBase ? Eigen::Vector3d(states[i].Base + states[i].Step)
                                               : peaks[i].Euler;
        sample.ReflectSource = peaks[i].Reflect;
        group.push_back(sample);
        owner.push_back(i);
      }
    }
    if (!group.empty())
    {
      EvaluateCorrelationSamples(
        chart == 1 ? quarterTurnSource : source, target, group, bandwidth, threads);
      samples.insert(samples.end(), group.begin(), group.end());
    }
  }
  return samples;
}

// One Newton update of a peak from its evaluated trial point. A trial point that lowers C
// halves the step; a peak is done when its Newton step is below 1e-6 rad (the step is then
// applied without another pass: the position error left is of order |step|^2 times the
// bandwidth, and the score is the quadratic model's value there).
void AdvancePeak(const SO3CorrelationSample& sample, double maximumStep, PolishState& state,
  Peak& peak)
{
  if (state.HasBase && sample.Value < state.BaseValue - 1e-14 * std::abs(state.BaseValue))
  {
    // Uphill step went too far: halve it (the base stays the answer if it never works).
    state.Step *= 0.5;
    state.Done = ++state.Halvings > 40;
    return;
  }
  state.Base = sample.EulerAngles;
  state.BaseValue = sample.Value;
  state.HasBase = true;
  state.Halvings = 0;
  peak.Euler = state.Base;
  peak.Score = state.BaseValue;
  Eigen::Vector3d step = MaximizingNewtonStep(sample.Gradient, sample.Hessian);
  if (step.norm() > maximumStep)
  {
    step *= maximumStep / step.norm();
  }
  if (step.norm() < 1e-6)
  {
    const double model =
      sample.Value + sample.Gradient.dot(step) + 0.5 * step.dot(sample.Hessian * step);
    if (model >= sample.Value)
    {
      peak.Euler = state.Base + step;
      peak.Score = model;
    }
    state.Done = true;
    return;
  }
  state.Step = step;
}

// A peak that climbed within `separation` of a better one is the same peak (or would be
// dropped next to it): it stops polishing.
void StopMergedPeaks(const std::vector<Peak>& peaks, double separation,
  std::vector<PolishState>& states)
{
  for (std::size_t i = 0; i < peaks.size(); ++i)
  {
    if (states[i].Done)
    {
      continue;
    }
    const Eigen::Matrix3d transform = PeakTransform(peaks[i]);
    for (std::size_t j = 0; j < peaks.size(); ++j)
    {
      if (j != i && peaks[j].Reflect == peaks[i].Reflect && peaks[j].Score > peaks[i].Score &&
        RotationAngleBetween(PeakTransform(peaks[j]), transform) < separation)
      {
        states[i].Done = true;
        break;
      }
    }
  }
}

// Stage 2: Newton's method on the correlation over bands l < bandwidth for all peaks at once
// (one EvaluateCorrelationSamples pass per iteration, AdvancePeak for each peak).
void PolishPeaks(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int bandwidth, double maximumStep,
  double separation, int threads, std::vector<Peak>& peaks)
{
  std::vector<PolishState> states(peaks.size());
  const int maximumPasses = 8;
  const SphericalHarmonicCoefficients quarterTurnSource =
    MoveOffSingularChart(source, bandwidth, threads, peaks);
  for (int pass = 0; pass < maximumPasses; ++pass)
  {
    std::vector<std::size_t> owner;
    const std::vector<SO3CorrelationSample> samples = EvaluateTrialPoints(
      source, quarterTurnSource, target, bandwidth, threads, peaks, states, owner);
    if (samples.empty())
    {
      break;
    }
    for (std::size_t s = 0; s < samples.size(); ++s)
    {
      AdvancePeak(samples[s], maximumStep, states[owner[s]], peaks[owner[s]]);
    }
    StopMergedPeaks(peaks, separation, states);
  }
}

// |f_l| |g_l| per band l < B (|f_l| the norm of band l's coefficients) and their sum: by
// Cauchy-Schwarz, band l changes the correlation anywhere by at most this product.
std::vector<double> BandNormProducts(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, int B, double& total)
{
  std::vector<double> product(B);
  total = 0;
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
  return product;
}
}

int ChooseCorrelationBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance, int minimum, int maximum)
{
  const int B = std::min(source.Bandwidth, target.Bandwidth);
  double total = 0;
  const std::vector<double> product = BandNormProducts(source, target, B, total);
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

int ChooseRefinementBandwidth(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, double tolerance)
{
  const int B = std::min(source.Bandwidth, target.Bandwidth);
  if (!(tolerance > 0))
  {
    return B;
  }
  double total = 0;
  const std::vector<double> product = BandNormProducts(source, target, B, total);
  int bandwidth = B;
  double tail = 0;
  while (bandwidth > 1)
  {
    const double l = bandwidth - 1;
    const double next = tail + (l + 1) * (l + 1) * product[bandwidth - 1];
    if (next > tolerance * total)
    {
      break;
    }
    tail = next;
    --bandwidth;
  }
  return std::max(bandwidth, std::min(B, 2));
}

namespace
{
using Complex = std::complex<double>;
using BlockMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
using BlockMap = Eigen::Map<BlockMatrix>;

// Phase tables per sample c and index 0 <= j < B, at c * B + j: e^{-ijα} i^j, e^{-ijγ} i^{-j}
// and e^{-ijβ}.
struct SamplePhases
{
  std::vector<Complex> Alpha, Gamma, Beta;
};

SamplePhases ComputeSamplePhases(const std::vector<SO3CorrelationSample>& samples, int B)
{
  const int count = static_cast<int>(samples.size());
  const std::size_t table = static_cast<std::size_t>(count) * B;
  SamplePhases phases{ std::vector<Complex>(table), std::vector<Complex>(table),
    std::vector<Complex>(table) };
  for (int c = 0; c < count; ++c)
  {
    const Eigen::Vector3d& e = samples[c].EulerAngles;
    static const Complex powersOfI[4] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
    for (int m = 0; m < B; ++m)
    {
      phases.Alpha[c * B + m] = std::polar(1.0, -m * e[0]) * powersOfI[m & 3];
      phases.Gamma[c * B + m] = std::polar(1.0, -m * e[2]) * powersOfI[(4 - (m & 3)) & 3];
      phases.Beta[c * B + m] = std::polar(1.0, -m * e[1]);
    }
  }
  return phases;
}

// One thread's buffers for the bands it correlates, sized for the largest band.
struct BandScratch
{
  std::vector<double> Work;
  std::vector<double> Delta;  // four blocks E[kp][mp], column-major
  std::vector<double> Right;  // per mp: real and imaginary right-hand sides
  std::vector<double> Result; // per kp: P (real parts of u, v) and Q (imaginary parts)
};

// Band l's blocks, split by the parity of their indices, in a thread's scratch: rows[p] of
// the indices in [0, l] with parity p; Delta[kp][mp] the Δ_km with k, m of those parities;
// Right[mp][part] and Result[kp][part] the real (part 0) and imaginary (part 1) parts of the
// 6 columns per sample.
struct BandBlocks
{
  int Rows[2];
  double* Delta[2][2];
  double* Right[2][2];
  double* Result[2][2];

  BandBlocks(int l, std::size_t half, int columns, BandScratch& s)
    : Rows{ l / 2 + 1, (l + 1) / 2 }
  {
    for (int p = 0; p < 2; ++p)
    {
      for (int q = 0; q < 2; ++q)
      {
        this->Delta[p][q] = s.Delta.data() + (2 * p + q) * half * half;
        this->Right[p][q] = s.Right.data() + (2 * p + q) * half * columns;
        this->Result[p][q] = s.Result.data() + (2 * p + q) * half * columns;
      }
    }
  }
};

// The Wigner Δ^l blocks, rows and columns split by parity.
void FillDeltaBlocks(int l, BandScratch& s, BandBlocks& blocks)
{
  const int* rows = blocks.Rows;
  VisitWignerDeltaColumns(l, s.Work, [&](int m, const double* column) {
    const int mp = m & 1;
    double* even = blocks.Delta[0][mp] + static_cast<std::size_t>(m >> 1) * rows[0];
    double* odd = blocks.Delta[1][mp] + static_cast<std::size_t>(m >> 1) * rows[1];
    for (int i = 0; i < rows[0]; ++i)
    {
      even[i] = column[2 * i];
    }
    for (int i = 0; i < rows[1]; ++i)
    {
      odd[i] = column[2 * i + 1];
    }
  });
}

// Right-hand sides: Right[mp][0] = w Re(.), Right[mp][1] = w Im(.), rows m = 2j + mp, the
// columns a, ∂α a, ∂α² a, b, ∂γ b, ∂γ² b of each sample.
void FillRightHandSides(int l, const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const std::vector<SO3CorrelationSample>& samples,
  const SamplePhases& phases, int B, BandBlocks& blocks)
{
  const int count = static_cast<int>(samples.size());
  for (int c = 0; c < count; ++c)
  {
    const double sourceSign = (samples[c].ReflectSource && (l & 1)) ? -1.0 : 1.0;
    for (int m = 0; m <= l; ++m)
    {
      const double w = m == 0 ? 1.0 : 2.0;
      const Complex a = w * std::conj(target(l, m)) * phases.Alpha[c * B + m];
      const Complex b = (w * sourceSign) * source(l, m) * phases.Gamma[c * B + m];
      const Complex minusIm(0, -m);
      const Complex values[6] = { a, minusIm * a, -double(m) * m * a, b, minusIm * b,
        -double(m) * m * b };
      const int mp = m & 1;
      const std::size_t row = m >> 1;
      for (int q = 0; q < 6; ++q)
      {
        const std::size_t index = static_cast<std::size_t>(6 * c + q) * blocks.Rows[mp] + row;
        blocks.Right[mp][0][index] = values[q].real();
        blocks.Right[mp][1][index] = values[q].imag();
      }
    }
  }
}

// The four real block products: u_k and v_k for every k >= 0, real and imaginary parts.
void MultiplyBlocks(int l, int columns, BandBlocks& blocks)
{
  const int* rows = blocks.Rows;
  for (int kp = 0; kp < 2; ++kp)
  {
    if (rows[kp] == 0)
    {
      continue;
    }
    const int realParity = (l + kp) & 1; // m ≡ l + k contributes to the real part
    for (int part = 0; part < 2; ++part)
    {
      const int mp = part == 0 ? realParity : 1 - realParity;
      BlockMap out(blocks.Result[kp][part], rows[kp], columns);
      if (rows[mp] == 0)
      {
        out.setZero();
        continue;
      }
      const BlockMap delta(blocks.Delta[kp][mp], rows[kp], rows[mp]);
      const BlockMap rhs(blocks.Right[mp][part], rows[mp], columns);
      out.noalias() = delta * rhs;
    }
  }
}

// Band l's 10 sums of sample c (C, ∂α, ∂β, ∂γ, αα, αβ, αγ, ββ, βγ, γγ) from u and v:
// Re Σ_{k>=0} w_k u_k v_k e^{-ikβ} and its derivatives, ∂β bringing down -ik.
void SumBand(int l, int c, const BandBlocks& blocks, const Complex* betaPhase, double* sum)
{
  std::fill(sum, sum + 10, 0.0);
  for (int k = 0; k <= l; ++k)
  {
    const int kp = k & 1;
    const std::size_t i = k >> 1;
    auto at = [&](int q) {
      const std::size_t index = static_cast<std::size_t>(6 * c + q) * blocks.Rows[kp] + i;
      return Complex(blocks.Result[kp][0][index], blocks.Result[kp][1][index]);
    };
    const Complex u0 = at(0), u1 = at(1), u2 = at(2), v0 = at(3), v1 = at(4), v2 = at(5);
    const Complex e = (k == 0 ? 1.0 : 2.0) * betaPhase[k];
    const Complex t(0, -k); // ∂β
    const Complex u0e = u0 * e;
    const Complex u1e = u1 * e;
    const Complex value = u0e * v0;
    sum[0] += value.real();
    sum[1] += (u1e * v0).real();
    sum[2] += (t * value).real();
    sum[3] += (u0e * v1).real();
    sum[4] += (u2 * e * v0).real();
    sum[5] += (t * u1e * v0).real();
    sum[6] += (u1e * v1).real();
    sum[7] += (t * t * value).real();
    sum[8] += (t * u0e * v1).real();
    sum[9] += (u0e * v2).real();
  }
}

// Each sample's value, gradient and Hessian: the per-band sums added in band order (the
// same for any number of threads).
void AddBands(const std::vector<double>& perBand, int B, std::vector<SO3CorrelationSample>& samples)
{
  const int count = static_cast<int>(samples.size());
  for (int c = 0; c < count; ++c)
  {
    double total[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
    for (int l = 0; l < B; ++l)
    {
      const double* band = perBand.data() + (static_cast<std::size_t>(l) * count + c) * 10;
      for (int q = 0; q < 10; ++q)
      {
        total[q] += band[q];
      }
    }
    SO3CorrelationSample& sample = samples[c];
    sample.Value = total[0];
    sample.Gradient = Eigen::Vector3d(total[1], total[2], total[3]);
    sample.Hessian << total[4], total[5], total[6], total[5], total[7], total[8], total[6],
      total[8], total[9];
  }
}
}

// Per band l, with a_m = conj(g_lm) e^{-imα} i^m and b_n = ±f_ln e^{-inγ} i^{-n}
// (d = i^(m-n) Σ_k Δ_km Δ_kn e^{-ikβ}):
//   C = Σ_k u_k v_k e^{-ikβ},  u_k = Σ_m Δ_km a_m,  v_k = Σ_n Δ_kn b_n,  |k|, |m|, |n| <= l.
// Real g gives a_{-m} = (-1)^m conj(a_m), and with Δ_{k,-m} = (-1)^(l+k) Δ_km, for k >= 0
//   u_k = Σ_{m>=0, m ≡ l+k} Δ_km w_m Re a_m + i Σ_{m>=0, m ≢ l+k} Δ_km w_m Im a_m
// (w_0 = 1, w_m = 2; mod 2), and u_{-k} = (-1)^k conj(u_k), likewise for v; so
//   C = Re Σ_{k>=0} w_k u_k v_k e^{-ikβ}.
// Splitting k and m by parity, each band is four real products of a Δ block (about l/2 square)
// with 6 columns per sample (a, ∂α a, ∂α² a, b, ∂γ b, ∂γ² b); ∂β brings down -ik.
void EvaluateCorrelationSamples(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, std::vector<SO3CorrelationSample>& samples,
  int bandwidth, int numberOfThreads)
{
  int B = std::min(source.Bandwidth, target.Bandwidth);
  if (bandwidth > 0)
  {
    B = std::min(B, bandwidth);
  }
  const int count = static_cast<int>(samples.size());
  for (SO3CorrelationSample& sample : samples)
  {
    sample.Value = 0;
    sample.Gradient.setZero();
    sample.Hessian.setZero();
  }
  if (count == 0 || B <= 0)
  {
    return;
  }
  const int threads = std::min(ResolveThreadCount(numberOfThreads), B);
  const SamplePhases phases = ComputeSamplePhases(samples, B);
  const int columns = 6 * count;
  const std::size_t half = static_cast<std::size_t>(B + 1) / 2 + 1; // >= rows of any block
  std::vector<BandScratch> scratch(threads);
  for (BandScratch& s : scratch)
  {
    s.Delta.resize(4 * half * half);
    s.Right.resize(4 * half * columns);
    s.Result.resize(4 * half * columns);
  }
  // 10 sums per sample and band: C, ∂α, ∂β, ∂γ, αα, αβ, αγ, ββ, βγ, γγ.
  std::vector<double> perBand(static_cast<std::size_t>(B) * count * 10, 0.0);
  ParallelFor(B, threads, [&](int task, int thread) {
    const int l = B - 1 - task; // large bands first
    BandBlocks blocks(l, half, columns, scratch[thread]);
    FillDeltaBlocks(l, scratch[thread], blocks);
    FillRightHandSides(l, source, target, samples, phases, B, blocks);
    MultiplyBlocks(l, columns, blocks);
    for (int c = 0; c < count; ++c)
    {
      SumBand(l, c, blocks, phases.Beta.data() + c * B,
        perBand.data() + (static_cast<std::size_t>(l) * count + c) * 10);
    }
  });
  AddBands(perBand, B, samples);
}

SO3Candidate ScoredCandidate(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform, double score)
{
  SO3Candidate candidate;
  candidate.Determinant = transform.determinant() < 0 ? -1.0 : 1.0;
  candidate.Transform = transform;
  candidate.EulerAngles = MatrixToEulerZYZ(candidate.Determinant * transform);
  candidate.Score = score;
  const double sourceEnergy = Energy(source), targetEnergy = Energy(target);
  const double energySum = sourceEnergy + targetEnergy;
  // The constant band (Y_00 is invariant under every orthogonal T) contributes f_00 g_00 to
  // C(T) and |f_00|^2, |g_00|^2 to the energies; without it, the mean-free signals.
  const bool both = source.Bandwidth > 0 && target.Bandwidth > 0;
  const double constantProduct = both ? std::real(source(0, 0) * std::conj(target(0, 0))) : 0.0;
  const double meanFreeNorms = both
    ? std::sqrt(std::max(0.0, sourceEnergy - std::norm(source(0, 0))) *
        std::max(0.0, targetEnergy - std::norm(target(0, 0))))
    : 0.0;
  candidate.RegistrationError = energySum > 0 ? (energySum - 2.0 * score) / energySum : 0.0;
  candidate.CorrelationCoefficient = meanFreeNorms > 0
    ? std::max(-1.0, std::min(1.0, (score - constantProduct) / meanFreeNorms))
    : 0.0;
  return candidate;
}

SO3Candidate ScoreTransform(const SphericalHarmonicCoefficients& source,
  const SphericalHarmonicCoefficients& target, const Eigen::Matrix3d& transform,
  int numberOfThreads)
{
  std::vector<SO3CorrelationSample> samples(1);
  samples[0].ReflectSource = transform.determinant() < 0;
  samples[0].EulerAngles =
    MatrixToEulerZYZ(samples[0].ReflectSource ? Eigen::Matrix3d(-transform) : transform);
  EvaluateCorrelationSamples(source, target, samples, 0, numberOfThreads);
  return ScoredCandidate(source, target, transform, samples[0].Value);
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
  result.RefinementBandwidth = bandwidth;
  const int wanted = std::max(1, options.NumberOfCandidates);
  const int refinementBandwidth =
    std::max(bandwidth, ChooseRefinementBandwidth(source, target, options.RefinementTolerance));
  // Polished even when B'' = B': the polish also handles peaks at degenerate Euler angles.
  const bool polish = options.RefinePeaks;
  // Truncation can reorder peaks whose scores are close, so a couple more than wanted go
  // through the refinement and are ranked by their refined scores.
  const int carried = polish ? wanted + 2 : wanted;
  // The two determinant classes run one after the other so only one tensor is alive.
  std::vector<Peak> peaks;
  // Progress: each determinant class's grid search gets an equal share of the first 90%.
  const int classes = options.Reflections == SO3ReflectionMode::Both ? 2 : 1;
  int searched = 0;
  auto search = [&](bool reflect) {
    auto classProgress = [&](double fraction) {
      return !options.Progress || options.Progress(0.9 * (searched + fraction) / classes);
    };
    auto found = SearchGrid(
      source, target, bandwidth, reflect, options, threads, carried, classProgress, result.Aborted);
    peaks.insert(peaks.end(), found.begin(), found.end());
    ++searched;
  };
  if (options.Reflections != SO3ReflectionMode::ReflectionsOnly)
  {
    search(false);
  }
  if (!result.Aborted && options.Reflections != SO3ReflectionMode::RotationsOnly)
  {
    search(true);
  }
  if (result.Aborted)
  {
    return result;
  }
  if (polish)
  {
    result.RefinementBandwidth = refinementBandwidth;
    PolishPeaks(source, target, refinementBandwidth, M_PI / bandwidth,
      options.MinimumCandidateSeparation, threads, peaks);
  }
  if (options.Progress && !options.Progress(1.0))
  {
    result.Aborted = true;
    return result;
  }
  std::stable_sort(peaks.begin(), peaks.end(),
    [](const Peak& x, const Peak& y) { return x.Score > y.Score; });
  peaks = SelectSeparated(peaks, options.MinimumCandidateSeparation, wanted);
  for (const Peak& peak : peaks)
  {
    const double determinant = peak.Reflect ? -1.0 : 1.0;
    result.Candidates.push_back(
      ScoredCandidate(source, target, determinant * PeakRotation(peak), peak.Score));
  }
  TakeFirstCandidate(result);
  return result;
}

void TakeFirstCandidate(SO3CorrelationResult& result)
{
  if (result.Candidates.empty())
  {
    return;
  }
  const SO3Candidate& best = result.Candidates.front();
  result.Transform = best.Transform;
  result.Determinant = best.Determinant;
  result.EulerAngles = best.EulerAngles;
  result.Score = best.Score;
  result.RegistrationError = best.RegistrationError;
  result.CorrelationCoefficient = best.CorrelationCoefficient;
}
}
