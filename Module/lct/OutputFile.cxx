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
  int fd = -1;
  std::random_device entropy;
  for (int attempt = 0; fd < 0 && attempt < 16; ++attempt)
  {
    temporary = (target.parent_path() /
      ("." + target.filename().string() + "." + std::to_string(::getpid()) + "." +
        std::to_string(entropy()) + ".part"))
                  .string();
    // O_EXCL also refuses a symbolic link in the temporary's place.
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST)
    {
      break;
    }
  }
  if (fd < 0)
  {
    why = "cannot write " + temporary + ": " + std::strerror(errno);
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
  if (writeError == 0 && ::rename(temporary.c_str(), target.c_str()) != 0)
  {
    why = "cannot rename " + temporary + " to " + target.string() + ": " + std::strerror(errno);
    ::unlink(temporary.c_str());
    return false;
  }
  if (writeError != 0)
  {
    ::unlink(temporary.c_str());
    why = "cannot write " + temporary + ": " + std::strerror(writeError);
    return false;
  }
  return true;
}

} // namespace lct
