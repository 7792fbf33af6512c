// libFuzzer target: the Medit parser on any bytes, as a .mesh and as the .sol of the mesh read.
// What it accepts must survive a round trip: written back and read again, it is the same mesh
// (same counts and connectivity); otherwise the fuzzer stops with the input.
#include "amMeditFormat.h"

#include <cstdlib>
#include <sstream>
#include <string>

namespace
{
bool Same(const amMeditFormat::Mesh& a, const amMeditFormat::Mesh& b)
{
  if (a.Points.size() != b.Points.size() || a.PointRefs != b.PointRefs || a.Blocks.size() != b.Blocks.size())
    return false;
  for (size_t i = 0; i < a.Blocks.size(); ++i)
    if (a.Blocks[i].Keyword != b.Blocks[i].Keyword || a.Blocks[i].Connectivity != b.Blocks[i].Connectivity ||
      a.Blocks[i].Refs != b.Blocks[i].Refs)
      return false;
  return true;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  amMeditFormat::Mesh mesh;
  std::string error;
  std::istringstream in(text);
  if (amMeditFormat::ReadMesh(in, mesh, error))
  {
    std::ostringstream out;
    if (!amMeditFormat::WriteMesh(out, mesh))
      return 0; // refused on write (e.g. a non-finite coordinate): a message, not a file
    std::istringstream again(out.str());
    amMeditFormat::Mesh back;
    if (!amMeditFormat::ReadMesh(again, back, error) || !Same(mesh, back))
      std::abort();
  }
  // The same bytes as the solution of a small mesh (8 vertices), and of the mesh read, if any.
  amMeditFormat::Mesh cube;
  cube.Points.assign(24, 0.0);
  cube.PointRefs.assign(8, 0);
  std::istringstream sol(text);
  amMeditFormat::ReadSolution(sol, cube, error);
  if (!mesh.Points.empty())
  {
    std::istringstream sol2(text);
    amMeditFormat::ReadSolution(sol2, mesh, error);
  }
  return 0;
}
