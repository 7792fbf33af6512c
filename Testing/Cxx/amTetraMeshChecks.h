// Checks of a multi-region tetrahedral mesh against its boundary and interface triangles (the two
// outputs of amTetrahedralize and amLabelMapTetrahedralize), for tests.
#ifndef amTetraMeshChecks_h
#define amTetraMeshChecks_h

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace amTest
{
/// The first way the interfaces do not match the mesh, empty when they do: every point in a
/// tetrahedron (solvers assemble over all points), every face between two
/// regions or on the mesh's boundary is one interface triangle and no other face is; each
/// triangle's Labels name the regions on its two sides (background outside), its normal pointing
/// into the Labels[1] side; its Tetra array names a tetrahedron holding it on each side.
inline std::string InterfaceProblems(vtkUnstructuredGrid* grid, vtkPolyData* interfaces, int background = 0)
{
  using Key = std::array<vtkIdType, 3>;
  std::map<Key, std::vector<vtkIdType>> faces;
  vtkDataArray* region = grid->GetCellData()->GetArray("Region");
  vtkDataArray* labels = interfaces->GetCellData()->GetArray("Labels");
  vtkDataArray* tetra = interfaces->GetCellData()->GetArray("Tetra");
  if (!region || !labels || !tetra)
    return "no Region, Labels or Tetra array";
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    for (int i = 0; i < 4; ++i)
    {
      Key f = { ids[(i + 1) % 4], ids[(i + 2) % 4], ids[(i + 3) % 4] };
      std::sort(f.begin(), f.end());
      faces[f].push_back(c);
    }
  }
  std::vector<char> used(grid->GetNumberOfPoints(), 0);
  for (const auto& face : faces)
    for (vtkIdType v : face.first)
      used[v] = 1;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
    if (!used[p])
      return "point " + std::to_string(p) + " is in no tetrahedron";
  std::map<Key, vtkIdType> triangles;
  for (vtkIdType s = 0; s < interfaces->GetNumberOfCells(); ++s)
  {
    vtkIdType n;
    const vtkIdType* ids;
    interfaces->GetCellPoints(s, n, ids);
    Key f = { ids[0], ids[1], ids[2] };
    std::sort(f.begin(), f.end());
    if (!triangles.emplace(f, s).second)
      return "triangle " + std::to_string(s) + " twice";
    const auto it = faces.find(f);
    if (it == faces.end() || it->second.size() > 2)
      return "triangle " + std::to_string(s) + " is not a face of one or two tetrahedra";
    double a[3], b[3], c[3];
    interfaces->GetPoint(ids[0], a);
    interfaces->GetPoint(ids[1], b);
    interfaces->GetPoint(ids[2], c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double normal[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    int side[2] = { background, background };
    vtkIdType sideTetra[2] = { -1, -1 };
    for (vtkIdType t : it->second)
    {
      vtkIdType nt;
      const vtkIdType* tv;
      grid->GetCellPoints(t, nt, tv);
      double centre[3] = { 0, 0, 0 };
      for (int k = 0; k < 4; ++k)
      {
        double p[3];
        grid->GetPoint(tv[k], p);
        for (int d = 0; d < 3; ++d)
          centre[d] += p[d] / 4;
      }
      const double along =
        normal[0] * (centre[0] - a[0]) + normal[1] * (centre[1] - a[1]) + normal[2] * (centre[2] - a[2]);
      const int k = along > 0 ? 1 : 0;
      side[k] = static_cast<int>(region->GetComponent(t, 0));
      sideTetra[k] = t;
    }
    for (int k = 0; k < 2; ++k)
    {
      if (static_cast<int>(labels->GetComponent(s, k)) != side[k])
      {
        std::ostringstream os;
        os << "triangle " << s << " has Labels " << labels->GetComponent(s, 0) << " " << labels->GetComponent(s, 1)
           << " but regions " << side[0] << " " << side[1] << " on its sides";
        return os.str();
      }
      if (static_cast<vtkIdType>(tetra->GetComponent(s, k)) != sideTetra[k])
        return "triangle " + std::to_string(s) + ": Tetra does not name the tetrahedron on its side " +
          std::to_string(k);
    }
  }
  for (const auto& kv : faces)
  {
    const bool interface =
      kv.second.size() == 1 || region->GetComponent(kv.second[0], 0) != region->GetComponent(kv.second[1], 0);
    if (interface != (triangles.count(kv.first) > 0))
      return std::string(interface ? "an interface face is missing from" : "an inner face is in") + " the triangles";
  }
  return "";
}
}

#endif
