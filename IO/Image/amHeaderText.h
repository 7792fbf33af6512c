// Internal: the text helpers of the image header checks and the reader, which read "key = value"
// and "key: value" lines and name data files relative to their header.
#ifndef amHeaderText_h
#define amHeaderText_h

#include <string>

namespace amHeaderText
{
/// The text without leading and trailing blanks (spaces, tabs, line ends).
inline std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// The folder of a path ("." for a bare file name), where a header's relative data file lies.
inline std::string FolderOf(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}
}

#endif
