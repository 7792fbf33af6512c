#include "amQualityBars.h"

#include "amMeshQuality.h"
#include "amUnusedPoints.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <sstream>

amQualityBars::Result amQualityBars::Check(vtkUnstructuredGrid* mesh, double maximumQuality, double minimumDihedral)
{
  Result r;
  double worstScore = -1;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    if (mesh->GetCellType(c) != VTK_TETRA)
      continue;
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, n, ids);
    double p[4][3];
    for (int a = 0; a < 4; ++a)
      mesh->GetPoint(ids[a], p[a]);
    double q, minDihedral, maxDihedral, radiusRatio, volume;
    amMeshQuality::TetraQuality(p[0], p[1], p[2], p[3], q, minDihedral, maxDihedral, radiusRatio, volume);
    r.AboveQuality += q > maximumQuality;
    r.BelowDihedral += minDihedral < minimumDihedral;
    r.Poor += q > maximumQuality || minDihedral < minimumDihedral;
    r.WorstQuality = std::max(r.WorstQuality, q);
    r.SmallestDihedral = std::min(r.SmallestDihedral, minDihedral);
    // The worst element: the smallest dihedral angle, ties broken by Q.
    const double score = (180.0 - minDihedral) * 1e6 + q;
    if (score > worstScore)
    {
      worstScore = score;
      r.WorstCell = c;
    }
  }
  return r;
}

std::string amQualityBars::Finish(
  vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, vtkIdType& poor, const std::string& remedy)
{
  // Every point in a tetrahedron: solvers that assemble over all points need it.
  amUnusedPoints::Remove(mesh, interfaces);
  const Result bars = Check(mesh);
  poor = bars.Poor;
  return Warning(mesh, bars, remedy);
}

std::string amQualityBars::Warning(
  vtkUnstructuredGrid* mesh, const Result& r, const std::string& remedy, double maximumQuality, double minimumDihedral)
{
  if (r.AboveQuality == 0 && r.BelowDihedral == 0)
    return "";
  std::ostringstream text;
  text << "the mesh misses the element bars: " << r.AboveQuality << " tetrahedra above Q " << maximumQuality
       << " (worst " << r.WorstQuality << "), " << r.BelowDihedral << " with a dihedral angle under " << minimumDihedral
       << " degrees (smallest " << r.SmallestDihedral << ")";
  if (r.WorstCell >= 0)
  {
    double centre[3] = { 0, 0, 0 }, x[3];
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(r.WorstCell, n, ids);
    for (vtkIdType a = 0; a < n; ++a)
    {
      mesh->GetPoint(ids[a], x);
      for (int d = 0; d < 3; ++d)
        centre[d] += x[d] / n;
    }
    text << "; the worst, tetrahedron " << r.WorstCell << ", at (" << centre[0] << ", " << centre[1] << ", "
         << centre[2] << ") mm";
    if (vtkDataArray* regions = mesh->GetCellData()->GetArray("Region"))
      text << " in region " << regions->GetComponent(r.WorstCell, 0);
  }
  text << ". " << remedy;
  return text.str();
}
