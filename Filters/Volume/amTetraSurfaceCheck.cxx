#include "amTetraSurfaceCheck.h"

#include "amMessage.h"
#include "amSurfaceMesh.h"
#include "amSurfaceTopology.h"

#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <map>

std::string amTetraSurfaceCheck::List(const std::vector<vtkIdType>& tris)
{
  std::ostringstream os;
  const size_t shown = std::min<size_t>(tris.size(), 10);
  for (size_t i = 0; i < shown; ++i)
    os << (i ? ", " : "") << tris[i];
  if (tris.size() > shown)
    os << " and " << tris.size() - shown << " more";
  return os.str();
}

bool amTetraSurfaceCheck::Check(vtkPolyData* input, const amSurfaceMesh& mesh, int background, std::string& why)
{
  const int bg = background;
  const vtkIdType nt = mesh.NumberOfTriangles();
  if (mesh.Labels.size() != static_cast<size_t>(nt))
  {
    why = amMessage() << "The input surface has no 2-component cell array \"Labels\" (the regions on "
                         "either side of each triangle, as amLabelSurface makes).";
    return false;
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
      why = amMessage() << "Triangles " << amTetraSurfaceCheck::List(same)
                        << " have the same label on both sides: not an interface.";
      return false;
    }
    if (!degenerate.empty())
    {
      why = amMessage() << "Triangles " << amTetraSurfaceCheck::List(degenerate) << " are degenerate (zero area).";
      return false;
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
      why = amMessage() << "The surface is open: a region's boundary has a free edge at triangles "
                        << amTetraSurfaceCheck::List(open) << ". Every region must be closed to be meshed.";
      return false;
    }
  }
  std::vector<amSurfaceTopology::Region> regions;
  if (!amSurfaceTopology::Analyse(input, regions, why, bg))
  {
    why = amMessage() << "Input surface: " << why;
    return false;
  }
  for (const auto& r : regions)
  {
    const double scale = std::pow(std::max(r.Area, 1e-300), 1.5);
    if (!(r.Volume > 1e-9 * scale))
    {
      why = amMessage() << "Region " << r.Label << " encloses no volume (" << r.Triangles
                        << " triangles, enclosed volume " << r.Volume
                        << " mm^3): it has no interior to mesh, or its triangles face the wrong way.";
      return false;
    }
  }
  return true;
}
