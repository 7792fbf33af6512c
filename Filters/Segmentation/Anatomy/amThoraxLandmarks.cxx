// The heart's axis, apex and base, the stimulus site and the 12-lead electrodes, from the labels.
#include "amThoraxLandmarks.h"

#include "../Torso/amVoxelGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using Vec = std::array<double, 3>;

constexpr std::uint8_t Outside = 0, RightLung = 3, LeftLung = 4, Myocardium = 5, LeftVentricle = 6, Aorta = 8,
                       Spine = 9, Ribs = 10, Atria = 11;
constexpr double IntercostalSpace = 25.0; // mm, one rib space
constexpr double SternalBorder = 25.0;    // mm from the mid-line
constexpr double ArmNeck = 10.0;          // mm: an arm's depth (about 40) above its contact with the trunk

double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

// The eigenvector of the largest eigenvalue of a symmetric 3x3 matrix (power iteration from a
// start no principal axis is orthogonal to in practice).
Vec PrincipalAxis(const double c[3][3])
{
  Vec v{ 0.577, -0.577, -0.577 };
  for (int it = 0; it < 200; ++it)
  {
    Vec w{ c[0][0] * v[0] + c[0][1] * v[1] + c[0][2] * v[2], c[1][0] * v[0] + c[1][1] * v[1] + c[1][2] * v[2],
      c[2][0] * v[0] + c[2][1] * v[1] + c[2][2] * v[2] };
    const double norm = std::sqrt(Dot(w, w));
    if (norm == 0.0)
      break;
    for (auto& x : w)
      x /= norm;
    v = w;
  }
  return v;
}

struct Voxels
{
  const amThoraxLandmarks::Grid& G;
  const std::vector<std::uint8_t>& L;
  Vec At(std::size_t v) const
  {
    const std::size_t i = v % G.N[0], j = (v / G.N[0]) % G.N[1], k = v / (static_cast<std::size_t>(G.N[0]) * G.N[1]);
    Vec x;
    for (int r = 0; r < 3; ++r)
      x[r] = G.Row[r][0] * i + G.Row[r][1] * j + G.Row[r][2] * k + G.Row[r][3];
    return x;
  }
  // The trunk: the body's part that holds the LV's pool, where the body is cut into the basins of
  // its depth (parts joined to the rest by a neck at least ArmNeck thinner than their own deepest
  // point). Arms in the field, apart from the trunk or lying against it, are body but carry no
  // chest electrode.
  std::vector<char> Trunk() const
  {
    amVoxelGrid g;
    for (int a = 0; a < 3; ++a)
    {
      g.N[a] = G.N[a];
      g.Spacing[a] = std::sqrt(G.Row[0][a] * G.Row[0][a] + G.Row[1][a] * G.Row[1][a] + G.Row[2][a] * G.Row[2][a]);
    }
    amVoxelMask body(L.size());
    for (std::size_t v = 0; v < L.size(); ++v)
      body[v] = L[v] != Outside;
    std::vector<int> basin;
    const int count = amVoxel::Basins(g, body, amVoxel::Depth(g, body), ArmNeck, basin);
    std::vector<std::size_t> pool(count, 0);
    for (std::size_t v = 0; v < L.size(); ++v)
      if (L[v] == LeftVentricle && basin[v] >= 0)
        ++pool[basin[v]];
    const int trunk = static_cast<int>(std::max_element(pool.begin(), pool.end()) - pool.begin());
    std::vector<char> inTrunk(L.size(), 0);
    for (std::size_t v = 0; v < L.size(); ++v)
      inTrunk[v] = count > 0 && basin[v] == trunk;
    return inTrunk;
  }
  // The trunk's voxels with a face neighbour outside it (outside the body, or an arm lying against
  // it; not the image's border: a cut field of view has no skin there).
  std::vector<Vec> Skin(const std::vector<char>& trunk) const
  {
    std::vector<Vec> skin;
    const std::size_t sx = 1, sy = G.N[0], sz = static_cast<std::size_t>(G.N[0]) * G.N[1];
    for (int k = 0; k < G.N[2]; ++k)
      for (int j = 0; j < G.N[1]; ++j)
        for (int i = 0; i < G.N[0]; ++i)
        {
          const std::size_t v = k * sz + j * sy + i * sx;
          if (!trunk[v])
            continue;
          const bool out = (i > 0 && !trunk[v - sx]) || (i + 1 < G.N[0] && !trunk[v + sx]) ||
            (j > 0 && !trunk[v - sy]) || (j + 1 < G.N[1] && !trunk[v + sy]) || (k > 0 && !trunk[v - sz]) ||
            (k + 1 < G.N[2] && !trunk[v + sz]);
          if (out)
            skin.push_back(this->At(v));
        }
    return skin;
  }
};

// The skin at one axial level: its points within half a slab of z.
struct Level
{
  std::vector<Vec> Skin;
  Vec Centre{};
  double Left = 0.0, Right = 0.0; // x extent
};

Level SkinLevel(const std::vector<Vec>& skin, double z, double slab)
{
  Level level;
  double lo = std::numeric_limits<double>::max();
  for (const auto& p : skin)
    lo = std::min(lo, std::fabs(p[2] - z));
  for (const auto& p : skin)
    if (std::fabs(p[2] - z) <= lo + slab)
      level.Skin.push_back(p);
  if (level.Skin.empty())
    return level;
  level.Left = -std::numeric_limits<double>::max();
  level.Right = std::numeric_limits<double>::max();
  for (const auto& p : level.Skin)
  {
    for (int a = 0; a < 3; ++a)
      level.Centre[a] += p[a] / level.Skin.size();
    level.Left = std::max(level.Left, p[0]);
    level.Right = std::min(level.Right, p[0]);
  }
  return level;
}

// The front of the skin at x: its most anterior point (least y) within tolerance of x, or of the
// nearest x the level has.
Vec Front(const Level& level, double x, double tolerance)
{
  double nearest = std::numeric_limits<double>::max();
  for (const auto& p : level.Skin)
    nearest = std::min(nearest, std::fabs(p[0] - x));
  const double reach = std::max(tolerance, nearest + 1e-9);
  Vec best = level.Centre;
  double bestY = std::numeric_limits<double>::max();
  for (const auto& p : level.Skin)
    if (std::fabs(p[0] - x) <= reach && p[1] < bestY)
    {
      best = p;
      bestY = p[1];
    }
  return best;
}

double Angle(const Level& level, const Vec& p)
{
  return std::atan2(p[1] - level.Centre[1], p[0] - level.Centre[0]);
}

// The skin at the angle about the level's centre (the outermost point there).
Vec AtAngle(const Level& level, double angle)
{
  Vec best = level.Centre;
  double bestScore = std::numeric_limits<double>::max();
  for (const auto& p : level.Skin)
  {
    double d = std::fabs(Angle(level, p) - angle);
    d = std::min(d, 2.0 * M_PI - d);
    const double r = std::hypot(p[0] - level.Centre[0], p[1] - level.Centre[1]);
    const double score = d - 1e-4 * r; // the angle first, then the farthest out
    if (score < bestScore)
    {
      bestScore = score;
      best = p;
    }
  }
  return best;
}

double HalfWay(double a, double b)
{
  // The mean of two angles along the shorter arc.
  double d = b - a;
  while (d > M_PI)
    d -= 2.0 * M_PI;
  while (d < -M_PI)
    d += 2.0 * M_PI;
  return a + 0.5 * d;
}
/// The LV's long axis from its base where its pool meets the atria or the aortic root (the centre
/// of the pool's voxels against them) to the pool's voxel farthest from there; false where fewer
/// than 8 voxels meet them (a heart without atria, as the phantom's).
bool AxisFromTheBase(const Voxels& voxels, Vec& axis)
{
  const auto& g = voxels.G;
  const auto& l = voxels.L;
  const std::size_t step[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  Vec base{};
  std::size_t count = 0;
  std::vector<Vec> pool;
  for (std::size_t v = 0; v < l.size(); ++v)
  {
    if (l[v] != LeftVentricle)
      continue;
    pool.push_back(voxels.At(v));
    const int c[3] = { static_cast<int>(v % g.N[0]), static_cast<int>((v / g.N[0]) % g.N[1]),
      static_cast<int>(v / step[2]) };
    bool touches = false;
    for (int a = 0; a < 3; ++a)
      for (const int d : { -1, 1 })
        if (c[a] + d >= 0 && c[a] + d < g.N[a])
        {
          const std::uint8_t n = l[d < 0 ? v - step[a] : v + step[a]];
          touches = touches || n == Aorta || n == Atria;
        }
    if (touches)
    {
      for (int a = 0; a < 3; ++a)
        base[a] += pool.back()[a];
      ++count;
    }
  }
  if (count < 8)
    return false;
  for (auto& x : base)
    x /= static_cast<double>(count);
  double far = 0.0;
  for (const Vec& p : pool)
  {
    const Vec d = Sub(p, base);
    const double length = std::sqrt(Dot(d, d));
    if (length > far)
    {
      far = length;
      for (int a = 0; a < 3; ++a)
        axis[a] = d[a] / length;
    }
  }
  return far > 0.0;
}

/// The LV pool's ends along the long axis: the endocardial apex and the valve plane's centre (the
/// pool within 5 mm of its basal end); and the epicardial apex, the wall beyond the endocardial
/// apex within 15 mm of the axis through it.
void Apexes(const std::vector<Vec>& pool, const std::vector<Vec>& wall, const Vec& centre, const Vec& axis, Vec& endo,
  Vec& base, Vec& epi)
{
  double top = -std::numeric_limits<double>::max(), bottom = std::numeric_limits<double>::max();
  endo = centre;
  for (const auto& p : pool)
  {
    const double s = Dot(Sub(p, centre), axis);
    if (s > top)
    {
      top = s;
      endo = p;
    }
    bottom = std::min(bottom, s);
  }
  base = Vec{};
  double count = 0.0;
  for (const auto& p : pool)
    if (Dot(Sub(p, centre), axis) <= bottom + 5.0)
    {
      for (int a = 0; a < 3; ++a)
        base[a] += p[a];
      ++count;
    }
  for (auto& x : base)
    x /= count;
  // The epicardial apex: the wall beyond the endocardial apex, within 15 mm of the axis through it.
  epi = endo;
  double farthest = 0.0;
  for (const auto& p : wall)
  {
    const Vec d = Sub(p, endo);
    const double s = Dot(d, axis);
    const double off = std::sqrt(std::max(0.0, Dot(d, d) - s * s));
    if (off <= 15.0 && s > farthest)
    {
      farthest = s;
      epi = p;
    }
  }
}
// The sternum at level z: the bone within half an intercostal space of z, in front of the heart
// (y below heartY), that spans the mid-line: of the bone within 30 mm of it, the run of occupied
// x (bins of a voxel) that holds the mid-line's bin, 10-60 mm wide. Its right and left borders
// (world x) and its centre; false where no bone spans the mid-line there (the phantom's ribs end
// short of it, and some scans do not reach that level).
struct Sternum
{
  double Right = 0.0, Left = 0.0;
  Vec Centre{};
};

bool SternumAt(const Voxels& voxels, double z, double midline, double heartY, double voxel, Sternum& sternum)
{
  constexpr double reach = 30.0;
  const int bins = static_cast<int>(std::ceil(2.0 * reach / voxel)) + 1;
  std::vector<std::vector<Vec>> column(bins);
  for (std::size_t v = 0; v < voxels.L.size(); ++v)
  {
    if (voxels.L[v] != Spine && voxels.L[v] != Ribs)
      continue;
    const Vec p = voxels.At(v);
    if (std::fabs(p[2] - z) > 0.5 * IntercostalSpace || p[1] >= heartY || std::fabs(p[0] - midline) > reach)
      continue;
    column[static_cast<int>(std::floor((p[0] - midline + reach) / voxel))].push_back(p);
  }
  const int middle = static_cast<int>(std::floor(reach / voxel));
  if (column[middle].empty())
    return false;
  int lo = middle, hi = middle;
  while (lo > 0 && !column[lo - 1].empty())
    --lo;
  while (hi + 1 < bins && !column[hi + 1].empty())
    ++hi;
  const double width = (hi - lo + 1) * voxel;
  if (width < 10.0 || width > 60.0)
    return false;
  sternum.Right = std::numeric_limits<double>::max();
  sternum.Left = -std::numeric_limits<double>::max();
  std::size_t count = 0;
  for (int b = lo; b <= hi; ++b)
    for (const Vec& p : column[b])
    {
      sternum.Right = std::min(sternum.Right, p[0]);
      sternum.Left = std::max(sternum.Left, p[0]);
      for (int a = 0; a < 3; ++a)
        sternum.Centre[a] += p[a];
      ++count;
    }
  for (int a = 0; a < 3; ++a)
    sternum.Centre[a] /= static_cast<double>(count);
  return true;
}
}

amThoraxLandmarks::Result amThoraxLandmarks::Find(const Grid& grid, const std::vector<std::uint8_t>& labels)
{
  Result r;
  const Voxels voxels{ grid, labels };
  const double voxel = std::max(
    { std::sqrt(grid.Row[0][0] * grid.Row[0][0] + grid.Row[1][0] * grid.Row[1][0] + grid.Row[2][0] * grid.Row[2][0]),
      std::sqrt(grid.Row[0][1] * grid.Row[0][1] + grid.Row[1][1] * grid.Row[1][1] + grid.Row[2][1] * grid.Row[2][1]),
      std::sqrt(grid.Row[0][2] * grid.Row[0][2] + grid.Row[1][2] * grid.Row[1][2] + grid.Row[2][2] * grid.Row[2][2]) });

  // The LV pool's centre and principal axis.
  std::vector<Vec> pool, wall;
  double lungTop = -std::numeric_limits<double>::max(), lungBottom = std::numeric_limits<double>::max();
  double bodyBottom = std::numeric_limits<double>::max();
  for (std::size_t v = 0; v < labels.size(); ++v)
  {
    const std::uint8_t l = labels[v];
    if (l == LeftVentricle)
      pool.push_back(voxels.At(v));
    else if (l == Myocardium)
      wall.push_back(voxels.At(v));
    else if (l == RightLung || l == LeftLung)
    {
      const double z = voxels.At(v)[2];
      lungTop = std::max(lungTop, z);
      lungBottom = std::min(lungBottom, z);
    }
  }
  if (pool.size() < 8)
  {
    r.Problem = "no left-ventricular blood pool (label 6) to find the heart's axis from";
    return r;
  }
  if (wall.empty())
  {
    r.Problem = "no myocardium (label 5) around the left ventricle: no epicardial apex";
    return r;
  }
  if (lungTop < lungBottom)
  {
    r.Problem = "no lungs (labels 3 and 4): no levels for the limb electrodes";
    return r;
  }
  // The ventricles' long axis: from the LV's base where its pool meets the atria or the aortic root,
  // else the principal axis of their mass (walls and pools), longer from base to apex than across.
  Vec centre{};
  const double mass = static_cast<double>(pool.size() + wall.size());
  for (const auto* part : { &pool, &wall })
    for (const auto& p : *part)
      for (int a = 0; a < 3; ++a)
        centre[a] += p[a] / mass;
  double cov[3][3] = {};
  for (const auto* part : { &pool, &wall })
    for (const auto& p : *part)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          cov[a][b] += (p[a] - centre[a]) * (p[b] - centre[b]) / mass;
  Vec axis = PrincipalAxis(cov);
  // Towards the patient's left, front and feet: LPS (+x, -y, -z).
  if (!AxisFromTheBase(voxels, axis) && axis[0] - axis[1] - axis[2] < 0.0)
    for (auto& x : axis)
      x = -x;
  r.LongAxis = axis;

  Vec endo, base, epi;
  Apexes(pool, wall, centre, axis, endo, base, epi);
  r.LongAxisLength = Dot(Sub(epi, base), axis);
  const Vec stimulus{ 0.5 * (endo[0] + epi[0]), 0.5 * (endo[1] + epi[1]), 0.5 * (endo[2] + epi[2]) };

  // The electrodes on the trunk's skin.
  const std::vector<char> trunk = voxels.Trunk();
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (trunk[v])
      bodyBottom = std::min(bodyBottom, voxels.At(v)[2]);
  const std::vector<Vec> skin = voxels.Skin(trunk);
  if (skin.empty())
  {
    r.Problem = "no skin: no body voxel beside the outside (a field of view inside the body)";
    return r;
  }
  // V4: straight forward (-y) from the epicardial apex.
  Vec v4 = epi;
  double bestOff = std::numeric_limits<double>::max();
  for (const auto& p : skin)
  {
    if (p[1] >= epi[1])
      continue;
    const double off = std::hypot(p[0] - epi[0], p[2] - epi[2]);
    if (off < bestOff - 1e-9 || (off < bestOff + 1e-9 && p[1] < v4[1]))
    {
      bestOff = off;
      v4 = p;
    }
  }
  if (bestOff > 2.0 * voxel + 10.0)
  {
    r.Problem = "the skin in front of the apex is not in the image (a field of view that cuts the chest)";
    return r;
  }
  const double slab = 0.5 * voxel;
  const Level fifth = SkinLevel(skin, v4[2], slab);
  const Level fourth = SkinLevel(skin, v4[2] + IntercostalSpace, slab);
  // V1 and V2 beside the sternum where it is found, else SternalBorder either side of the skin's
  // mid-line.
  const double midline4 = 0.5 * (fourth.Left + fourth.Right);
  Sternum sternum;
  const bool sternumFound = SternumAt(voxels, fourth.Centre[2], midline4, centre[1], voxel, sternum);
  const Vec v1 = Front(fourth, sternumFound ? sternum.Right : midline4 - SternalBorder, voxel);
  const Vec v2 = Front(fourth, sternumFound ? sternum.Left : midline4 + SternalBorder, voxel);
  Vec v6 = fifth.Skin.front();
  for (const auto& p : fifth.Skin)
    if (p[0] > v6[0])
      v6 = p;
  const Vec v5 = AtAngle(fifth, HalfWay(Angle(fifth, v4), Angle(fifth, v6)));
  const Level third = SkinLevel(skin, 0.5 * (v2[2] + v4[2]), slab);
  const Vec v3 = AtAngle(third, HalfWay(Angle(third, v2), Angle(third, v4)));
  const Level shoulders = SkinLevel(skin, lungTop, slab);
  const double midlineS = 0.5 * (shoulders.Left + shoulders.Right), halfS = 0.5 * (shoulders.Left - shoulders.Right);
  const Vec ra = Front(shoulders, midlineS - 0.6 * halfS, voxel);
  const Vec la = Front(shoulders, midlineS + 0.6 * halfS, voxel);
  const Level hips = SkinLevel(skin, std::max(lungBottom - 50.0, bodyBottom + voxel), slab);
  const double midlineH = 0.5 * (hips.Left + hips.Right), halfH = 0.5 * (hips.Left - hips.Right);
  const Vec ll = Front(hips, midlineH + 0.6 * halfH, voxel);

  r.Points = { { "RA", ra }, { "LA", la }, { "LL", ll }, { "V1", v1 }, { "V2", v2 }, { "V3", v3 }, { "V4", v4 },
    { "V5", v5 }, { "V6", v6 }, { "LVApexEndocardium", endo }, { "LVApexEpicardium", epi }, { "LVBase", base },
    { "Stimulus", stimulus } };
  if (sternumFound)
    r.Points.push_back({ "Sternum", sternum.Centre });
  return r;
}

bool amThoraxLandmarks::Get(const Result& r, const std::string& name, double x[3])
{
  for (const auto& p : r.Points)
    if (p.Name == name)
    {
      std::copy(p.X.begin(), p.X.end(), x);
      return true;
    }
  return false;
}
