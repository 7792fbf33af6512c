#include "amThoraxPhantomModel.h"

#include <cmath>

namespace
{
constexpr double Pi = 3.14159265358979323846;

void RotationAboutZ(double degrees, double axes[3][3])
{
  const double t = degrees * Pi / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  const double r[3][3] = { { c, s, 0.0 }, { -s, c, 0.0 }, { 0.0, 0.0, 1.0 } };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      axes[i][j] = r[i][j];
}

amThoraxPhantomModel::Ellipsoid MakeEllipsoid(const double c[3], const double r[3], const double axes[3][3])
{
  amThoraxPhantomModel::Ellipsoid e{};
  for (int i = 0; i < 3; ++i)
  {
    e.Center[i] = c[i];
    e.Radii[i] = r[i];
    for (int j = 0; j < 3; ++j)
      e.Axes[i][j] = axes[i][j];
  }
  return e;
}

// World position of a point given in the local frame of 'parent' (rows of Axes = local axes).
void LocalToWorld(const amThoraxPhantomModel::Ellipsoid& parent, const double local[3], double world[3])
{
  for (int j = 0; j < 3; ++j)
  {
    world[j] = parent.Center[j];
    for (int i = 0; i < 3; ++i)
      world[j] += parent.Axes[i][j] * local[i];
  }
}
}

bool amThoraxPhantomModel::Ellipsoid::Inside(const double x[3]) const
{
  const double d[3] = { x[0] - this->Center[0], x[1] - this->Center[1], x[2] - this->Center[2] };
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double l = (this->Axes[i][0] * d[0] + this->Axes[i][1] * d[1] + this->Axes[i][2] * d[2]) / this->Radii[i];
    sum += l * l;
  }
  return sum <= 1.0;
}

double amThoraxPhantomModel::Ellipsoid::Volume() const
{
  return 4.0 / 3.0 * Pi * this->Radii[0] * this->Radii[1] * this->Radii[2];
}

amThoraxPhantomModel::amThoraxPhantomModel()
  : amThoraxPhantomModel(Habitus())
{
}

amThoraxPhantomModel::amThoraxPhantomModel(const Habitus& habitus)
{
  // The inner body (138 x 93 x 88 mm semi-axes) is fixed; the fat lies over it.
  this->FatThickness = habitus.FatThickness;
  this->BodyRadii[0] = 138.0 + this->FatThickness;
  this->BodyRadii[1] = 93.0 + this->FatThickness;
  this->BodyRadii[2] = 88.0 + this->FatThickness;
  this->BodyExponent = 6.0;

  double identity[3][3];
  RotationAboutZ(0.0, identity);
  const double rlc[3] = { -70.0, 5.0, 5.0 }, rlr[3] = { 48.0, 62.0, 75.0 };
  const double llc[3] = { 72.0, 5.0, 5.0 }, llr[3] = { 46.0, 62.0, 75.0 };
  this->Lungs[0] = MakeEllipsoid(rlc, rlr, identity);
  this->Lungs[1] = MakeEllipsoid(llc, llr, identity);

  // Heart: long axis turned (by default 30 degrees) towards the patient's left-anterior side.
  double heartAxes[3][3];
  RotationAboutZ(habitus.HeartAngle, heartAxes);
  const double k = this->HeartScale = habitus.HeartScale;
  const double hc[3] = { 15.0, -25.0, -25.0 }, hr[3] = { 58.0 * k, 45.0 * k, 45.0 * k };
  this->Heart = MakeEllipsoid(hc, hr, heartAxes);
  double lvc[3], rvc[3];
  const double lvLocal[3] = { 12.0 * k, 8.0 * k, -3.0 * k }, lvr[3] = { 26.0 * k, 18.0 * k, 30.0 * k };
  const double rvLocal[3] = { -26.0 * k, -15.0 * k, -3.0 * k }, rvr[3] = { 17.0 * k, 12.0 * k, 26.0 * k };
  LocalToWorld(this->Heart, lvLocal, lvc);
  LocalToWorld(this->Heart, rvLocal, rvc);
  this->LeftVentricle = MakeEllipsoid(lvc, lvr, heartAxes);
  this->RightVentricle = MakeEllipsoid(rvc, rvr, heartAxes);
  this->HeartShape = habitus.HeartShape == Ventricles ? Ventricles : Ellipsoidal;
  if (this->HeartShape == Ventricles)
  {
    // The same centre and azimuth, the long axis turned 25 degrees apex-down about the horizontal
    // axis that points to the RV (right-anterior); the heart's frame (Heart's Axes) turns with it.
    const double tilt = 25.0 * Pi / 180.0, c = std::cos(tilt), s = std::sin(tilt);
    double axes[3][3];
    for (int j = 0; j < 3; ++j)
    {
      axes[0][j] = c * heartAxes[0][j] - s * heartAxes[2][j];
      axes[1][j] = -heartAxes[1][j];
    }
    axes[2][0] = axes[0][1] * axes[1][2] - axes[0][2] * axes[1][1];
    axes[2][1] = axes[0][2] * axes[1][0] - axes[0][0] * axes[1][2];
    axes[2][2] = axes[0][0] * axes[1][1] - axes[0][1] * axes[1][0];
    this->Heart = MakeEllipsoid(hc, hr, axes);
    this->AnatomicalVentricles = amPhantomVentricles(hc, axes, k);
  }

  this->ArchCenter[0] = 5.0;
  this->ArchCenter[1] = 10.0;
  this->ArchCenter[2] = 36.0;
  this->ArchRadius = 30.0;
  this->AortaRadius = 11.0;
  this->AscendingBottom = 26.0;
  this->DescendingBottom = -75.0;

  this->SpineCenter[0] = 0.0;
  this->SpineCenter[1] = 66.0;
  this->SpineRadius = 12.0;
  this->SpineZ[0] = -70.0;
  this->SpineZ[1] = 70.0;

  this->NumberOfRibPairs = 7;
  this->RibRadius = 4.5;
  this->RibRing[0] = 8.0;  // ring = inner body cross-section at the rib's height, shrunk by this (mm)
  this->RibRing[1] = 20.0; // half-width (mm) of the gaps at the sternum and at the spine
  this->RibZTop = 60.0;
  this->RibSpacing = 20.0;
  this->RibTilt = 0.25; // ribs run down towards the front: dz/dy
  // Ring of rib pair k: the inner body's cross-section at its height, shrunk by RibRing[0].
  const double innerC = this->BodyRadii[2] - this->FatThickness;
  for (int k = 0; k < this->NumberOfRibPairs; ++k)
  {
    const double zk = this->RibZTop - k * this->RibSpacing;
    const double s = std::sqrt(1.0 - std::pow(std::fabs(zk / innerC), this->BodyExponent));
    this->RibHeight.push_back(zk);
    this->RibA.push_back((this->BodyRadii[0] - this->FatThickness) * s - this->RibRing[0]);
    this->RibB.push_back((this->BodyRadii[1] - this->FatThickness) * s - this->RibRing[0]);
  }
}

void amThoraxPhantomModel::WorldToHeartFrame(const double world[3], double frame[3]) const
{
  const double d[3] = { world[0] - this->Heart.Center[0], world[1] - this->Heart.Center[1],
    world[2] - this->Heart.Center[2] };
  for (int i = 0; i < 3; ++i)
    frame[i] = (this->Heart.Axes[i][0] * d[0] + this->Heart.Axes[i][1] * d[1] + this->Heart.Axes[i][2] * d[2]) /
      this->HeartScale;
}

void amThoraxPhantomModel::HeartFrameToWorld(const double frame[3], double world[3]) const
{
  const double local[3] = { frame[0] * this->HeartScale, frame[1] * this->HeartScale, frame[2] * this->HeartScale };
  LocalToWorld(this->Heart, local, world);
}

bool amThoraxPhantomModel::InsideSuperquadric(const double x[3], const double radii[3], double q)
{
  const double u = x[0] / radii[0], v = x[1] / radii[1], w = std::fabs(x[2] / radii[2]);
  if (w > 1.0)
    return false;
  // w^q depends on the height alone, and points come slice by slice, each tested against the
  // outer and the inner body: the last two powers are kept (pow was most of the phantom's time).
  thread_local double lastW[2] = { -1.0, -1.0 }, lastQ[2] = { 0.0, 0.0 }, lastPower[2] = { 0.0, 0.0 };
  thread_local int slot = 0;
  double power;
  if (w == lastW[0] && q == lastQ[0])
    power = lastPower[0];
  else if (w == lastW[1] && q == lastQ[1])
    power = lastPower[1];
  else
  {
    power = std::pow(w, q);
    lastW[slot] = w;
    lastQ[slot] = q;
    lastPower[slot] = power;
    slot ^= 1;
  }
  return u * u + v * v + power <= 1.0;
}

double amThoraxPhantomModel::SuperquadricVolume(const double radii[3], double q)
{
  // Cross-section at height z is an ellipse of area pi*a*b*(1-|z/c|^q); integrate over [-c, c].
  return 2.0 * Pi * radii[0] * radii[1] * radii[2] * q / (q + 1.0);
}

bool amThoraxPhantomModel::InsideBody(const double x[3]) const
{
  return InsideSuperquadric(x, this->BodyRadii, this->BodyExponent);
}

bool amThoraxPhantomModel::InsideInnerBody(const double x[3]) const
{
  const double r[3] = { this->BodyRadii[0] - this->FatThickness, this->BodyRadii[1] - this->FatThickness,
    this->BodyRadii[2] - this->FatThickness };
  return InsideSuperquadric(x, r, this->BodyExponent);
}

bool amThoraxPhantomModel::InsideLung(const double x[3], bool left) const
{
  return this->Lungs[left ? 1 : 0].Inside(x);
}

bool amThoraxPhantomModel::InsideHeart(const double x[3]) const
{
  if (this->HeartShape == Ventricles)
    return this->AnatomicalVentricles.InsideHeart(x);
  return this->Heart.Inside(x);
}

bool amThoraxPhantomModel::InsideLeftVentricle(const double x[3]) const
{
  if (this->HeartShape == Ventricles)
    return this->AnatomicalVentricles.InsideLeftVentricle(x);
  return this->LeftVentricle.Inside(x);
}

bool amThoraxPhantomModel::InsideRightVentricle(const double x[3]) const
{
  if (this->HeartShape == Ventricles)
    return this->AnatomicalVentricles.InsideRightVentricle(x);
  return this->RightVentricle.Inside(x);
}

bool amThoraxPhantomModel::InsideAorta(const double x[3]) const
{
  const double r2 = this->AortaRadius * this->AortaRadius;
  const double dx = x[0] - this->ArchCenter[0];
  const double dy = x[1] - this->ArchCenter[1];
  const double dz = x[2] - this->ArchCenter[2];
  if (dz >= 0.0)
  {
    // Upper half torus whose axis is the x axis through ArchCenter.
    const double rho = std::sqrt(dy * dy + dz * dz) - this->ArchRadius;
    return rho * rho + dx * dx <= r2;
  }
  if (x[2] >= this->AscendingBottom)
  {
    const double ay = dy + this->ArchRadius;
    if (ay * ay + dx * dx <= r2)
      return true;
  }
  if (x[2] >= this->DescendingBottom)
  {
    const double dd = dy - this->ArchRadius;
    if (dd * dd + dx * dx <= r2)
      return true;
  }
  return false;
}

bool amThoraxPhantomModel::InsideSpine(const double x[3]) const
{
  if (x[2] < this->SpineZ[0] || x[2] > this->SpineZ[1])
    return false;
  const double dx = x[0] - this->SpineCenter[0], dy = x[1] - this->SpineCenter[1];
  return dx * dx + dy * dy <= this->SpineRadius * this->SpineRadius;
}

bool amThoraxPhantomModel::InsideRib(const double x[3]) const
{
  if (std::fabs(x[0]) < this->RibRing[1])
    return false;
  for (int k = 0; k < this->NumberOfRibPairs; ++k)
  {
    const double dz = x[2] - (this->RibHeight[k] + this->RibTilt * x[1]);
    if (std::fabs(dz) > this->RibRadius)
      continue;
    const double A = this->RibA[k], B = this->RibB[k];
    const double rho = std::sqrt((x[0] / A) * (x[0] / A) + (x[1] / B) * (x[1] / B));
    if (rho <= 0.0)
      continue;
    const double inPlane = (rho - 1.0) * std::sqrt(x[0] * x[0] + x[1] * x[1]) / rho;
    if (inPlane * inPlane + dz * dz <= this->RibRadius * this->RibRadius)
      return true;
  }
  return false;
}

unsigned char amThoraxPhantomModel::LabelAt(const double x[3]) const
{
  if (!this->InsideBody(x))
    return Background;
  if (!this->InsideInnerBody(x))
    return Fat;
  if (this->InsideRib(x))
    return Ribs;
  if (this->InsideSpine(x))
    return Spine;
  if (this->InsideAorta(x))
    return Aorta;
  if (this->InsideHeart(x))
  {
    if (this->InsideLeftVentricle(x))
      return LeftVentricleBlood;
    if (this->InsideRightVentricle(x))
      return RightVentricleBlood;
    return Myocardium;
  }
  if (this->Lungs[1].Inside(x))
    return LeftLung;
  if (this->Lungs[0].Inside(x))
    return RightLung;
  return SoftTissue;
}

double amThoraxPhantomModel::HounsfieldUnits(int label)
{
  static const double hu[NumberOfLabels] = { -1000.0, 40.0, -100.0, -850.0, -850.0, 50.0, 300.0, 300.0, 300.0, 700.0,
    700.0 };
  return (label >= 0 && label < NumberOfLabels) ? hu[label] : 0.0;
}

const char* amThoraxPhantomModel::LabelName(int label)
{
  static const char* names[NumberOfLabels] = { "Background", "SoftTissue", "Fat", "RightLung", "LeftLung", "Myocardium",
    "LeftVentricleBlood", "RightVentricleBlood", "Aorta", "Spine", "Ribs" };
  return (label >= 0 && label < NumberOfLabels) ? names[label] : "Unknown";
}

double amThoraxPhantomModel::BodyVolume() const
{
  return SuperquadricVolume(this->BodyRadii, this->BodyExponent);
}

double amThoraxPhantomModel::ExactVolume(int label) const
{
  const double r2 = this->AortaRadius * this->AortaRadius;
  switch (label)
  {
    case Fat:
    {
      const double inner[3] = { this->BodyRadii[0] - this->FatThickness, this->BodyRadii[1] - this->FatThickness,
        this->BodyRadii[2] - this->FatThickness };
      return this->BodyVolume() - SuperquadricVolume(inner, this->BodyExponent);
    }
    case Myocardium:
      if (this->HeartShape == Ventricles)
        return -1.0; // the RV's crescent is not closed-form
      return this->Heart.Volume() - this->LeftVentricle.Volume() - this->RightVentricle.Volume();
    case LeftVentricleBlood:
      if (this->HeartShape == Ventricles)
        return this->AnatomicalVentricles.LeftVentricleVolume();
      return this->LeftVentricle.Volume();
    case RightVentricleBlood:
      if (this->HeartShape == Ventricles)
        return -1.0;
      return this->RightVentricle.Volume();
    case Aorta:
      return Pi * r2 *
        ((this->ArchCenter[2] - this->AscendingBottom) + (this->ArchCenter[2] - this->DescendingBottom)) +
        Pi * Pi * this->ArchRadius * r2;
    case Spine:
      return Pi * this->SpineRadius * this->SpineRadius * (this->SpineZ[1] - this->SpineZ[0]);
    default:
      return -1.0;
  }
}

void amThoraxPhantomModel::GetBodyBounds(double bounds[6]) const
{
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = -this->BodyRadii[i];
    bounds[2 * i + 1] = this->BodyRadii[i];
  }
}

void amThoraxPhantomModel::GetOrganCenter(int label, double center[3]) const
{
  const double inner[3] = { 0.0, 0.0, 0.0 };
  const double* c = inner;
  double tmp[3];
  switch (label)
  {
    case Fat:
      tmp[0] = 0.0;
      tmp[1] = -(this->BodyRadii[1] - 0.5 * this->FatThickness);
      tmp[2] = 0.0;
      c = tmp;
      break;
    case SoftTissue:
      tmp[0] = 0.0;
      tmp[1] = -(this->BodyRadii[1] - this->FatThickness - 6.0);
      tmp[2] = 0.0;
      c = tmp;
      break;
    case RightLung:
      c = this->Lungs[0].Center;
      break;
    case LeftLung:
      c = this->Lungs[1].Center;
      break;
    case Myocardium:
    {
      // In the free wall of the left ventricle, half-way between the blood pool and the epicardium.
      const double local[3] = { 47.0, 8.0, -3.0 };
      if (this->HeartShape == Ventricles)
        this->AnatomicalVentricles.FreeWallCenter(tmp);
      else
        LocalToWorld(this->Heart, local, tmp);
      c = tmp;
      break;
    }
    case LeftVentricleBlood:
      c = this->LeftVentricle.Center;
      if (this->HeartShape == Ventricles)
      {
        this->AnatomicalVentricles.LeftVentricleCenter(tmp);
        c = tmp;
      }
      break;
    case RightVentricleBlood:
      c = this->RightVentricle.Center;
      if (this->HeartShape == Ventricles)
      {
        this->AnatomicalVentricles.RightVentricleCenter(tmp);
        c = tmp;
      }
      break;
    case Aorta:
      tmp[0] = this->ArchCenter[0];
      tmp[1] = this->ArchCenter[1] + this->ArchRadius;
      tmp[2] = 0.0;
      c = tmp;
      break;
    case Spine:
      tmp[0] = this->SpineCenter[0];
      tmp[1] = this->SpineCenter[1];
      tmp[2] = 0.0;
      c = tmp;
      break;
    case Ribs:
    {
      // On the centre line of the third rib, on the patient's left side.
      tmp[0] = this->RibA[2];
      tmp[1] = 0.0;
      tmp[2] = this->RibHeight[2];
      c = tmp;
      break;
    }
    default:
      tmp[0] = -this->BodyRadii[0] - 5.0;
      tmp[1] = -this->BodyRadii[1] - 5.0;
      tmp[2] = 0.0;
      c = tmp;
      break;
  }
  center[0] = c[0];
  center[1] = c[1];
  center[2] = c[2];
}

void amThoraxPhantomModel::StandardElectrodes(double positions[9][3])
{
  // Body: superquadric with half-axes 150 (left-right), 105 (front-back), 100 mm (up-down); the
  // heart sits at z = -25 mm, in front (-y) and to the left (+x) of the centre.
  static const double electrodes[9][3] = {
    { -125.0, 0.0, 80.0 },    // RA: right shoulder
    { 125.0, 0.0, 80.0 },     // LA: left shoulder
    { 110.0, 0.0, -85.0 },    // LL: left lower torso
    { -15.0, -105.0, -30.0 }, // V1: right sternal border
    { 15.0, -105.0, -30.0 },  // V2: left sternal border
    { 37.5, -102.0, -35.0 },  // V3: half-way from V2 to V4
    { 60.0, -96.0, -40.0 },   // V4: mid-clavicular line
    { 100.0, -78.0, -40.0 },  // V5: anterior axillary line
    { 150.0, 0.0, -40.0 },    // V6: mid-axillary line
  };
  for (int e = 0; e < 9; ++e)
    for (int c = 0; c < 3; ++c)
      positions[e][c] = electrodes[e][c];
}
