// Helpers shared by the unit tests of the VTK classes: an ErrorEvent counter and conversions
// between vtkMatrix4x4 and Eigen.
#ifndef lct_test_VtkTestHelpers_h
#define lct_test_VtkTestHelpers_h

#include "vtkCommand.h"
#include "vtkMatrix4x4.h"

#include <Eigen/Core>

#include <string>

namespace lct_test
{

/// Counts ErrorEvents and keeps the last message, so tests can check errors are reported.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Count = 0;
  std::string Last;
};

inline void toVtk(const Eigen::Matrix4d& m, vtkMatrix4x4* out)
{
  for (int i = 0; i < 16; ++i)
  {
    out->SetElement(i / 4, i % 4, m(i / 4, i % 4));
  }
}

inline Eigen::Matrix4d fromVtk(vtkMatrix4x4* m)
{
  Eigen::Matrix4d out;
  for (int i = 0; i < 16; ++i)
  {
    out(i / 4, i % 4) = m->GetElement(i / 4, i % 4);
  }
  return out;
}

} // namespace lct_test

#endif
