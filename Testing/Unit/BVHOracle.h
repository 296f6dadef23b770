/**
 * @file BVHOracle.h
 * @brief A small reader for Biovision hierarchy (BVH) motion-capture files, and their forward
 *        kinematics: the independent oracle of Unit.SkeletonReader (the module reads motion
 *        through vtkSkeletonAnimationReader only). Header-only, standard library only.
 *
 * Format read:
 *
 *     HIERARCHY
 *     ROOT name { OFFSET x y z  CHANNELS n c1 .. cn  (JOINT name { ... } | End Site { OFFSET x y z
 * })* } MOTION Frames: F Frame Time: dt F lines of channel values, in the depth-first order of the
 * joints' CHANNELS
 *
 * Channels are Xposition Yposition Zposition Xrotation Yrotation Zrotation, in any order per
 * joint. Several ROOTs are accepted. Data lines beyond the F announced are ignored (some
 * exporters write an extra frame) and reported in BVHResult::warning; fewer lines, or a line
 * with the wrong number of values, is an error.
 *
 * Kinematics (the BVH convention): a joint's local transform at a frame is
 *     L = T(offset + (Xposition, Yposition, Zposition)) * R(c1) * R(c2) * ...
 * with the rotation matrices multiplied in the order the channels are listed (degrees, right
 * handed, column vectors), and its world transform is W = W(parent) * L. An End Site is a joint
 * without channels: L = T(offset). Joint world positions are the translation columns of W.
 *
 * Nothing here throws or aborts on bad input: ParseBVH/LoadBVH return a BVHResult whose error
 * names the problem and the line.
 */
#ifndef lct_bench_BVH_h
#define lct_bench_BVH_h

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lct_bench
{

/// A row-major 4x4 matrix (the layout of vtkMatrix4x4::DeepCopy(const double[16])).
using Matrix4 = std::array<double, 16>;

enum class BVHChannel
{
  Xposition,
  Yposition,
  Zposition,
  Xrotation,
  Yrotation,
  Zrotation
};

/// One node of the hierarchy: a ROOT, a JOINT or an End Site.
struct BVHJoint
{
  std::string name;                 ///< End Sites are named "<parent> End Site"
  int parent = -1;                  ///< index in BVHMotion::joints, -1 for a ROOT
  std::array<double, 3> offset{};   ///< OFFSET, in the parent's frame
  std::vector<BVHChannel> channels; ///< in file order (empty for an End Site)
  int firstChannel = 0;             ///< index of channels[0] within a frame's values
  bool endSite = false;
};

/// A parsed file. Joints are in depth-first file order, so a parent precedes its children.
struct BVHMotion
{
  std::vector<BVHJoint> joints;
  int channelCount = 0; ///< values per frame
  int frameCount = 0;
  double frameTime = 0.0;
  std::vector<double> values; ///< frameCount x channelCount, row per frame

  const double* Frame(int frame) const
  {
    return this->values.data() + static_cast<std::size_t>(frame) * this->channelCount;
  }
};

/// The outcome of a parse: motion is valid only when error is empty.
struct BVHResult
{
  BVHMotion motion;
  std::string error;   ///< empty on success
  std::string warning; ///< non-fatal oddities (e.g. extra data lines)
  bool Ok() const { return this->error.empty(); }
};

// ------------------------------------------------------------------------------------------
// Matrices

inline Matrix4 Identity4()
{
  return { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
}

/// a * b for affine matrices (bottom rows (0,0,0,1)).
inline Matrix4 MultiplyAffine(const Matrix4& a, const Matrix4& b)
{
  Matrix4 c = Identity4();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      double s = (j == 3) ? a[i * 4 + 3] : 0.0;
      for (int k = 0; k < 3; ++k)
      {
        s += a[i * 4 + k] * b[k * 4 + j];
      }
      c[i * 4 + j] = s;
    }
  }
  return c;
}

/// The rotation by `degrees` about the x (axis 0), y (1) or z (2) axis.
inline Matrix4 AxisRotation(int axis, double degrees)
{
  const double a = degrees * 3.14159265358979323846 / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  Matrix4 m = Identity4();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3; // the plane rotated: (y,z), (z,x), (x,y)
  m[i * 4 + i] = c;
  m[i * 4 + j] = -s;
  m[j * 4 + i] = s;
  m[j * 4 + j] = c;
  return m;
}

/// The local transform of joint `j` at a frame (see the file comment).
inline Matrix4 LocalTransform(const BVHMotion& motion, int j, const double* frame)
{
  const BVHJoint& joint = motion.joints[j];
  std::array<double, 3> t = joint.offset;
  Matrix4 r = Identity4();
  for (std::size_t c = 0; c < joint.channels.size(); ++c)
  {
    const double v = frame[joint.firstChannel + c];
    switch (joint.channels[c])
    {
      case BVHChannel::Xposition:
        t[0] += v;
        break;
      case BVHChannel::Yposition:
        t[1] += v;
        break;
      case BVHChannel::Zposition:
        t[2] += v;
        break;
      case BVHChannel::Xrotation:
        r = MultiplyAffine(r, AxisRotation(0, v));
        break;
      case BVHChannel::Yrotation:
        r = MultiplyAffine(r, AxisRotation(1, v));
        break;
      case BVHChannel::Zrotation:
        r = MultiplyAffine(r, AxisRotation(2, v));
        break;
    }
  }
  r[3] = t[0];
  r[7] = t[1];
  r[11] = t[2];
  return r;
}

/// World positions of every joint from the local transforms of every joint (locals.size() ==
/// joints.size()). `world` is scratch space (resized), positions are written as x,y,z triples.
inline void ForwardKinematics(const BVHMotion& motion, const std::vector<Matrix4>& locals,
  std::vector<Matrix4>& world, std::vector<double>& positions)
{
  const std::size_t n = motion.joints.size();
  world.resize(n);
  positions.resize(3 * n);
  for (std::size_t j = 0; j < n; ++j)
  {
    const int p = motion.joints[j].parent;
    world[j] = (p < 0) ? locals[j] : MultiplyAffine(world[p], locals[j]);
    positions[3 * j + 0] = world[j][3];
    positions[3 * j + 1] = world[j][7];
    positions[3 * j + 2] = world[j][11];
  }
}

// ------------------------------------------------------------------------------------------
// Parsing

namespace detail
{

/// Whitespace-separated tokens, with '{' and '}' always tokens of their own; tracks lines.
class Lexer
{
public:
  explicit Lexer(const std::string& text)
    : Text(text)
  {
  }

  /// The next token, or false at the end of the text.
  bool Next(std::string& token)
  {
    this->SkipSpace();
    if (this->Pos >= this->Text.size())
    {
      return false;
    }
    this->TokenLine = this->Line;
    const std::size_t start = this->Pos;
    if (this->Text[this->Pos] == '{' || this->Text[this->Pos] == '}')
    {
      ++this->Pos;
    }
    else
    {
      while (this->Pos < this->Text.size() && !IsSpace(this->Text[this->Pos]) &&
        this->Text[this->Pos] != '{' && this->Text[this->Pos] != '}')
      {
        ++this->Pos;
      }
    }
    token.assign(this->Text, start, this->Pos - start);
    return true;
  }

  /// The next non-blank line (without its end of line), starting after the current line.
  bool NextLine(std::string& line)
  {
    for (;;)
    {
      if (this->Pos >= this->Text.size())
      {
        return false;
      }
      // Move to the start of the next line.
      while (this->Pos < this->Text.size() && this->Text[this->Pos] != '\n')
      {
        ++this->Pos;
      }
      if (this->Pos >= this->Text.size())
      {
        return false;
      }
      ++this->Pos;
      ++this->Line;
      std::size_t end = this->Pos;
      while (end < this->Text.size() && this->Text[end] != '\n')
      {
        ++end;
      }
      line.assign(this->Text, this->Pos, end - this->Pos);
      this->TokenLine = this->Line;
      if (line.find_first_not_of(" \t\r\f\v") != std::string::npos)
      {
        return true;
      }
    }
  }

  int TokenLine = 1; ///< line of the last token or line returned

private:
  static bool IsSpace(char c)
  {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }
  void SkipSpace()
  {
    while (this->Pos < this->Text.size() && IsSpace(this->Text[this->Pos]))
    {
      if (this->Text[this->Pos] == '\n')
      {
        ++this->Line;
      }
      ++this->Pos;
    }
  }

  const std::string& Text;
  std::size_t Pos = 0;
  int Line = 1;
};

inline bool ParseNumber(const std::string& s, double& value)
{
  if (s.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(value);
}

inline bool ParseChannel(const std::string& s, BVHChannel& channel)
{
  static const char* const names[] = { "Xposition", "Yposition", "Zposition", "Xrotation",
    "Yrotation", "Zrotation" };
  for (int i = 0; i < 6; ++i)
  {
    if (s == names[i])
    {
      channel = static_cast<BVHChannel>(i);
      return true;
    }
  }
  return false;
}

class Parser
{
public:
  explicit Parser(const std::string& text)
    : Lex(text)
  {
  }

  BVHResult Run()
  {
    BVHResult result;
    this->Out = &result.motion;
    std::string token;
    if (!this->Lex.Next(token) || token != "HIERARCHY")
    {
      return this->Fail(result, "expected HIERARCHY at the start of the file");
    }
    if (!this->Lex.Next(token))
    {
      return this->Fail(result, "no ROOT after HIERARCHY");
    }
    while (token == "ROOT")
    {
      if (!this->ParseJoint(-1, false))
      {
        return this->Fail(result, this->Error);
      }
      if (!this->Lex.Next(token))
      {
        return this->Fail(result, "unexpected end of file: no MOTION section");
      }
    }
    if (this->Out->joints.empty())
    {
      return this->Fail(result, "expected ROOT after HIERARCHY, found '" + token + "'");
    }
    if (token != "MOTION")
    {
      return this->Fail(
        result, "expected MOTION or ROOT after the hierarchy, found '" + token + "'");
    }
    std::string a, b;
    double frames = 0.0;
    if (!this->Lex.Next(a) || a != "Frames:" || !this->Lex.Next(b) || !ParseNumber(b, frames) ||
      frames < 0 || frames != std::floor(frames))
    {
      return this->Fail(result, "expected 'Frames: <count>' after MOTION");
    }
    double frameTime = 0.0;
    if (!this->Lex.Next(a) || a != "Frame" || !this->Lex.Next(b) || b != "Time:" ||
      !this->Lex.Next(token) || !ParseNumber(token, frameTime) || frameTime <= 0.0)
    {
      return this->Fail(result, "expected 'Frame Time: <seconds > 0>' after Frames:");
    }
    BVHMotion& m = *this->Out;
    m.frameCount = static_cast<int>(frames);
    m.frameTime = frameTime;
    m.values.resize(static_cast<std::size_t>(m.frameCount) * m.channelCount);
    std::string line;
    for (int f = 0; f < m.frameCount; ++f)
    {
      if (!this->Lex.NextLine(line))
      {
        return this->Fail(result,
          "the file ends after " + std::to_string(f) + " of the " + std::to_string(m.frameCount) +
            " frames announced");
      }
      std::istringstream in(line);
      int n = 0;
      std::string value;
      while (in >> value)
      {
        double v = 0.0;
        if (!ParseNumber(value, v))
        {
          return this->Fail(
            result, "frame " + std::to_string(f) + ": '" + value + "' is not a finite number");
        }
        if (n < m.channelCount)
        {
          m.values[static_cast<std::size_t>(f) * m.channelCount + n] = v;
        }
        ++n;
      }
      if (n != m.channelCount)
      {
        return this->Fail(result,
          "frame " + std::to_string(f) + " has " + std::to_string(n) +
            " values, the hierarchy declares " + std::to_string(m.channelCount) + " channels");
      }
    }
    int extra = 0;
    while (this->Lex.NextLine(line))
    {
      ++extra;
    }
    if (extra > 0)
    {
      result.warning = std::to_string(extra) + " data line(s) after the " +
        std::to_string(m.frameCount) + " frames announced were ignored";
    }
    return result;
  }

private:
  BVHResult& Fail(BVHResult& result, const std::string& message)
  {
    result.error = "line " + std::to_string(this->Lex.TokenLine) + ": " + message;
    result.motion = BVHMotion();
    return result;
  }

  bool SetError(const std::string& message)
  {
    this->Error = message;
    return false;
  }

  bool ReadOffset(std::array<double, 3>& offset)
  {
    std::string token;
    if (!this->Lex.Next(token) || token != "OFFSET")
    {
      return this->SetError("expected OFFSET, found '" + token + "'");
    }
    for (double& v : offset)
    {
      if (!this->Lex.Next(token) || !ParseNumber(token, v))
      {
        return this->SetError("OFFSET needs three numbers, found '" + token + "'");
      }
    }
    return true;
  }

  /// Reads "name { OFFSET .. CHANNELS .. children }" (or "Site { OFFSET .. }" for an End Site);
  /// the ROOT/JOINT/End keyword has been read.
  bool ParseJoint(int parent, bool endSite)
  {
    std::string token;
    BVHJoint joint;
    joint.parent = parent;
    joint.endSite = endSite;
    if (!this->Lex.Next(token) || token == "{" || token == "}")
    {
      return this->SetError("expected a joint name, found '" + token + "'");
    }
    if (endSite)
    {
      if (token != "Site")
      {
        return this->SetError("expected 'End Site', found 'End " + token + "'");
      }
      joint.name = this->Out->joints[parent].name + " End Site";
    }
    else
    {
      joint.name = token;
    }
    if (!this->Lex.Next(token) || token != "{")
    {
      return this->SetError("expected '{' after '" + joint.name + "', found '" + token + "'");
    }
    if (!this->ReadOffset(joint.offset))
    {
      return false;
    }
    if (endSite)
    {
      if (!this->Lex.Next(token) || token != "}")
      {
        return this->SetError("expected '}' closing the End Site of '" +
          this->Out->joints[parent].name + "', found '" + token + "'");
      }
      this->Out->joints.push_back(joint);
      return true;
    }
    double count = 0.0;
    if (!this->Lex.Next(token) || token != "CHANNELS" || !this->Lex.Next(token) ||
      !ParseNumber(token, count) || count < 0 || count > 6 || count != std::floor(count))
    {
      return this->SetError("joint '" + joint.name + "': expected 'CHANNELS <0..6>' after OFFSET");
    }
    for (int c = 0; c < static_cast<int>(count); ++c)
    {
      BVHChannel channel;
      if (!this->Lex.Next(token) || !ParseChannel(token, channel))
      {
        return this->SetError("joint '" + joint.name + "': unknown channel '" + token + "'");
      }
      joint.channels.push_back(channel);
    }
    joint.firstChannel = this->Out->channelCount;
    this->Out->channelCount += static_cast<int>(joint.channels.size());
    const int self = static_cast<int>(this->Out->joints.size());
    this->Out->joints.push_back(joint);
    for (;;)
    {
      if (!this->Lex.Next(token))
      {
        return this->SetError("unexpected end of file inside joint '" + joint.name + "'");
      }
      if (token == "}")
      {
        return true;
      }
      if (token == "JOINT" || token == "End")
      {
        if (!this->ParseJoint(self, token == "End"))
        {
          return false;
        }
        continue;
      }
      return this->SetError(
        "joint '" + joint.name + "': expected JOINT, End Site or '}', found '" + token + "'");
    }
  }

  Lexer Lex;
  BVHMotion* Out = nullptr;
  std::string Error;
};

} // namespace detail

/// Parses BVH text (see the file comment for the format accepted).
inline BVHResult ParseBVH(const std::string& text)
{
  return detail::Parser(text).Run();
}

/// Reads and parses a BVH file; a file that cannot be read is an error, not a crash.
inline BVHResult LoadBVH(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    BVHResult result;
    result.error = "cannot open '" + path + "'";
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  BVHResult result = ParseBVH(text.str());
  if (!result.Ok())
  {
    result.error = path + ": " + result.error;
  }
  return result;
}

} // namespace lct_bench

#endif
