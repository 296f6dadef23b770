// The skip for the open defect D19 (Testing/Fuzz/README.md), shared by the targets that drive
// vtkTransformInterpolatorLCT (FuzzTransformInterpolator, FuzzRenderKeys.h), and what else may
// refuse a curve point between accepted keys.
#ifndef lct_fuzz_FuzzMissingKeyLog_h
#define lct_fuzz_FuzzMissingKeyLog_h

#include "FuzzInput.h"

#include "lct/Affine.h"
#include "lct/Parametrisation.h"
#include "lct/Status.h"

#include <algorithm>
#include <string>
#include <vector>

namespace lct_fuzz
{

// KNOWN: D19 (Testing/Fuzz/README.md). The transform interpolator accepts a key when the log of
// the step to its neighbours exists, but a curve point needs the relative log of every weighted
// key about the reference (up to three keys apart), and ConsistentRotation the absolute log of
// each key. When one of those is refused, InterpolateTransform fails inside the accepted key
// range (with an error, never silently). True when the mirror of the key logs (keys in time
// order, pairs within lct::KeyLogs::kReach = 7) finds such a missing log (the caller says
// Known("D19")).
inline bool MissingKeyLog(
  const std::vector<Eigen::Matrix4d>& keys, lct::Parametrisation p, bool absolute)
{
  const int n = static_cast<int>(keys.size());
  for (int r = 0; r < n; ++r)
  {
    if (absolute && !lct::logarithm(keys[r], p).ok())
    {
      return true;
    }
    for (int i = std::max(0, r - 7); i < std::min(n, r + 8); ++i)
    {
      if (!lct::logarithm(lct::relativeStep(keys[r], keys[i]), p).ok())
      {
        return true;
      }
    }
  }
  return false;
}

/// Whether an interpolator's error names a refusal lct/KeyLogs.h documents for a combination of
/// accepted keys: a result out of range, too ill-conditioned, or inaccurate between
/// ill-conditioned keys (NaN or Inf only for non-finite input).
inline bool ExplainedRefusal(const std::string& message)
{
  for (const lct::Status s : { lct::Status::NonFinite, lct::Status::OutOfRange,
         lct::Status::IllConditioned, lct::Status::InaccurateResult })
  {
    if (message.find(lct::describe(s)) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

} // namespace lct_fuzz

#endif
