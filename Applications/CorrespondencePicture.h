// The picture of a dense correspondence in the style of the paper's Figure 10: the source
// surface colored by its own position (x, y, z -> red, green, blue) next to the target
// surface colored by the colors the inverse map brings over from the source.
#ifndef CorrespondencePicture_h
#define CorrespondencePicture_h

#include "vtkPolyData.h"

#include <string>

/// Renders offscreen (GLX: needs an X display, e.g. under xvfb-run) and writes a PNG.
/// `alignedSource`: the source map aligned by vtkSO3Register; `target`: the target's
/// centered map; both with `SurfacePoints`. Fails with a message instead of aborting when
/// there is no display.
bool RenderCorrespondencePicture(vtkPolyData* alignedSource, vtkPolyData* target,
  const std::string& pngPath, std::string& error, int width = 1200, int height = 600);

#endif
