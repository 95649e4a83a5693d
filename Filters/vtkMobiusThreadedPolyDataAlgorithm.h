/**
 * @class   vtkMobiusThreadedPolyDataAlgorithm
 * @brief   A filter of the module with parallel parts: the NumberOfThreads property.
 *
 * The filters that run on one thread derive from vtkMobiusPolyDataAlgorithm directly, so
 * that none of them has a property it ignores.
 */
#ifndef vtkMobiusThreadedPolyDataAlgorithm_h
#define vtkMobiusThreadedPolyDataAlgorithm_h

#include "vtkMobiusPolyDataAlgorithm.h"
#include "vtkMobiusRegistrationFiltersModule.h" // For export macro

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkMobiusThreadedPolyDataAlgorithm
  : public vtkMobiusPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMobiusThreadedPolyDataAlgorithm, vtkMobiusPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Threads for the parallel parts of this filter: 0 (default) is automatic, one per core
   * this process may run on (its CPU affinity mask: taskset, a cpuset, an MPI launcher's
   * binding), at most VTK_SMP_MAX_THREADS when that environment variable is set; clamped to
   * 0..1024. The output is the same, bit for bit, whatever the count. Field data
   * `NumberOfThreadsUsed` reports the count the filter ran with.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkMobiusThreadedPolyDataAlgorithm() = default;
  ~vtkMobiusThreadedPolyDataAlgorithm() override = default;

  int NumberOfThreads = 0;

private:
  vtkMobiusThreadedPolyDataAlgorithm(const vtkMobiusThreadedPolyDataAlgorithm&) = delete;
  void operator=(const vtkMobiusThreadedPolyDataAlgorithm&) = delete;
};

#endif
