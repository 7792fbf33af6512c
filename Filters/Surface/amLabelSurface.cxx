#include "amLabelSurface.h"

#include "amInputCheck.h"
#include "amLabelSurfaceExtractor.h"
#include "amProvenance.h"
#include "amSurfaceTopology.h"
#include "amThreading.h"
#include "amUnits.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

vtkStandardNewMacro(amLabelSurface);

amLabelSurface::amLabelSurface()
  : BackgroundLabel(0)
  , ComputeTopology(true)
  , ResolvedEdges(0)
  , SplitCorners(0)
  , RelabeledVoxels(0)
{
  amThreading::Initialize();
  this->SetNumberOfOutputPorts(2);
}

amLabelSurface::~amLabelSurface() = default;

int amLabelSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int amLabelSurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

namespace
{
/// A label's rank among the grid's sorted values.
std::uint16_t Rank(const amLabelGrid& g, int v)
{
  return static_cast<std::uint16_t>(std::lower_bound(g.Values.begin(), g.Values.end(), v) - g.Values.begin());
}

/// Every voxel's label as its rank among the grid's values, slice by slice on the threads.
void RankLabels(vtkDataArray* scalars, amLabelGrid& g)
{
  const vtkIdType nVox = scalars->GetNumberOfTuples();
  const vtkIdType slice = static_cast<vtkIdType>(g.N[0]) * g.N[1];
  auto readSlice = [&](vtkIdType k, std::vector<double>& row) {
    if (scalars->HasStandardMemoryLayout())
    {
      // Typed copy from the raw buffer (GetData/GetComponent go through virtual calls).
      switch (scalars->GetDataType())
      {
        vtkTemplateMacro({
          const VTK_TT* p = static_cast<const VTK_TT*>(scalars->GetVoidPointer(k * slice));
          std::copy(p, p + slice, row.begin());
        });
      }
      return;
    }
    vtkNew<vtkDoubleArray> buffer;
    buffer->SetArray(row.data(), slice, 1);
    scalars->GetData(k * slice, (k + 1) * slice - 1, 0, 0, buffer);
  };
  g.Labels.resize(static_cast<size_t>(nVox));
  vtkSMPTools::For(0, g.N[2], [&](vtkIdType k0, vtkIdType k1) {
    std::vector<double> row(static_cast<size_t>(slice));
    for (vtkIdType k = k0; k < k1; ++k)
    {
      readSlice(k, row);
      double last = std::numeric_limits<double>::quiet_NaN();
      std::uint16_t lastRank = 0;
      for (vtkIdType i = 0; i < slice; ++i)
      {
        if (row[i] != last)
        {
          last = row[i];
          lastRank = Rank(g, static_cast<int>(last));
        }
        g.Labels[k * slice + i] = lastRank;
      }
    }
  });
}

/// The extractor's points, triangles and label pairs moved into the output (its buffers freed).
void MoveToPolyData(amLabelSurfaceExtractor& extractor, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(extractor.Points.size() / 3));
  std::copy(
    extractor.Points.begin(), extractor.Points.end(), static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0));
  std::vector<float>().swap(extractor.Points);
  const vtkIdType nTri = static_cast<vtkIdType>(extractor.Labels.size() / 2);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nTri + 1);
  connectivity->SetNumberOfTuples(3 * nTri);
  vtkNew<vtkIntArray> labelArray;
  labelArray->SetName("Labels");
  labelArray->SetNumberOfComponents(2);
  labelArray->SetNumberOfTuples(nTri);
  std::copy(extractor.Triangles.begin(), extractor.Triangles.end(), connectivity->GetPointer(0));
  std::copy(extractor.Labels.begin(), extractor.Labels.end(), labelArray->GetPointer(0));
  std::vector<vtkIdType>().swap(extractor.Triangles);
  std::vector<int>().swap(extractor.Labels);
  vtkIdType* off = offsets->GetPointer(0);
  for (vtkIdType t = 0; t <= nTri; ++t)
    off[t] = 3 * t;
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(labelArray);
}

// The topology table with each region's voxel volume beside its enclosed volume, and field data
// "LabelVoxelVolumes" (label, mm^3) on the surface itself, so the mesh made from it can be compared
// with the label map downstream (amTetrahedralize's RegionVolumes).
void AddVolumes(const amLabelGrid& g, const std::vector<amSurfaceTopology::Region>& regions, int background,
  vtkTable* table, vtkPolyData* output)
{
  std::vector<vtkIdType> count(g.Values.size(), 0);
  for (std::uint16_t l : g.Labels)
    ++count[l];
  std::map<int, vtkIdType> voxels;
  for (size_t r = 0; r < g.Values.size(); ++r)
    voxels[g.Values[r]] = count[r];
  vtkSmartPointer<vtkTable> t = amSurfaceTopology::ToTable(regions);
  vtkNew<vtkDoubleArray> vv;
  vv->SetName("VoxelVolume");
  amUnits::Set(vv, "mm3");
  vv->SetNumberOfTuples(static_cast<vtkIdType>(regions.size()));
  const double voxelVolume = g.Spacing[0] * g.Spacing[1] * g.Spacing[2];
  for (size_t r = 0; r < regions.size(); ++r)
    vv->SetValue(static_cast<vtkIdType>(r), voxels[regions[r].Label] * voxelVolume);
  t->AddColumn(vv);
  table->ShallowCopy(t);
  vtkNew<vtkDoubleArray> labelVolumes;
  labelVolumes->SetName("LabelVoxelVolumes");
  labelVolumes->SetNumberOfComponents(2);
  for (size_t r = 0; r < g.Values.size(); ++r)
    if (g.Values[r] != background)
    {
      const double row[2] = { static_cast<double>(g.Values[r]), count[r] * voxelVolume };
      labelVolumes->InsertNextTuple(row);
    }
  output->GetFieldData()->AddArray(labelVolumes);
}
}

int amLabelSurface::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  this->ResolvedEdges = this->SplitCorners = this->RelabeledVoxels = 0;
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }

  amLabelSurfaceExtractor extractor;
  amLabelGrid& g = extractor.Grid;
  input->GetDimensions(g.N);
  input->GetExtent(g.Extent);
  input->GetOrigin(g.Origin);
  input->GetSpacing(g.Spacing);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      g.Direction[3 * r + c] = input->GetDirectionMatrix()->GetElement(r, c);
  for (int d = 0; d < 3; ++d)
    if (!(g.Spacing[d] > 0))
    {
      vtkErrorMacro("The label map's spacing along axis " << d << " is " << g.Spacing[d] << "; it must be positive.");
      return 0;
    }
  std::map<int, vtkIdType> counts;
  if (!amInputCheck::LabelCounts(scalars, -amInputCheck::LargestLabel, amInputCheck::LargestLabel, counts, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  for (const auto& lv : counts)
    g.Values.push_back(lv.first);
  g.Values.push_back(this->BackgroundLabel);
  std::sort(g.Values.begin(), g.Values.end());
  g.Values.erase(std::unique(g.Values.begin(), g.Values.end()), g.Values.end());
  if (g.Values.size() == 1)
  {
    vtkErrorMacro("The label map has no voxel with a label other than the background ("
      << this->BackgroundLabel << "): there is no surface to extract.");
    return 0;
  }
  if (!amInputCheck::LabelCount(g.Values.size() - 1, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  g.Background = Rank(g, this->BackgroundLabel);
  RankLabels(scalars, g);
  this->UpdateProgress(0.1);

  extractor.Mirrored = input->GetDirectionMatrix()->Determinant() < 0;
  extractor.Extract([this](double f) { this->UpdateProgress(f); });
  this->ResolvedEdges = extractor.ResolvedEdges;
  this->SplitCorners = extractor.SplitCorners;
  this->RelabeledVoxels = extractor.RelabeledVoxels;
  if (this->RelabeledVoxels > 0)
    vtkWarningMacro(<< this->RelabeledVoxels
                    << " voxel(s) relabelled where a label touched itself only at a voxel corner "
                       "between other regions (no vertex split can make that manifold).");

  MoveToPolyData(extractor, output);
  vtkNew<vtkDoubleArray> voxelSize;
  voxelSize->SetName("VoxelSize");
  voxelSize->InsertNextValue(std::min({ g.Spacing[0], g.Spacing[1], g.Spacing[2] }));
  output->GetFieldData()->AddArray(voxelSize);
  std::ostringstream params;
  params << "BackgroundLabel=" << this->BackgroundLabel << " ResolvedEdges=" << this->ResolvedEdges
         << " SplitCorners=" << this->SplitCorners << " RelabeledVoxels=" << this->RelabeledVoxels;
  amProvenance::Record(output, input, "amLabelSurface", params.str());
  this->UpdateProgress(0.85);

  if (this->ComputeTopology)
  {
    std::vector<amSurfaceTopology::Region> regions;
    if (!amSurfaceTopology::Analyse(output, regions, why, this->BackgroundLabel))
    {
      vtkErrorMacro("Topology check failed: " << why);
      return 0;
    }
    AddVolumes(g, regions, this->BackgroundLabel, table, output);
    for (const auto& r : regions)
      if (r.BoundaryEdges || r.NonManifoldEdges || r.MisorientedEdges)
        vtkWarningMacro("Region " << r.Label << " is not a closed oriented manifold: " << r.BoundaryEdges
                                  << " boundary, " << r.NonManifoldEdges << " non-manifold, " << r.MisorientedEdges
                                  << " misoriented edges.");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void amLabelSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n";
  os << indent << "ComputeTopology: " << this->ComputeTopology << "\n";
}
