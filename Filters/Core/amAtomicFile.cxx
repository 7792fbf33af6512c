#include "amAtomicFile.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
std::string DirectoryOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Removes ".<stem>.tmp<pid>[_<n>]<ext>" files of processes that no longer run: what a killed
// writer of the same target left.
void RemoveStaleTemporaries(const std::string& dir, const std::string& stem, const std::string& ext)
{
  DIR* d = opendir(dir.c_str());
  if (!d)
    return;
  const std::string prefix = "." + stem + ".tmp";
  while (const dirent* e = readdir(d))
  {
    const std::string name = e->d_name;
    if (name.size() <= prefix.size() + ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
      continue;
    const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
    const std::string digits = middle.substr(0, middle.find('_'));
    if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
      continue;
    const std::string rest = middle.substr(digits.size());
    if (!rest.empty() && (rest[0] != '_' || !std::all_of(rest.begin() + 1, rest.end(), ::isdigit)))
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH)
      std::remove((dir + "/" + name).c_str());
  }
  closedir(d);
}
}

std::string amAtomicFile::Extension(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  for (char& c : name)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string gz;
  if (name.size() > 3 && name.compare(name.size() - 3, 3, ".gz") == 0)
  {
    gz = ".gz";
    name.resize(name.size() - 3);
  }
  const auto dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0)
    return gz;
  return name.substr(dot) + gz;
}

amAtomicFile::amAtomicFile(const std::string& target)
  : Target(target)
{
  static std::atomic<unsigned> counter{ 0 };
  const std::string dir = DirectoryOf(target);
  const auto slash = target.find_last_of('/');
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  const std::string ext = Extension(target);
  const std::string stem = name.substr(0, name.size() - std::min(name.size(), ext.size()));
  RemoveStaleTemporaries(dir, stem, ext);
  this->Temporary = (dir == "." && slash == std::string::npos ? std::string() : dir + "/") + "." + stem + ".tmp" +
    std::to_string(::getpid()) + "_" + std::to_string(counter++) + ext;
}

amAtomicFile::~amAtomicFile()
{
  if (!this->Committed)
    std::remove(this->Temporary.c_str());
}

bool amAtomicFile::CanWrite(std::string& why) const
{
  const std::string dir = DirectoryOf(this->Target);
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
  {
    why = "folder '" + dir + "' does not exist";
    return false;
  }
  if (::access(dir.c_str(), W_OK) != 0)
  {
    why = "folder '" + dir + "' is not writable";
    return false;
  }
  if (::stat(this->Target.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    why = "'" + this->Target + "' is a folder";
    return false;
  }
  return true;
}

bool amAtomicFile::WriteTemporary(const std::string& bytes, std::string& why) const
{
  const int fd = ::open(this->Temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    why = std::strerror(errno);
    return false;
  }
  std::size_t done = 0;
  while (done < bytes.size())
  {
    const ssize_t n = ::write(fd, bytes.data() + done, std::min<std::size_t>(bytes.size() - done, 1 << 26));
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
    {
      // A short write is followed by the call that names the reason (ENOSPC, EFBIG).
      why = std::strerror(n < 0 ? errno : ENOSPC);
      ::close(fd);
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  struct stat st;
  const bool sized = ::fstat(fd, &st) == 0 && static_cast<std::size_t>(st.st_size) == bytes.size();
  if (::close(fd) != 0)
  {
    why = std::strerror(errno);
    return false;
  }
  if (!sized)
    why = "the file on the disk does not have the size written";
  return sized;
}

bool amAtomicFile::Commit(std::string& why)
{
  // fsync reports what a deferred write-back could not store (quota, a full thin-provisioned disk)
  // while the old file is still in place.
  const int fd = ::open(this->Temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0)
  {
    why = "cannot write '" + this->Target + "': " + std::strerror(errno);
    if (fd >= 0)
      ::close(fd);
    return false;
  }
  ::close(fd);
  if (std::rename(this->Temporary.c_str(), this->Target.c_str()) != 0)
  {
    why = "cannot rename '" + this->Temporary + "' to '" + this->Target + "': " + std::strerror(errno);
    return false;
  }
  this->Committed = true;
  // The rename itself reaches the disk with the folder's entry.
  const int dir = ::open(DirectoryOf(this->Target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0)
  {
    ::fsync(dir);
    ::close(dir);
  }
  return true;
}
