#include "amP1Assembly.h"

#include "amSparseMatrix.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

void amP1Assembly::Gradients(vtkIdType t, double g[4][3], double& volume) const
{
  const auto& tet = this->Tetrahedra[t];
  const double* p0 = this->Points[tet[0]].data();
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      e[k][c] = this->Points[tet[k + 1]][c] - p0[c];
  // Rows of the inverse of [e1 e2 e3]^T are the gradients of barycentrics 1..3.
  double cof[3][3];
  cof[0][0] = e[1][1] * e[2][2] - e[1][2] * e[2][1];
  cof[0][1] = e[1][2] * e[2][0] - e[1][0] * e[2][2];
  cof[0][2] = e[1][0] * e[2][1] - e[1][1] * e[2][0];
  cof[1][0] = e[2][1] * e[0][2] - e[2][2] * e[0][1];
  cof[1][1] = e[2][2] * e[0][0] - e[2][0] * e[0][2];
  cof[1][2] = e[2][0] * e[0][1] - e[2][1] * e[0][0];
  cof[2][0] = e[0][1] * e[1][2] - e[0][2] * e[1][1];
  cof[2][1] = e[0][2] * e[1][0] - e[0][0] * e[1][2];
  cof[2][2] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
  const double det = e[0][0] * cof[0][0] + e[0][1] * cof[0][1] + e[0][2] * cof[0][2];
  volume = std::fabs(det) / 6.0;
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      g[a + 1][c] = det != 0 ? cof[a][c] / det : 0.0;
  for (int c = 0; c < 3; ++c)
    g[0][c] = -(g[1][c] + g[2][c] + g[3][c]);
}

vtkIdType amP1Assembly::FindDegenerate() const
{
  const vtkIdType n = static_cast<vtkIdType>(this->Tetrahedra.size());
  for (vtkIdType t = 0; t < n; ++t)
  {
    const auto& tet = this->Tetrahedra[t];
    double longest = 0;
    bool finite = true;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
      {
        double d2 = 0;
        for (int c = 0; c < 3; ++c)
        {
          const double d = this->Points[tet[a]][c] - this->Points[tet[b]][c];
          d2 += d * d;
        }
        finite = finite && std::isfinite(d2);
        longest = std::max(longest, std::sqrt(d2));
      }
    double g[4][3], volume;
    this->Gradients(t, g, volume);
    if (!finite || !(volume > 1e-9 * longest * longest * longest))
      return t;
  }
  return -1;
}

std::array<double, 6> amP1Assembly::FiberTensor(double sigmaL, double sigmaT, const double f[3])
{
  const double norm = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  if (!(norm > 0))
    return { sigmaL, sigmaL, sigmaL, 0, 0, 0 };
  const double u[3] = { f[0] / norm, f[1] / norm, f[2] / norm };
  const double d = sigmaL - sigmaT;
  return { sigmaT + d * u[0] * u[0], sigmaT + d * u[1] * u[1], sigmaT + d * u[2] * u[2], d * u[0] * u[1],
    d * u[1] * u[2], d * u[0] * u[2] };
}

void amP1Assembly::Assemble(
  const std::vector<std::array<double, 6>>* conductivity, amSparseMatrix& mass, amSparseMatrix& stiffness) const
{
  const vtkIdType n = static_cast<vtkIdType>(this->Points.size());
  mass.BuildPattern(n, this->Tetrahedra);
  stiffness.RowStart = mass.RowStart;
  stiffness.Columns = mass.Columns;
  stiffness.Values.assign(mass.Columns.size(), 0.0);

  // Node -> tetrahedra, in tetrahedron order (the fixed summation order of every row).
  std::vector<vtkIdType> start(n + 1, 0);
  for (const auto& t : this->Tetrahedra)
    for (vtkIdType v : t)
      ++start[v + 1];
  for (vtkIdType i = 0; i < n; ++i)
    start[i + 1] += start[i];
  std::vector<vtkIdType> fill(start.begin(), start.end() - 1), cells(start[n]);
  for (std::size_t c = 0; c < this->Tetrahedra.size(); ++c)
    for (vtkIdType v : this->Tetrahedra[c])
      cells[fill[v]++] = static_cast<vtkIdType>(c);

  vtkSMPTools::For(0, n, 1024, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
      for (vtkIdType k = start[i]; k < start[i + 1]; ++k)
      {
        const vtkIdType t = cells[k];
        const auto& tet = this->Tetrahedra[t];
        double g[4][3], volume;
        this->Gradients(t, g, volume);
        int a = 0;
        while (tet[a] != i)
          ++a;
        double sg[3] = { g[a][0], g[a][1], g[a][2] }; // Sigma g_a
        if (conductivity)
        {
          const auto& s = (*conductivity)[t];
          sg[0] = s[0] * g[a][0] + s[3] * g[a][1] + s[5] * g[a][2];
          sg[1] = s[3] * g[a][0] + s[1] * g[a][1] + s[4] * g[a][2];
          sg[2] = s[5] * g[a][0] + s[4] * g[a][1] + s[2] * g[a][2];
        }
        for (int b = 0; b < 4; ++b)
        {
          const vtkIdType pos = mass.Find(i, tet[b]);
          mass.Values[pos] += volume * (a == b ? 2.0 : 1.0) / 20.0;
          stiffness.Values[pos] += volume * (sg[0] * g[b][0] + sg[1] * g[b][1] + sg[2] * g[b][2]);
        }
      }
  });
}
