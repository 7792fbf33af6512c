#include "amPhantomVentricles.h"

#include <cmath>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// The shapes, in the heart's frame at scale 1 (mm): see the class documentation.
constexpr double LVCenter[3] = { -10.0, -8.0, 0.0 };
constexpr double LVCavity[3] = { 50.0, 23.0, 23.0 };
constexpr double LVWall = 10.0;
constexpr double RVCenter[3] = { -5.0, 31.0, 0.0 };
constexpr double RVCavity[3] = { 40.0, 14.0, 30.0 };
constexpr double RVWall = 4.0;
constexpr double CavityBase = -32.0; // the base plane of both cavities, along u
constexpr double BaseCap = 8.0;      // the muscle above it

bool InsideEllipsoid(const double l[3], const double c[3], const double r[3], double grow)
{
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double t = (l[i] - c[i]) / (r[i] + grow);
    sum += t * t;
  }
  return sum <= 1.0;
}
}

amPhantomVentricles::amPhantomVentricles(const double center[3], const double axes[3][3], double scale)
  : Scale(scale)
{
  for (int i = 0; i < 3; ++i)
  {
    this->Center[i] = center[i];
    for (int j = 0; j < 3; ++j)
      this->Axes[i][j] = axes[i][j];
  }
}

void amPhantomVentricles::ToLocal(const double x[3], double local[3]) const
{
  const double d[3] = { x[0] - this->Center[0], x[1] - this->Center[1], x[2] - this->Center[2] };
  for (int i = 0; i < 3; ++i)
    local[i] = (this->Axes[i][0] * d[0] + this->Axes[i][1] * d[1] + this->Axes[i][2] * d[2]) / this->Scale;
}

void amPhantomVentricles::ToWorld(const double local[3], double x[3]) const
{
  for (int j = 0; j < 3; ++j)
  {
    x[j] = this->Center[j];
    for (int i = 0; i < 3; ++i)
      x[j] += this->Axes[i][j] * local[i] * this->Scale;
  }
}

bool amPhantomVentricles::InsideHeart(const double x[3]) const
{
  double l[3];
  this->ToLocal(x, l);
  if (l[0] < CavityBase - BaseCap)
    return false;
  return InsideEllipsoid(l, LVCenter, LVCavity, LVWall) || InsideEllipsoid(l, RVCenter, RVCavity, RVWall);
}

bool amPhantomVentricles::InsideLeftVentricle(const double x[3]) const
{
  double l[3];
  this->ToLocal(x, l);
  return l[0] >= CavityBase && InsideEllipsoid(l, LVCenter, LVCavity, 0.0);
}

bool amPhantomVentricles::InsideRightVentricle(const double x[3]) const
{
  double l[3];
  this->ToLocal(x, l);
  return l[0] >= CavityBase && InsideEllipsoid(l, RVCenter, RVCavity, 0.0) &&
    !InsideEllipsoid(l, LVCenter, LVCavity, LVWall);
}

void amPhantomVentricles::LeftVentricleCenter(double x[3]) const
{
  // Mid-way between the base plane and the apex, on the cavity's axis.
  const double l[3] = { 0.5 * (CavityBase + LVCenter[0] + LVCavity[0]), LVCenter[1], LVCenter[2] };
  this->ToWorld(l, x);
}

void amPhantomVentricles::RightVentricleCenter(double x[3]) const
{
  // In the crescent, half-way between the septum (the LV's wall) and the RV's free wall.
  const double septum = LVCenter[1] + LVCavity[1] + LVWall, free = RVCenter[1] + RVCavity[1];
  const double l[3] = { RVCenter[0], 0.5 * (septum + free), RVCenter[2] };
  this->ToWorld(l, x);
}

void amPhantomVentricles::FreeWallCenter(double x[3]) const
{
  // Half-way through the LV's lateral wall (opposite the RV), at the cavity's mid level.
  const double l[3] = { LVCenter[0], LVCenter[1] - LVCavity[1] - 0.5 * LVWall, LVCenter[2] };
  this->ToWorld(l, x);
}

double amPhantomVentricles::LeftVentricleVolume() const
{
  // The prolate cap from the base plane to the apex: pi b^2 integral of (1 - s^2/a^2) ds.
  const double a = LVCavity[0], b = LVCavity[1];
  const double s0 = CavityBase - LVCenter[0], s1 = a;
  const double integral = (s1 - s0) - (s1 * s1 * s1 - s0 * s0 * s0) / (3.0 * a * a);
  return Pi * b * b * integral * this->Scale * this->Scale * this->Scale;
}
