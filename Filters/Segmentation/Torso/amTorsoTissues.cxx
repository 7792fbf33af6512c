// Tissue labels of the torso from the intensity classes: exterior, body, fat, lungs, bone.
#include "amTorsoLabels.h"

#include <algorithm>
#include <numeric>

namespace
{
// The air components (id) open to the sides of the first two axes: through a piece of a side at
// least minimumArea (mm^2) across. The air round the body meets a side over a wide patch; the
// lumens of the bronchi, where a field cuts the lungs, meet it in small ones, and the outside
// does not enter the airways through them.
std::vector<char> OpenToTheSides(const amVoxelGrid& g, const std::vector<int>& id, int count, double minimumArea)
{
  std::vector<char> open(count, 0);
  std::vector<char> in;
  std::vector<int> piece;
  for (int a = 0; a < 2; ++a)
    for (const int at : { 0, g.N[a] - 1 })
    {
      // The side across axis a at index at: its pixels run along the other first axis, then k.
      const int b = 1 - a, width = g.N[b];
      in.assign(static_cast<std::size_t>(width) * g.N[2], 0);
      std::vector<std::size_t> voxel(in.size());
      for (int k = 0; k < g.N[2]; ++k)
        for (int u = 0; u < width; ++u)
        {
          const std::size_t p = static_cast<std::size_t>(k) * width + u;
          voxel[p] = a == 0 ? g.Index(at, u, k) : g.Index(u, at, k);
          in[p] = id[voxel[p]] >= 0;
        }
      const int pieces = amVoxel::SlicePieces(in, width, piece);
      std::vector<std::size_t> area(pieces, 0);
      for (const int q : piece)
        if (q >= 0)
          ++area[q];
      const double pixel = g.Spacing[b] * g.Spacing[2];
      for (std::size_t p = 0; p < in.size(); ++p)
        if (piece[p] >= 0 && area[piece[p]] * pixel >= minimumArea)
          open[id[voxel[p]]] = 1;
    }
  return open;
}

// The air outside the body, and the patient table (which the outside air passes).
amVoxelMask Exterior(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, const amVoxelMask& table,
  double gap, double minimumOpening)
{
  amVoxelMask air(classes.size());
  for (std::size_t v = 0; v < classes.size(); ++v)
    air[v] = classes[v] == amTorso::AirClass || table[v];
  std::vector<float> fromBody;
  if (gap > 0.0)
  {
    // Air farther than the gap from the body: a body wall with holes narrower than twice the gap
    // (a thin wall whose fat reads as air) does not let the outside in.
    amVoxelMask body(classes.size());
    for (std::size_t v = 0; v < classes.size(); ++v)
      body[v] = !air[v];
    fromBody = amVoxel::DistanceWithin(g, body, gap);
    for (std::size_t v = 0; v < classes.size(); ++v)
      air[v] = air[v] && fromBody[v] > gap;
  }
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int n = amVoxel::Components(g, air, id, sizes);
  // Open to the sides of the first two axes; not the ends of the third, where a trachea may leave
  // the field of view.
  const std::vector<char> open = OpenToTheSides(g, id, n, minimumOpening);
  amVoxelMask exterior(classes.size(), 0);
  for (std::size_t v = 0; v < classes.size(); ++v)
    exterior[v] = id[v] >= 0 && open[id[v]];
  if (gap > 0.0)
  {
    // Back to the body's surface: the air within the gap of the outside air is outside too.
    const std::vector<float> fromOutside = amVoxel::DistanceWithin(g, exterior, gap);
    for (std::size_t v = 0; v < classes.size(); ++v)
      exterior[v] = (classes[v] == amTorso::AirClass || table[v]) && fromOutside[v] <= gap;
  }
  for (std::size_t v = 0; v < classes.size(); ++v)
    exterior[v] = exterior[v] || table[v];
  return exterior;
}

double WorldX(const amVoxelGrid& g, std::size_t v, const double row[4])
{
  int c[3];
  g.Ijk(v, c);
  return row[0] * c[0] + row[1] * c[1] + row[2] * c[2] + row[3];
}

// Components of the mask ordered by decreasing size (ties: first voxel first).
std::vector<int> BySize(const std::vector<std::size_t>& sizes)
{
  std::vector<int> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sizes[a] > sizes[b]; });
  return order;
}
// The air components that may be lungs, largest first. The lungs are thick: components are ranked
// by their voxels at least two voxels deep in the air (a thin layer of air, between an arm and the
// chest, or a skin fold, has none). Aerated lung is darker than soft tissue but brighter than gas:
// with gasIsNotLung, a component mostly of the air class is gas (the stomach, the bowel), whatever
// its size, and not lung.
std::vector<int> LungCandidates(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes,
  const amVoxelMask& lungs, const std::vector<int>& id, const std::vector<std::size_t>& sizes, bool gasIsNotLung)
{
  const std::size_t n = lungs.size();
  const std::vector<float> depth = amVoxel::Depth(g, lungs);
  const double thick = 2.0 * std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  std::vector<std::size_t> deep(sizes.size(), 0), parenchyma(sizes.size(), 0);
  for (std::size_t v = 0; v < n; ++v)
    if (id[v] >= 0)
    {
      deep[id[v]] += depth[v] >= thick;
      parenchyma[id[v]] += classes[v] == amTorso::LungClass;
    }
  std::vector<int> order = BySize(deep);
  order.erase(std::remove_if(order.begin(), order.end(),
                [&](int c) { return deep[c] == 0 || (gasIsNotLung && 2 * parenchyma[c] < sizes[c]); }),
    order.end());
  return order;
}

// Bone: the bone class (or, where the window clips bone, ClippedBone), never contrast blood of
// the seeded pools' vessels, its partial volume (brighter than BonePartialLevel within two voxels of
// it), and the trabecular bone it encloses (darker, among soft tissue and contrast blood in
// intensity, but inside a cortical ring in a slice; the spinal canal's fluid and cord and the
// marrow's fat are darker than TrabecularLevel and stay out).
amVoxelMask BoneMask(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, const amVoxelMask& exterior,
  const amTorso::TissueParameters& p)
{
  const std::size_t n = classes.size();
  const amVoxelMask nearVessels = p.Vessels ? amVoxel::Dilate26(g, *p.Vessels, 2) : amVoxelMask(n, 0);
  amVoxelMask mask(n);
  if (p.HU && p.BoneClipped)
    mask = amTorso::ClippedBone(g, classes, exterior, nearVessels, p);
  else
    for (std::size_t v = 0; v < n; ++v)
      mask[v] = classes[v] == amTorso::BoneClass && !exterior[v] && !nearVessels[v];
  if (!p.HU)
    return mask;
  if (p.BonePartialLevel < 1e30)
    for (int ring = 0; ring < 2; ++ring)
    {
      amVoxelMask grown = mask;
      for (std::size_t v = 0; v < n; ++v)
        if (!mask[v] && !exterior[v] && !nearVessels[v] && p.HU[v] > p.BonePartialLevel)
          g.AllNeighbours(v, [&](std::size_t w) { grown[v] = grown[v] || mask[w]; });
      mask.swap(grown);
    }
  // A ring in one slice may be open in another (a 3 mm slice's partial volume, a foramen): the
  // marrow is what a ring encloses in a slice across any of the three axes.
  amVoxelMask marrow(n, 0);
  for (int a = 0; a < 3; ++a)
  {
    const double pixel = g.Spacing[(a + 1) % 3] * g.Spacing[(a + 2) % 3];
    const amVoxelMask holes = amVoxel::SliceHoles(g, mask, a, static_cast<std::size_t>(p.MaximumMarrowArea / pixel));
    for (std::size_t v = 0; v < n; ++v)
      marrow[v] = marrow[v] || holes[v];
  }
  for (std::size_t v = 0; v < n; ++v)
    if (marrow[v] && !exterior[v] && !(p.Vessels && (*p.Vessels)[v]) && p.HU[v] > p.TrabecularLevel)
      mask[v] = 1;
  return mask;
}
}

amTorso::TissueReport amTorso::Tissues(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes,
  const double worldX[4], const TissueParameters& p, std::vector<std::uint8_t>& labels)
{
  const std::size_t minimumVoxels = p.MinimumVoxels;
  TissueReport report;
  const std::size_t n = classes.size();
  const amVoxelMask table =
    p.FindTable ? amTorso::PatientTable(g, classes, p.SuperiorAxis, amTorso::TableParameters()) : amVoxelMask(n, 0);
  for (const auto t : table)
    report.TableVoxels += t != 0;
  const amVoxelMask exterior = Exterior(g, classes, table, p.BodyGap, p.MinimumOpening);
  labels.assign(n, Phantom::SoftTissue);
  double bodyX = 0.0;
  for (std::size_t v = 0; v < n; ++v)
    if (exterior[v])
    {
      labels[v] = Phantom::Background;
      ++report.ExteriorVoxels;
    }
    else
      bodyX += WorldX(g, v, worldX);
  if (report.ExteriorVoxels < n)
    bodyX /= static_cast<double>(n - report.ExteriorVoxels);

  // Fat, without the one-voxel sheets that partial volume leaves between lung and soft tissue.
  amVoxelMask mask(n);
  for (std::size_t v = 0; v < n; ++v)
    mask[v] = classes[v] == FatClass && !exterior[v];
  const amVoxelMask fat = amVoxel::Open6(g, mask);
  for (std::size_t v = 0; v < n; ++v)
    if (mask[v])
    {
      labels[v] = fat[v] ? Phantom::Fat : amVoxel::Pending;
      report.FatPartialVolume += !fat[v];
    }

  // Lungs: the air inside the body.
  for (std::size_t v = 0; v < n; ++v)
    mask[v] = (classes[v] == LungClass || classes[v] == AirClass) && !exterior[v];
  amVoxelMask lungs = mask;
  if (p.LungOpening > 0.0)
  {
    // Opening by a ball: the lungs are thick, the fat that reads as air beside them (below a
    // window that starts above fat) is a layer a few mm thick.
    const std::vector<float> depth = amVoxel::Depth(g, mask);
    amVoxelMask core(n);
    for (std::size_t v = 0; v < n; ++v)
      core[v] = depth[v] > p.LungOpening;
    const std::vector<float> fromCore = amVoxel::DistanceWithin(g, core, p.LungOpening);
    for (std::size_t v = 0; v < n; ++v)
      lungs[v] = mask[v] && fromCore[v] <= p.LungOpening;
  }
  const amVoxelMask gas = amTorso::GasBelowLungs(g, lungs, p.SuperiorAxis, p.SuperiorSign);
  for (std::size_t v = 0; v < n; ++v)
    if (gas[v])
    {
      lungs[v] = 0;
      ++report.GasBelowLungs;
    }
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  amVoxel::Components(g, lungs, id, sizes);
  const std::vector<int> order = LungCandidates(g, classes, lungs, id, sizes, p.GasIsNotLung);
  for (const int c : order)
    report.LungComponents += sizes[c] >= minimumVoxels;
  const int first = order.empty() || sizes[order[0]] < minimumVoxels ? -1 : order[0];
  // A second lung is a component of at least a tenth of the first (else the lungs are joined).
  const int second =
    order.size() < 2 || sizes[order[1]] < std::max(minimumVoxels, sizes[order[0]] / 10) ? -1 : order[1];
  std::vector<double> centre(sizes.size(), 0.0);
  for (std::size_t v = 0; v < n; ++v)
    if (id[v] >= 0)
      centre[id[v]] += WorldX(g, v, worldX);
  for (std::size_t c = 0; c < sizes.size(); ++c)
    centre[c] /= static_cast<double>(sizes[c]);
  report.LungsSplit = first >= 0 && second < 0;
  const bool firstIsLeft = second >= 0 && centre[first] > centre[second];
  // One component holding both lungs is parted where they meet; the part whose centre lies
  // further to the patient's left (world x) is the left lung.
  std::vector<std::uint8_t> side;
  bool sideOneIsLeft = false;
  if (report.LungsSplit)
  {
    amVoxelMask joined(n);
    for (std::size_t v = 0; v < n; ++v)
      joined[v] = id[v] == first;
    report.LungsSplitAtMidPlane = !amTorso::SplitJoinedLungs(g, joined, minimumVoxels, side);
    if (!report.LungsSplitAtMidPlane)
    {
      double x[3] = { 0, 0, 0 }, count[3] = { 0, 0, 0 };
      for (std::size_t v = 0; v < n; ++v)
        if (side[v])
        {
          x[side[v]] += WorldX(g, v, worldX);
          ++count[side[v]];
        }
      sideOneIsLeft = x[1] / count[1] > x[2] / count[2];
    }
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    const int c = id[v];
    if (c < 0)
    {
      if (mask[v])
        labels[v] = p.LeftoverAirIsFat ? Phantom::Fat : amVoxel::Pending;
      continue;
    }
    if (c == first && second < 0 && !report.LungsSplitAtMidPlane)
      labels[v] = (side[v] == 1) == sideOneIsLeft ? Phantom::LeftLung : Phantom::RightLung;
    else if (c == first && second < 0)
      labels[v] = WorldX(g, v, worldX) > bodyX ? Phantom::LeftLung : Phantom::RightLung;
    else if (c == first)
      labels[v] = firstIsLeft ? Phantom::LeftLung : Phantom::RightLung;
    else if (c == second)
      labels[v] = firstIsLeft ? Phantom::RightLung : Phantom::LeftLung;
    else
      labels[v] = p.LeftoverAirIsFat ? Phantom::Fat : amVoxel::Pending;
  }

  // Bone: the vertebral column within the largest piece (ribs joined to it at their joints parted
  // from it), the rest ribs.
  mask = BoneMask(g, classes, exterior, p);
  amVoxel::Components(g, mask, id, sizes);
  const std::vector<int> bones = BySize(sizes);
  for (const int c : bones)
    report.BoneComponents += sizes[c] >= minimumVoxels;
  amVoxelMask column;
  if (!bones.empty())
  {
    for (std::size_t v = 0; v < n; ++v)
      mask[v] = id[v] == bones[0];
    ColumnParameters cp;
    cp.Midline = bodyX;
    column = amTorso::VertebralColumn(g, mask, worldX, p.SuperiorAxis, cp);
  }
  for (std::size_t v = 0; v < n; ++v)
  {
    const int c = id[v];
    if (c < 0)
      continue;
    if (sizes[c] < minimumVoxels)
      labels[v] = amVoxel::Pending;
    else
      labels[v] = column[v] ? Phantom::Spine : Phantom::Ribs;
    report.RibsJoinedToSpine += c == bones[0] && !column[v];
  }
  return report;
}
