// The picture of a dense correspondence in the style of the paper's Figure 10: the source
// surface colored by its own position (x, y, z -> red, green, blue) next to the target's own
// surface with the colors the map carries over (each target point takes the color of the
// source where the map places the source there). A good map shows the colors laid out on
// the target as on the source.
#ifndef CorrespondencePicture_h
#define CorrespondencePicture_h

#include "vtkPolyData.h"

#include <string>

/// Renders offscreen (GLX: needs an X display, e.g. under xvfb-run) into the bytes of a PNG
/// file, `png`.
/// `alignedSource`: the source map aligned by vtkSO3Register, with `SurfacePoints`;
/// `targetMap`: the target's (centered) map, with `SurfacePoints`;
/// `correspondence`: the map (vtkDenseCorrespondence or vtkCorrespondenceRefinement output)
/// with `MappedPoints`. Fails with a message instead of aborting when
/// there is no display.
bool RenderCorrespondencePicture(vtkPolyData* alignedSource, vtkPolyData* targetMap,
  vtkPolyData* correspondence, std::string& png, std::string& error, int width = 1200,
  int height = 600);

#endif
