#include "amRuleBasedFibres.h"

#include "amSparseCholesky.h"
#include "amSparseMatrix.h"
#include "amVentricularTags.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
constexpr double Degree = 3.14159265358979323846 / 180.0;

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Cross(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

bool Normalise(double a[3])
{
  const double n = std::sqrt(Dot(a, a));
  if (!(n > 1e-300))
    return false;
  for (int c = 0; c < 3; ++c)
    a[c] /= n;
  return true;
}

// The longitudinal direction: the axis without its part along t; where the axis is nearly along t
// (the apex), any direction normal to t.
void Longitudinal(const double axis[3], const double t[3], double l[3])
{
  const double along = Dot(axis, t);
  for (int c = 0; c < 3; ++c)
    l[c] = axis[c] - along * t[c];
  if (Dot(l, l) < 1e-4)
  {
    const double x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
    Cross(t, std::fabs(t[0]) < 0.9 ? x : y, l);
  }
  Normalise(l);
}

// Laplace's equation for each of 'fields' (count x n values, the Dirichlet values set, the rest free):
// one factor of K on the free nodes serves them all.
bool SolveLaplace(const amSparseMatrix& K, const std::vector<unsigned char>& fixed, std::vector<double>& fields,
  int count, std::string& error)
{
  amSparseCholesky factor;
  factor.BlasThreads = 1;
  if (!factor.Factor(&K, &fixed))
  {
    error = factor.Error();
    return false;
  }
  return factor.Solve(nullptr, fields.data(), count);
}
}

double amRuleBasedFibres::HelixAngle(const double f[3], const double t[3], const double a[3])
{
  double l[3], c[3];
  Longitudinal(a, t, l);
  Cross(l, t, c);
  double angle = std::atan2(Dot(f, l), Dot(f, c)) / Degree;
  if (angle > 90)
    angle -= 180;
  if (angle <= -90)
    angle += 180;
  return angle;
}

bool amRuleBasedFibres::Compute(const amP1Assembly& fem, const std::vector<unsigned char>& tag, const Parameters& p)
{
  const vtkIdType n = static_cast<vtkIdType>(fem.Points.size());
  const std::size_t nt = fem.Tetrahedra.size();
  bool hasLV = false, hasRV = false, hasEpi = false;
  for (unsigned char t : tag)
  {
    hasLV |= t == amVentricularTags::LVEndocardium;
    hasRV |= t == amVentricularTags::RVEndocardium;
    hasEpi |= t == amVentricularTags::Epicardium;
  }
  if (!hasLV || !hasEpi)
  {
    this->Error = !hasLV ? "the heart has no LV endocardium (no triangle faces a left-ventricular blood region)"
                         : "the heart has no epicardium (every boundary triangle faces a blood or base region)";
    return false;
  }
  double axis[3] = { p.ApexToBase[0], p.ApexToBase[1], p.ApexToBase[2] };
  if (!Normalise(axis))
  {
    this->Error = "the apex-to-base axis is zero";
    return false;
  }

  amSparseMatrix M, K;
  fem.Assemble(nullptr, M, K);
  std::vector<unsigned char> fixed(n, 0);
  for (vtkIdType i = 0; i < n; ++i)
    fixed[i] = tag[i] == amVentricularTags::LVEndocardium || tag[i] == amVentricularTags::RVEndocardium ||
      tag[i] == amVentricularTags::Epicardium;
  // phi_LV and phi_RV one after the other (phi_RV stays 0 without an RV).
  std::vector<double> phi(2 * static_cast<std::size_t>(n), 0.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    phi[i] = tag[i] == amVentricularTags::LVEndocardium ? 1.0 : 0.0;
    phi[n + i] = tag[i] == amVentricularTags::RVEndocardium ? 1.0 : 0.0;
  }
  if (!SolveLaplace(K, fixed, phi, hasRV ? 2 : 1, this->Error))
  {
    this->Error = "the transmural Laplace problem cannot be solved: " + this->Error;
    return false;
  }
  const std::vector<double> phiLV(phi.begin(), phi.begin() + n), phiRV(phi.begin() + n, phi.end());

  this->TransmuralDepth.assign(n, 0.0);
  this->Ventricle.assign(n, 0);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const bool rv = phiRV[i] > phiLV[i];
    this->Ventricle[i] = rv;
    this->TransmuralDepth[i] = std::min(1.0, std::max(0.0, 1.0 - (rv ? phiRV[i] : phiLV[i])));
    const double h = Dot(fem.Points[i].data(), axis);
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  this->ApicoBasal.assign(n, 0.0);
  for (vtkIdType i = 0; i < n; ++i)
    this->ApicoBasal[i] = hi > lo ? (Dot(fem.Points[i].data(), axis) - lo) / (hi - lo) : 0.0;

  this->Fibres.assign(nt, { 0, 0, 0 });
  this->Sheets.assign(nt, { 0, 0, 0 });
  for (std::size_t k = 0; k < nt; ++k)
  {
    double g[4][3], volume;
    fem.Gradients(static_cast<vtkIdType>(k), g, volume);
    const auto& tet = fem.Tetrahedra[k];
    double lv = 0, rv = 0, d = 0;
    for (int a = 0; a < 4; ++a)
    {
      lv += phiLV[tet[a]];
      rv += phiRV[tet[a]];
      d += 0.25 * this->TransmuralDepth[tet[a]];
    }
    const std::vector<double>& phi = rv > lv ? phiRV : phiLV;
    double t[3] = { 0, 0, 0 };
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c)
        t[c] -= phi[tet[a]] * g[a][c];
    if (!Normalise(t))
    {
      // A tetrahedron whose field is flat (between nodes of one value): the axis's normal.
      const double x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
      Cross(axis, std::fabs(axis[0]) < 0.9 ? x : y, t);
      Normalise(t);
    }
    double l[3], c[3];
    Longitudinal(axis, t, l);
    Cross(l, t, c);
    const double alpha = (p.HelixEndocardium + (p.HelixEpicardium - p.HelixEndocardium) * d) * Degree;
    const double beta = (p.TransverseEndocardium + (p.TransverseEpicardium - p.TransverseEndocardium) * d) * Degree;
    double f[3], n3[3];
    for (int q = 0; q < 3; ++q)
      f[q] = std::cos(alpha) * c[q] + std::sin(alpha) * l[q];
    // The sheet: e_t turned about f by beta (towards f x e_t).
    Cross(f, t, n3);
    for (int q = 0; q < 3; ++q)
    {
      this->Fibres[k][q] = f[q];
      this->Sheets[k][q] = std::cos(beta) * t[q] + std::sin(beta) * n3[q];
    }
  }
  return true;
}
