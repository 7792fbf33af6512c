#include "amLabelMapTetrahedralize.h"

#include "amInputCheck.h"
#include "amProvenance.h"
#include "amQualityBars.h"
#include "amRegionVolumes.h"
#include "amTetraGeometry.h"
#include "amTetraMeshOptimizer.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_3/initialize_triangulation_from_labeled_image.h>
#include <CGAL/Mesh_3/polylines_to_protect.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_constant_domain_field_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/lloyd_optimize_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <CGAL/refine_mesh_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(amLabelMapTetrahedralize);

namespace
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using ImageDomain = CGAL::Labeled_mesh_domain_3<K>;
using Domain = CGAL::Mesh_domain_with_polyline_features_3<ImageDomain>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Point = K::Point_3;
using SizeField = CGAL::Mesh_constant_domain_field_3<Tr::Geom_traits, Domain::Index>;
}

amLabelMapTetrahedralize::amLabelMapTetrahedralize()
  : BackgroundLabel(0)
  , FacetDistance(0.5)
  , FacetSize(4.0)
  , FacetAngle(30.0)
  , CellSize(8.0)
  , CellRadiusEdgeRatio(2.0)
  , ProtectJunctions(1)
  , EdgeSize(0.0)
  , Odt(0)
  , Lloyd(0)
  , Perturb(1)
  , Exude(1)
  , SliverBound(12.0)
  , ImproveQuality(1)
  , PreserveVolumes(1)
  , ImprovementPasses(4)
  , MaximumSurfaceDeviation(0.2)
  , NumberOfSlivers(0)
  , SurfaceDeviation(0)
  , NumberOfTetrahedra(0)
{
  this->SetNumberOfOutputPorts(2);
}

amLabelMapTetrahedralize::~amLabelMapTetrahedralize() = default;

void amLabelMapTetrahedralize::AddRegionCellSize(double label, double size)
{
  this->RegionCellSizes.push_back(label);
  this->RegionCellSizes.push_back(size);
  this->Modified();
}

void amLabelMapTetrahedralize::RemoveAllRegionCellSizes()
{
  if (!this->RegionCellSizes.empty())
  {
    this->RegionCellSizes.clear();
    this->Modified();
  }
}

int amLabelMapTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

int amLabelMapTetrahedralize::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int amLabelMapTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* interfaces = vtkPolyData::GetData(outputVector, 1);
  this->NumberOfTetrahedra = 0;

  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  int dims[3];
  double spacing[3], origin[3];
  input->GetDimensions(dims);
  input->GetSpacing(spacing);
  input->GetOrigin(origin);
  const double* direction = input->GetDirectionMatrix()->GetData();
  const vtkIdType nv = scalars->GetNumberOfTuples();
  const int bg = this->BackgroundLabel;

  // Any whole-number labels, any count: CGAL meshes a compact image (background 0, the other
  // labels 1..K in increasing order, 8-bit up to 255 labels, 16-bit beyond) and the regions are
  // given their own labels back.
  std::map<int, vtkIdType> voxelsOf; // own label -> voxel count
  for (vtkIdType i = 0; i < nv; ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (!(std::fabs(v) < 2.0e9 && v == std::floor(v)))
    {
      vtkErrorMacro("Voxel " << i << " has the value " << v << ": a label map holds whole numbers (the "
                             << scalars->GetDataTypeAsString() << " input looks like an intensity image).");
      return 0;
    }
    ++voxelsOf[static_cast<int>(v)];
  }
  if (!amInputCheck::LabelCount(voxelsOf.size() - voxelsOf.count(bg), why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  if (voxelsOf.size() == 1 && voxelsOf.begin()->first == bg)
  {
    vtkErrorMacro("The label map holds only the background label " << bg << ": nothing to mesh.");
    return 0;
  }
  std::vector<int> labelOf{ bg }; // compact index -> own label
  std::map<int, int> compactOf{ { bg, 0 } };
  for (const auto& lv : voxelsOf)
    if (lv.first != bg)
    {
      compactOf[lv.first] = static_cast<int>(labelOf.size());
      labelOf.push_back(lv.first);
    }
  const size_t nLabels = labelOf.size() - 1;
  if (nLabels > 65535)
  {
    vtkErrorMacro("The label map holds " << nLabels << " labels; this backend meshes at most 65535.");
    return 0;
  }
  const bool wide = nLabels > 255;
  // One voxel of background all round: CGAL's image domain ends at the centres of the outermost
  // voxels, which would cut the labels on the border in half (a one-voxel label there vanished).
  const int padded[3] = { dims[0] + 2, dims[1] + 2, dims[2] + 2 };
  _image* raw = ::_createImage(
    padded[0], padded[1], padded[2], 1, spacing[0], spacing[1], spacing[2], wide ? 2 : 1, WK_FIXED, SGN_UNSIGNED);
  if (!raw)
  {
    vtkErrorMacro("Could not allocate the CGAL image (" << nv << " voxels).");
    return 0;
  }
  CGAL::Image_3 image(raw);
  {
    const size_t total = static_cast<size_t>(padded[0]) * padded[1] * padded[2];
    std::fill_n(static_cast<unsigned char*>(raw->data), total * (wide ? 2 : 1), 0);
    // Runs of one label are common: the map lookup only where the value changes.
    double last = std::numeric_limits<double>::quiet_NaN();
    int index = 0;
    for (vtkIdType i = 0; i < nv; ++i)
    {
      const double v = scalars->GetComponent(i, 0);
      if (v != last)
      {
        last = v;
        index = compactOf[static_cast<int>(v)];
      }
      const vtkIdType x = i % dims[0], y = (i / dims[0]) % dims[1], z = i / (static_cast<vtkIdType>(dims[0]) * dims[1]);
      const size_t at = static_cast<size_t>(((z + 1) * padded[1] + (y + 1)) * padded[0] + (x + 1));
      if (wide)
        static_cast<unsigned short*>(raw->data)[at] = static_cast<unsigned short>(index);
      else
        static_cast<unsigned char*>(raw->data)[at] = static_cast<unsigned char>(index);
    }
  }
  std::map<int, vtkIdType> count; // compact index -> voxel count
  for (const auto& lv : voxelsOf)
    count[compactOf[lv.first]] = lv.second;
  auto toLabel = [&labelOf](int subdomain) { return labelOf[static_cast<size_t>(subdomain)]; };
  this->UpdateProgress(0.05);

  CGAL::Random rng(0);
  Domain domain = Domain::create_labeled_image_mesh_domain(image, CGAL::parameters::relative_error_bound = 1e-6,
    CGAL::parameters::value_outside = 0, CGAL::parameters::p_rng = &rng);
  const double edgeSize = this->EdgeSize > 0 ? this->EdgeSize : this->FacetSize;
  std::size_t curves = 0;
  if (this->ProtectJunctions)
  {
    std::vector<std::vector<Point>> polylines;
    if (wide)
      CGAL::polylines_to_protect<Point, unsigned short>(image, polylines);
    else
      CGAL::polylines_to_protect<Point, unsigned char>(image, polylines);
    curves = polylines.size();
    domain.add_features(polylines.begin(), polylines.end());
  }
  this->UpdateProgress(0.1);

  // Per-region sizes: cells by subdomain, facets by the pair of subdomains they separate.
  std::map<int, double> regionSize; // CGAL subdomain index -> cell size
  for (std::size_t k = 0; k + 1 < this->RegionCellSizes.size(); k += 2)
  {
    const double value = this->RegionCellSizes[k], size = this->RegionCellSizes[k + 1];
    if (!(std::fabs(value) < 2.0e9 && value == std::floor(value)) || static_cast<int>(value) == bg)
    {
      vtkErrorMacro("RegionCellSizes names the label " << value << ", which is not a meshed label (a whole number, "
                                                       << "not the background " << bg << ").");
      return 0;
    }
    if (!(size > 0) || !std::isfinite(size))
    {
      vtkErrorMacro("RegionCellSizes gives label " << value << " the size " << size << ": sizes must be > 0 mm.");
      return 0;
    }
    const auto found = compactOf.find(static_cast<int>(value));
    if (found == compactOf.end())
    {
      vtkWarningMacro("RegionCellSizes names label " << value << ", which is not in the label map.");
      continue;
    }
    const int subdomain = found->second;
    regionSize[subdomain] = size;
  }
  SizeField cellSize(this->CellSize), facetSize(this->FacetSize);
  for (const auto& rs : regionSize)
    cellSize.set_size(rs.second, 3, domain.index_from_subdomain_index(rs.first));
  for (const auto& a : count)
    for (const auto& b : count)
    {
      if (a.first >= b.first)
        continue;
      double size = this->FacetSize;
      for (int s : { a.first, b.first })
        if (regionSize.count(s))
          size = std::min(size, regionSize[s] * this->FacetSize / this->CellSize);
      if (size < this->FacetSize)
        for (const auto& patch : { std::make_pair(a.first, b.first), std::make_pair(b.first, a.first) })
          facetSize.set_size(size, 2, domain.index_from_surface_patch_index(patch));
    }

  namespace p = CGAL::parameters;
  Criteria criteria(p::edge_size = edgeSize, p::facet_angle = this->FacetAngle, p::facet_size = facetSize,
    p::facet_distance = this->FacetDistance, p::cell_radius_edge_ratio = this->CellRadiusEdgeRatio,
    p::cell_size = cellSize);
  C3t3 c3t3;
  try
  {
    {
      // Every connected component of every label gets initial points, shot from a voxel inside
      // it to its boundary: from Mesh_3's default start (random points on the domain) a small
      // region can be missed entirely. The shots' directions come from CGAL's default random
      // numbers, seeded here so that the same input gives the same mesh; the search's report on
      // std::cout is not passed on.
      CGAL::get_default_random() = CGAL::Random(0);
      std::streambuf* const out = std::cout.rdbuf(nullptr);
      struct Restore
      {
        std::streambuf* Out;
        ~Restore()
        {
          std::cout.rdbuf(this->Out);
          std::cout.clear();
        }
      } restore{ out };
      if (wide)
        initialize_triangulation_from_labeled_image(
          c3t3, domain, image, criteria, static_cast<unsigned short>(0), this->ProtectJunctions != 0);
      else
        initialize_triangulation_from_labeled_image(
          c3t3, domain, image, criteria, static_cast<unsigned char>(0), this->ProtectJunctions != 0);
    }
    // (The protecting balls of the junction curves stay: no reset of the triangulation.)
    CGAL::refine_mesh_3(c3t3, domain, criteria, p::no_perturb(), p::no_exude(), p::no_reset_c3t3());
    this->UpdateProgress(0.6);
    if (this->Odt)
      CGAL::odt_optimize_mesh_3(c3t3, domain, p::time_limit = 0, p::max_iteration_number = 20);
    if (this->Lloyd)
      CGAL::lloyd_optimize_mesh_3(c3t3, domain, p::time_limit = 0, p::max_iteration_number = 20);
    this->UpdateProgress(0.75);
    if (this->Perturb)
      CGAL::perturb_mesh_3(c3t3, domain, p::time_limit = 0, p::sliver_bound = this->SliverBound);
    this->UpdateProgress(0.85);
    if (this->Exude)
      CGAL::exude_mesh_3(c3t3, p::time_limit = 0, p::sliver_bound = this->SliverBound);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("CGAL Mesh_3 failed: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.9);
  if (c3t3.number_of_cells_in_complex() == 0)
  {
    vtkErrorMacro("CGAL Mesh_3 produced no tetrahedra (are the regions thinner than the sizes asked for?"
      << (this->ProtectJunctions ? " With ProtectJunctions, specks of a few stray voxels can also stop it: remove "
                                   "small components first, e.g. MorphologyCleaning's MinimumComponentVolume, or "
                                   "turn ProtectJunctions off."
                                 : "")
      << ")");
    return 0;
  }

  // Output: the vertices of the complex's cells, in the world frame.
  const Tr& tr = c3t3.triangulation();
  auto world = [&](Tr::Vertex_handle v) {
    const Point p = tr.geom_traits().construct_point_3_object()(tr.point(v));
    const double local[3] = { p.x() - spacing[0], p.y() - spacing[1], p.z() - spacing[2] }; // (the padding)
    std::array<double, 3> x;
    for (int r = 0; r < 3; ++r)
      x[r] =
        origin[r] + direction[3 * r] * local[0] + direction[3 * r + 1] * local[1] + direction[3 * r + 2] * local[2];
    return x;
  };
  std::map<Tr::Vertex_handle, vtkIdType> pointId;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto id = [&](Tr::Vertex_handle v) {
    auto it = pointId.find(v);
    if (it != pointId.end())
      return it->second;
    const auto x = world(v);
    const vtkIdType n = points->InsertNextPoint(x.data());
    pointId.emplace(v, n);
    return n;
  };
  auto signedVolume = [&](const vtkIdType ids[4]) {
    double p[4][3];
    for (int k = 0; k < 4; ++k)
      points->GetPoint(ids[k], p[k]);
    return amTetraGeometry::SignedVolume(p[0], p[1], p[2], p[3]);
  };

  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIntArray> region;
  region->SetName("Region");
  std::map<Tr::Cell_handle, vtkIdType> cellId;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
      ids[k] = id(c->vertex(k));
    if (signedVolume(ids) < 0)
      std::swap(ids[2], ids[3]);
    cellId.emplace(c, cells->InsertNextCell(4, ids));
    region->InsertNextValue(toLabel(c3t3.subdomain_index(c)));
  }
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetCellData()->AddArray(region);

  // Port 1: every facet of the complex (interfaces and boundary) once, higher label first.
  vtkNew<vtkCellArray> faces;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> adjacent;
  adjacent->SetName("Tetra");
  adjacent->SetNumberOfComponents(2);
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
  {
    Tr::Cell_handle c = f->first;
    int i = f->second;
    if (tr.is_infinite(c)) // look from the finite side (the apex below must be a real point)
    {
      const Tr::Facet mirror = tr.mirror_facet(*f);
      c = mirror.first;
      i = mirror.second;
    }
    Tr::Cell_handle m = c->neighbor(i);
    const int li = c3t3.is_in_complex(c) ? toLabel(c3t3.subdomain_index(c)) : bg;
    const int lm = c3t3.is_in_complex(m) ? toLabel(c3t3.subdomain_index(m)) : bg;
    if (li == lm)
      continue;
    // Labels[0]: the higher label, the background always second (as amLabelSurface).
    const bool cFirst = (li != bg && (lm == bg || li > lm));
    vtkIdType tri[3];
    for (int k = 0, n = 0; k < 4; ++k)
      if (k != i)
        tri[n++] = id(c->vertex(k));
    // Normal from the Labels[0] side into the other: away from c's vertex i when c is first.
    double p[4][3];
    for (int k = 0; k < 3; ++k)
      points->GetPoint(tri[k], p[k]);
    const auto apex = world(c->vertex(i));
    std::copy(apex.begin(), apex.end(), p[3]);
    const double side =
      amTetraGeometry::SignedVolume(p[0], p[1], p[2], p[3]); // > 0: the normal (b-a)x(c-a) points towards the apex
    if ((side > 0) == cFirst)
      std::swap(tri[1], tri[2]);
    faces->InsertNextCell(3, tri);
    const int pair[2] = { cFirst ? li : lm, cFirst ? lm : li };
    labels->InsertNextTypedTuple(pair);
    const int cId = c3t3.is_in_complex(c) ? static_cast<int>(cellId[c]) : -1;
    const int mId = c3t3.is_in_complex(m) ? static_cast<int>(cellId[m]) : -1;
    const int tets[2] = { cFirst ? cId : mId, cFirst ? mId : cId };
    adjacent->InsertNextTypedTuple(tets);
  }
  interfaces->SetPoints(points);
  interfaces->SetPolys(faces);
  interfaces->GetCellData()->AddArray(labels);
  interfaces->GetCellData()->AddArray(adjacent);

  std::ostringstream improvement;
  this->NumberOfSlivers = 0;
  this->SurfaceDeviation = 0;
  this->VolumeDisplacement = 0;
  std::map<int, double> voxelVolumes; // label -> mm^3: the correction's targets and the report's reference
  for (const auto& lv : voxelsOf)
    if (lv.first != bg)
      voxelVolumes[lv.first] = lv.second * spacing[0] * spacing[1] * spacing[2];
  const bool improve = this->ImproveQuality && this->ImprovementPasses > 0;
  if (improve || this->PreserveVolumes)
  {
    amTetraMeshOptimizer::Options options;
    options.Passes = improve ? this->ImprovementPasses : 0;
    options.MaximumSurfaceDeviation = improve ? this->MaximumSurfaceDeviation : 0;
    if (this->PreserveVolumes)
    {
      options.TargetVolumes = voxelVolumes;
      // The voxels' staircase lies up to half a voxel from any smooth surface through them: the
      // surface may move that far, or FacetDistance where that is more.
      options.MaximumVolumeOffset =
        std::max(this->FacetDistance, 0.5 * std::max({ spacing[0], spacing[1], spacing[2] }));
    }
    amTetraMeshOptimizer::Report report;
    std::string why;
    if (!amTetraMeshOptimizer::ImproveGrid(
          output, interfaces, options, report, why, [this](double f) { this->UpdateProgress(0.92 + 0.08 * f); }))
    {
      vtkErrorMacro("Quality improvement: " << why);
      return 0;
    }
    improvement << " improvement: " << report.Describe();
    this->NumberOfSlivers = report.Slivers;
    this->SurfaceDeviation = report.SurfaceDeviation;
    this->VolumeDisplacement = report.VolumeDisplacement;
  }

  // Each region's volume against its voxels (as amTetrahedralize reports it).
  {
    vtkNew<vtkDoubleArray> voxels;
    voxels->SetNumberOfComponents(2);
    for (const auto& lv : voxelVolumes)
    {
      const double row[2] = { static_cast<double>(lv.first), lv.second };
      voxels->InsertNextTuple(row);
    }
    const auto misses = amRegionVolumes::Compare(output, "Region", voxels, 1000.0, 0.02);
    this->NumberOfVolumeMisses = static_cast<vtkIdType>(misses.size());
    if (!misses.empty())
      vtkWarningMacro(<< amRegionVolumes::Warning(misses));
  }

  this->NumberOfTetrahedra = output->GetNumberOfCells();
  // Every point in a tetrahedron, and the element bars checked whatever the parameters.
  const std::string barWarning = amQualityBars::Finish(output, interfaces, this->NumberOfSlivers,
    "Smaller FacetSize, FacetDistance or CellSize, or a larger MaximumSurfaceDeviation, frees them.");
  if (!barWarning.empty())
    vtkWarningMacro(<< barWarning);
  std::ostringstream params;
  params << "FacetDistance=" << this->FacetDistance << " FacetSize=" << this->FacetSize
         << " FacetAngle=" << this->FacetAngle << " CellSize=" << this->CellSize
         << " CellRadiusEdgeRatio=" << this->CellRadiusEdgeRatio << " ProtectJunctions=" << this->ProtectJunctions
         << " EdgeSize=" << edgeSize << " curves=" << curves << " Odt=" << this->Odt << " Lloyd=" << this->Lloyd
         << " Perturb=" << this->Perturb << " Exude=" << this->Exude << " SliverBound=" << this->SliverBound
         << " PreserveVolumes=" << this->PreserveVolumes << " ImproveQuality=" << this->ImproveQuality
         << " ImprovementPasses=" << this->ImprovementPasses
         << " MaximumSurfaceDeviation=" << this->MaximumSurfaceDeviation << " tetrahedra=" << this->NumberOfTetrahedra
         << improvement.str();
  for (std::size_t k = 0; k + 1 < this->RegionCellSizes.size(); k += 2)
    params << (k ? "," : " RegionCellSizes=") << this->RegionCellSizes[k] << "," << this->RegionCellSizes[k + 1];
  amProvenance::Record(output, input, "amLabelMapTetrahedralize", params.str());
  amProvenance::Record(interfaces, input, "amLabelMapTetrahedralize", params.str());
  this->UpdateProgress(1.0);
  return 1;
}

void amLabelMapTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BackgroundLabel: " << this->BackgroundLabel << "\n"
     << indent << "FacetDistance: " << this->FacetDistance << "\n"
     << indent << "FacetSize: " << this->FacetSize << "\n"
     << indent << "FacetAngle: " << this->FacetAngle << "\n"
     << indent << "CellSize: " << this->CellSize << "\n"
     << indent << "CellRadiusEdgeRatio: " << this->CellRadiusEdgeRatio << "\n"
     << indent << "RegionCellSizes: " << this->RegionCellSizes.size() / 2 << " region(s)\n"
     << indent << "ProtectJunctions: " << this->ProtectJunctions << "\n"
     << indent << "EdgeSize: " << this->EdgeSize << "\n"
     << indent << "Odt: " << this->Odt << " Lloyd: " << this->Lloyd << " Perturb: " << this->Perturb
     << " Exude: " << this->Exude << "\n"
     << indent << "SliverBound: " << this->SliverBound << "\n"
     << indent << "PreserveVolumes: " << this->PreserveVolumes << "\n"
     << indent << "ImproveQuality: " << this->ImproveQuality << " ImprovementPasses: " << this->ImprovementPasses
     << " MaximumSurfaceDeviation: " << this->MaximumSurfaceDeviation << "\n";
}
