/**
 * @file    vtkLCTLastOutput.h
 * @brief   (private to the module) the last valid output of a filter: RequestData hands it back
 *          when an execution fails, so bad input never changes what the pipeline downstream sees
 */
#ifndef vtkLCTLastOutput_h
#define vtkLCTLastOutput_h

#include "vtkDataObject.h"
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"

#include <algorithm>

class vtkLCTLastOutput
{
public:
  /// Puts the last valid output back into `output` (empties it before the first) and enters the
  /// failed state (see WithFailure); returns 0, RequestData's failure, so a filter can
  /// `return last.Restore(output);`.
  int Restore(vtkDataObject* output)
  {
    this->Failed = true;
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

  /// A filter's GetMTime passes its MTime through this: after a failed execution it is raised to
  /// a fresh time on every call, so the next Update executes again and reports the error again.
  /// (The pipeline counts a failed execution as up to date: without this a second Update would
  /// return 1 on the restored output; Modified() inside RequestData is older than the output.)
  vtkMTimeType WithFailure(vtkMTimeType mtime)
  {
    if (!this->Failed)
    {
      return mtime;
    }
    this->FailureStamp.Modified();
    return std::max(mtime, this->FailureStamp.GetMTime());
  }

  /// Keeps a shallow copy of `output` as the last valid one (and leaves the failed state).
  void Remember(vtkDataObject* output)
  {
    this->Failed = false;
    this->Last.TakeReference(output->NewInstance());
    this->Last->ShallowCopy(output);
  }

private:
  vtkSmartPointer<vtkDataObject> Last;
  bool Failed = false;
  vtkTimeStamp FailureStamp;
};

#endif
