/**
 * @file    vtkLCTLastOutput.h
 * @brief   (private to the module) the last valid output of a filter: RequestData hands it back
 *          when an execution fails, so bad input never changes what the pipeline downstream sees
 */
#ifndef vtkLCTLastOutput_h
#define vtkLCTLastOutput_h

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"

class vtkLCTLastOutput
{
public:
  /// Puts the last valid output back into `output` (empties it before the first); returns 0,
  /// RequestData's failure, so a filter can `return last.Restore(output);`.
  int Restore(vtkDataObject* output) const
  {
    if (output && this->Last)
    {
      output->ShallowCopy(this->Last);
    }
    else if (output)
    {
      output->Initialize();
    }
    return 0;
  }

  /// Keeps a shallow copy of `output` as the last valid one.
  void Remember(vtkDataObject* output)
  {
    this->Last.TakeReference(output->NewInstance());
    this->Last->ShallowCopy(output);
  }

private:
  vtkSmartPointer<vtkDataObject> Last;
};

#endif
