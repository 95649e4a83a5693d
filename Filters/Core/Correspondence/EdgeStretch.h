// How far a dense surface map is from an isometry, vertex by vertex: what a user colors the
// map by to see where it can be trusted.
#ifndef mobius_EdgeStretch_h
#define mobius_EdgeStretch_h

#include "MeshTypes.h"

namespace mobius
{
/// Per source vertex, the mean over the edges around it of |log(|f(a) - f(b)| / (s |a - b|))|,
/// where f(a) is the mapped point of vertex a and s the median of those ratios over all
/// edges (the two surfaces' relative scale): 0 where the map keeps the edge lengths, 0.69
/// where it doubles or halves them. An edge whose source length is zero is left out; a
/// vertex with no edge left gets 0.
Vector EdgeStretch(const Points& source, const Triangles& triangles, const Points& mapped);

/// The area-weighted mean of EdgeStretch over the source's vertices (their lumped masses).
double MeanEdgeStretch(const Points& source, const Triangles& triangles, const Points& mapped);
}

#endif
