#include "amAtomicFile.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
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

bool amAtomicFile::Commit(std::string& why)
{
  if (std::rename(this->Temporary.c_str(), this->Target.c_str()) != 0)
  {
    why = "cannot rename '" + this->Temporary + "' to '" + this->Target + "': " + std::strerror(errno);
    return false;
  }
  this->Committed = true;
  return true;
}
