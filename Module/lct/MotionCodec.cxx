#include "lct/MotionCodec.h"

#include "lct/BSplineFit.h"
#include "lct/Format.h"
#include "lct/PolarParametrisation.h"
#include "lct/SO3.h"

#include <Eigen/LU>
#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <lzma.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

namespace lct
{
namespace
{

constexpr char kMagic[4] = { 'L', 'C', 'T', 'M' };
constexpr std::uint8_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 16;
constexpr std::uint32_t kMaxPayloadBytes = 1u << 30;
constexpr int kMaxJoints = 10000;        // the reader's bounds
constexpr double kMaxTransforms = 3e7;
constexpr int kGroupCount = 3;           // translation, rotation, stretch
constexpr int kGroupOffset[kGroupCount] = { 0, 3, 6 };
constexpr int kGroupSize[kGroupCount] = { 3, 3, 6 };
constexpr double kConstantShare = 1e-4;  // of a track's position budget: below it, constant
constexpr double kMaxQuantised = 9007199254740992.0; // 2^53: integers exact in double
constexpr double kVerifyMargin = 1.0 - 1e-9; // room for the decimal digits of a written BVH
constexpr double kTwistPrior = 1e-3; // of the arms' weight: pins the twist of a single arm
constexpr double kFirstBudget = 0.3;
constexpr double kMaxCorrection = 0.5; // radians: beyond it the linearisation is not trusted
constexpr double kRepairClimb = 1.2;
constexpr int kRepairRounds = 2;

enum class TrackKind : std::uint8_t
{
  Zero = 0,
  ConstantFloat = 1,
  ConstantDouble = 2,
  Curve = 3
};

// ---------------------------------------------------------------------------------------
// Byte streams

class ByteWriter
{
public:
  void Byte(std::uint8_t b) { this->Bytes.push_back(static_cast<char>(b)); }
  void Varint(std::uint64_t v)
  {
    while (v >= 0x80)
    {
      this->Byte(static_cast<std::uint8_t>(v | 0x80));
      v >>= 7;
    }
    this->Byte(static_cast<std::uint8_t>(v));
  }
  void Signed(std::int64_t v)
  {
    this->Varint((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  template <typename T>
  void Raw(T v)
  {
    char buffer[sizeof(T)];
    std::memcpy(buffer, &v, sizeof(T));
    this->Bytes.append(buffer, sizeof(T));
  }
  void Text(const std::string& s)
  {
    this->Varint(s.size());
    this->Bytes += s;
  }
  std::string Bytes;
};

class ByteReader
{
public:
  ByteReader(const char* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  bool Byte(std::uint8_t& b)
  {
    if (this->Position >= this->Size)
    {
      return false;
    }
    b = static_cast<std::uint8_t>(this->Data[this->Position++]);
    return true;
  }
  bool Varint(std::uint64_t& v)
  {
    v = 0;
    for (int shift = 0; shift < 64; shift += 7)
    {
      std::uint8_t b;
      if (!this->Byte(b))
      {
        return false;
      }
      v |= static_cast<std::uint64_t>(b & 0x7f) << shift;
      if (!(b & 0x80))
      {
        return true;
      }
    }
    return false;
  }
  bool Signed(std::int64_t& v)
  {
    std::uint64_t u;
    if (!this->Varint(u))
    {
      return false;
    }
    v = static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1);
    return true;
  }
  /// A count no larger than `limit`.
  bool Count(std::uint64_t limit, std::uint64_t& v) { return this->Varint(v) && v <= limit; }
  template <typename T>
  bool Raw(T& v)
  {
    if (this->Size - this->Position < sizeof(T))
    {
      return false;
    }
    std::memcpy(&v, this->Data + this->Position, sizeof(T));
    this->Position += sizeof(T);
    return true;
  }
  bool Text(std::string& s, std::uint64_t limit)
  {
    std::uint64_t n;
    if (!this->Count(limit, n) || this->Size - this->Position < n)
    {
      return false;
    }
    s.assign(this->Data + this->Position, static_cast<std::size_t>(n));
    this->Position += static_cast<std::size_t>(n);
    return true;
  }
  /// A sub-stream of `n` bytes.
  bool Take(std::uint64_t n, ByteReader& part)
  {
    if (this->Size - this->Position < n)
    {
      return false;
    }
    part = ByteReader(this->Data + this->Position, static_cast<std::size_t>(n));
    this->Position += static_cast<std::size_t>(n);
    return true;
  }
  bool AtEnd() const { return this->Position == this->Size; }

private:
  const char* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

void putU32(std::string& s, std::size_t at, std::uint32_t v)
{
  for (int i = 0; i < 4; ++i)
  {
    s[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  }
}

std::uint32_t getU32(const std::string& s, std::size_t at)
{
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
  {
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + static_cast<std::size_t>(i)]))
      << (8 * i);
  }
  return v;
}

// ---------------------------------------------------------------------------------------
// LZMA2, raw (no xz container: the header above carries size and checksum)

lzma_options_lzma lzmaOptions()
{
  lzma_options_lzma options;
  lzma_lzma_preset(&options, 9 | LZMA_PRESET_EXTREME);
  return options;
}

bool lzmaCompress(const std::string& in, std::string& out)
{
  lzma_options_lzma options = lzmaOptions();
  const lzma_filter filters[] = { { LZMA_FILTER_LZMA2, &options },
    { LZMA_VLI_UNKNOWN, nullptr } };
  std::string buffer(in.size() + in.size() / 2 + 1024, '\0');
  std::size_t written = 0;
  const lzma_ret ret = lzma_raw_buffer_encode(filters, nullptr,
    reinterpret_cast<const std::uint8_t*>(in.data()), in.size(),
    reinterpret_cast<std::uint8_t*>(&buffer[0]), &written, buffer.size());
  if (ret != LZMA_OK)
  {
    return false;
  }
  buffer.resize(written);
  out += buffer;
  return true;
}

/// Decodes exactly `expected` bytes from `in`, which must be consumed exactly.
bool lzmaDecompress(const char* in, std::size_t size, std::size_t expected, std::string& out)
{
  lzma_options_lzma options = lzmaOptions();
  const lzma_filter filters[] = { { LZMA_FILTER_LZMA2, &options },
    { LZMA_VLI_UNKNOWN, nullptr } };
  out.assign(expected, '\0');
  std::size_t inPosition = 0;
  std::size_t outPosition = 0;
  const lzma_ret ret = lzma_raw_buffer_decode(filters, nullptr,
    reinterpret_cast<const std::uint8_t*>(in), &inPosition, size,
    reinterpret_cast<std::uint8_t*>(&out[0]), &outPosition, out.size());
  // LZMA_OK with everything consumed, or LZMA_STREAM_END; anything left over is corruption.
  return (ret == LZMA_OK || ret == LZMA_STREAM_END) && inPosition == size &&
    outPosition == expected;
}

// ---------------------------------------------------------------------------------------
// The motion as tracks

struct Track
{
  Eigen::MatrixXd samples; ///< d x frames
  TrackKind kind = TrackKind::Zero;
  double positionScale = 1.0; ///< position error per unit of this track's error (1 or R_j)
  /// Rotation tracks: the joints below, in the joint's own frame, per frame (3 x frames *
  /// armCount, frame-major), so a rotation error is measured where it shows: a twist about a
  /// bone moves nothing on that bone.
  Eigen::Matrix3Xd arms;
  int armCount = 0;
  std::vector<int> armJoints; ///< the joints the arms lead to
  /// J_r(w_f), the right Jacobian of exp on so(3): exp(w_f + d) ~ exp(w_f) exp(J_r d), so a
  /// change d of the rotation vector turns the arms by J_r d (to first order).
  std::vector<Eigen::Matrix3d> jacobians;
};

struct MotionTracks
{
  std::vector<std::array<Track, kGroupCount>> joints;
  int chainDepth = 1; ///< the most varying tracks on one root-to-leaf path
  /// No stretch anywhere: each rotation track is fitted to the rotation that puts its joint's
  /// world orientation right under the *decoded* parent, so orientation errors do not add up
  /// along a chain (only the position errors of the joints do, each bone's own).
  bool compensate = false;
  std::vector<Eigen::Matrix3d> worldRotations; ///< of the input, frame-major
  std::vector<double> worldPositions;          ///< of the input, lct::worldPositions
  /// 2: each rotation track is fitted to the rotation that puts the joints it moves (its arms)
  /// nearest their input positions from the decoded position of its joint (Wahba's problem,
  /// the input orientation as a weak prior for the twist), so that position errors are
  /// corrected at every joint, not only orientation errors. 1: orientation only. 0: none.
  int compensation = 0;
};

/// J_r(w) = I - (1 - cos t)/t^2 hat(w) + (t - sin t)/t^3 hat(w)^2, t = |w| (its series near 0).
Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& w)
{
  const double t2 = w.squaredNorm();
  const Eigen::Matrix3d h = hat(w);
  double a;
  double b;
  if (t2 < 1e-8)
  {
    a = 0.5 - t2 / 24.0;
    b = 1.0 / 6.0 - t2 / 120.0;
  }
  else
  {
    const double t = std::sqrt(t2);
    a = (1.0 - std::cos(t)) / t2;
    b = (t - std::sin(t)) / (t2 * t);
  }
  return Eigen::Matrix3d::Identity() - a * h + b * h * h;
}

bool representableAsFloat(const Eigen::VectorXd& v)
{
  for (Eigen::Index i = 0; i < v.size(); ++i)
  {
    if (static_cast<double>(static_cast<float>(v(i))) != v(i))
    {
      return false;
    }
  }
  return true;
}

Status toTracks(const SkeletalAnimation& a, double tolerance, MotionTracks& tracks, std::string& why)
{
  const int joints = a.jointCount();
  const int frames = a.frames;
  std::vector<Eigen::Matrix<double, 12, Eigen::Dynamic>> coords(static_cast<std::size_t>(joints));
  for (int j = 0; j < joints; ++j)
  {
    auto& c = coords[static_cast<std::size_t>(j)];
    c.resize(12, frames);
    for (int f = 0; f < frames; ++f)
    {
      const Eigen::Vector3d reference =
        f > 0 ? Eigen::Vector3d(c.block<3, 1>(3, f - 1)) : Eigen::Vector3d::Zero();
      const Result<LogCoords> log = polarLog(a.local(f, j), f > 0 ? &reference : nullptr);
      if (!log)
      {
        why = "the local transform of joint '" + a.joints[static_cast<std::size_t>(j)].name +
          "' at frame " + std::to_string(f) + " has no Polar logarithm: " + describe(log.status);
        return log.status;
      }
      c.col(f) = log.value;
    }
  }

  // R_j: how far a rotation (or stretch) error of joint j travels to the joints below it.
  tracks.worldPositions = worldPositions(a);
  const std::vector<double>& positions = tracks.worldPositions;
  std::vector<double> reach(static_cast<std::size_t>(joints), 0.0);
  for (int f = 0; f < frames; ++f)
  {
    const double* p = &positions[static_cast<std::size_t>(f) * 3 * joints];
    for (int k = 0; k < joints; ++k)
    {
      for (int j = a.joints[static_cast<std::size_t>(k)].parent; j >= 0;
           j = a.joints[static_cast<std::size_t>(j)].parent)
      {
        const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(p + 3 * k) -
          Eigen::Map<const Eigen::Vector3d>(p + 3 * j);
        reach[static_cast<std::size_t>(j)] = std::max(reach[static_cast<std::size_t>(j)], d.norm());
      }
    }
  }

  std::vector<std::vector<int>> below(static_cast<std::size_t>(joints));
  for (int k = 0; k < joints; ++k)
  {
    for (int j = a.joints[static_cast<std::size_t>(k)].parent; j >= 0;
         j = a.joints[static_cast<std::size_t>(j)].parent)
    {
      below[static_cast<std::size_t>(j)].push_back(k);
    }
  }
  std::vector<Eigen::Matrix4d> world;
  tracks.compensate = true;
  for (int j = 0; j < joints; ++j)
  {
    const Eigen::Matrix<double, 6, Eigen::Dynamic> y = coords[static_cast<std::size_t>(j)].bottomRows<6>();
    const double scale = std::max(reach[static_cast<std::size_t>(j)], tolerance);
    tracks.compensate = tracks.compensate &&
      y.colwise().norm().maxCoeff() * scale <= kConstantShare * tolerance;
  }
  tracks.worldRotations.resize(static_cast<std::size_t>(frames) * joints);
  for (int f = 0; f < frames; ++f)
  {
    worldTransforms(a, f, world);
    for (int j = 0; j < joints; ++j)
    {
      tracks.worldRotations[static_cast<std::size_t>(f) * joints + j] =
        world[static_cast<std::size_t>(j)].block<3, 3>(0, 0);
    }
  }

  tracks.joints.assign(static_cast<std::size_t>(joints), {});
  std::vector<int> depth(static_cast<std::size_t>(joints), 0);
  tracks.chainDepth = 1;
  for (int j = 0; j < joints; ++j)
  {
    const auto& c = coords[static_cast<std::size_t>(j)];
    int varying = 0;
    for (int g = 0; g < kGroupCount; ++g)
    {
      Track& t = tracks.joints[static_cast<std::size_t>(j)][static_cast<std::size_t>(g)];
      t.samples = c.block(kGroupOffset[g], 0, kGroupSize[g], frames);
      // A rotation or stretch error theta moves the joints below by at most theta R_j; joints
      // with nothing below (R_j = 0) still keep their rotation to the tolerance in radians.
      t.positionScale = g == 0 ? 1.0 : std::max(reach[static_cast<std::size_t>(j)], tolerance);
      const double negligible = kConstantShare * tolerance / t.positionScale;
      const double spread = (t.samples.colwise() - t.samples.col(0)).colwise().norm().maxCoeff();
      if (g == 2 && t.samples.colwise().norm().maxCoeff() <= negligible)
      {
        t.kind = TrackKind::Zero;
      }
      else if (spread <= negligible)
      {
        t.kind = representableAsFloat(t.samples.col(0)) ? TrackKind::ConstantFloat
                                                        : TrackKind::ConstantDouble;
      }
      else
      {
        t.kind = TrackKind::Curve;
        ++varying;
      }
    }
    const int parent = a.joints[static_cast<std::size_t>(j)].parent;
    depth[static_cast<std::size_t>(j)] =
      (parent >= 0 ? depth[static_cast<std::size_t>(parent)] : 0) + varying;
    tracks.chainDepth = std::max(tracks.chainDepth, depth[static_cast<std::size_t>(j)]);
  }
  for (int j = 0; j < joints; ++j)
  {
    Track& rotation = tracks.joints[static_cast<std::size_t>(j)][1];
    if (rotation.kind == TrackKind::Curve)
    {
      // With compensation, an orientation error of j moves the joints below it up to (and
      // including) the first one whose own rotation track corrects it.
      std::vector<int> arms;
      for (int k : below[static_cast<std::size_t>(j)])
      {
        bool reached = true;
        for (int i = a.joints[static_cast<std::size_t>(k)].parent;
             tracks.compensate && tracks.compensation > 0 && i != j;
             i = a.joints[static_cast<std::size_t>(i)].parent)
        {
          reached = reached && tracks.joints[static_cast<std::size_t>(i)][1].kind != TrackKind::Curve;
        }
        if (reached)
        {
          arms.push_back(k);
        }
      }
      double armReach = 0.0;
      rotation.armCount = static_cast<int>(arms.size());
      rotation.armJoints = arms;
      rotation.arms.resize(3, static_cast<Eigen::Index>(frames) * rotation.armCount);
      rotation.jacobians.resize(static_cast<std::size_t>(frames));
      for (int f = 0; f < frames; ++f)
      {
        const std::size_t at = static_cast<std::size_t>(f) * joints;
        // The linear part of the world transform may stretch; its inverse maps back.
        const Eigen::Matrix3d toJoint = tracks.worldRotations[at + static_cast<std::size_t>(j)].inverse();
        const Eigen::Map<const Eigen::Vector3d> pj(&positions[3 * (at + static_cast<std::size_t>(j))]);
        for (int i = 0; i < rotation.armCount; ++i)
        {
          const std::size_t k = at + static_cast<std::size_t>(arms[static_cast<std::size_t>(i)]);
          auto arm = rotation.arms.col(static_cast<Eigen::Index>(f) * rotation.armCount + i);
          arm = toJoint * (Eigen::Map<const Eigen::Vector3d>(&positions[3 * k]) - pj);
          armReach = std::max(armReach, arm.norm());
        }
        rotation.jacobians[static_cast<std::size_t>(f)] = rightJacobian(rotation.samples.col(f));
      }
      if (tracks.compensate && tracks.compensation > 0)
      {
        rotation.positionScale = std::max(armReach, tolerance);
      }
    }
  }
  return Status::Ok;
}

// ---------------------------------------------------------------------------------------
// Encoding

struct EncodeCounts
{
  int curveTracks = 0;
  int constantTracks = 0;
  int controlPoints = 0;
  int knots = 0;
  int cubicTracks = 0;
};

double estimatedCost(const BSplineCurve& curve)
{
  return static_cast<double>(curve.controlPointCount()) * static_cast<double>(
           curve.controlPoints.rows()) +
    0.5 * static_cast<double>(curve.interiorKnots.size());
}

/// Per track (joint-major, kGroupCount per joint): the position budget per frame, and the
/// curve degree (0: try 1 and 3 and keep the cheaper; the choice is written back).
struct TrackBudgets
{
  std::vector<Eigen::VectorXd> budgets;
  std::vector<int> degrees;
};

Status fitTrack(const Track& track, const Eigen::VectorXd& budget,
  const MotionCompressionOptions& options, int& degree, BSplineCurve& best, double& step)
{
  const int d = static_cast<int>(track.samples.rows());
  // One step for the track, fine enough for its tight frames (the 10th percentile budget).
  Eigen::VectorXd sorted = budget;
  std::sort(sorted.data(), sorted.data() + sorted.size());
  const double typical = sorted(sorted.size() / 10);
  step = 2.0 * options.quantisationShare * typical /
    (std::sqrt(static_cast<double>(d)) * track.positionScale);
  const double quantum = step;
  ToleranceFit fit;
  fit.sampleTolerances = budget;
  fit.adjust = [quantum](BSplineCurve& curve) {
    curve.controlPoints = (curve.controlPoints / quantum).array().round().matrix() * quantum;
  };
  if (track.armCount > 0)
  {
    // The largest displacement of a joint below when w_f becomes `value`.
    // The largest displacement of a joint below when w_f becomes `value`, to first order in
    // the change (it is a fraction of a degree where it matters; the final check is exact).
    fit.error = [&track](int f, const Eigen::VectorXd& value) {
      const Eigen::Vector3d turn = track.jacobians[static_cast<std::size_t>(f)] *
        (Eigen::Vector3d(value) - track.samples.col(f));
      const Eigen::Index first = static_cast<Eigen::Index>(f) * track.armCount;
      double worst = 0.0;
      for (Eigen::Index i = first; i < first + track.armCount; ++i)
      {
        worst = std::max(worst, turn.cross(track.arms.col(i)).squaredNorm());
      }
      return std::sqrt(worst);
    };
  }
  else if (track.positionScale != 1.0)
  {
    const double scale = track.positionScale;
    fit.error = [&track, scale](int f, const Eigen::VectorXd& value) {
      return scale * (value - track.samples.col(f)).norm();
    };
  }
  const int wanted = options.degree != 0 ? options.degree : degree;
  bool found = false;
  for (int candidate : { 1, 2, 3 })
  {
    if (wanted == 0 ? candidate == 2 : candidate != wanted)
    {
      continue;
    }
    Result<BSplineCurve> curve = fitWithinTolerance(track.samples, candidate, fit);
    if (!curve)
    {
      return curve.status;
    }
    if (!found || estimatedCost(curve.value) < estimatedCost(best))
    {
      best = std::move(curve.value);
      found = true;
      degree = candidate;
    }
  }
  return Status::Ok;
}

Status encodePayload(const SkeletalAnimation& a, const MotionMetadata& metadata,
  const MotionTracks& tracks, TrackBudgets& budgets, const MotionCompressionOptions& options,
  std::string& payload, EncodeCounts& counts)
{
  ByteWriter head;
  ByteWriter structure;
  ByteWriter knots;
  ByteWriter values;
  head.Text(metadata.rotationOrder);
  head.Varint(static_cast<std::uint64_t>(std::max(metadata.inputChannels, 0)));
  head.Raw<double>(a.frameTime);
  head.Raw<double>(metadata.tolerance);
  head.Raw<double>(metadata.height);
  head.Varint(static_cast<std::uint64_t>(a.frames));
  head.Varint(static_cast<std::uint64_t>(a.jointCount()));
  for (const SkeletonJoint& joint : a.joints)
  {
    head.Text(joint.name);
    head.Varint(static_cast<std::uint64_t>(joint.parent + 1));
    head.Byte(joint.endSite ? 1 : 0);
  }

  counts = EncodeCounts();
  const int frames = a.frames;
  const int jointCount = a.jointCount();
  // The world rotations and positions the decoder will form, joint by joint (parents first).
  const int compensation = tracks.compensate ? tracks.compensation : 0;
  std::vector<Eigen::Matrix3d> decodedWorld;
  std::vector<Eigen::Vector3d> decodedPosition;
  if (compensation > 0)
  {
    decodedWorld.resize(static_cast<std::size_t>(frames) * jointCount);
    decodedPosition.resize(static_cast<std::size_t>(frames) * jointCount);
  }
  Track compensated;
  for (int j = 0; j < jointCount; ++j)
  {
    const int parent = a.joints[static_cast<std::size_t>(j)].parent;
    Eigen::MatrixXd decodedRotation;    // 3 x frames: the rotation vectors the decoder reads
    Eigen::MatrixXd decodedTranslation; // 3 x frames
    for (int group = 0; group < kGroupCount; ++group)
    {
      const Track* track = &tracks.joints[static_cast<std::size_t>(j)][static_cast<std::size_t>(group)];
      if (group == 1 && compensation > 0 && track->kind == TrackKind::Curve)
      {
        compensated.kind = track->kind;
        compensated.positionScale = track->positionScale;
        compensated.arms = track->arms;
        compensated.armCount = track->armCount;
        compensated.samples.resize(3, frames);
        compensated.jacobians.resize(static_cast<std::size_t>(frames));
        for (int f = 0; f < frames; ++f)
        {
          const std::size_t at = static_cast<std::size_t>(f) * jointCount;
          const Eigen::Matrix3d& input = tracks.worldRotations[at + static_cast<std::size_t>(j)];
          Eigen::Matrix3d world = input;
          if (compensation == 2 && track->armCount > 0)
          {
            // Wahba: the rotation R maximising tr(R^T B), B = sum d_i a_i^T + mu R_input,
            // a_i the arms in the joint's frame, d_i from the decoded joint to the input
            // positions of the joints they lead to.
            const Eigen::Vector3d origin = parent < 0
              ? Eigen::Vector3d(decodedTranslation.col(f))
              : Eigen::Vector3d(decodedPosition[at + static_cast<std::size_t>(parent)] +
                  decodedWorld[at + static_cast<std::size_t>(parent)] * decodedTranslation.col(f));
            Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
            double weight = 0.0;
            for (int i = 0; i < track->armCount; ++i)
            {
              const auto arm = track->arms.col(static_cast<Eigen::Index>(f) * track->armCount + i);
              const std::size_t k = at + static_cast<std::size_t>(track->armJoints[static_cast<std::size_t>(i)]);
              const Eigen::Vector3d target =
                Eigen::Map<const Eigen::Vector3d>(&tracks.worldPositions[3 * k]) - origin;
              b += target * arm.transpose();
              weight += arm.squaredNorm();
            }
            b += kTwistPrior * weight * input;
            // One Gauss-Newton step from the input orientation: R = R_in exp(hat omega) with
            // (tr S - S) omega = vee(C - C^T), C = R_in^T B, S its symmetric part (the first-
            // order polar factor of C: its corrections are at the tolerance, so second order
            // is far below it, and the final check measures the real error anyway).
            const Eigen::Matrix3d c = input.transpose() * b;
            const Eigen::Matrix3d sym = 0.5 * (c + c.transpose());
            const Eigen::Vector3d skew(c(2, 1) - c(1, 2), c(0, 2) - c(2, 0), c(1, 0) - c(0, 1));
            const Eigen::Matrix3d normal = sym.trace() * Eigen::Matrix3d::Identity() - sym;
            const Eigen::Vector3d omega = normal.ldlt().solve(skew);
            if (omega.allFinite() && omega.norm() < kMaxCorrection)
            {
              world = input * expSO3(omega);
            }
          }
          const Eigen::Matrix3d target = parent < 0
            ? world
            : Eigen::Matrix3d(decodedWorld[at + static_cast<std::size_t>(parent)].transpose() * world);
          const Eigen::Vector3d near = f > 0 ? Eigen::Vector3d(compensated.samples.col(f - 1))
                                             : Eigen::Vector3d(track->samples.col(0));
          compensated.samples.col(f) = logSO3Nearest(target, near);
          compensated.jacobians[static_cast<std::size_t>(f)] = rightJacobian(compensated.samples.col(f));
        }
        track = &compensated;
      }
      structure.Byte(static_cast<std::uint8_t>(track->kind));
      if (track->kind == TrackKind::ConstantFloat || track->kind == TrackKind::ConstantDouble)
      {
        ++counts.constantTracks;
        Eigen::Vector3d stored = Eigen::Vector3d::Zero();
        for (Eigen::Index i = 0; i < track->samples.rows(); ++i)
        {
          if (track->kind == TrackKind::ConstantFloat)
          {
            const float v = static_cast<float>(track->samples(i, 0));
            structure.Raw<float>(v);
            stored(std::min<Eigen::Index>(i, 2)) = static_cast<double>(v);
          }
          else
          {
            structure.Raw<double>(track->samples(i, 0));
            stored(std::min<Eigen::Index>(i, 2)) = track->samples(i, 0);
          }
        }
        if (group == 0)
        {
          decodedTranslation = stored.replicate(1, frames);
        }
        if (group == 1)
        {
          decodedRotation = stored.replicate(1, frames);
        }
        continue;
      }
      if (track->kind != TrackKind::Curve)
      {
        if (group == 0)
        {
          decodedTranslation.setZero(3, frames);
        }
        if (group == 1)
        {
          decodedRotation.setZero(3, frames);
        }
        continue;
      }
      BSplineCurve curve;
      double step = 0.0;
      const std::size_t index = static_cast<std::size_t>(j * kGroupCount + group);
      const Status fitted =
        fitTrack(*track, budgets.budgets[index], options, budgets.degrees[index], curve, step);
      if (fitted != Status::Ok)
      {
        return fitted;
      }
      if (group == 0 && compensation > 0)
      {
        decodedTranslation = evaluateAtSamples(curve);
      }
      if (group == 1 && compensation > 0)
      {
        decodedRotation = evaluateAtSamples(curve);
      }
      ++counts.curveTracks;
      counts.controlPoints += curve.controlPointCount();
      counts.knots += static_cast<int>(curve.interiorKnots.size());
      counts.cubicTracks += curve.degree == 3 ? 1 : 0;
      structure.Byte(static_cast<std::uint8_t>(curve.degree));
      structure.Raw<double>(step);
      structure.Varint(curve.interiorKnots.size());
      int previousKnot = 0;
      for (int k : curve.interiorKnots)
      {
        knots.Varint(static_cast<std::uint64_t>(k - previousKnot));
        previousKnot = k;
      }
      for (Eigen::Index i = 0; i < curve.controlPoints.rows(); ++i)
      {
        std::int64_t previous = 0;
        for (Eigen::Index k = 0; k < curve.controlPoints.cols(); ++k)
        {
          const double scaled = std::round(curve.controlPoints(i, k) / step);
          if (!(std::abs(scaled) < kMaxQuantised))
          {
            return Status::InaccurateResult;
          }
          const auto quantised = static_cast<std::int64_t>(scaled);
          values.Signed(quantised - previous);
          previous = quantised;
        }
      }
    }
    if (compensation > 0)
    {
      for (int f = 0; f < frames; ++f)
      {
        const std::size_t at = static_cast<std::size_t>(f) * jointCount;
        const Eigen::Matrix3d local = expSO3(decodedRotation.col(f));
        if (parent < 0)
        {
          decodedWorld[at + static_cast<std::size_t>(j)] = local;
          decodedPosition[at + static_cast<std::size_t>(j)] = decodedTranslation.col(f);
        }
        else
        {
          const std::size_t p = at + static_cast<std::size_t>(parent);
          decodedWorld[at + static_cast<std::size_t>(j)] = decodedWorld[p] * local;
          decodedPosition[at + static_cast<std::size_t>(j)] =
            decodedPosition[p] + decodedWorld[p] * decodedTranslation.col(f);
        }
      }
    }
  }
  ByteWriter all;
  for (const ByteWriter* part : { &head, &structure, &knots, &values })
  {
    all.Varint(part->Bytes.size());
    all.Bytes += part->Bytes;
  }
  payload.swap(all.Bytes);
  return Status::Ok;
}

std::string frameFile(const std::string& payload)
{
  std::string file(kHeaderBytes, '\0');
  std::memcpy(&file[0], kMagic, 4);
  file[4] = static_cast<char>(kVersion);
  putU32(file, 8, static_cast<std::uint32_t>(payload.size()));
  putU32(file, 12,
    lzma_crc32(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size(), 0));
  if (!lzmaCompress(payload, file))
  {
    return std::string();
  }
  return file;
}

// ---------------------------------------------------------------------------------------
// Decoding

bool decodeFail(std::string* why, const std::string& reason)
{
  if (why)
  {
    *why = reason;
  }
  return false;
}

bool readCurve(ByteReader& structure, ByteReader& knots, ByteReader& values, int frames,
  int dimension, Eigen::MatrixXd& samples, std::string* why)
{
  std::uint8_t degree;
  double step;
  std::uint64_t knotCount;
  if (!structure.Byte(degree) || !structure.Raw<double>(step) ||
    !structure.Count(static_cast<std::uint64_t>(std::max(frames - 2, 0)), knotCount))
  {
    return decodeFail(why, "a curve header is truncated or its knot count exceeds the frames");
  }
  if (!(step > 0.0) || !std::isfinite(step))
  {
    return decodeFail(why, "a curve has a quantisation step that is not positive and finite");
  }
  BSplineCurve curve;
  curve.degree = degree;
  curve.samples = frames;
  curve.interiorKnots.resize(static_cast<std::size_t>(knotCount));
  std::uint64_t knot = 0;
  for (auto& k : curve.interiorKnots)
  {
    std::uint64_t gap;
    if (!knots.Count(static_cast<std::uint64_t>(frames), gap))
    {
      return decodeFail(why, "the knot stream is truncated or holds a gap beyond the frames");
    }
    knot += gap;
    k = static_cast<int>(std::min<std::uint64_t>(knot, static_cast<std::uint64_t>(frames)));
  }
  if (degree > 3)
  {
    return decodeFail(why, "a curve degree above 3");
  }
  const char* problem = nullptr;
  curve.controlPoints.setZero(dimension, curve.controlPointCount());
  if (!isWellFormed(curve, &problem))
  {
    return decodeFail(why, problem);
  }
  for (int i = 0; i < dimension; ++i)
  {
    std::uint64_t value = 0; // wraps on a corrupted stream instead of overflowing
    for (int k = 0; k < curve.controlPointCount(); ++k)
    {
      std::int64_t delta;
      if (!values.Signed(delta))
      {
        return decodeFail(why, "the control-point stream is truncated");
      }
      value += static_cast<std::uint64_t>(delta);
      curve.controlPoints(i, k) = static_cast<double>(static_cast<std::int64_t>(value)) * step;
    }
  }
  if (!curve.controlPoints.allFinite())
  {
    return decodeFail(why, "a control point that is not finite");
  }
  samples = evaluateAtSamples(curve);
  return true;
}

bool decodePayload(const std::string& payload, SkeletalAnimation& a, MotionMetadata& metadata,
  std::string* why)
{
  ByteReader all(payload.data(), payload.size());
  ByteReader parts[4] = { all, all, all, all };
  for (ByteReader& part : parts)
  {
    std::uint64_t size;
    if (!all.Varint(size) || !all.Take(size, part))
    {
      return decodeFail(why, "the payload's sections are truncated");
    }
  }
  if (!all.AtEnd())
  {
    return decodeFail(why, "bytes after the payload's last section");
  }
  ByteReader& head = parts[0];
  std::uint64_t channels, frames, joints;
  if (!head.Text(metadata.rotationOrder, 3) ||
    !head.Count(static_cast<std::uint64_t>(std::numeric_limits<int>::max()), channels) ||
    !head.Raw<double>(a.frameTime) || !head.Raw<double>(metadata.tolerance) ||
    !head.Raw<double>(metadata.height) || !head.Count(static_cast<std::uint64_t>(kMaxTransforms), frames) ||
    !head.Count(kMaxJoints, joints))
  {
    return decodeFail(why, "the header is truncated or holds a count beyond the limits");
  }
  metadata.inputChannels = static_cast<int>(channels);
  if (frames == 0 || joints == 0 ||
    static_cast<double>(frames) * static_cast<double>(joints) > kMaxTransforms)
  {
    return decodeFail(why, "no frames or joints, or more than 3e7 transforms");
  }
  if (!(a.frameTime > 0.0) || !std::isfinite(a.frameTime) || !std::isfinite(metadata.tolerance) ||
    !std::isfinite(metadata.height))
  {
    return decodeFail(why, "a frame time that is not positive, or a non-finite figure");
  }
  a.frames = static_cast<int>(frames);
  a.joints.resize(static_cast<std::size_t>(joints));
  for (std::size_t j = 0; j < a.joints.size(); ++j)
  {
    std::uint64_t parent;
    std::uint8_t flags;
    if (!head.Text(a.joints[j].name, 4096) || !head.Count(j, parent) || !head.Byte(flags) ||
      flags > 1)
    {
      return decodeFail(why, "a joint record is truncated or names a parent that does not precede it");
    }
    a.joints[j].parent = static_cast<int>(parent) - 1;
    a.joints[j].endSite = flags == 1;
  }
  if (!head.AtEnd())
  {
    return decodeFail(why, "bytes after the joint records");
  }

  ByteReader& structure = parts[1];
  ByteReader& knots = parts[2];
  ByteReader& values = parts[3];
  const int n = a.frames;
  a.locals.assign(static_cast<std::size_t>(n) * a.joints.size(), Eigen::Matrix4d::Identity());
  Eigen::MatrixXd groups[kGroupCount];
  for (std::size_t j = 0; j < a.joints.size(); ++j)
  {
    bool stretched = false;
    bool turning = false;
    for (int g = 0; g < kGroupCount; ++g)
    {
      std::uint8_t kind;
      if (!structure.Byte(kind) || kind > static_cast<std::uint8_t>(TrackKind::Curve))
      {
        return decodeFail(why, "a track record is truncated or of an unknown kind");
      }
      Eigen::MatrixXd& samples = groups[g];
      samples.setZero(kGroupSize[g], n);
      switch (static_cast<TrackKind>(kind))
      {
        case TrackKind::Zero:
          break;
        case TrackKind::ConstantFloat:
        case TrackKind::ConstantDouble:
          for (int i = 0; i < kGroupSize[g]; ++i)
          {
            double v;
            float f;
            const bool single = static_cast<TrackKind>(kind) == TrackKind::ConstantFloat;
            if (!(single ? structure.Raw<float>(f) : structure.Raw<double>(v)))
            {
              return decodeFail(why, "a constant track is truncated");
            }
            samples.row(i).setConstant(single ? static_cast<double>(f) : v);
          }
          break;
        case TrackKind::Curve:
          if (!readCurve(structure, knots, values, n, kGroupSize[g], samples, why))
          {
            return false;
          }
          break;
      }
      if (!samples.allFinite())
      {
        return decodeFail(why, "a track value that is not finite");
      }
      stretched = stretched || (g == 2 && static_cast<TrackKind>(kind) != TrackKind::Zero);
      turning = turning || (g == 1 && static_cast<TrackKind>(kind) == TrackKind::Curve);
    }
    const Eigen::Matrix3d fixedRotation = expSO3(groups[1].col(0));
    for (int f = 0; f < n; ++f)
    {
      Eigen::Matrix4d& local = a.locals[static_cast<std::size_t>(f) * a.joints.size() + j];
      if (stretched)
      {
        LogCoords c;
        c << groups[0].col(f), groups[1].col(f), groups[2].col(f);
        const Result<Eigen::Matrix4d> m = polarExp(c);
        if (!m)
        {
          return decodeFail(why, std::string("a joint transform cannot be formed: ") + describe(m.status));
        }
        local = m.value;
      }
      else
      {
        // Finite: the track values were checked, exp of a finite vector is a rotation.
        local.block<3, 3>(0, 0) = turning ? expSO3(groups[1].col(f)) : fixedRotation;
        local.block<3, 1>(0, 3) = groups[0].col(f);
      }
    }
  }
  if (!structure.AtEnd() || !knots.AtEnd() || !values.AtEnd())
  {
    return decodeFail(why, "bytes left over after the last track");
  }
  return true;
}

} // namespace

Result<SkeletalAnimation> decompressMotion(
  const std::string& bytes, MotionMetadata* metadata, std::string* why)
{
  using Out = Result<SkeletalAnimation>;
  auto fail = [why](const std::string& reason) {
    if (why)
    {
      *why = reason;
    }
    return Out::failure(Status::InvalidArgument);
  };
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, 4) != 0)
  {
    return fail("not an .lctm file (no LCTM signature)");
  }
  if (static_cast<std::uint8_t>(bytes[4]) != kVersion || bytes[5] || bytes[6] || bytes[7])
  {
    return fail("an .lctm file of version " +
      std::to_string(static_cast<unsigned>(static_cast<std::uint8_t>(bytes[4]))) +
      " or with unknown flags (this build reads version 1)");
  }
  const std::uint32_t size = getU32(bytes, 8);
  const std::uint32_t checksum = getU32(bytes, 12);
  if (size > kMaxPayloadBytes)
  {
    return fail("the payload size in the header exceeds 1 GiB: a corrupted file");
  }
  std::string payload;
  if (!lzmaDecompress(bytes.data() + kHeaderBytes, bytes.size() - kHeaderBytes, size, payload))
  {
    return fail("the compressed stream is truncated or corrupted");
  }
  if (lzma_crc32(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size(), 0) !=
    checksum)
  {
    return fail("checksum mismatch: the file is corrupted");
  }
  Out out;
  MotionMetadata read;
  if (!decodePayload(payload, out.value, read, why))
  {
    return Out::failure(Status::InvalidArgument);
  }
  if (metadata)
  {
    *metadata = read;
  }
  return out;
}

Result<std::string> compressMotion(const SkeletalAnimation& animation,
  const MotionMetadata& metadata, const MotionCompressionOptions& options,
  MotionCompressionReport* report, std::string* why)
{
  using Out = Result<std::string>;
  auto fail = [why](Status status, const std::string& reason) {
    if (why)
    {
      *why = reason;
    }
    return Out::failure(status);
  };
  std::string problem;
  if (!isConsistent(animation, &problem))
  {
    return fail(Status::InvalidArgument, "an inconsistent animation: " + problem);
  }
  if (animation.jointCount() > kMaxJoints ||
    static_cast<double>(animation.frames) * animation.jointCount() > kMaxTransforms)
  {
    return fail(Status::InvalidArgument, "more than 10000 joints or 3e7 transforms");
  }
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
  {
    return fail(Status::InvalidArgument, "the tolerance must be positive and finite");
  }
  // (A non-finite resolution is an input beyond double's range, which the checks below name.)
  if (std::isfinite(options.inputResolution) && options.tolerance < options.inputResolution)
  {
    const std::string share = metadata.height > 0.0
      ? " (" + formatNumber(100.0 * options.inputResolution / metadata.height) + " % of H)"
      : std::string();
    return fail(Status::InvalidArgument,
      "the tolerance " + formatNumber(options.tolerance) +
        " is below the precision of the input as read: its values are float32, which can put "
        "world positions up to " + formatNumber(options.inputResolution) + share +
        " from the file's own values");
  }
  if (!(options.quantisationShare > 0.0 && options.quantisationShare < 1.0) ||
    options.degree < 0 || options.degree > 3 || options.searchSteps < 0 ||
    options.searchSteps > 64 || metadata.rotationOrder.size() > 3 ||
    !(animation.frameTime > 0.0) || !std::isfinite(animation.frameTime))
  {
    return fail(Status::InvalidArgument,
      "a bad option (quantisation share outside (0, 1), degree outside 0..3, search steps "
      "outside 0..64, a rotation order longer than 3) or a frame time that is not positive");
  }
  for (const Eigen::Matrix4d& m : animation.locals)
  {
    if (!m.allFinite())
    {
      return fail(Status::NonFinite, "a local transform holds NaN or Inf");
    }
  }
  MotionMetadata meta = metadata;
  meta.tolerance = options.tolerance;
  MotionTracks tracks;
  tracks.compensation = options.compensation;
  const Status split = toTracks(animation, options.tolerance, tracks, problem);
  if (split != Status::Ok)
  {
    return fail(split, problem);
  }
  const std::vector<double> reference = worldPositions(animation);
  const double bound = options.tolerance * kVerifyMargin;
  const int frames = animation.frames;
  const int joints = animation.jointCount();
  const std::size_t trackCount = static_cast<std::size_t>(joints) * kGroupCount;

  struct Trial
  {
    std::string file;
    PositionErrorStatistics error;
    EncodeCounts counts;
    std::size_t payloadBytes = 0;
    double beta = 0.0;
    bool passed = false;
  };
  Trial best;
  int trials = 0;
  Eigen::MatrixXd pointErrors(frames, joints); // of the last trial
  TrackBudgets budgets;
  budgets.degrees.assign(trackCount, 0);
  auto attempt = [&](double beta, Trial& trial) -> Status {
    ++trials;
    std::string payload;
    trial = Trial();
    trial.beta = beta;
    const Status encoded =
      encodePayload(animation, meta, tracks, budgets, options, payload, trial.counts);
    if (encoded != Status::Ok)
    {
      return encoded;
    }
    trial.payloadBytes = payload.size();
    SkeletalAnimation decoded;
    MotionMetadata ignored;
    if (!decodePayload(payload, decoded, ignored, nullptr))
    {
      return Status::NumericalFailure;
    }
    const std::vector<double> positions = worldPositions(decoded);
    for (int f = 0; f < frames; ++f)
    {
      for (int k = 0; k < joints; ++k)
      {
        const std::size_t at = (static_cast<std::size_t>(f) * joints + k) * 3;
        const double e = Eigen::Vector3d(positions[at] - reference[at],
          positions[at + 1] - reference[at + 1], positions[at + 2] - reference[at + 2])
                           .norm();
        pointErrors(f, k) = std::isfinite(e) ? e : HUGE_VAL;
      }
    }
    trial.error = positionErrors(reference, decoded);
    trial.passed = trial.error.max <= bound;
    if (trial.passed)
    {
      trial.file = frameFile(payload);
      if (trial.file.empty())
      {
        return Status::NumericalFailure;
      }
      if (best.file.empty() || trial.file.size() < best.file.size())
      {
        best = trial;
      }
    }
    if (options.progress)
    {
      std::ostringstream line;
      line << "trial " << trials << ": budget scale " << beta << ", payload " << payload.size()
           << " bytes" << (trial.passed ? ", file " + std::to_string(trial.file.size()) : std::string())
           << ", max error " << trial.error.max << " (frame " << trial.error.worstFrame << ", joint " << trial.error.worstJoint << ")" << (trial.passed ? " (within)" : " (over)");
      options.progress(line.str());
    }
    return Status::Ok;
  };
  auto uniform = [&](double beta) {
    budgets.budgets.assign(trackCount, Eigen::VectorXd::Constant(frames, beta * options.tolerance));
  };

  // 1. One budget for every track. The worst-case sum along a chain is within the tolerance
  //    at beta = 1 / depth; measured errors add far less (with compensation, beta ~ 0.3-0.5
  //    on the CMU clips), so the search starts there, falls back towards the safe beta, then
  //    climbs and bisects.
  double passing = std::max(kFirstBudget, 1.0 / tracks.chainDepth);
  Trial trial;
  Status status = Status::Ok;
  double failing = 0.0;
  for (int retry = 0; retry < 6; ++retry)
  {
    uniform(passing);
    status = attempt(passing, trial);
    if (status != Status::Ok || trial.passed)
    {
      break;
    }
    failing = passing;
    passing = std::max(passing / 3.0, 1e-3 / tracks.chainDepth);
  }
  if (status != Status::Ok || best.file.empty())
  {
    return fail(status == Status::Ok ? Status::InaccurateResult : status,
      status == Status::InaccurateResult || status == Status::Ok
        ? "no encoding met the tolerance: it is at or below the precision of the input values"
        : std::string("encoding failed: ") + describe(status));
  }
  if (options.searchBudget)
  {
    for (double beta = passing * 1.5; failing == 0.0 && beta <= 8.0; beta *= 1.5)
    {
      uniform(beta);
      if (attempt(beta, trial) != Status::Ok || !trial.passed)
      {
        failing = beta;
        break;
      }
      passing = beta;
    }
    for (int s = 0; s < options.searchSteps && failing > 0.0; ++s)
    {
      const double beta = std::sqrt(passing * failing);
      uniform(beta);
      if (attempt(beta, trial) == Status::Ok && trial.passed)
      {
        passing = beta;
      }
      else
      {
        failing = beta;
      }
    }
  }

  // 2. Local repair: the measured error is far below the worst-case sum almost everywhere;
  //    where several tracks' errors line up (a foot strike, a sharp turn) it peaks. Above the
  //    best single budget, tighten only there: every track of the joints whose subtree holds a
  //    point over the bound, within a few frames of it (a control point reaches a few frames
  //    either side), by the factor it is over, and measure again; climb while that succeeds.
  std::vector<std::vector<int>> affected(static_cast<std::size_t>(joints));
  for (int k = 0; k < joints; ++k)
  {
    for (int j = k; j >= 0; j = animation.joints[static_cast<std::size_t>(j)].parent)
    {
      affected[static_cast<std::size_t>(j)].push_back(k);
    }
  }
  constexpr int kWindow = 24;
  constexpr double kRepairTarget = 0.85;
  auto tighten = [&]() {
    for (int j = 0; j < joints; ++j)
    {
      Eigen::VectorXd over = Eigen::VectorXd::Ones(frames);
      for (int f = 0; f < frames; ++f)
      {
        for (int k : affected[static_cast<std::size_t>(j)])
        {
          const double ratio = pointErrors(f, k) / (kRepairTarget * bound);
          if (ratio > 1.0)
          {
            const int from = std::max(0, f - kWindow);
            const int to = std::min(frames - 1, f + kWindow);
            for (int g = from; g <= to; ++g)
            {
              over(g) = std::max(over(g), ratio);
            }
          }
        }
      }
      for (int g = 0; g < kGroupCount; ++g)
      {
        Eigen::VectorXd& b = budgets.budgets[static_cast<std::size_t>(j * kGroupCount + g)];
        b = b.cwiseQuotient(over);
      }
    }
  };
  double beta = best.beta;
  for (int step = 0; step < options.refineSteps; ++step)
  {
    beta *= kRepairClimb;
    uniform(beta);
    bool repaired = false;
    for (int round = 0; round <= kRepairRounds && !repaired; ++round)
    {
      if (round > 0)
      {
        tighten();
      }
      repaired = attempt(beta, trial) == Status::Ok && trial.passed;
    }
    if (!repaired)
    {
      break;
    }
  }
  if (report)
  {
    report->error = best.error;
    report->bytes = best.file.size();
    report->payloadBytes = best.payloadBytes;
    report->budgetScale = best.beta;
    report->trials = trials;
    report->curveTracks = best.counts.curveTracks;
    report->constantTracks = best.counts.constantTracks;
    report->controlPoints = best.counts.controlPoints;
    report->knots = best.counts.knots;
    report->cubicTracks = best.counts.cubicTracks;
  }
  Out out;
  out.value = std::move(best.file);
  return out;
}

} // namespace lct
