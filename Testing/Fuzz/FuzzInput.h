// Shared by the fuzz targets in Testing/Fuzz/: turning fuzzer bytes into the numbers and matrices
// the module must survive, the check that stops a run on a broken property, and the list of known
// defects a target may skip.
//
// FuzzedDataProvider alone never yields NaN, +-Inf, denormals or the exactly special matrices
// where the closed forms branch (rotations by exactly pi, singular or repeated-eigenvalue stretch,
// the exact identity, scales of 1e+-300). Every value here is therefore drawn through a selector
// byte that chooses between raw IEEE bit patterns (which include NaN, Inf and denormals), a table
// of special values, ordinary ranges, and structured constructions such as
// R(axis, pi) diag(s1, s2, s3) + translation.
#ifndef lct_fuzz_FuzzInput_h
#define lct_fuzz_FuzzInput_h

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace lct_fuzz
{

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Stops the run: libFuzzer saves the input as a crash artifact. `what` names the property.
[[noreturn]] inline void Fail(
  const char* file, int line, const char* what, const std::string& detail)
{
  std::fprintf(
    stderr, "\n%s:%d: fuzz property violated: %s\n%s\n", file, line, what, detail.c_str());
  std::fflush(stderr);
  std::abort();
}

} // namespace lct_fuzz

/// Checks a property; `detail` is streamed (e.g. `"t = " << t`) and printed on failure.
#define LCT_FUZZ_CHECK(condition, detail)                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::ostringstream lct_fuzz_detail;                                                          \
      lct_fuzz_detail.precision(17);                                                               \
      lct_fuzz_detail << detail;                                                                   \
      ::lct_fuzz::Fail(__FILE__, __LINE__, #condition, lct_fuzz_detail.str());                     \
    }                                                                                              \
  } while (false)

namespace lct_fuzz
{

/// LCT_FUZZ_PRINT=1 in the environment makes a target print the inputs it decoded (for turning a
/// crash artifact into a description of the defect).
inline bool Verbose()
{
  static const bool verbose = std::getenv("LCT_FUZZ_PRINT") != nullptr;
  return verbose;
}

/// Under LCT_FUZZ_PRINT, prints one step of a target's operation sequence.
#define LCT_FUZZ_TRACE(what)                                                                       \
  do                                                                                               \
  {                                                                                                \
    if (::lct_fuzz::Verbose())                                                                     \
    {                                                                                              \
      std::ostringstream lct_fuzz_trace;                                                           \
      lct_fuzz_trace.precision(17);                                                                \
      lct_fuzz_trace << what;                                                                      \
      std::fprintf(stderr, "> %s\n", lct_fuzz_trace.str().c_str());                                \
    }                                                                                              \
  } while (false)

/// Whether an interpolator's error at evaluation is one that lct/KeyLogs.h documents for a
/// combination of accepted keys: the in-between out of range, beyond the conditioning limit, or
/// inaccurate between ill-conditioned keys (NaN or Inf only for non-finite input). A missing
/// logarithm never is: the interpolators refuse every key and setting that would leave a log a
/// curve point combines missing (D19), and say "a defect of vtkLCT" should one be missing anyway.
inline bool ExplainedRefusal(const std::string& message)
{
  if (message.find("a defect of vtkLCT") != std::string::npos ||
    (message.find("the combination of the keys failed") == std::string::npos &&
      message.find("the absolute logarithms (ConsistentRotation) failed") == std::string::npos))
  {
    return false;
  }
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

/// A defect in Module/ or Examples/ that a target skips until it is fixed (each one is described
/// in the fuzzing report and has a regression input in the target's corpus). Returns `matches`,
/// and says once per process that the skip was taken, so a skipped defect stays visible.
inline bool Known(const char* id, bool matches)
{
  if (matches)
  {
    // Compared by address, not content: string comparisons would feed libFuzzer's dictionary.
    static std::vector<const char*> reported;
    if (std::find(reported.begin(), reported.end(), id) == reported.end())
    {
      reported.push_back(id);
      std::fprintf(stderr, "note: skipping known defect %s (see Testing/Fuzz/README.md)\n", id);
    }
  }
  return matches;
}

template <typename Derived>
std::string Show(const Eigen::DenseBase<Derived>& m)
{
  std::ostringstream s;
  s.precision(17);
  s << m;
  return s.str();
}

template <typename Derived>
bool AllFinite(const Eigen::DenseBase<Derived>& m)
{
  return m.derived().array().isFinite().all();
}

inline bool AllFinite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}

inline std::string Show(const double* v, int n)
{
  std::ostringstream s;
  s.precision(17);
  for (int i = 0; i < n; ++i)
  {
    s << (i ? " " : "") << v[i];
  }
  return s.str();
}

/// Bitwise equality, so that "unchanged" also holds for -0.0 and NaN payloads.
inline bool SameBits(const double* a, const double* b, int n)
{
  return std::memcmp(a, b, sizeof(double) * n) == 0;
}

/// Values where the closed forms change branch or the arithmetic changes regime.
inline double SpecialValue(unsigned index)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double values[] = { 0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 3.0, -2.0, nan, inf, -inf,
    std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
    -std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
    -std::numeric_limits<double>::max(), kEps, 1.0 + kEps, 1.0 - 0.5 * kEps, 1e-300, 1e300, -1e300,
    1e-150, 1e150, 1e-16, 1e-8, 1e8, 1e16, kPi, -kPi, 0.5 * kPi, 2.0 * kPi,
    std::nextafter(kPi, 0.0), std::nextafter(kPi, 4.0), kPi - 1e-8, 180.0, 90.0, 179.0, 1e-5,
    1.0 / (8.0 * kEps), 8.0 * kEps, 1e154, 1e-154, 1e103, 1e-103, 0.25, 709.0, 710.0, -745.0, 1e308,
    0.1 };
  constexpr unsigned count = sizeof(values) / sizeof(values[0]);
  return values[index % count];
}

/// Fuzzer bytes as the inputs of the module. Every method consumes a bounded number of bytes and
/// returns something (zeros once the data is used up), so loops over it terminate.
class Input
{
public:
  Input(const uint8_t* data, size_t size)
    : P(data, size)
  {
  }

  FuzzedDataProvider& Provider() { return this->P; }
  bool Empty() { return this->P.remaining_bytes() == 0; }
  uint8_t Byte() { return this->P.ConsumeIntegral<uint8_t>(); }
  bool Bool() { return this->P.ConsumeBool(); }
  int Int(int lo, int hi) { return this->P.ConsumeIntegralInRange<int>(lo, hi); }

  /// Any double, NaN/Inf/denormals included, with the special and ordinary ones likelier than
  /// raw bits would make them.
  double Double()
  {
    switch (this->Byte() % 8)
    {
      case 0:
      case 1:
      {
        const uint64_t bits = this->P.ConsumeIntegral<uint64_t>();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
      case 2:
        return SpecialValue(this->Byte());
      case 3:
        return static_cast<double>(this->Int(-4, 4));
      case 4:
        return this->P.ConsumeFloatingPointInRange<double>(-10.0, 10.0);
      case 5:
      {
        // Log-uniform magnitude over the whole range of normal and denormal doubles.
        const double e = this->P.ConsumeFloatingPointInRange<double>(-320.0, 308.0);
        return (this->Bool() ? -1.0 : 1.0) * std::pow(10.0, e);
      }
      case 6:
        return this->P.ConsumeFloatingPoint<double>();
      default:
        return this->P.ConsumeProbability<double>();
    }
  }

  /// A finite double (NaN/Inf replaced by 0), for values the caller wants finite.
  double Finite()
  {
    const double d = this->Double();
    return std::isfinite(d) ? d : 0.0;
  }

  /// minCount..maxCount finite times, sorted, repeats removed (so possibly fewer), as key times.
  std::vector<double> KeyTimes(int minCount, int maxCount)
  {
    const int n = this->Int(minCount, maxCount);
    std::vector<double> times;
    for (int i = 0; i < n; ++i)
    {
      times.push_back(this->Finite());
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
  }

  /// A query time: any double but NaN (callers reject NaN before asking for curve weights).
  double QueryTime()
  {
    const double t = this->Double();
    return std::isnan(t) ? 0.0 : t;
  }

  /// A positive scale factor: 1, repeated, huge, tiny, or at the singularity threshold of the
  /// polar log (the smallest stretch eigenvalue must exceed 8 eps times the largest).
  double Scale()
  {
    switch (this->Byte() % 8)
    {
      case 0:
        return 1.0;
      case 1:
        return SpecialValue(this->Byte());
      case 2:
        return std::pow(10.0, this->P.ConsumeFloatingPointInRange<double>(-300.0, 300.0));
      case 3:
        return std::pow(10.0, this->P.ConsumeFloatingPointInRange<double>(-3.0, 3.0));
      case 4:
        return 8.0 * kEps * (1.0 + this->P.ConsumeFloatingPointInRange<double>(-1e-3, 1e-3));
      case 5:
        return this->P.ConsumeFloatingPointInRange<double>(0.1, 10.0);
      case 6:
        return 1.0 + this->P.ConsumeFloatingPointInRange<double>(-1e-12, 1e-12);
      default:
        return this->Double();
    }
  }

  /// An angle, with pi (and its neighbouring doubles), 2 pi and multiples likelier.
  double Angle()
  {
    switch (this->Byte() % 6)
    {
      case 0:
      {
        const double angles[] = { 0.0, kPi, -kPi, 0.5 * kPi, 2.0 * kPi, 3.0 * kPi,
          std::nextafter(kPi, 0.0), std::nextafter(kPi, 4.0), kPi - 1e-8, kPi + 1e-8, 1e-8, 1e-16,
          2.0 * kPi / 3.0, 0.75 * kPi, 100.0 * kPi, 1e6 };
        return angles[this->Byte() % (sizeof(angles) / sizeof(angles[0]))];
      }
      case 1:
        return kPi + this->P.ConsumeFloatingPointInRange<double>(-1e-6, 1e-6);
      case 2:
        return this->Double();
      default:
        return this->P.ConsumeFloatingPointInRange<double>(-4.0 * kPi, 4.0 * kPi);
    }
  }

  /// An axis (not necessarily unit, not necessarily non-zero).
  Eigen::Vector3d Axis()
  {
    switch (this->Byte() % 6)
    {
      case 0:
        return Eigen::Vector3d::Unit(this->Int(0, 2));
      case 1:
        return Eigen::Vector3d(1.0, 1.0, 1.0).normalized();
      case 2:
        return Eigen::Vector3d(1.0, -1.0, 0.0).normalized();
      case 3:
        return Eigen::Vector3d(this->Double(), this->Double(), this->Double());
      default:
      {
        Eigen::Vector3d v(this->P.ConsumeFloatingPointInRange<double>(-1.0, 1.0),
          this->P.ConsumeFloatingPointInRange<double>(-1.0, 1.0),
          this->P.ConsumeFloatingPointInRange<double>(-1.0, 1.0));
        return v.norm() > 1e-3 ? Eigen::Vector3d(v.normalized()) : Eigen::Vector3d::UnitZ();
      }
    }
  }

  Eigen::Vector3d Vector()
  {
    switch (this->Byte() % 4)
    {
      case 0:
        return Eigen::Vector3d::Zero();
      case 1:
        return Eigen::Vector3d(this->Double(), this->Double(), this->Double());
      case 2:
        return this->Scale() * this->Axis();
      default:
        return Eigen::Vector3d(this->P.ConsumeFloatingPointInRange<double>(-10.0, 10.0),
          this->P.ConsumeFloatingPointInRange<double>(-10.0, 10.0),
          this->P.ConsumeFloatingPointInRange<double>(-10.0, 10.0));
    }
  }

  /// R(axis, angle) computed in floating point (Rodrigues through Eigen).
  Eigen::Matrix3d Rotation()
  {
    const double angle = this->Angle();
    Eigen::Vector3d axis = this->Axis();
    const double n = axis.norm();
    if (n > 0.0 && std::isfinite(n))
    {
      axis /= n;
    }
    return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  }

  /// One of the 24 rotations with entries in {-1, 0, 1}: exact half turns (diag(1, -1, -1), ...),
  /// quarter turns and the identity, with no round-off at all.
  Eigen::Matrix3d ExactRotation()
  {
    static const int permutations[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
      { 2, 0, 1 }, { 2, 1, 0 } };
    const int* p = permutations[this->Byte() % 6];
    const int signs = this->Byte();
    Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i)
    {
      r(i, p[i]) = (signs >> i) & 1 ? -1.0 : 1.0;
    }
    if (r.determinant() < 0.0)
    {
      r.row(2) = -r.row(2);
    }
    return r;
  }

  Eigen::Matrix3d Diagonal()
  {
    switch (this->Byte() % 4)
    {
      case 0:
      {
        const double s = this->Scale();
        return s * Eigen::Matrix3d::Identity();
      }
      case 1:
      {
        // Two equal eigenvalues.
        const double a = this->Scale();
        const double b = this->Scale();
        return Eigen::Vector3d(a, a, b).asDiagonal();
      }
      default:
      {
        const double a = this->Scale();
        const double b = this->Scale();
        const double c = this->Scale();
        return Eigen::Vector3d(a, b, c).asDiagonal();
      }
    }
  }

  /// A 3x3 linear part: raw, rotation times stretch, exact rotations, singular, sheared,
  /// reflected, near the identity.
  Eigen::Matrix3d Linear()
  {
    switch (this->Byte() % 12)
    {
      case 0:
      {
        Eigen::Matrix3d m;
        for (int i = 0; i < 9; ++i)
        {
          m(i / 3, i % 3) = this->Double();
        }
        return m;
      }
      case 1:
      case 2:
        return this->Rotation() * this->Diagonal();
      case 3:
        return this->ExactRotation() * this->Diagonal();
      case 4:
        return Eigen::Matrix3d::Identity();
      case 5:
      {
        // Rank deficient: a zero column, two equal columns or an outer product.
        Eigen::Matrix3d m = this->Rotation() * this->Diagonal();
        switch (this->Byte() % 3)
        {
          case 0:
            m.col(this->Int(0, 2)).setZero();
            break;
          case 1:
            m.col(2) = m.col(1);
            break;
          default:
            m = this->Vector() * this->Vector().transpose();
            break;
        }
        return m;
      }
      case 6:
        return this->Rotation() * this->Diagonal() * this->Rotation();
      case 7:
      {
        Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
        shear(0, 1) = this->Double();
        shear(0, 2) = this->Double();
        shear(1, 2) = this->Double();
        return this->Rotation() * shear * this->Diagonal();
      }
      case 8:
      {
        // A reflection: det < 0.
        Eigen::Matrix3d m = this->Rotation() * this->Diagonal();
        m.col(0) = -m.col(0);
        return m;
      }
      case 9:
      {
        Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
        const double size = std::pow(10.0, -this->Int(1, 17));
        for (int i = 0; i < 9; ++i)
        {
          m(i / 3, i % 3) += size * this->P.ConsumeFloatingPointInRange<double>(-1.0, 1.0);
        }
        return m;
      }
      case 10:
      {
        // A half turn perturbed by a few ulps: the eigenvector branch of logSO3 and the
        // negative-eigenvalue test of MatrixLog.
        Eigen::Matrix3d m = this->ExactRotation();
        for (int i = 0; i < 9; ++i)
        {
          m(i / 3, i % 3) += kEps * this->Int(-4, 4);
        }
        return m * this->Diagonal();
      }
      default:
        return this->Rotation();
    }
  }

  /// A 4x4 matrix, mostly affine (bottom row 0 0 0 1), sometimes not.
  Eigen::Matrix4d Affine()
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = this->Linear();
    m.topRightCorner<3, 1>() = this->Vector();
    switch (this->Byte() % 16)
    {
      case 0:
        m(3, this->Int(0, 3)) = this->Double();
        break;
      case 1:
        m(3, 3) = -0.0 + (this->Bool() ? 1.0 : 1.0 + kEps);
        break;
      case 2:
        m(3, this->Int(0, 2)) = -0.0; // equal to 0: still affine
        break;
      default:
        break;
    }
    return m;
  }

  /// Sixteen arbitrary doubles, row-major.
  Eigen::Matrix4d RawMatrix()
  {
    Eigen::Matrix4d m;
    for (int i = 0; i < 16; ++i)
    {
      m(i / 4, i % 4) = this->Double();
    }
    return m;
  }

  /// Either of the above.
  Eigen::Matrix4d Matrix() { return this->Byte() % 4 == 0 ? this->RawMatrix() : this->Affine(); }

  /// Twelve log coordinates: raw, or with a rotation part of length k pi, a similarity
  /// (Y = c I), a rigid map (Y = 0) or a large stretch.
  lct::LogCoords Coordinates()
  {
    lct::LogCoords c;
    for (int i = 0; i < 12; ++i)
    {
      c[i] = this->Double();
    }
    switch (this->Byte() % 5)
    {
      case 0:
      {
        Eigen::Vector3d axis = this->Axis();
        const double n = axis.norm();
        lct::rotationPart(c) = (n > 0.0 && std::isfinite(n) ? axis / n : axis) * this->Angle();
        break;
      }
      case 1:
      {
        const double s = this->Double();
        lct::symmetricPart(c) << s, s, s, 0.0, 0.0, 0.0;
        break;
      }
      case 2:
        lct::symmetricPart(c).setZero();
        break;
      default:
        break;
    }
    return c;
  }

private:
  FuzzedDataProvider P;
};

/// Counts vtkErrorMacro / vtkWarningMacro calls on the objects it observes (ErrorEvent and
/// WarningEvent), so errors do not flood the fuzzer's output and each call can be checked
/// against the error it reported or did not report.
class ErrorObserver
{
public:
  ErrorObserver()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject* caller, unsigned long event, void* self, void* data) {
      auto* o = static_cast<ErrorObserver*>(self);
      if (event == vtkCommand::ErrorEvent)
      {
        ++o->Errors;
        o->Last = data ? static_cast<const char*>(data) : "";
        o->LastSource = caller;
      }
      else
      {
        ++o->Warnings;
      }
    });
  }
  void Observe(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
    object->AddObserver(vtkCommand::WarningEvent, this->Command);
  }
  int Errors = 0;
  int Warnings = 0;
  std::string Last;
  vtkObject* LastSource = nullptr;

private:
  vtkNew<vtkCallbackCommand> Command;
};

/// Swallows the text of errors and warnings from objects nobody observes (vtkCamera,
/// vtkXMLDataParser, inverse transforms created by VTK), counting them.
class QuietOutputWindow : public vtkOutputWindow
{
public:
  static QuietOutputWindow* New() { return new QuietOutputWindow; }
  vtkTypeMacro(QuietOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char*) override { ++this->Errors; }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  int Errors = 0;

  /// Installs the window once per process and returns it.
  static QuietOutputWindow* Install()
  {
    static QuietOutputWindow* window = [] {
      QuietOutputWindow* w = QuietOutputWindow::New();
      vtkOutputWindow::SetInstance(w);
      // VTK 9 also sends unobserved errors to vtkLogger, which prints to stderr.
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
      return w;
    }();
    return window;
  }
};

/// VTK's row-major 4x4 storage.
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

/// A new vtkMatrix4x4 holding m.
inline vtkSmartPointer<vtkMatrix4x4> ToVtk(const Eigen::Matrix4d& m)
{
  auto v = vtkSmartPointer<vtkMatrix4x4>::New();
  const RowMajor4 rows = m;
  v->DeepCopy(rows.data());
  return v;
}

inline Eigen::Matrix4d FromVtk(vtkMatrix4x4* m)
{
  return RowMajor4(Eigen::Map<const RowMajor4>(m->GetData()));
}

} // namespace lct_fuzz

#endif
