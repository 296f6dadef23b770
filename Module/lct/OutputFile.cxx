#include "lct/OutputFile.h"

#include <cerrno>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lct
{

std::filesystem::path outputTarget(const std::filesystem::path& name)
{
  namespace fs = std::filesystem;
  fs::path target = name;
  std::error_code error;
  for (int links = 0; fs::is_symlink(fs::symlink_status(target, error)); ++links)
  {
    const fs::path to = fs::read_symlink(target, error);
    if (error || links == 40)
    {
      return name;
    }
    target = to.is_absolute() ? to : target.parent_path() / to;
  }
  return target;
}

std::string notARegularFile(const std::filesystem::path& name)
{
  const std::filesystem::path target = outputTarget(name);
  struct stat s;
  if (::lstat(target.c_str(), &s) != 0 || S_ISREG(s.st_mode))
  {
    return "";
  }
  return name.string() + (target == name ? "" : " (a link to " + target.string() + ")") +
    " exists and is not a regular file";
}

int createTemporaryBeside(
  const std::filesystem::path& target, std::string& temporary, std::string& why)
{
  const std::filesystem::path directory = target.parent_path();
  long nameMax = ::pathconf(directory.empty() ? "." : directory.c_str(), _PC_NAME_MAX);
  if (nameMax <= 0)
  {
    nameMax = 255;
  }
  std::random_device entropy;
  int error = 0;
  for (int attempt = 0; attempt < 16; ++attempt)
  {
    const std::string suffix =
      "." + std::to_string(::getpid()) + "." + std::to_string(entropy()) + ".part";
    // The whole of a long name does not fit beside the suffix (a 240-byte name was refused as
    // "File name too long"): its start is enough to tell whose temporary it is.
    const std::string name = target.filename().string();
    const std::size_t room = static_cast<std::size_t>(nameMax) - 1 - suffix.size();
    temporary = (directory / ("." + name.substr(0, room) + suffix)).string();
    // O_EXCL: a new file or nothing (never through a link or a FIFO put in its place).
    const int fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0)
    {
      return fd;
    }
    error = errno;
    if (error != EEXIST)
    {
      break;
    }
  }
  why = "cannot write " + temporary + ": " + std::strerror(error);
  return -1;
}

bool replaceWithTemporary(
  const std::string& temporary, const std::filesystem::path& target, std::string& why)
{
  why = notARegularFile(target);
  if (!why.empty())
  {
    ::unlink(temporary.c_str());
    return false;
  }
  // The file replaced keeps its owner (where this process may set it) and its permission bits:
  // a private file must not become readable by everyone because it was rewritten.
  struct stat existing;
  if (::stat(target.c_str(), &existing) == 0)
  {
    if (::chown(temporary.c_str(), existing.st_uid, existing.st_gid) != 0)
    {
      // Not permitted for another owner: the file becomes this user's, as any rewrite would.
    }
    ::chmod(temporary.c_str(), existing.st_mode & 07777);
  }
  if (::rename(temporary.c_str(), target.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(temporary.c_str());
    why = "cannot rename " + temporary + " to " + target.string() + ": " + std::strerror(error);
    return false;
  }
  return true;
}

bool writeFileAtomically(
  const std::filesystem::path& name, const std::string& bytes, std::string& why)
{
  const std::filesystem::path target = outputTarget(name);
  why = notARegularFile(name);
  if (!why.empty())
  {
    return false;
  }
  std::string temporary;
  const int fd = createTemporaryBeside(target, temporary, why);
  if (fd < 0)
  {
    return false;
  }
  std::size_t done = 0;
  int writeError = 0;
  while (done < bytes.size() && writeError == 0)
  {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n > 0)
    {
      done += static_cast<std::size_t>(n);
    }
    else if (n == 0 || errno != EINTR)
    {
      writeError = n == 0 ? EIO : errno;
    }
  }
  if (::close(fd) != 0 && writeError == 0)
  {
    writeError = errno;
  }
  if (writeError != 0)
  {
    ::unlink(temporary.c_str());
    why = "cannot write " + temporary + ": " + std::strerror(writeError);
    return false;
  }
  return replaceWithTemporary(temporary, target, why);
}

} // namespace lct
