// Regression image: a centered map rotated away (left), the same map after vtkSO3Register
// (middle) and the target it was aligned with (right), colored by log area distortion; the
// middle and right pictures must match.
#include "MobiusTestRendering.h"
#include "MobiusTestUtilities.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"

#include <Eigen/Geometry>

int TestSO3RegisterImage(int argc, char* argv[])
{
  auto map = mobius_test::MakeSphericalMap(4, mobius_test::BumpySurface, { 0.2, -0.1, 0.3 });
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->Update();
  vtkNew<vtkPolyData> target;
  target->DeepCopy(center->GetOutput());
  vtkNew<vtkPolyData> source;
  source->DeepCopy(target);
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, -1, 0.5).normalized()).toRotationMatrix();
  for (vtkIdType i = 0; i < source->GetNumberOfPoints(); ++i)
  {
    double p[3];
    source->GetPoint(i, p);
    const Eigen::Vector3d q = rotation * Eigen::Vector3d(p[0], p[1], p[2]);
    source->GetPoints()->SetPoint(i, q.data());
  }
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(source);
  registration->SetTargetData(target);
  registration->SetResolution(128);
  registration->Update();
  vtkNew<vtkPolyData> aligned;
  aligned->DeepCopy(registration->GetOutput());
  for (vtkPolyData* data : { source.Get(), aligned.Get(), target.Get() })
  {
    mobius_test::AddLogAreaDistortion(data);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(900, 300);
  mobius_test::View view;
  view.Array = "LogAreaDistortion";
  view.Range[0] = -1.5;
  view.Range[1] = 1.5;
  mobius_test::AddView(window, source, view, 0.0, 1.0 / 3);
  mobius_test::AddView(window, aligned, view, 1.0 / 3, 2.0 / 3);
  mobius_test::AddView(window, target, view, 2.0 / 3, 1.0);
  return mobius_test::CompareWithBaseline(window, argc, argv);
}
