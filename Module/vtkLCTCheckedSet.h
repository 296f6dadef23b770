/**
 * @file    vtkLCTCheckedSet.h
 * @brief   (private to the module) a setter that refuses a value outside its setting's range
 *          with an error and keeps the previous value, where vtkSetClampMacro would clamp it
 *          silently (bad input never passes silently; a NaN never gets in)
 */
#ifndef vtkLCTCheckedSet_h
#define vtkLCTCheckedSet_h

#include "vtkObject.h"
#include "vtkSetGet.h"

namespace vtkLCTCheckedSet
{

/// Whether min <= value <= max; otherwise an error from `self` naming the setting, its range
/// and its current value, which stays (for setters that check more before they set).
template <typename T>
bool InRange(vtkObject* self, const char* setting, const T& current, T value, T min, T max)
{
  if (!(value >= min && value <= max))
  {
    vtkErrorWithObjectMacro(self, << "Set" << setting << "(" << value << "): outside [" << min
                                  << ", " << max << "]; " << setting << " stays " << current
                                  << ".");
    return false;
  }
  return true;
}

/// Sets `member` to `value` (Modified() when it changes) and returns 1 when
/// min <= value <= max; otherwise the error of InRange, `member` unchanged, and 0.
template <typename T>
int Set(vtkObject* self, const char* setting, T& member, T value, T min, T max)
{
  if (!InRange(self, setting, member, value, min, max))
  {
    return 0;
  }
  if (member != value)
  {
    member = value;
    self->Modified();
  }
  return 1;
}

} // namespace vtkLCTCheckedSet

#endif
