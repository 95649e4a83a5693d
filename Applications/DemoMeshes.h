// The demo's input: CGAL's cow (CC0, from Debian's libcgal-demo, unpacked at configure
// time) and a deformed, rotated copy of it. Vertex i of one corresponds to vertex i of the
// other, so the demo can say how accurate the map it found is.
#ifndef DemoMeshes_h
#define DemoMeshes_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>

struct DemoMeshes
{
  std::string SourcePath;
  vtkSmartPointer<vtkPolyData> Source, Target;
};

/// Reads the cow and makes the deformed copy: bent along its body, its legs stretched, and
/// rotated by an arbitrary rotation. Fails if the example meshes are not there.
bool MakeDemoMeshes(DemoMeshes& demo, std::string& error);

/// Mean distance between MappedPoints and the target point of the same index, divided by
/// the square root of the target's area: the demo's known ground truth.
double DemoMeanError(vtkPolyData* correspondence, vtkPolyData* target);

#endif
