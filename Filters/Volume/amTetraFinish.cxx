#include "amTetraFinish.h"

#include "amQualityBars.h"

#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

std::string amTetraFinish::Result::Describe() const
{
  return this->Improved ? " improvement: " + this->Report.Describe() : std::string();
}

bool amTetraFinish::Run(
  vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const Settings& settings, Result& result, std::string& why)
{
  result = Result();
  if (settings.Improve)
  {
    if (!amTetraMeshOptimizer::ImproveGrid(mesh, interfaces, settings.Options, result.Report, why, settings.Progress))
    {
      why = "Quality improvement: " + why;
      return false;
    }
    result.Improved = true;
    result.Poor = result.Report.Slivers;
  }
  if (settings.VoxelVolumes)
  {
    result.VolumeMisses =
      amRegionVolumes::Compare(mesh, "Region", settings.VoxelVolumes, MinimumRegionVolume, RegionVolumeTolerance);
    if (!result.VolumeMisses.empty())
      result.VolumeWarning = amRegionVolumes::Warning(result.VolumeMisses);
  }
  // Every point in a tetrahedron, and the element bars checked whatever the parameters.
  result.BarWarning = amQualityBars::Finish(mesh, interfaces, result.Poor, settings.Remedy);
  return true;
}
