#include "amTetGenRun.h"

#include "amDescriptorIO.h"
#include "amGradedSizeField.h"
#include "amSurfaceMesh.h"
#include "amTetraGeometry.h"

#define TETLIBRARY
#include <tetgen.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
/// Sizing callback state: TetGen's callback has no user pointer, and TetGen runs on the calling
/// thread, so a thread-local pointer keeps concurrent filters apart.
struct Sizing
{
  const amGradedSizeField* Field = nullptr;
  double Factor = 0.75; // split when circumradius > Factor * h
};
thread_local Sizing CurrentSizing;

bool TetTooBig(REAL* pa, REAL* pb, REAL* pc, REAL* pd, REAL*, REAL)
{
  const double radius = amTetraGeometry::Circumradius(pa, pb, pc, pd);
  if (!std::isfinite(radius))
    return false; // flat: TetGen's own quality checks deal with it
  const double centroid[3] = { (pa[0] + pb[0] + pc[0] + pd[0]) / 4, (pa[1] + pb[1] + pc[1] + pd[1]) / 4,
    (pa[2] + pb[2] + pc[2] + pd[2]) / 4 };
  return radius > CurrentSizing.Factor * CurrentSizing.Field->Evaluate(centroid);
}

const char* TetGenError(int code)
{
  switch (code)
  {
    case 1:
      return "TetGen ran out of memory";
    case 2:
      return "TetGen hit an internal error";
    case 3:
      return "the surface intersects itself";
    case 4:
      return "the surface has a feature smaller than TetGen's tolerance (nearly coincident points)";
    case 5:
      return "two surface facets are too close to each other (nearly overlapping triangles)";
    case 10:
      return "TetGen rejected the input";
    default:
      return "TetGen failed";
  }
}

/// TetGen in a child process. TetGen 1.5.0 frees its memory twice when it stops on an error in
/// library mode (terminatetetgen, then the mesh destructor), which crashes the caller: in a
/// child, an error or a crash of TetGen becomes a message here. Several children run at once.
struct Child
{
  pid_t Pid = -1;
  int Data = -1, Message = -1; // the result's bytes; TetGen's words (its stdout)
  std::vector<char> Bytes;
  std::string Said;
};

/// Forks the child that tetrahedralizes 'in'; "" on success.
std::string Start(std::string& switches, tetgenio& in, Child& child)
{
  int fds[2], msg[2];
  if (::pipe(fds) != 0)
    return std::string("cannot create a pipe to TetGen: ") + std::strerror(errno);
  if (::pipe(msg) != 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return std::string("cannot create a pipe to TetGen: ") + std::strerror(errno);
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    for (int fd : { fds[0], fds[1], msg[0], msg[1] })
      ::close(fd);
    return std::string("cannot start TetGen's process: ") + std::strerror(errno);
  }
  if (pid == 0)
  {
    ::close(fds[0]);
    ::close(msg[0]);
    ::dup2(msg[1], STDOUT_FILENO); // TetGen prints its diagnostics on stdout
    ::close(msg[1]);
#ifdef __GLIBC__
    // The child shares the parent's heap, free blocks included (the anatomesh command keeps
    // freed memory instead of returning it to the kernel), copy on write: TetGen's blocks there
    // would each copy a page of the parent's first, and the parent writing to its own pages would
    // copy them too while the child lives. Handed back here, the child's free pages come new.
    ::malloc_trim(0);
#endif
    int code = 0;
    tetgenio out;
    try
    {
      tetrahedralize(&switches[0], &in, &out);
    }
    catch (int c)
    {
      code = c;
    }
    catch (...)
    {
      code = 2;
    }
    if (code == 0 && (!out.neighborlist || !out.trifacemarkerlist || !out.tetrahedronlist))
      code = 2;
    const long long header[4] = { code, code ? 0 : out.numberofpoints, code ? 0 : out.numberoftetrahedra,
      code ? 0 : out.numberoftrifaces };
    bool ok = amDescriptorIO::WriteAll(fds[1], header, sizeof(header));
    if (ok && code == 0)
      ok = amDescriptorIO::WriteAll(fds[1], out.pointlist, sizeof(REAL) * 3 * header[1]) &&
        amDescriptorIO::WriteAll(fds[1], out.tetrahedronlist, sizeof(int) * 4 * header[2]) &&
        amDescriptorIO::WriteAll(fds[1], out.neighborlist, sizeof(int) * 4 * header[2]) &&
        amDescriptorIO::WriteAll(fds[1], out.trifacelist, sizeof(int) * 3 * header[3]) &&
        amDescriptorIO::WriteAll(fds[1], out.trifacemarkerlist, sizeof(int) * header[3]);
    ::close(fds[1]);
    std::fflush(stdout);
    ::_exit(ok ? 0 : 1);
  }
  ::close(fds[1]);
  ::close(msg[1]);
  child.Pid = pid;
  child.Data = fds[0];
  child.Message = msg[0];
  return "";
}

/// Reads every started child's pipes until all are closed (a child's pipe not read would stop it
/// once full).
void Collect(std::vector<Child>& children)
{
  std::vector<pollfd> polls;
  std::vector<std::pair<size_t, int>> owner; // child, 0 data / 1 message
  for (size_t c = 0; c < children.size(); ++c)
    if (children[c].Pid > 0)
    {
      polls.push_back({ children[c].Data, POLLIN, 0 });
      owner.emplace_back(c, 0);
      polls.push_back({ children[c].Message, POLLIN, 0 });
      owner.emplace_back(c, 1);
    }
  char buffer[1 << 16];
  size_t open = polls.size();
  while (open > 0)
  {
    if (::poll(polls.data(), polls.size(), -1) < 0)
    {
      if (errno == EINTR)
        continue;
      break;
    }
    for (size_t k = 0; k < polls.size(); ++k)
    {
      if (polls[k].fd < 0 || !(polls[k].revents & (POLLIN | POLLHUP | POLLERR)))
        continue;
      const ssize_t n = ::read(polls[k].fd, buffer, sizeof(buffer));
      if (n < 0 && errno == EINTR)
        continue;
      Child& child = children[owner[k].first];
      if (n <= 0)
      {
        ::close(polls[k].fd);
        polls[k].fd = -1;
        --open;
      }
      else if (owner[k].second == 0)
        child.Bytes.insert(child.Bytes.end(), buffer, buffer + n);
      else if (child.Said.size() < 4096)
        child.Said.append(buffer, static_cast<size_t>(n));
    }
  }
  for (auto& pfd : polls)
    if (pfd.fd >= 0)
      ::close(pfd.fd);
}

/// Waits for the child and reads its result; "" on success.
std::string Finish(Child& child, amTetGenRun::Result& result)
{
  std::string said = child.Said;
  // TetGen's own words, on one line.
  for (char& c : said)
    if (c == '\n' || c == '\t')
      c = ' ';
  while (said.find("  ") != std::string::npos)
    said.replace(said.find("  "), 2, " ");
  while (!said.empty() && said.back() == ' ')
    said.pop_back();
  const std::string tetgenSaid = said.empty() ? "" : " TetGen said: \"" + said + "\"";
  int status = 0;
  while (::waitpid(child.Pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  const std::vector<char>& data = child.Bytes;
  long long header[4] = { 0, 0, 0, 0 };
  if (data.size() < sizeof(header))
  {
    // TetGen 1.5.0 crashes while cleaning up after an error: its message says which.
    result.Code = -1;
    if (said.find("intersect") != std::string::npos)
      result.Code = 3;
    else if (said.find("duplicated") != std::string::npos || said.find("very close") != std::string::npos)
      result.Code = 5;
    return std::string("TetGen stopped") +
      (WIFSIGNALED(status) ? " (signal " + std::to_string(WTERMSIG(status)) + ")" : std::string()) + "." + tetgenSaid;
  }
  std::memcpy(header, data.data(), sizeof(header));
  result.Code = static_cast<int>(header[0]);
  if (result.Code != 0)
    return std::string(TetGenError(result.Code)) + " (TetGen code " + std::to_string(result.Code) + ")." + tetgenSaid;
  result.NumberOfPoints = header[1];
  result.NumberOfTetrahedra = header[2];
  result.NumberOfFaces = header[3];
  const size_t expected =
    sizeof(header) + sizeof(double) * 3 * header[1] + sizeof(int) * 8 * header[2] + sizeof(int) * 4 * header[3];
  if (data.size() != expected)
    return "TetGen's result was cut short (" + std::to_string(data.size()) + " of " + std::to_string(expected) +
      " bytes).";
  const char* p = data.data() + sizeof(header);
  auto take = [&p](auto& v, size_t n) {
    v.resize(n);
    std::memcpy(v.data(), p, sizeof(v[0]) * n);
    p += sizeof(v[0]) * n;
  };
  take(result.Points, 3 * header[1]);
  take(result.Tetrahedra, 4 * header[2]);
  take(result.Neighbors, 4 * header[2]);
  take(result.Faces, 3 * header[3]);
  take(result.FaceMarkers, header[3]);
  return "";
}
}

std::vector<std::string> amTetGenRun::RunEach(const std::vector<Input>& inputs, const amGradedSizeField& field,
  const std::string& switches, std::vector<Result>& results, const std::function<void()>& meanwhile)
{
  const size_t n = inputs.size();
  results.assign(n, Result());
  std::vector<std::string> failures(n);
  std::vector<Child> children(n);
  CurrentSizing.Field = &field; // the children inherit it
  for (size_t i = 0; i < n; ++i)
  {
    const amSurfaceMesh& mesh = *inputs[i].Mesh;
    const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
    tetgenio in;
    in.firstnumber = 0;
    in.numberofpoints = static_cast<int>(np);
    in.pointlist = new REAL[3 * np];
    for (vtkIdType v = 0; v < np; ++v)
      for (int d = 0; d < 3; ++d)
        in.pointlist[3 * v + d] = mesh.Points[v][d];
    in.numberoffacets = static_cast<int>(nt);
    in.facetlist = new tetgenio::facet[nt];
    in.facetmarkerlist = new int[nt];
    for (vtkIdType t = 0; t < nt; ++t)
    {
      tetgenio::facet& f = in.facetlist[t];
      tetgenio::init(&f);
      f.numberofpolygons = 1;
      f.polygonlist = new tetgenio::polygon[1];
      tetgenio::init(&f.polygonlist[0]);
      f.polygonlist[0].numberofvertices = 3;
      f.polygonlist[0].vertexlist = new int[3];
      for (int k = 0; k < 3; ++k)
        f.polygonlist[0].vertexlist[k] = static_cast<int>(mesh.Triangles[t][k]);
      in.facetmarkerlist[t] = static_cast<int>(t + 1);
    }
    const std::vector<std::array<double, 3>>& holes = inputs[i].Holes;
    if (!holes.empty())
    {
      in.numberofholes = static_cast<int>(holes.size());
      in.holelist = new REAL[3 * holes.size()];
      for (size_t h = 0; h < holes.size(); ++h)
        for (int d = 0; d < 3; ++d)
          in.holelist[3 * h + d] = holes[h][d];
    }
    in.tetunsuitable = &TetTooBig;
    std::string sw = switches;
    failures[i] = Start(sw, in, children[i]);
    in.tetunsuitable = nullptr;
  }
  if (meanwhile)
    meanwhile(); // the children block on their full pipes until it ends, at most
  Collect(children);
  for (size_t i = 0; i < n; ++i)
    if (children[i].Pid > 0)
      failures[i] = Finish(children[i], results[i]);
  CurrentSizing.Field = nullptr;
  return failures;
}

std::string amTetGenRun::Run(
  const amSurfaceMesh& mesh, const amGradedSizeField& field, const std::string& switches, Result& result)
{
  std::vector<Result> results;
  const std::string failure = RunEach({ Input{ &mesh, {} } }, field, switches, results).front();
  result = std::move(results.front());
  return failure;
}
