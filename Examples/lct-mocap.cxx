// lct-mocap: error-bounded compression of skeletal animation in log coordinates.
//
//   lct-mocap compress IN --tolerance 1% -o OUT.lctm     any file vtkSkeletonAnimationReader reads
//   lct-mocap decompress IN.lctm -o OUT.bvh              a BVH file other tools read
//   lct-mocap info IN.lctm                               what a file holds
//   lct-mocap analyse IN [-o DIR]                        error against size, per representation
//
// The method and the file format are in Module/lct/MotionCodec.h; the README's "Motion capture
// compression" section has the measurements. Exit codes: 0 ok, 1 error, 2 usage.
#include "MocapAnalysis.h"

#include "vtkSkeletonAnimationReader.h"

#include "lct/BVHWriter.h"
#include "lct/MotionCodec.h"
#include "lct/MotionError.h"
#include "lct/OutputFile.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkCommand.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPNGWriter.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

const char* const Usage =
  R"(usage: lct-mocap compress IN [--tolerance T] [--frames A:B] [--degree D] -o OUT.lctm
       lct-mocap decompress IN.lctm [--rotation-order XYZ] -o OUT.bvh
       lct-mocap info IN.lctm
       lct-mocap compare A B [--tolerance T] [--frames A:B]
       lct-mocap analyse IN [-o DIR] [--quick]

compress     IN: any file vtkSkeletonAnimationReader reads (BVH, FBX, glTF, Collada, X, ...).
             The largest distance between an original and a decoded joint or End Site, at any
             data row, is at most T: "1%" (default) is 1 % of the skeleton height H (the Y
             extent of the rest pose), a number without % is in the file's units. The tool
             decodes what it wrote and verifies the bound before it renames the file into place.
             --frames A:B keeps rows A..B-1 only; --degree 1|2|3 fixes the curve degree
             (default: per track the better of 1 and 3); --quiet drops the progress lines.
decompress   writes the decoded motion as BVH: same joint names, hierarchy, offsets and frame
             time; rotation channels in the input's order (or --rotation-order).
info         the header and figures of an .lctm file.
compare      the position error of B against A (either a motion file or an .lctm): max, p99,
             mean, where the max is; with --tolerance, exit 1 when the max exceeds it;
             --frames A:B compares rows A..B-1 of the first file with the second.
analyse      prints a table (and writes DIR/analysis.csv and DIR/analysis.png, default
             DIR = .) of the position error (max, p99, mean, % of H) against the compression
             factor for: Euler channels and rotation vectors kept every k-th row, Alexa's 4x4
             logs and Polar logs reduced by PCA, uniform key subsampling with the LCT spline,
             and this compressor at several tolerances.

Factor = 4 bytes x data rows x channels of the input / output bytes. Outputs are written to a
temporary name (.NAME.PID.RANDOM.part, created new) and renamed; on failure nothing is left behind. An -o that is a
symbolic link writes the file it leads to; one that is (or leads to) a directory, FIFO or device
is refused, before any work.
exit codes: 0 ok, 1 error (unreadable or bad input, bound not met, write failed), 2 usage.
)";

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

bool ReadFile(const std::string& path, std::string& bytes, std::string& why)
{
  constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 30;
  std::error_code error;
  if (!fs::is_regular_file(path, error))
  {
    why = path + ": not a readable file";
    return false;
  }
  if (fs::file_size(path, error) > kMaxFileBytes)
  {
    why = path + ": larger than 1 GiB";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  if (!in && !in.eof())
  {
    why = path + ": read error";
    return false;
  }
  bytes = content.str();
  return true;
}

/// What `mode` is, for a file that is not a regular one.
std::string FileKind(mode_t mode)
{
  return S_ISDIR(mode) ? "a directory"
    : S_ISFIFO(mode)   ? "a FIFO"
    : S_ISCHR(mode)    ? "a character device"
    : S_ISBLK(mode)    ? "a block device"
    : S_ISSOCK(mode)   ? "a socket"
                       : "not a regular file";
}

/// The file that writing `output` replaces: `output`, or where its symbolic links lead (renaming
/// over a link would turn the link, and over a FIFO or a device that, into a regular file).
/// False with the reason when it exists and is not a regular file, or when its directory cannot
/// take a new file, so that the work is not done for a write that must fail.
bool OutputTarget(const fs::path& output, fs::path& target, std::string& why)
{
  target = lct::outputTarget(output);
  struct stat s;
  const int found = ::lstat(target.c_str(), &s);
  if (found == 0 && S_ISLNK(s.st_mode))
  {
    // outputTarget leaves a loop, or a chain of more than 40 links, where it starts.
    why = "cannot write " + output.string() + ": " + std::strerror(ELOOP);
    return false;
  }
  const int statError = found == 0 ? 0 : errno;
  const std::string name =
    target == output ? output.string() : output.string() + " (a link to " + target.string() + ")";
  if (found == 0)
  {
    if (!S_ISREG(s.st_mode))
    {
      why = name + " is " + FileKind(s.st_mode) + ", not a regular file";
      return false;
    }
  }
  else if (statError != ENOENT)
  {
    why = "cannot write " + name + ": " + std::strerror(statError);
    return false;
  }
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (::access(directory.c_str(), W_OK | X_OK) != 0)
  {
    why = "cannot write " + name + ": " + directory.string() + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

struct Arguments
{
  std::string command;
  std::string input;
  std::string second; ///< compare: the file compared with `input`
  std::string output;
  std::string tolerance;
  std::string frames;
  std::string rotationOrder;
  int degree = 0;
  bool quiet = false;
  bool quick = false;
};

/// Returns the usage error, or an empty string.
std::string Parse(int argc, char* argv[], Arguments& a)
{
  if (argc < 2)
  {
    return "no command";
  }
  a.command = argv[1];
  if (a.command == "-h" || a.command == "--help")
  {
    return "";
  }
  if (a.command != "compress" && a.command != "decompress" && a.command != "info" &&
    a.command != "compare" && a.command != "analyse" && a.command != "analyze")
  {
    return "unknown command '" + a.command + "'";
  }
  for (int i = 2; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& into) {
      if (i + 1 >= argc)
      {
        return false;
      }
      into = argv[++i];
      return true;
    };
    std::string v;
    if (arg == "-o" || arg == "--output")
    {
      if (!value(a.output))
      {
        return arg + " needs a value";
      }
    }
    else if (arg == "-t" || arg == "--tolerance")
    {
      if (!value(a.tolerance))
      {
        return arg + " needs a value";
      }
    }
    else if (arg == "--frames")
    {
      if (!value(a.frames))
      {
        return arg + " needs a value";
      }
      // The form here (a usage error, exit 2); the bound against the file's rows once it is read.
      int first = 0, last = 0;
      char colon = 0;
      std::istringstream range(a.frames);
      if (!(range >> first >> colon >> last) || colon != ':' || !range.eof() || first < 0 ||
        last <= first)
      {
        return "--frames " + a.frames + ": want A:B, integers with 0 <= A < B";
      }
    }
    else if (arg == "--rotation-order")
    {
      if (!value(a.rotationOrder))
      {
        return arg + " needs a value";
      }
      if (!lct::isRotationOrder(a.rotationOrder))
      {
        return "--rotation-order " + a.rotationOrder +
          ": want a permutation of XYZ (e.g. ZXY, the CMU files' order)";
      }
    }
    else if (arg == "--degree")
    {
      if (!value(v) || (v != "1" && v != "2" && v != "3"))
      {
        return "--degree takes 1, 2 or 3";
      }
      a.degree = std::atoi(v.c_str());
    }
    else if (arg == "--quiet")
    {
      a.quiet = true;
    }
    else if (arg == "--quick")
    {
      a.quick = true;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      return "unknown option " + arg;
    }
    else if (a.input.empty())
    {
      a.input = arg;
    }
    else if (a.command == "compare" && a.second.empty())
    {
      a.second = arg;
    }
    else
    {
      return "more than one input file";
    }
  }
  if (a.input.empty())
  {
    return "no input file";
  }
  if (a.command == "compare" && a.second.empty())
  {
    return "compare needs two files";
  }
  if ((a.command == "compress" || a.command == "decompress") && a.output.empty())
  {
    return a.command + " needs -o OUT";
  }
  return "";
}

/// Keeps the text of the last error a VTK object reported.
class ErrorText : public vtkCommand
{
public:
  static ErrorText* New() { return new ErrorText; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Last = callData ? static_cast<const char*>(callData) : "";
  }
  std::string Last;
};

/// Reads IN through the module's reader; its error comes back as text.
bool ReadMotion(const std::string& path, lct_mocap::Clip& clip, std::string& why)
{
  vtkNew<vtkSkeletonAnimationReader> reader;
  vtkNew<ErrorText> errors;
  vtkNew<ErrorText> pipelineErrors; // the executive's "returned failure": said once, below
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipelineErrors);
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  const lct::SkeletalAnimation* animation = reader->GetAnimation();
  if (!animation)
  {
    // VTK's message is "ERROR: In <file>, line <n>\n<class> (<address>): <text>": keep <text>.
    std::string text = errors->Last;
    const std::size_t at = text.find("): ");
    text = at == std::string::npos ? text : text.substr(at + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    // The reader's messages start with the file name.
    why = text.empty() ? path + ": not a skeletal animation the reader takes" : text;
    return false;
  }
  clip.animation = *animation;
  clip.name = fs::path(path).filename().string();
  lct_mocap::ScanBVHHeader(path, clip);
  return true;
}

bool Slice(lct_mocap::Clip& clip, const std::string& range, std::string& why)
{
  if (range.empty())
  {
    return true;
  }
  int first = 0;
  int last = 0;
  char colon = 0;
  std::istringstream in(range);
  if (!(in >> first >> colon >> last) || colon != ':' || !in.eof() || first < 0 || last <= first ||
    last > clip.animation.frames)
  {
    why = "--frames " + range +
      ": want A:B with 0 <= A < B <= " + std::to_string(clip.animation.frames);
    return false;
  }
  lct::SkeletalAnimation& a = clip.animation;
  const std::size_t joints = a.joints.size();
  a.locals =
    std::vector<Eigen::Matrix4d>(a.locals.begin() + static_cast<std::ptrdiff_t>(first * joints),
      a.locals.begin() + static_cast<std::ptrdiff_t>(last * joints));
  a.frames = last - first;
  return true;
}

int Compress(const Arguments& args)
{
  std::string why;
  fs::path target;
  if (!OutputTarget(args.output, target, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  lct_mocap::Clip clip;
  if (!ReadMotion(args.input, clip, why) || !Slice(clip, args.frames, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  double tolerance = 0.0;
  if (!lct_mocap::ParseTolerance(
        args.tolerance.empty() ? "1%" : args.tolerance, clip.height, tolerance, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 2;
  }
  lct::MotionMetadata metadata;
  metadata.rotationOrder = clip.rotationOrder;
  metadata.inputChannels = clip.channels;
  metadata.height = clip.height;
  lct::MotionCompressionOptions options;
  options.tolerance = tolerance;
  options.inputResolution = lct::float32PositionResolution(clip.animation); // assimp's float32
  options.degree = args.degree;
  if (!args.quiet)
  {
    options.progress = [](const std::string& line) { std::cerr << "  " << line << "\n"; };
  }
  lct::MotionCompressionReport report;
  const auto start = Clock::now();
  const lct::Result<std::string> file =
    lct::compressMotion(clip.animation, metadata, options, &report, &why);
  const double seconds = Seconds(start);
  if (!file)
  {
    std::cerr << "lct-mocap: " << args.input << ": " << why << "; nothing written.\n";
    return 1;
  }
  if (!lct_mocap::WriteAtomically(args.output, file.value, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  const double raw = lct_mocap::RawBytes(clip);
  const double duration = clip.animation.frames * clip.animation.frameTime;
  std::printf("%s: %d rows x %d channels, %d joints, H = %.4g\n", args.input.c_str(),
    clip.animation.frames, clip.channels, clip.animation.jointCount(), clip.height);
  std::printf("tolerance %.4g (%.4g %% of H): max %.4g (%.4g %%), p99 %.4g, mean %.4g\n", tolerance,
    100.0 * tolerance / clip.height, report.error.max, 100.0 * report.error.max / clip.height,
    report.error.p99, report.error.mean);
  std::printf("%s: %zu bytes, factor %.1f (raw %.0f bytes); %d curve tracks (%d cubic), %d "
              "control points, %d constant tracks\n",
    args.output.c_str(), report.bytes, raw / static_cast<double>(report.bytes), raw,
    report.curveTracks, report.cubicTracks, report.controlPoints, report.constantTracks);
  std::printf("compressed in %.2f s (%.1fx real time, %d trials)\n", seconds, duration / seconds,
    report.trials);
  return 0;
}

int Decompress(const Arguments& args)
{
  std::string bytes;
  std::string why;
  fs::path target;
  if (!OutputTarget(args.output, target, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  if (!ReadFile(args.input, bytes, why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  lct::MotionMetadata metadata;
  const auto start = Clock::now();
  const lct::Result<lct::SkeletalAnimation> motion = lct::decompressMotion(bytes, &metadata, &why);
  const double seconds = Seconds(start);
  if (!motion)
  {
    std::cerr << "lct-mocap: " << args.input << ": " << why << "; nothing written.\n";
    return 1;
  }
  const std::string order =
    args.rotationOrder.empty() ? metadata.rotationOrder : args.rotationOrder;
  std::ostringstream text;
  if (!lct::writeBVH(motion.value, order, text, &why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  if (!lct_mocap::WriteAtomically(args.output, text.str(), why))
  {
    std::cerr << "lct-mocap: " << why << "; nothing written.\n";
    return 1;
  }
  const double duration = motion.value.frames * motion.value.frameTime;
  std::printf("%s: %d rows, %d joints; decoded in %.2f ms (%.0fx real time); wrote %s\n",
    args.input.c_str(), motion.value.frames, motion.value.jointCount(), 1e3 * seconds,
    duration / seconds, args.output.c_str());
  return 0;
}

/// A motion from a file the reader takes, or from an .lctm file (by its signature).
bool ReadAny(const std::string& path, lct_mocap::Clip& clip, std::string& why)
{
  std::string bytes;
  std::ifstream probe(path, std::ios::binary);
  char magic[4] = {};
  if (probe.read(magic, 4) && std::memcmp(magic, "LCTM", 4) == 0)
  {
    lct::MotionMetadata metadata;
    if (!ReadFile(path, bytes, why))
    {
      return false;
    }
    const lct::Result<lct::SkeletalAnimation> motion =
      lct::decompressMotion(bytes, &metadata, &why);
    if (!motion)
    {
      why = path + ": " + why;
      return false;
    }
    clip.animation = motion.value;
    clip.name = fs::path(path).filename().string();
    clip.height = lct::restPoseHeight(clip.animation);
    return true;
  }
  return ReadMotion(path, clip, why);
}

int Compare(const Arguments& args)
{
  std::string why;
  lct_mocap::Clip a;
  lct_mocap::Clip b;
  if (!ReadAny(args.input, a, why) || !ReadAny(args.second, b, why) || !Slice(a, args.frames, why))
  {
    std::cerr << "lct-mocap: " << why << "\n";
    return 1;
  }
  if (a.animation.frames != b.animation.frames ||
    a.animation.jointCount() != b.animation.jointCount())
  {
    std::cerr << "lct-mocap: " << args.input << " has " << a.animation.frames << " rows and "
              << a.animation.jointCount() << " joints, " << args.second << " " << b.animation.frames
              << " and " << b.animation.jointCount() << ": not comparable\n";
    return 1;
  }
  for (int j = 0; j < a.animation.jointCount(); ++j)
  {
    if (a.animation.joints[static_cast<std::size_t>(j)].parent !=
      b.animation.joints[static_cast<std::size_t>(j)].parent)
    {
      std::cerr << "lct-mocap: the hierarchies differ at joint " << j << "\n";
      return 1;
    }
  }
  double tolerance = 0.0;
  if (!args.tolerance.empty() &&
    !lct_mocap::ParseTolerance(args.tolerance, a.height, tolerance, why))
  {
    std::cerr << "lct-mocap: " << why << "\n";
    return 2;
  }
  const lct::PositionErrorStatistics e =
    lct::positionErrors(lct::worldPositions(a.animation), b.animation);
  const double h = a.height > 0.0 ? 100.0 / a.height : 0.0;
  std::printf(
    "%s vs %s: max %.6g (%.4g %% of H), p99 %.6g, mean %.6g; worst at row %d, joint '%s'\n",
    args.input.c_str(), args.second.c_str(), e.max, e.max * h, e.p99, e.mean, e.worstFrame,
    a.animation.joints[static_cast<std::size_t>(e.worstJoint)].name.c_str());
  if (!args.tolerance.empty() && !(e.max <= tolerance))
  {
    std::printf("over the tolerance %.6g\n", tolerance);
    return 1;
  }
  return 0;
}

int Info(const Arguments& args)
{
  std::string bytes;
  std::string why;
  if (!ReadFile(args.input, bytes, why))
  {
    std::cerr << "lct-mocap: " << why << "\n";
    return 1;
  }
  lct::MotionMetadata metadata;
  const lct::Result<lct::SkeletalAnimation> motion = lct::decompressMotion(bytes, &metadata, &why);
  if (!motion)
  {
    std::cerr << "lct-mocap: " << args.input << ": " << why << "\n";
    return 1;
  }
  const double raw = 4.0 * motion.value.frames * metadata.inputChannels;
  std::printf("%s: .lctm version 1, %zu bytes\n", args.input.c_str(), bytes.size());
  std::printf("%d rows at %.6g s, %d joints, input channels %d, rotation order %s\n",
    motion.value.frames, motion.value.frameTime, motion.value.jointCount(), metadata.inputChannels,
    metadata.rotationOrder.c_str());
  std::printf("tolerance %.4g (%.4g %% of H = %.4g), factor %.1f\n", metadata.tolerance,
    metadata.height > 0 ? 100.0 * metadata.tolerance / metadata.height : 0.0, metadata.height,
    raw / static_cast<double>(bytes.size()));
  return 0;
}

} // namespace

bool lct_mocap::WriteAtomically(const fs::path& output, const std::string& bytes, std::string& why)
{
  fs::path target;
  return OutputTarget(output, target, why) && lct::writeFileAtomically(target, bytes, why);
}

bool lct_mocap::PlotAnalysis(const std::vector<AnalysisRow>& rows, double height,
  const std::string& title, const std::string& png, std::string& why)
{
  if (!std::getenv("DISPLAY"))
  {
    why = "no DISPLAY for the PNG (run under xvfb-run -a); the table and the CSV are written";
    return false;
  }
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetSize(1000, 640);
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->SetShowLegend(true);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("compression factor (float32 channels / bytes)");
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("max position error, % of skeleton height");
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  const unsigned char palette[][3] = { { 31, 119, 180 }, { 255, 127, 14 }, { 44, 160, 44 },
    { 214, 39, 40 }, { 148, 103, 189 }, { 0, 0, 0 } };
  std::vector<std::string> names;
  for (const AnalysisRow& r : rows)
  {
    if (std::find(names.begin(), names.end(), r.representation) == names.end())
    {
      names.push_back(r.representation);
    }
  }
  std::vector<vtkSmartPointer<vtkTable>> tables;
  for (std::size_t n = 0; n < names.size(); ++n)
  {
    std::vector<std::pair<double, double>> points;
    for (const AnalysisRow& r : rows)
    {
      if (r.representation == names[n] && r.factor > 0.0 && r.error.max > 0.0 &&
        std::isfinite(r.error.max))
      {
        points.emplace_back(r.factor, 100.0 * r.error.max / height);
      }
    }
    if (points.empty())
    {
      continue;
    }
    std::sort(points.begin(), points.end());
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> factor;
    factor->SetName("factor");
    vtkNew<vtkDoubleArray> error;
    error->SetName(names[n].c_str());
    for (const auto& p : points)
    {
      factor->InsertNextValue(p.first);
      error->InsertNextValue(p.second);
    }
    table->AddColumn(factor);
    table->AddColumn(error);
    tables.push_back(table);
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    const unsigned char* c = palette[n % 6];
    line->SetColor(c[0], c[1], c[2], 255);
    line->SetWidth(n + 1 == names.size() ? 3.0f : 2.0f);
    if (auto* points2D = vtkPlotPoints::SafeDownCast(line))
    {
      points2D->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    }
  }
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->ReadFrontBufferOff();
  grab->Update();
  // To memory, then through lct::writeFileAtomically: vtkPNGWriter opening a temporary under a
  // name one could foresee wrote through a link or hung on a FIFO put there.
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* encoded = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !encoded || encoded->GetNumberOfValues() == 0)
  {
    why = "cannot encode " + png + " as PNG";
    return false;
  }
  const std::string bytes(reinterpret_cast<const char*>(encoded->GetPointer(0)),
    static_cast<std::size_t>(encoded->GetNumberOfValues()));
  return lct_mocap::WriteAtomically(fs::path(png), bytes, why);
}

int main(int argc, char* argv[])
{
  // A file-size limit (ulimit -f) must fail the write (EFBIG: reported, the temporary removed),
  // not end the process with SIGXFSZ and leave the temporary behind.
  std::signal(SIGXFSZ, SIG_IGN);
  Arguments args;
  const std::string usageError = Parse(argc, argv, args);
  if (args.command == "-h" || args.command == "--help")
  {
    std::cout << Usage;
    return 0;
  }
  if (!usageError.empty())
  {
    std::cerr << "lct-mocap: " << usageError << "\n(lct-mocap --help for usage)\n";
    return 2;
  }
  if (args.command == "compress")
  {
    return Compress(args);
  }
  if (args.command == "decompress")
  {
    return Decompress(args);
  }
  if (args.command == "info")
  {
    return Info(args);
  }
  if (args.command == "compare")
  {
    return Compare(args);
  }
  lct_mocap::Clip clip;
  std::string why;
  if (!ReadMotion(args.input, clip, why))
  {
    std::cerr << "lct-mocap: " << why << "\n";
    return 1;
  }
  return lct_mocap::Analyse(clip, args.output.empty() ? "." : args.output, args.quick);
}
