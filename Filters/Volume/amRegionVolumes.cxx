#include "amRegionVolumes.h"

#include "amTetraGeometry.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

std::vector<amRegionVolumes::Miss> amRegionVolumes::Compare(
  vtkUnstructuredGrid* mesh, const char* regionArray, vtkDataArray* voxelVolumes, double minimum, double tolerance)
{
  std::map<int, double> meshVolume;
  vtkDataArray* region = mesh->GetCellData()->GetArray(regionArray);
  const vtkIdType n = mesh->GetNumberOfCells();
  for (vtkIdType c = 0; c < n && region; ++c)
  {
    vtkIdType np;
    const vtkIdType* ids;
    mesh->GetCellPoints(c, np, ids);
    if (np != 4)
      continue;
    double x[4][3];
    for (int k = 0; k < 4; ++k)
      mesh->GetPoint(ids[k], x[k]);
    meshVolume[static_cast<int>(region->GetComponent(c, 0))] +=
      std::fabs(amTetraGeometry::SignedVolume(x[0], x[1], x[2], x[3]));
  }
  vtkNew<vtkDoubleArray> table;
  table->SetName("RegionVolumes");
  table->SetNumberOfComponents(4);
  std::vector<Miss> misses;
  for (vtkIdType i = 0; i < voxelVolumes->GetNumberOfTuples(); ++i)
  {
    const int label = static_cast<int>(voxelVolumes->GetComponent(i, 0));
    const double voxels = voxelVolumes->GetComponent(i, 1);
    const auto it = meshVolume.find(label);
    if (it == meshVolume.end() && voxels <= 0)
      continue;
    const double volume = it == meshVolume.end() ? 0.0 : it->second;
    const double difference = voxels > 0 ? (volume - voxels) / voxels : 0.0;
    const double row[4] = { static_cast<double>(label), voxels, volume, difference };
    table->InsertNextTuple(row);
    if (voxels >= minimum && std::fabs(difference) > tolerance)
      misses.push_back({ label, voxels, volume });
  }
  mesh->GetFieldData()->AddArray(table);
  std::sort(misses.begin(), misses.end(), [](const Miss& a, const Miss& b) {
    const double da = std::fabs(a.Mesh - a.Voxels) / a.Voxels, db = std::fabs(b.Mesh - b.Voxels) / b.Voxels;
    return da != db ? da > db : a.Label < b.Label;
  });
  return misses;
}

std::string amRegionVolumes::Describe(const std::vector<Miss>& misses, size_t count)
{
  std::ostringstream os;
  os.precision(3);
  for (size_t i = 0; i < misses.size() && i < count; ++i)
    os << (i ? ", " : "") << "label " << misses[i].Label << " (" << misses[i].Voxels / 1000.0 << " cm3 of voxels, "
       << misses[i].Mesh / 1000.0 << " in the mesh, " << std::showpos
       << 100.0 * (misses[i].Mesh - misses[i].Voxels) / misses[i].Voxels << std::noshowpos << " %)";
  if (misses.size() > count)
    os << " and " << misses.size() - count << " more";
  return os.str();
}

std::string amRegionVolumes::Warning(const std::vector<Miss>& misses)
{
  return std::to_string(misses.size()) +
    " region(s) of at least 1 cm3 differ from their label's voxel volume by "
    "more than 2 % (field data RegionVolumes): " +
    Describe(misses, 5) + ".";
}
