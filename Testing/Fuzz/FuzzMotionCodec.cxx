// Fuzz target: the motion-capture codec (lct/MotionCodec.h). The first byte picks a mode:
//  0  the bytes as an .lctm file (signature, version, size, checksum, LZMA2 stream);
//  1  the bytes as the payload of a well-formed file (this target writes the header, the
//     checksum and the LZMA2 stream), so the parser behind the checksum is reached;
//  2  a small skeleton (1..6 joints, 1..40 frames) and a tolerance made from the bytes
//     (rotations through and beyond pi, stretch, translations up to 1e6, NaN and Inf through
//     the selector of FuzzInput.h) compressed, then decoded.
// Properties: no crash, sanitizer report or hang; a refused file says why; a decoded motion is
// consistent (parents precede children, frames x joints transforms) and finite; mode 2: either
// the compressor refuses (with a reason) or the decoded motion is within its tolerance at every
// joint and frame (lct::positionErrors, and the report agrees).
#include "FuzzInput.h"

#include "lct/MotionCodec.h"
#include "lct/MotionError.h"
#include "lct/SO3.h"

#include <lzma.h>

#include <cstring>
#include <string>

namespace
{

void CheckDecoded(const lct::Result<lct::SkeletalAnimation>& r, const std::string& why)
{
  if (!r)
  {
    LCT_FUZZ_CHECK(!why.empty(), "a refused file says why");
    return;
  }
  std::string problem;
  LCT_FUZZ_CHECK(lct::isConsistent(r.value, &problem), "a decoded motion is consistent: " << problem);
  for (const Eigen::Matrix4d& m : r.value.locals)
  {
    LCT_FUZZ_CHECK(m.allFinite(), "decoded transforms are finite");
  }
}

std::string WellFormedFile(const std::string& payload)
{
  std::string file(16, '\0');
  std::memcpy(&file[0], "LCTM", 4);
  file[4] = 1;
  const std::uint32_t size = static_cast<std::uint32_t>(payload.size());
  const std::uint32_t crc =
    lzma_crc32(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size(), 0);
  for (int i = 0; i < 4; ++i)
  {
    file[8 + i] = static_cast<char>((size >> (8 * i)) & 0xff);
    file[12 + i] = static_cast<char>((crc >> (8 * i)) & 0xff);
  }
  lzma_options_lzma options;
  lzma_lzma_preset(&options, 6);
  const lzma_filter filters[] = { { LZMA_FILTER_LZMA2, &options }, { LZMA_VLI_UNKNOWN, nullptr } };
  std::string stream(payload.size() + payload.size() / 2 + 1024, '\0');
  std::size_t written = 0;
  if (lzma_raw_buffer_encode(filters, nullptr, reinterpret_cast<const std::uint8_t*>(payload.data()),
        payload.size(), reinterpret_cast<std::uint8_t*>(&stream[0]), &written, stream.size()) != LZMA_OK)
  {
    return std::string();
  }
  stream.resize(written);
  return file + stream;
}

lct::SkeletalAnimation Skeleton(lct_fuzz::Input& in)
{
  lct::SkeletalAnimation a;
  const int joints = in.Int(1, 6);
  a.frames = in.Int(1, 40);
  a.frameTime = 1.0 / 120.0;
  for (int j = 0; j < joints; ++j)
  {
    a.joints.push_back({ "j" + std::to_string(j), j == 0 ? -1 : in.Int(0, j - 1),
      false });
  }
  // Per joint: a start and an end rotation vector (beyond pi allowed), a stretch, an offset.
  struct Motion
  {
    Eigen::Vector3d from, to, offset, drift;
    double stretch;
  };
  std::vector<Motion> motions;
  for (int j = 0; j < joints; ++j)
  {
    Motion m;
    for (int i = 0; i < 3; ++i)
    {
      m.from(i) = in.Provider().ConsumeFloatingPointInRange(-7.0, 7.0);
      m.to(i) = in.Provider().ConsumeFloatingPointInRange(-7.0, 7.0);
      m.offset(i) = in.Bool() ? in.Double() : in.Provider().ConsumeFloatingPointInRange(-1e6, 1e6);
      m.drift(i) = j == 0 ? in.Provider().ConsumeFloatingPointInRange(-100.0, 100.0) : 0.0;
    }
    m.stretch = in.Bool() ? in.Provider().ConsumeFloatingPointInRange(-0.5, 0.5) : 0.0;
    motions.push_back(m);
  }
  a.locals.resize(static_cast<std::size_t>(a.frames * joints));
  for (int f = 0; f < a.frames; ++f)
  {
    const double u = a.frames > 1 ? double(f) / (a.frames - 1) : 0.0;
    for (int j = 0; j < joints; ++j)
    {
      const Motion& m = motions[static_cast<std::size_t>(j)];
      Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
      local.block<3, 3>(0, 0) = lct::expSO3((1.0 - u) * m.from + u * m.to) *
        Eigen::Vector3d(std::exp(m.stretch * u), 1.0, 1.0).asDiagonal();
      local.block<3, 1>(0, 3) = m.offset + u * m.drift;
      a.locals[static_cast<std::size_t>(f * joints + j)] = local;
    }
  }
  return a;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  if (size == 0)
  {
    return 0;
  }
  const int mode = data[0] % 3;
  const std::string bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  std::string why;
  if (mode == 0)
  {
    CheckDecoded(lct::decompressMotion(bytes, nullptr, &why), why);
    return 0;
  }
  if (mode == 1)
  {
    const std::string file = WellFormedFile(bytes);
    if (!file.empty())
    {
      CheckDecoded(lct::decompressMotion(file, nullptr, &why), why);
    }
    return 0;
  }
  lct_fuzz::Input in(data + 1, size - 1);
  const lct::SkeletalAnimation animation = Skeleton(in);
  lct::MotionCompressionOptions options;
  options.tolerance = in.Bool() ? in.Double() : in.Provider().ConsumeFloatingPointInRange(1e-6, 10.0);
  options.degree = in.Int(0, 3);
  options.compensation = in.Int(0, 2);
  options.searchSteps = in.Int(0, 3);
  options.refineSteps = in.Int(0, 2);
  lct::MotionCompressionReport report;
  const lct::Result<std::string> file =
    lct::compressMotion(animation, lct::MotionMetadata(), options, &report, &why);
  if (!file)
  {
    LCT_FUZZ_CHECK(!why.empty() && file.value.empty(), "a refused compression says why");
    return 0;
  }
  const lct::Result<lct::SkeletalAnimation> decoded = lct::decompressMotion(file.value, nullptr, &why);
  LCT_FUZZ_CHECK(decoded.ok(), "the compressor's own file decodes: " << why);
  CheckDecoded(decoded, why);
  const lct::PositionErrorStatistics error =
    lct::positionErrors(lct::worldPositions(animation), decoded.value);
  LCT_FUZZ_CHECK(error.max <= options.tolerance,
    "the decoded motion is within the tolerance: max " << error.max << " > " << options.tolerance);
  LCT_FUZZ_CHECK(std::abs(error.max - report.error.max) <= 1e-9 * (1.0 + error.max),
    "the report's max error is the measured one: " << report.error.max << " vs " << error.max);
  return 0;
}
