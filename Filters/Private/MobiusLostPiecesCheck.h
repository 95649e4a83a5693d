/**
 * @file MobiusLostPiecesCheck.h
 * @brief Refuses pieces that an upstream filter is known to have lost on the way between
 * the ranks (private to the module; MobiusDistributedInputs asks it before joining them).
 *
 * ParaView's *Redistribute DataSet* (vtkRedistributeDataSetFilter) sends each rank its
 * cells as VTK XML with raw appended data, and each rank reads them back with VTK's XML
 * reader. VTK 9.1 and 9.2 feed that reader's expat parser in a way that expat's "reparse
 * deferral" (expat 2.6, and Debian bookworm's libexpat1 2.5.0-1+deb12u2 and later, which
 * backport it) breaks: every block larger than a few kilobytes fails to parse ("not
 * well-formed (invalid token)"), and the filter's output silently lacks those cells. The
 * joined surface then has holes where the lost cells were, which a filter could mistake
 * for the input's own (and fill them, with FillHoles). So when such a filter is upstream,
 * the check serializes a small grid the same way and reads it back, once per process:
 * if that fails, the pieces are refused with the reason. D3 (vtkPDistributedDataFilter)
 * sends legacy VTK data and is not affected.
 */
#ifndef MobiusLostPiecesCheck_h
#define MobiusLostPiecesCheck_h

#include <string>

class vtkAlgorithm;

namespace mobius
{
namespace vtk
{
/// Why the pieces `filter` receives (on any input, through any filter upstream) are
/// missing cells, or an empty string when no filter upstream is known to lose them here.
std::string LostPiecesReason(vtkAlgorithm* filter);

/// True when VTK's XML reader reads back, in this process, an unstructured grid that VTK's
/// XML writer wrote to a string with LZ4-compressed raw appended data (as
/// vtkRedistributeDataSetFilter exchanges its pieces). Checked once, then remembered.
bool XMLExchangeReadsBack();
}
}

#endif
