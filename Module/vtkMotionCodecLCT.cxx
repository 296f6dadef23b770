#include "vtkMotionCodecLCT.h"

#include "vtkSkeletonAnimationReader.h"

#include "lct/BVHWriter.h"
#include "lct/MotionCodec.h"
#include "lct/MotionError.h"
#include "lct/OutputFile.h"

#include "vtkObjectFactory.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMotionCodecLCT);

//------------------------------------------------------------------------------
vtkMotionCodecLCT::vtkMotionCodecLCT() = default;

//------------------------------------------------------------------------------
vtkMotionCodecLCT::~vtkMotionCodecLCT()
{
  this->SetRotationOrder(nullptr);
}

//------------------------------------------------------------------------------
void vtkMotionCodecLCT::ResetFigures()
{
  this->CompressedBytes = 0;
  this->CompressionFactor = 0.0;
  this->MaximumError = 0.0;
  this->P99Error = 0.0;
  this->MeanError = 0.0;
  this->SkeletonHeight = 0.0;
}

//------------------------------------------------------------------------------
int vtkMotionCodecLCT::Compress(vtkSkeletonAnimationReader* reader, const char* fileName)
{
  try
  {
    return this->CompressOrThrow(reader, fileName);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Compress: out of memory for this animation; nothing written.");
    return 0;
  }
}

//------------------------------------------------------------------------------
int vtkMotionCodecLCT::CompressOrThrow(vtkSkeletonAnimationReader* reader, const char* fileName)
{
  this->ResetFigures();
  const lct::SkeletalAnimation* animation = reader ? reader->GetAnimation() : nullptr;
  if (!animation || !fileName || !*fileName)
  {
    vtkErrorMacro(<< "Compress: "
                  << (!reader         ? "no reader"
                         : !animation ? "the reader has no animation (UpdateInformation() first)"
                                      : "no file name")
                  << "; nothing written.");
    return 0;
  }
  const double height = lct::restPoseHeight(*animation);
  if (!std::isfinite(this->Tolerance))
  {
    vtkErrorMacro(<< "Compress: Tolerance is " << this->Tolerance
                  << ": it must be finite (0 or less uses RelativeTolerance); nothing written.");
    return 0;
  }
  const std::string order = this->RotationOrder ? this->RotationOrder : "ZYX";
  if (!lct::isRotationOrder(order))
  {
    vtkErrorMacro(<< "Compress: the rotation order \"" << order
                  << "\" is not a permutation of XYZ; nothing written.");
    return 0;
  }
  const double tolerance =
    this->Tolerance > 0.0 ? this->Tolerance : this->RelativeTolerance * height;
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
  {
    vtkErrorMacro(<< "Compress: the tolerance " << tolerance
                  << " is not positive and finite (Tolerance " << this->Tolerance
                  << ", RelativeTolerance " << this->RelativeTolerance << ", H " << height
                  << "); nothing written.");
    return 0;
  }
  lct::MotionMetadata metadata;
  metadata.rotationOrder = order;
  metadata.height = height;
  int channels = 0;
  for (const lct::SkeletonJoint& joint : animation->joints)
  {
    channels += joint.endSite ? 0 : joint.parent < 0 ? 6 : 3;
  }
  metadata.inputChannels = channels;
  lct::MotionCompressionOptions options;
  options.tolerance = tolerance;
  options.inputResolution = lct::float32PositionResolution(*animation); // assimp's float32
  lct::MotionCompressionReport report;
  std::string why;
  const lct::Result<std::string> file =
    lct::compressMotion(*animation, metadata, options, &report, &why);
  if (!file)
  {
    vtkErrorMacro(<< "Compress: " << why << "; nothing written.");
    return 0;
  }
  if (!lct::writeFileAtomically(fileName, file.value, why))
  {
    vtkErrorMacro(<< "Compress: " << why << "; nothing written.");
    return 0;
  }
  this->CompressedBytes = static_cast<vtkIdType>(file.value.size());
  this->CompressionFactor =
    4.0 * animation->frames * channels / static_cast<double>(file.value.size());
  this->MaximumError = report.error.max;
  this->P99Error = report.error.p99;
  this->MeanError = report.error.mean;
  this->SkeletonHeight = height;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkMotionCodecLCT::Decompress(const char* lctmFile, const char* bvhFile)
{
  try
  {
    return this->DecompressOrThrow(lctmFile, bvhFile);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Decompress: out of memory for the animation " << lctmFile
                  << " describes; nothing written.");
    return 0;
  }
}

//------------------------------------------------------------------------------
int vtkMotionCodecLCT::DecompressOrThrow(const char* lctmFile, const char* bvhFile)
{
  if (!lctmFile || !*lctmFile || !bvhFile || !*bvhFile)
  {
    vtkErrorMacro(<< "Decompress: no file name; nothing written.");
    return 0;
  }
  std::ifstream in(lctmFile, std::ios::binary);
  if (!in)
  {
    vtkErrorMacro(<< "Decompress: " << lctmFile << " cannot be read; nothing written.");
    return 0;
  }
  // The signature first, then at most what a valid file can hold: reading the whole stream first
  // never returned on /dev/zero or a FIFO (1.4 GB after 10 s).
  std::string content(4, '\0');
  if (!in.read(&content[0], 4) || content != "LCTM")
  {
    vtkErrorMacro(<< "Decompress: " << lctmFile
                  << ": not an .lctm file (no LCTM signature); nothing written.");
    return 0;
  }
  constexpr std::size_t kMaxFileBytes = (std::size_t(1) << 30) + (std::size_t(1) << 20);
  std::vector<char> chunk(std::size_t(1) << 16);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
  {
    content.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (content.size() > kMaxFileBytes)
    {
      vtkErrorMacro(<< "Decompress: " << lctmFile
                    << " is larger than any .lctm file (a payload of at most 1 GiB, compressed); "
                       "nothing written.");
      return 0;
    }
  }
  lct::MotionMetadata metadata;
  std::string why;
  const lct::Result<lct::SkeletalAnimation> motion =
    lct::decompressMotion(content, &metadata, &why);
  if (!motion)
  {
    vtkErrorMacro(<< "Decompress: " << lctmFile << ": " << why << "; nothing written.");
    return 0;
  }
  std::ostringstream text;
  const std::string order = this->RotationOrder ? this->RotationOrder : metadata.rotationOrder;
  if (!lct::writeBVH(motion.value, order, text, &why) ||
    !lct::writeFileAtomically(bvhFile, text.str(), why))
  {
    vtkErrorMacro(<< "Decompress: " << why << "; nothing written.");
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkMotionCodecLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "RelativeTolerance: " << this->RelativeTolerance << "\n";
  os << indent << "RotationOrder: " << (this->RotationOrder ? this->RotationOrder : "(null)")
     << "\n";
  os << indent << "CompressedBytes: " << this->CompressedBytes << "\n";
  os << indent << "CompressionFactor: " << this->CompressionFactor << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "P99Error: " << this->P99Error << "\n";
  os << indent << "MeanError: " << this->MeanError << "\n";
  os << indent << "SkeletonHeight: " << this->SkeletonHeight << "\n";
}
