#include "amTetrahedralize.h"

#include "amGradedSizeField.h"
#include "amProvenance.h"
#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amSurfaceTopology.h"
#include "amTetraGeometry.h"
#include "amTetraMeshOptimizer.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#define TETLIBRARY
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <unordered_map>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

vtkStandardNewMacro(amTetrahedralize);

namespace
{
using Vec = amTetraGeometry::Vec;
constexpr auto Cross = &amTetraGeometry::Cross;
constexpr auto Dot = &amTetraGeometry::Dot;
constexpr auto Sub = &amTetraGeometry::Sub;

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

struct FaceKey
{
  std::array<vtkIdType, 3> V;
  bool operator==(const FaceKey& o) const { return this->V == o.V; }
};
struct FaceHash
{
  size_t operator()(const FaceKey& k) const
  {
    uint64_t h = 1469598103934665603ull;
    for (vtkIdType v : k.V)
    {
      h ^= static_cast<uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return static_cast<size_t>(h);
  }
};
FaceKey MakeKey(vtkIdType a, vtkIdType b, vtkIdType c)
{
  FaceKey k{ { a, b, c } };
  std::sort(k.V.begin(), k.V.end());
  return k;
}

std::string ListTriangles(const std::vector<vtkIdType>& tris)
{
  std::ostringstream os;
  const size_t shown = std::min<size_t>(tris.size(), 10);
  for (size_t i = 0; i < shown; ++i)
    os << (i ? ", " : "") << tris[i];
  if (tris.size() > shown)
    os << " and " << tris.size() - shown << " more";
  return os.str();
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

/// What TetGen returns (or why it failed).
struct TetGenResult
{
  int Code = 0; // TetGen's error code, 0 on success
  vtkIdType NumberOfPoints = 0, NumberOfTetrahedra = 0, NumberOfFaces = 0;
  std::vector<double> Points;
  std::vector<int> Tetrahedra, Neighbors, Faces, FaceMarkers;
};

bool WriteAll(int fd, const void* data, size_t bytes)
{
  const char* p = static_cast<const char*>(data);
  while (bytes > 0)
  {
    const ssize_t n = ::write(fd, p, bytes);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return false;
    p += n;
    bytes -= static_cast<size_t>(n);
  }
  return true;
}

/// Runs TetGen in a child process. TetGen 1.5.0 frees its memory twice when it stops on an error
/// in library mode (terminatetetgen, then the mesh destructor), which crashes the caller: in a
/// child, an error or a crash of TetGen becomes a message here. Returns "" on success.
std::string RunTetGen(std::string& switches, tetgenio& in, TetGenResult& result)
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
    const long long header[4] = { code, code ? 0 : out.numberofpoints,
      code ? 0 : out.numberoftetrahedra, code ? 0 : out.numberoftrifaces };
    bool ok = WriteAll(fds[1], header, sizeof(header));
    if (ok && code == 0)
      ok = WriteAll(fds[1], out.pointlist, sizeof(REAL) * 3 * header[1]) &&
        WriteAll(fds[1], out.tetrahedronlist, sizeof(int) * 4 * header[2]) &&
        WriteAll(fds[1], out.neighborlist, sizeof(int) * 4 * header[2]) &&
        WriteAll(fds[1], out.trifacelist, sizeof(int) * 3 * header[3]) &&
        WriteAll(fds[1], out.trifacemarkerlist, sizeof(int) * header[3]);
    ::close(fds[1]);
    std::fflush(stdout);
    ::_exit(ok ? 0 : 1);
  }
  ::close(fds[1]);
  ::close(msg[1]);
  std::vector<char> data;
  std::string said;
  char buffer[1 << 16];
  pollfd polls[2] = { { fds[0], POLLIN, 0 }, { msg[0], POLLIN, 0 } };
  int open = 2;
  while (open > 0)
  {
    if (::poll(polls, 2, -1) < 0)
    {
      if (errno == EINTR)
        continue;
      break;
    }
    for (int k = 0; k < 2; ++k)
    {
      if (polls[k].fd < 0 || !(polls[k].revents & (POLLIN | POLLHUP | POLLERR)))
        continue;
      const ssize_t n = ::read(polls[k].fd, buffer, sizeof(buffer));
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0)
      {
        ::close(polls[k].fd);
        polls[k].fd = -1;
        --open;
      }
      else if (k == 0)
        data.insert(data.end(), buffer, buffer + n);
      else if (said.size() < 4096)
        said.append(buffer, static_cast<size_t>(n));
    }
  }
  for (auto& pfd : polls)
    if (pfd.fd >= 0)
      ::close(pfd.fd);
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
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
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
      (WIFSIGNALED(status) ? " (signal " + std::to_string(WTERMSIG(status)) + ")" : std::string()) +
      "." + tetgenSaid;
  }
  std::memcpy(header, data.data(), sizeof(header));
  result.Code = static_cast<int>(header[0]);
  if (result.Code != 0)
    return std::string(TetGenError(result.Code)) + " (TetGen code " + std::to_string(result.Code) + ")." + tetgenSaid;
  result.NumberOfPoints = header[1];
  result.NumberOfTetrahedra = header[2];
  result.NumberOfFaces = header[3];
  const size_t expected = sizeof(header) + sizeof(double) * 3 * header[1] + sizeof(int) * 8 * header[2] +
    sizeof(int) * 4 * header[3];
  if (data.size() != expected)
    return "TetGen's result was cut short (" + std::to_string(data.size()) + " of " +
      std::to_string(expected) + " bytes).";
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

amTetrahedralize::amTetrahedralize()
  : BackgroundLabel(0)
  , PreserveSurface(1)
  , MaximumRadiusEdgeRatio(1.5)
  , MinimumDihedralAngle(12.0)
  , Gradation(1.3)
  , MaximumSize(0.0)
  , SizeArrayName(nullptr)
  , OptimizationLevel(3)
  , ImproveQuality(1)
  , ImprovementPasses(4)
  , NumberOfTetrahedra(0)
  , NumberOfSteinerPoints(0)
  , WorstQualityBeforeImprovement(0)
  , MeanQualityBeforeImprovement(0)
{
  this->SetSizeArrayName("Size");
  this->SetNumberOfOutputPorts(2);
}

amTetrahedralize::~amTetrahedralize()
{
  this->SetSizeArrayName(nullptr);
}

int amTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int amTetrahedralize::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int amTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* interfaces = vtkPolyData::GetData(outputVector, 1);
  this->NumberOfTetrahedra = 0;
  this->NumberOfSteinerPoints = 0;
  const int bg = this->BackgroundLabel;

  // --- Input checks ------------------------------------------------------------------------------
  amSurfaceMesh mesh;
  std::string why;
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The input surface is empty: no triangles to mesh.");
    return 0;
  }
  if (!mesh.Build(input, why))
  {
    vtkErrorMacro("Input surface: " << why);
    return 0;
  }
  const vtkIdType np = mesh.NumberOfPoints(), nt = mesh.NumberOfTriangles();
  if (mesh.Labels.size() != static_cast<size_t>(nt))
  {
    vtkErrorMacro("The input surface has no 2-component cell array \"Labels\" (the regions on "
                  "either side of each triangle, as amLabelSurface makes).");
    return 0;
  }
  {
    std::vector<vtkIdType> same, degenerate;
    double diag = 0;
    double bounds[6];
    input->GetBounds(bounds);
    for (int d = 0; d < 3; ++d)
      diag += (bounds[2 * d + 1] - bounds[2 * d]) * (bounds[2 * d + 1] - bounds[2 * d]);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      if (mesh.Labels[t][0] == mesh.Labels[t][1])
        same.push_back(t);
      const auto n = mesh.TriangleNormal(t);
      const auto& tri = mesh.Triangles[t];
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) <= 1e-14 * diag)
        degenerate.push_back(t);
    }
    if (!same.empty())
    {
      vtkErrorMacro("Triangles " << ListTriangles(same)
                                 << " have the same label on both sides: not an interface.");
      return 0;
    }
    if (!degenerate.empty())
    {
      vtkErrorMacro("Triangles " << ListTriangles(degenerate) << " are degenerate (zero area).");
      return 0;
    }
  }
  // Open regions: an edge where a region's triangles occur an odd number of times.
  {
    std::vector<vtkIdType> open;
    std::map<int, int> count;
    for (size_t e = 0; e < mesh.Edges.size(); ++e)
    {
      count.clear();
      for (vtkIdType k = mesh.EdgeTriangleStart[e]; k < mesh.EdgeTriangleStart[e + 1]; ++k)
      {
        const auto& l = mesh.Labels[mesh.EdgeTriangles[k]];
        ++count[l[0]];
        ++count[l[1]];
      }
      bool odd = false;
      for (const auto& kv : count)
        odd = odd || (kv.first != bg && (kv.second % 2) != 0);
      if (odd)
        for (vtkIdType k = mesh.EdgeTriangleStart[e]; k < mesh.EdgeTriangleStart[e + 1]; ++k)
          open.push_back(mesh.EdgeTriangles[k]);
    }
    if (!open.empty())
    {
      std::sort(open.begin(), open.end());
      open.erase(std::unique(open.begin(), open.end()), open.end());
      vtkErrorMacro("The surface is open: a region's boundary has a free edge at triangles "
        << ListTriangles(open) << ". Every region must be closed to be meshed.");
      return 0;
    }
  }
  std::vector<amSurfaceTopology::Region> regions;
  if (!amSurfaceTopology::Analyse(input, regions, why, bg))
  {
    vtkErrorMacro("Input surface: " << why);
    return 0;
  }
  for (const auto& r : regions)
  {
    const double scale = std::pow(std::max(r.Area, 1e-300), 1.5);
    if (!(r.Volume > 1e-9 * scale))
    {
      vtkErrorMacro("Region " << r.Label << " encloses no volume (" << r.Triangles
                              << " triangles, enclosed volume " << r.Volume
                              << " mm^3): it has no interior to mesh, or its triangles face the wrong way.");
      return 0;
    }
  }
  this->UpdateProgress(0.05);

  // --- Sizes ---------------------------------------------------------------------------------------
  std::vector<double> sizes(static_cast<size_t>(np), 0.0);
  vtkDataArray* sizeArray = this->SizeArrayName && *this->SizeArrayName
    ? input->GetPointData()->GetArray(this->SizeArrayName)
    : nullptr;
  if (sizeArray && sizeArray->GetNumberOfComponents() == 1)
  {
    for (vtkIdType v = 0; v < np; ++v)
    {
      sizes[v] = sizeArray->GetComponent(v, 0);
      if (!std::isfinite(sizes[v]) || sizes[v] <= 0)
      {
        vtkErrorMacro("The sizing array \"" << this->SizeArrayName << "\" is " << sizes[v]
                                            << " at point " << v << ": sizes must be positive.");
        return 0;
      }
    }
  }
  else
  {
    for (vtkIdType v = 0; v < np; ++v)
    {
      double sum = 0;
      const vtkIdType k0 = mesh.RingStart[v], k1 = mesh.RingStart[v + 1];
      for (vtkIdType k = k0; k < k1; ++k)
      {
        const Vec d = Sub(mesh.Points[mesh.Ring[k]].data(), mesh.Points[v].data());
        sum += std::sqrt(Dot(d, d));
      }
      sizes[v] = k1 > k0 ? sum / static_cast<double>(k1 - k0) : 0.0;
    }
  }
  double bounds[6];
  input->GetBounds(bounds);
  amGradedSizeField field;
  if (!field.Build(mesh.Points, sizes, this->Gradation, this->MaximumSize, bounds, why))
  {
    vtkErrorMacro("Sizing: " << why);
    return 0;
  }
  this->UpdateProgress(0.1);

  // --- TetGen --------------------------------------------------------------------------------------
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
  CurrentSizing.Field = &field;
  in.tetunsuitable = &TetTooBig;

  std::ostringstream sw;
  sw << "pzQnM" << (this->PreserveSurface ? "Y" : "") << "q" << this->MaximumRadiusEdgeRatio << "/"
     << this->MinimumDihedralAngle << "O" << this->OptimizationLevel << "/7";
  std::string switches = sw.str();
  TetGenResult out;
  const std::string failure = RunTetGen(switches, in, out);
  CurrentSizing.Field = nullptr;
  in.tetunsuitable = nullptr;
  if (!failure.empty())
  {
    std::ostringstream msg;
    msg << "Tetrahedralization failed: " << failure;
    // Whatever TetGen said (it may also just crash), name triangles that cross, if any.
    const auto crossing = amSelfIntersection::AllTriangles(mesh, mesh.Points);
    if (!crossing.empty())
      msg << " The surface intersects itself: " << crossing.size()
          << " triangles cross others: " << ListTriangles(crossing) << ".";
    vtkErrorMacro(<< msg.str());
    return 0;
  }
  this->UpdateProgress(0.8);

  const vtkIdType nOutPoints = out.NumberOfPoints, nTets = out.NumberOfTetrahedra,
                  nSub = out.NumberOfFaces;
  if (nTets == 0)
  {
    vtkErrorMacro("TetGen produced no tetrahedra.");
    return 0;
  }
  if (this->PreserveSurface)
  {
    bool same = nOutPoints >= np && nSub == nt;
    for (vtkIdType v = 0; same && v < np; ++v)
      for (int d = 0; d < 3; ++d)
        same = same && out.Points[3 * v + d] == mesh.Points[v][d];
    if (!same)
    {
      vtkErrorMacro("TetGen did not keep the input surface (" << nSub << " boundary triangles for "
                                                              << nt << " input triangles).");
      return 0;
    }
  }

  // --- Regions: flood fill across faces that are not surface triangles ----------------------------
  std::unordered_map<FaceKey, vtkIdType, FaceHash> subfaceOf;
  subfaceOf.reserve(static_cast<size_t>(nSub) * 2);
  for (vtkIdType s = 0; s < nSub; ++s)
    subfaceOf[MakeKey(out.Faces[3 * s], out.Faces[3 * s + 1], out.Faces[3 * s + 2])] = s;
  auto sourceOf = [&](vtkIdType s) { return static_cast<vtkIdType>(out.FaceMarkers[s]) - 1; };
  for (vtkIdType s = 0; s < nSub; ++s)
    if (sourceOf(s) < 0 || sourceOf(s) >= nt)
    {
      vtkErrorMacro("TetGen returned a boundary triangle with no source triangle (marker "
        << out.FaceMarkers[s] << ").");
      return 0;
    }
  const int* tets = out.Tetrahedra.data();
  const REAL* P = out.Points.data();
  std::vector<int> component(static_cast<size_t>(nTets), -1);
  std::vector<int> componentLabel;
  std::vector<std::array<vtkIdType, 2>> subfaceTet(static_cast<size_t>(nSub), { -1, -1 });
  std::vector<vtkIdType> stack;
  std::vector<vtkIdType> conflicting;
  for (vtkIdType seed = 0; seed < nTets; ++seed)
  {
    if (component[seed] >= 0)
      continue;
    const int c = static_cast<int>(componentLabel.size());
    componentLabel.push_back(INT32_MIN);
    component[seed] = c;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const vtkIdType t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 4; ++i)
      {
        const int a = tets[4 * t + (i + 1) % 4], b = tets[4 * t + (i + 2) % 4], d = tets[4 * t + (i + 3) % 4];
        const auto it = subfaceOf.find(MakeKey(a, b, d));
        const int n = out.Neighbors[4 * t + i];
        if (it == subfaceOf.end())
        {
          if (n >= 0 && component[n] < 0)
          {
            component[n] = c;
            stack.push_back(n);
          }
          continue;
        }
        // A surface triangle: which side of its source is this tetrahedron on?
        const vtkIdType s = it->second, src = sourceOf(s);
        const auto& tri = mesh.Triangles[src];
        const double* q = P + 3 * tets[4 * t + i];
        const Vec nrm = Cross(Sub(mesh.Points[tri[1]].data(), mesh.Points[tri[0]].data()),
          Sub(mesh.Points[tri[2]].data(), mesh.Points[tri[0]].data()));
        const int side = Dot(nrm, Sub(q, mesh.Points[tri[0]].data())) > 0 ? 1 : 0;
        const int label = mesh.Labels[src][side];
        subfaceTet[s][side] = t;
        if (componentLabel[c] == INT32_MIN)
          componentLabel[c] = label;
        else if (componentLabel[c] != label)
          conflicting.push_back(src);
      }
    }
    if (componentLabel[c] == INT32_MIN)
      componentLabel[c] = bg; // bounded by no surface triangle: cannot happen for a valid PLC
  }
  if (!conflicting.empty())
  {
    std::sort(conflicting.begin(), conflicting.end());
    conflicting.erase(std::unique(conflicting.begin(), conflicting.end()), conflicting.end());
    vtkErrorMacro("The surface's labels are inconsistent: a connected part of the volume is bounded "
                  "by triangles that give it different labels (triangles "
      << ListTriangles(conflicting) << ").");
    return 0;
  }
  this->UpdateProgress(0.9);

  // --- Output --------------------------------------------------------------------------------------
  std::vector<vtkIdType> newTet(static_cast<size_t>(nTets), -1);
  std::vector<vtkIdType> newPoint(static_cast<size_t>(nOutPoints), -1);
  vtkIdType kept = 0;
  for (vtkIdType t = 0; t < nTets; ++t)
    if (componentLabel[component[t]] != bg)
    {
      newTet[t] = kept++;
      for (int i = 0; i < 4; ++i)
        newPoint[tets[4 * t + i]] = 0;
    }
  if (kept == 0)
  {
    vtkErrorMacro("No tetrahedron lies in a region other than the background " << bg << ".");
    return 0;
  }
  // Input surface points first, in order; then the Steiner points that are used.
  vtkIdType nPoints = 0;
  for (vtkIdType v = 0; v < std::min(np, nOutPoints); ++v)
    newPoint[v] = nPoints++;
  for (vtkIdType v = np; v < nOutPoints; ++v)
    if (newPoint[v] == 0)
      newPoint[v] = nPoints++;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nPoints);
  vtkNew<vtkIdTypeArray> surfaceId;
  surfaceId->SetName("SurfacePointId");
  surfaceId->SetNumberOfTuples(nPoints);
  for (vtkIdType v = 0; v < nOutPoints; ++v)
    if (newPoint[v] >= 0)
    {
      points->SetPoint(newPoint[v], P + 3 * v);
      surfaceId->SetValue(newPoint[v], v < np ? v : -1);
    }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(kept + 1);
  connectivity->SetNumberOfTuples(4 * kept);
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  region->SetNumberOfTuples(kept);
  for (vtkIdType t = 0; t < nTets; ++t)
  {
    const vtkIdType o = newTet[t];
    if (o < 0)
      continue;
    vtkIdType ids[4];
    for (int i = 0; i < 4; ++i)
      ids[i] = newPoint[tets[4 * t + i]];
    if (amTetraGeometry::SignedVolume(P + 3 * tets[4 * t], P + 3 * tets[4 * t + 1], P + 3 * tets[4 * t + 2],
          P + 3 * tets[4 * t + 3]) < 0)
      std::swap(ids[0], ids[1]);
    offsets->SetValue(o, 4 * o);
    for (int i = 0; i < 4; ++i)
      connectivity->SetValue(4 * o + i, ids[i]);
    region->SetValue(o, componentLabel[component[t]]);
  }
  offsets->SetValue(kept, 4 * kept);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetCellData()->AddArray(region);
  output->GetCellData()->SetActiveScalars("Region");
  output->GetPointData()->AddArray(surfaceId);

  vtkNew<vtkCellArray> faces;
  faces->AllocateExact(nSub, 3 * nSub);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  labels->SetNumberOfTuples(nSub);
  vtkNew<vtkIdTypeArray> source, adjacent;
  source->SetName("SourceTriangle");
  source->SetNumberOfTuples(nSub);
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  adjacent->SetNumberOfTuples(nSub);
  for (vtkIdType s = 0; s < nSub; ++s)
  {
    const vtkIdType src = sourceOf(s);
    vtkIdType ids[3] = { out.Faces[3 * s], out.Faces[3 * s + 1], out.Faces[3 * s + 2] };
    const auto& tri = mesh.Triangles[src];
    const Vec n0 = Cross(Sub(mesh.Points[tri[1]].data(), mesh.Points[tri[0]].data()),
      Sub(mesh.Points[tri[2]].data(), mesh.Points[tri[0]].data()));
    const Vec n1 = Cross(Sub(P + 3 * ids[1], P + 3 * ids[0]), Sub(P + 3 * ids[2], P + 3 * ids[0]));
    if (Dot(n0, n1) < 0)
      std::swap(ids[1], ids[2]);
    for (auto& id : ids)
      id = newPoint[id];
    faces->InsertNextCell(3, ids);
    labels->SetTypedTuple(s, mesh.Labels[src].data());
    source->SetValue(s, src);
    for (int k = 0; k < 2; ++k)
    {
      const vtkIdType t = subfaceTet[s][k];
      adjacent->SetComponent(s, k, t >= 0 ? static_cast<double>(newTet[t]) : -1.0);
    }
  }
  interfaces->SetPoints(points);
  interfaces->SetPolys(faces);
  interfaces->GetCellData()->AddArray(labels);
  interfaces->GetCellData()->AddArray(source);
  interfaces->GetCellData()->AddArray(adjacent);

  this->UpdateProgress(0.92);

  // --- Quality improvement: flips and smoothing inside the regions, the surface kept ------------
  std::ostringstream improvement;
  this->WorstQualityBeforeImprovement = this->MeanQualityBeforeImprovement = 0;
  if (this->ImproveQuality && this->ImprovementPasses > 0)
  {
    amTetraMeshOptimizer::Options options;
    options.Passes = this->ImprovementPasses;
    amTetraMeshOptimizer::Report report;
    if (!amTetraMeshOptimizer::ImproveGrid(output, interfaces, options, report, why,
          [this](double f) { this->UpdateProgress(0.92 + 0.08 * f); }))
    {
      vtkErrorMacro("Quality improvement: " << why);
      return 0;
    }
    this->WorstQualityBeforeImprovement = report.WorstBefore;
    this->MeanQualityBeforeImprovement = report.MeanBefore;
    improvement << " improvement: " << report.Describe();
  }

  this->NumberOfTetrahedra = output->GetNumberOfCells();
  this->NumberOfSteinerPoints = output->GetNumberOfPoints() - np;
  std::ostringstream params;
  params << "switches=" << switches << " Gradation=" << this->Gradation
         << " MaximumSize=" << this->MaximumSize << " ImproveQuality=" << this->ImproveQuality
         << " ImprovementPasses=" << this->ImprovementPasses << " tetrahedra=" << this->NumberOfTetrahedra
         << improvement.str();
  amProvenance::Record(output, input, "amTetrahedralize", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n";
  os << indent << "PreserveSurface: " << this->PreserveSurface << "\n";
  os << indent << "MaximumRadiusEdgeRatio: " << this->MaximumRadiusEdgeRatio << "\n";
  os << indent << "MinimumDihedralAngle: " << this->MinimumDihedralAngle << "\n";
  os << indent << "Gradation: " << this->Gradation << "\n";
  os << indent << "MaximumSize: " << this->MaximumSize << "\n";
  os << indent << "SizeArrayName: " << (this->SizeArrayName ? this->SizeArrayName : "(none)") << "\n";
  os << indent << "OptimizationLevel: " << this->OptimizationLevel << "\n";
  os << indent << "ImproveQuality: " << this->ImproveQuality << "\n";
  os << indent << "ImprovementPasses: " << this->ImprovementPasses << "\n";
}
