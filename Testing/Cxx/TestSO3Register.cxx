// vtkSO3Register: recovers a known rotation and a known reflection between two copies of a
// centered map; its matrix and Euler angles agree with applying them to points; its
// candidates are CandidateSeparation apart; clear errors for bad inputs; progress and abort
// during the correlation.
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkPolyDataAlgorithm.h"

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> CenteredBumpyMap()
{
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.2, -0.1, 0.3 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  return center->GetOutput();
}

// A copy of `map` with every point moved by `transform`; triangles reversed when it is a
// reflection, so they still face outward.
vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* map, const Eigen::Matrix3d& transform)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(map);
  for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
  {
    double p[3];
    copy->GetPoint(i, p);
    const Eigen::Vector3d q = transform * Eigen::Vector3d(p[0], p[1], p[2]);
    copy->GetPoints()->SetPoint(i, q.data());
  }
  if (transform.determinant() < 0)
  {
    for (vtkIdType c = 0; c < copy->GetNumberOfCells(); ++c)
    {
      copy->ReverseCell(c);
    }
  }
  return copy;
}

Eigen::Matrix3d FieldMatrix(vtkPolyData* data, const char* name)
{
  Eigen::Matrix3d m;
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  for (int k = 0; k < 9; ++k)
  {
    m(k / 3, k % 3) = array->GetComponent(0, k);
  }
  return m;
}

double AngleDegrees(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  const double c = std::max(-1.0, std::min(1.0, ((a * b.transpose()).trace() - 1) / 2));
  return std::acos(c) * 180 / vtkMath::Pi();
}

int TestRecovery()
{
  int failures = 0;
  auto target = CenteredBumpyMap();
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  // The source is the target rotated by `rotation`: the registration must undo it.
  auto source = Transformed(target, rotation);

  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(128);
  registration->Update();
  vtkPolyData* out = registration->GetOutput();
  const Eigen::Matrix3d found = FieldMatrix(out, "Rotation");
  const double error = AngleDegrees(found, rotation.transpose());
  std::cout << "rotation error " << error << " degrees\n";
  MOBIUS_EXPECT(error < 0.2);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "Determinant") == 1);
  MOBIUS_EXPECT(mobius_test::FieldValue(out, "RegistrationError") < 0.01);
  MOBIUS_EXPECT(out->GetFieldData()->GetArray("CandidateTransforms")->GetNumberOfTuples() >= 1);

  // Euler angles: R = Rz(alpha) Ry(beta) Rz(gamma).
  vtkDataArray* euler = out->GetFieldData()->GetArray("EulerAngles");
  const Eigen::Matrix3d fromEuler =
    (Eigen::AngleAxisd(euler->GetComponent(0, 0), Eigen::Vector3d::UnitZ()) *
      Eigen::AngleAxisd(euler->GetComponent(0, 1), Eigen::Vector3d::UnitY()) *
      Eigen::AngleAxisd(euler->GetComponent(0, 2), Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
  MOBIUS_EXPECT((fromEuler - found).norm() < 1e-9);

  // The output points are the source points moved by the matrix: back onto the target.
  double pointError = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], s[3];
    out->GetPoint(i, p);
    target->GetPoint(i, q);
    source->GetPoint(i, s);
    const Eigen::Vector3d moved = found * Eigen::Vector3d(s[0], s[1], s[2]);
    MOBIUS_EXPECT((moved - Eigen::Vector3d(p[0], p[1], p[2])).norm() < 1e-12);
    pointError = std::max(pointError, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  MOBIUS_EXPECT(pointError < 0.2 * vtkMath::Pi() / 180 * 1.01);

  // A mirror image is found with REFLECTIONS, and by ROTATIONS_AND_REFLECTIONS.
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  const Eigen::Matrix3d reflection = rotation * mirror;
  auto mirrored = Transformed(target, reflection);
  for (int mode : { vtkSO3Register::REFLECTIONS, vtkSO3Register::ROTATIONS_AND_REFLECTIONS })
  {
    registration->SetSourceData(mirrored);
    registration->SetTransformMode(mode);
    registration->Update();
    out = registration->GetOutput();
    MOBIUS_EXPECT(mobius_test::FieldValue(out, "Determinant") == -1);
    const Eigen::Matrix3d foundReflection = FieldMatrix(out, "Rotation");
    MOBIUS_EXPECT(std::abs(foundReflection.determinant() + 1) < 1e-9);
    const double reflectionError = AngleDegrees(foundReflection, reflection.inverse());
    std::cout << "reflection error " << reflectionError << " degrees\n";
    MOBIUS_EXPECT(reflectionError < 0.2);
  }
  return failures;
}

// The smallest angle (degrees) between two of the output's candidates; 360 with one.
double SmallestCandidateAngle(vtkPolyData* out)
{
  vtkDataArray* transforms = out->GetFieldData()->GetArray("CandidateTransforms");
  std::vector<Eigen::Matrix3d> candidates;
  for (vtkIdType c = 0; c < transforms->GetNumberOfTuples(); ++c)
  {
    Eigen::Matrix3d m;
    for (int k = 0; k < 9; ++k)
    {
      m(k / 3, k % 3) = transforms->GetComponent(c, k);
    }
    candidates.push_back(m);
  }
  double smallest = 360;
  for (size_t a = 0; a < candidates.size(); ++a)
  {
    for (size_t b = a + 1; b < candidates.size(); ++b)
    {
      smallest = std::min(smallest, AngleDegrees(candidates[a], candidates[b]));
    }
  }
  return smallest;
}

// Eight bumps round the equator of an egg: the correlation of the shape with itself peaks
// at every turn by 45 degrees about the axis.
Eigen::Vector3d EightBumps(const Eigen::Vector3d& x)
{
  double bumps = 1.0;
  for (int k = 0; k < 8; ++k)
  {
    const double angle = k * vtkMath::Pi() / 4;
    const Eigen::Vector3d centre(std::cos(angle), std::sin(angle), 0);
    bumps += 0.3 * std::exp(-20.0 * (x - centre).squaredNorm());
  }
  return Eigen::Vector3d(x.x(), x.y(), 1.4 * x.z() + 0.2 * x.z() * x.z()) * bumps;
}

// The candidates are at least CandidateSeparation apart (60 degrees by default): peaks near
// a better one give way to others. At 10 degrees (the search's own rule) the peaks 45
// degrees apart come back.
int TestCandidateSeparation()
{
  int failures = 0;
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(mobius_test::MakeSphericalMap(4, EightBumps));
  center->Update();
  vtkPolyData* target = center->GetOutput();
  auto source = Transformed(target,
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix());
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(64);
  registration->SetNumberOfCandidates(8);
  MOBIUS_EXPECT(registration->GetCandidateSeparation() == 60);
  registration->Update();
  const double wide = SmallestCandidateAngle(registration->GetOutput());
  registration->SetCandidateSeparation(10);
  registration->Update();
  const double narrow = SmallestCandidateAngle(registration->GetOutput());
  std::cout << "smallest angle between candidates: " << wide << " degrees at 60, " << narrow
            << " at 10\n";
  MOBIUS_EXPECT(wide >= 60 - 1e-6);
  MOBIUS_EXPECT(narrow >= 10 - 1e-6 && narrow < 60);
  return failures;
}

int ExpectError(vtkPolyData* source, vtkPolyData* target, int resolution, const std::string& words)
{
  int failures = 0;
  vtkNew<vtkSO3Register> registration;
  mobius_test::MessageCatcher catcher(registration);
  mobius_test::MessageCatcher executiveCatcher(registration->GetExecutive());
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(resolution);
  registration->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << "expected an error containing '" << words << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(registration->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

int TestBadInputs()
{
  int failures = 0;
  auto map = CenteredBumpyMap();
  failures += ExpectError(map, map, 31, "even and at least 8");
  failures += ExpectError(map, map, 6, "even and at least 8"); // 4 and 6 mapped rotated copies wrongly
  // Too large for any machine: refused before allocating, saying what would fit.
  MOBIUS_EXPECT(vtkSO3Register::LargestResolution(1e9) < 4000);
  MOBIUS_EXPECT(vtkSO3Register::EstimateMemory(vtkSO3Register::LargestResolution(1e9)) <= 1e9);
  failures += ExpectError(map, map, 2000000000, "would fit");
  auto noArea = vtkSmartPointer<vtkPolyData>::New();
  noArea->DeepCopy(map);
  noArea->GetCellData()->RemoveArray("SurfaceArea");
  failures += ExpectError(map, noArea, 16, "Target (port 1)");
  failures += ExpectError(noArea, map, 16, "SurfaceArea");
  auto offSphere = vtkSmartPointer<vtkPolyData>::New();
  offSphere->DeepCopy(map);
  offSphere->GetPoints()->SetPoint(0, 2, 0, 0);
  failures += ExpectError(offSphere, map, 16, "not on the unit sphere");
  return failures;
}

// Progress values seen, and (when AbortAt < 1) the abort button pressed at that fraction.
struct ProgressLog
{
  std::vector<double> Values;
  double AbortAt = 2.0;
};

void OnProgress(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* log = static_cast<ProgressLog*>(clientData);
  const double value = *static_cast<double*>(callData);
  log->Values.push_back(value);
  if (value >= log->AbortAt)
  {
    vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
  }
}

int RunWithProgress(vtkPolyData* map, ProgressLog& log)
{
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(map);
  registration->SetTargetData(map);
  registration->SetResolution(64);
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnProgress);
  callback->SetClientData(&log);
  registration->AddObserver(vtkCommand::ProgressEvent, callback);
  registration->Update();
  return static_cast<int>(registration->GetOutput()->GetNumberOfPoints());
}

// The correlation (after the two signals, 0 to 0.5) reports its progress between 0.5 and
// 0.95, slice by slice of the grid search, and stops when the abort flag is raised there.
int TestProgressAndAbort()
{
  int failures = 0;
  auto map = CenteredBumpyMap();
  ProgressLog full;
  MOBIUS_EXPECT(RunWithProgress(map, full) == map->GetNumberOfPoints());
  int duringCorrelation = 0;
  for (double value : full.Values)
  {
    duringCorrelation += value > 0.5 && value < 0.95;
  }
  MOBIUS_EXPECT(duringCorrelation >= 10);
  MOBIUS_EXPECT(std::is_sorted(full.Values.begin(), full.Values.end()));

  ProgressLog aborted;
  aborted.AbortAt = 0.6;
  MOBIUS_EXPECT(RunWithProgress(map, aborted) == 0);
  // Stopped within the grid search: after the value that raised the flag, at most one more
  // slice (the calling thread may already have started the next chunk) and the pipeline's
  // own final report (1).
  int after = 0;
  for (double value : aborted.Values)
  {
    after += value > 0.6 && value < 1.0;
  }
  MOBIUS_EXPECT(after <= 2);
  return failures;
}
}

int TestSO3Register(int, char*[])
{
  int failures = TestRecovery();
  failures += TestCandidateSeparation();
  failures += TestBadInputs();
  failures += TestProgressAndAbort();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
