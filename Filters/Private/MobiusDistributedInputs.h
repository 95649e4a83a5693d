/**
 * @file MobiusDistributedInputs.h
 * @brief How every filter of the module runs when ParaView splits its input over
 * processes (private to the module).
 *
 * A conformal map, a centering or a registration needs the whole closed surface: a piece
 * of it has holes where it was cut. When the filter's output is requested as piece p of P
 * and P is the number of processes of the global controller (pvbatch or pvserver over MPI
 * runs every pipeline so, one piece per rank), each input's pieces are gathered on rank
 * 0 and joined (MobiusMergePieces.h); rank 0 runs the algorithm on the whole surfaces and
 * the other ranks output an empty polydata: **the result lives on rank 0**. All ranks
 * return rank 0's status, so when it fails (a bad mesh) no rank runs the filters
 * downstream, which would wait for it in their own gathers; rank 0 reports the error.
 * Pieces that a filter upstream is known to have lost cells of (MobiusLostPiecesCheck.h) are
 * refused so.
 *
 * Any other request (one piece, or one process; also each rank running its own pipelines
 * on its own meshes, as the batch examples do) runs the algorithm on the input as it is,
 * with no communication.
 *
 * Either way an empty input (no points and no cells) on any port gives an empty output
 * and no error, as VTK's filters do: a rank without data, or an upstream filter that
 * produced nothing, is not a failure.
 */
#ifndef MobiusDistributedInputs_h
#define MobiusDistributedInputs_h

#include <functional>

class vtkAlgorithm;
class vtkInformationVector;

namespace mobius
{
namespace vtk
{
/// The filter's own work, given the whole inputs (an input vector per port, as
/// RequestData's); returns RequestData's status. An exception it throws becomes the
/// filter's error (ReportException) and a failure status.
using WholeInputsComputation = std::function<int(vtkInformationVector** wholeInputs)>;

/// RequestData for a filter whose algorithm needs the whole surface on every input port
/// (see above). Call it with RequestData's arguments.
int RequestDataOnWholeInputs(vtkAlgorithm* filter, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const WholeInputsComputation& compute);
}
}

#endif
