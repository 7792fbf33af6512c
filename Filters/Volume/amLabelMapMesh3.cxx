#include "amLabelMapMesh3.h"

#include "amTetraGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
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
#include <limits>
#include <map>
#include <sstream>
#include <vector>

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

namespace
{
// The labels as CGAL meshes them: 0 the background, the others 1..K in increasing order.
struct Compact
{
  std::vector<int> LabelOf;       // compact index -> own label
  std::map<int, int> CompactOf;   // own label -> compact index
  std::map<int, vtkIdType> Count; // compact index -> voxel count
  bool Wide = false;              // 16-bit (more than 255 labels)
};

// The compact image, padded by one voxel of background all round: CGAL's image domain ends at
// the centres of the outermost voxels, which would cut the labels on the border in half (a
// one-voxel label there vanished).
bool MakeImage(vtkDataArray* scalars, const amLabelMapMesh3::Grid& grid, const std::map<int, vtkIdType>& voxelsOf,
  int bg, Compact& c, _image*& raw, std::string& why)
{
  const int* dims = grid.Dims;
  const double* spacing = grid.Spacing;
  const vtkIdType nv = scalars->GetNumberOfTuples();
  std::vector<int>& labelOf = c.LabelOf;
  std::map<int, int>& compactOf = c.CompactOf;
  labelOf.assign(1, bg);
  compactOf = { { bg, 0 } };
  for (const auto& lv : voxelsOf)
    if (lv.first != bg)
    {
      compactOf[lv.first] = static_cast<int>(labelOf.size());
      labelOf.push_back(lv.first);
    }
  const size_t nLabels = labelOf.size() - 1;
  if (nLabels > 65535)
  {
    std::ostringstream message;
    message << "The label map holds " << nLabels << " labels; this backend meshes at most 65535.";
    why = message.str();
    return false;
  }
  const bool wide = c.Wide = nLabels > 255;
  // One voxel of background all round: CGAL's image domain ends at the centres of the outermost
  // voxels, which would cut the labels on the border in half (a one-voxel label there vanished).
  const int padded[3] = { dims[0] + 2, dims[1] + 2, dims[2] + 2 };
  raw = ::_createImage(
    padded[0], padded[1], padded[2], 1, spacing[0], spacing[1], spacing[2], wide ? 2 : 1, WK_FIXED, SGN_UNSIGNED);
  if (!raw)
  {
    std::ostringstream message;
    message << "Could not allocate the CGAL image (" << nv << " voxels).";
    why = message.str();
    return false;
  }
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
  for (const auto& lv : voxelsOf)
    c.Count[compactOf[lv.first]] = lv.second;

  return true;
}

// Per-region sizes: cells by subdomain, facets by the pair of subdomains they separate.
bool RegionSizes(const amLabelMapMesh3::Settings& s, const Compact& c, Domain& domain, SizeField& cellSize,
  SizeField& facetSize, amLabelMapMesh3::Result& result, std::string& why)
{
  const int bg = s.Background;
  std::map<int, double> regionSize; // CGAL subdomain index -> cell size
  for (std::size_t k = 0; k + 1 < s.RegionCellSizes.size(); k += 2)
  {
    const double value = s.RegionCellSizes[k], size = s.RegionCellSizes[k + 1];
    if (!(std::fabs(value) < 2.0e9 && value == std::floor(value)) || static_cast<int>(value) == bg)
    {
      std::ostringstream message;
      message << "RegionCellSizes names the label " << value << ", which is not a meshed label (a whole number, "
              << "not the background " << bg << ").";
      why = message.str();
      return false;
    }
    if (!(size > 0) || !std::isfinite(size))
    {
      std::ostringstream message;
      message << "RegionCellSizes gives label " << value << " the size " << size << ": sizes must be > 0 mm.";
      why = message.str();
      return false;
    }
    const auto found = c.CompactOf.find(static_cast<int>(value));
    if (found == c.CompactOf.end())
    {
      std::ostringstream message;
      message << "RegionCellSizes names label " << value << ", which is not in the label map.";
      result.Warnings.push_back(message.str());
      continue;
    }
    const int subdomain = found->second;
    regionSize[subdomain] = size;
  }
  for (const auto& rs : regionSize)
    cellSize.set_size(rs.second, 3, domain.index_from_subdomain_index(rs.first));
  for (const auto& a : c.Count)
    for (const auto& b : c.Count)
    {
      if (a.first >= b.first)
        continue;
      double size = s.FacetSize;
      for (int sub : { a.first, b.first })
        if (regionSize.count(sub))
          size = std::min(size, regionSize[sub] * s.FacetSize / s.CellSize);
      if (size < s.FacetSize)
        for (const auto& patch : { std::make_pair(a.first, b.first), std::make_pair(b.first, a.first) })
          facetSize.set_size(size, 2, domain.index_from_surface_patch_index(patch));
    }

  return true;
}

// Mesh_3's refinement from initial points in every component, then the optimisers asked for.
bool Refine(C3t3& c3t3, Domain& domain, const CGAL::Image_3& image, bool wide, const SizeField& cellSize,
  const SizeField& facetSize, double edgeSize, const amLabelMapMesh3::Settings& s,
  const std::function<void(double)>& progress, std::string& why)
{
  namespace p = CGAL::parameters;
  Criteria criteria(p::edge_size = edgeSize, p::facet_angle = s.FacetAngle, p::facet_size = facetSize,
    p::facet_distance = s.FacetDistance, p::cell_radius_edge_ratio = s.CellRadiusEdgeRatio, p::cell_size = cellSize);
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
          c3t3, domain, image, criteria, static_cast<unsigned short>(0), s.ProtectJunctions != 0);
      else
        initialize_triangulation_from_labeled_image(
          c3t3, domain, image, criteria, static_cast<unsigned char>(0), s.ProtectJunctions != 0);
    }
    // (The protecting balls of the junction curves stay: no reset of the triangulation.)
    CGAL::refine_mesh_3(c3t3, domain, criteria, p::no_perturb(), p::no_exude(), p::no_reset_c3t3());
    progress(0.6);
    if (s.Odt)
      CGAL::odt_optimize_mesh_3(c3t3, domain, p::time_limit = 0, p::max_iteration_number = 20);
    if (s.Lloyd)
      CGAL::lloyd_optimize_mesh_3(c3t3, domain, p::time_limit = 0, p::max_iteration_number = 20);
    progress(0.75);
    if (s.Perturb)
      CGAL::perturb_mesh_3(c3t3, domain, p::time_limit = 0, p::sliver_bound = s.SliverBound);
    progress(0.85);
    if (s.Exude)
      CGAL::exude_mesh_3(c3t3, p::time_limit = 0, p::sliver_bound = s.SliverBound);
  }
  catch (const std::exception& e)
  {
    std::ostringstream message;
    message << "CGAL Mesh_3 failed: " << e.what();
    why = message.str();
    return false;
  }
  if (c3t3.number_of_cells_in_complex() == 0)
  {
    std::ostringstream message;
    message << "CGAL Mesh_3 produced no tetrahedra (are the regions thinner than the sizes asked for?"
            << (s.ProtectJunctions ? " With ProtectJunctions, specks of a few stray voxels can also stop it: remove "
                                     "small components first, e.g. MorphologyCleaning's MinimumComponentVolume, or "
                                     "turn ProtectJunctions off."
                                   : "")
            << ")";
    why = message.str();
    return false;
  }

  return true;
}

// The complex's cells as tetrahedra in the world frame, and every facet of it once.
void Output(const C3t3& c3t3, const amLabelMapMesh3::Grid& grid, const Compact& compact, int bg,
  vtkUnstructuredGrid* output, vtkPolyData* interfaces)
{
  const double* spacing = grid.Spacing;
  const double* origin = grid.Origin;
  const double* direction = grid.Direction;
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
    region->InsertNextValue(compact.LabelOf.at(c3t3.subdomain_index(c)));
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
    const int li = c3t3.is_in_complex(c) ? compact.LabelOf.at(c3t3.subdomain_index(c)) : bg;
    const int lm = c3t3.is_in_complex(m) ? compact.LabelOf.at(c3t3.subdomain_index(m)) : bg;
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
}
}

bool amLabelMapMesh3::Mesh(vtkDataArray* scalars, const Grid& grid, const std::map<int, vtkIdType>& voxelsOf,
  const Settings& s, vtkUnstructuredGrid* output, vtkPolyData* interfaces, Result& result, std::string& why)
{
  result = Result();
  const auto progress = [&s](double f) {
    if (s.Progress)
      s.Progress(f);
  };
  Compact c;
  _image* raw = nullptr;
  if (!MakeImage(scalars, grid, voxelsOf, s.Background, c, raw, why))
    return false;
  CGAL::Image_3 image(raw);
  const bool wide = c.Wide;
  progress(0.05);
  CGAL::Random rng(0);
  Domain domain = Domain::create_labeled_image_mesh_domain(image, CGAL::parameters::relative_error_bound = 1e-6,
    CGAL::parameters::value_outside = 0, CGAL::parameters::p_rng = &rng);
  const double edgeSize = s.EdgeSize > 0 ? s.EdgeSize : s.FacetSize;
  std::size_t curves = 0;
  if (s.ProtectJunctions)
  {
    std::vector<std::vector<Point>> polylines;
    if (wide)
      CGAL::polylines_to_protect<Point, unsigned short>(image, polylines);
    else
      CGAL::polylines_to_protect<Point, unsigned char>(image, polylines);
    curves = polylines.size();
    domain.add_features(polylines.begin(), polylines.end());
  }
  progress(0.1);

  SizeField cellSize(s.CellSize), facetSize(s.FacetSize);
  if (!RegionSizes(s, c, domain, cellSize, facetSize, result, why))
    return false;
  C3t3 c3t3;
  if (!Refine(c3t3, domain, image, wide, cellSize, facetSize, edgeSize, s, progress, why))
    return false;
  progress(0.9);
  Output(c3t3, grid, c, s.Background, output, interfaces);
  result.Curves = curves;
  result.EdgeSize = edgeSize;
  return true;
}
