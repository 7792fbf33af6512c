#include "amLeadFields.h"

#include "amSparseCholesky.h"
#include "amSparseMatrix.h"

#include <algorithm>
#include <cmath>

bool amLeadFields::Compute(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& bulk,
  const std::vector<vtkIdType>& heart, const std::vector<std::array<double, 6>>& intracellular,
  const std::vector<vtkIdType>& electrodes, vtkIdType ground)
{
  const vtkIdType n = static_cast<vtkIdType>(fem.Points.size());
  amSparseMatrix M, A;
  fem.Assemble(&bulk, M, A);
  // The ground, and the points no tetrahedron uses (they carry no potential).
  std::vector<unsigned char> fixed(n, 1);
  for (const auto& t : fem.Tetrahedra)
    for (vtkIdType v : t)
      fixed[v] = 0;
  fixed[ground] = 1;
  amSparseCholesky factor;
  if (!factor.Factor(&A, &fixed))
  {
    this->Error = "the torso's matrix cannot be factored: " + factor.Error();
    return false;
  }
  const int ne = static_cast<int>(electrodes.size());
  std::vector<double> b(static_cast<std::size_t>(n) * ne, 0.0), z(static_cast<std::size_t>(n) * ne, 0.0);
  for (int k = 0; k < ne; ++k)
    if (electrodes[k] != ground)
      b[static_cast<std::size_t>(k) * n + electrodes[k]] = 1.0;
  if (!factor.Solve(b.data(), z.data(), ne))
  {
    this->Error = "no memory for the lead fields' solves";
    return false;
  }
  // K_i on the heart's tetrahedra alone: a mesh of those, on the same nodes.
  amP1Assembly heartFem;
  heartFem.Points = fem.Points;
  for (vtkIdType t : heart)
    heartFem.Tetrahedra.push_back(fem.Tetrahedra[t]);
  amSparseMatrix Mi, Ki;
  heartFem.Assemble(&intracellular, Mi, Ki);
  std::vector<unsigned char> used(n, 0);
  for (const auto& t : heartFem.Tetrahedra)
    for (vtkIdType v : t)
      used[v] = 1;
  this->Nodes.clear();
  for (vtkIdType i = 0; i < n; ++i)
    if (used[i])
      this->Nodes.push_back(i);
  this->Weights.assign(ne, std::vector<double>(this->Nodes.size(), 0.0));
  std::vector<double> w(n);
  for (int k = 0; k < ne; ++k)
  {
    Ki.Multiply(&z[static_cast<std::size_t>(k) * n], w.data());
    for (std::size_t j = 0; j < this->Nodes.size(); ++j)
      this->Weights[k][j] = -w[this->Nodes[j]];
  }
  return true;
}

std::vector<double> amLeadFields::Potentials(const std::vector<double>& vm) const
{
  std::vector<double> phi(this->Weights.size(), 0.0);
  for (std::size_t k = 0; k < this->Weights.size(); ++k)
  {
    double sum = 0;
    for (std::size_t j = 0; j < vm.size(); ++j)
      sum += this->Weights[k][j] * vm[j];
    phi[k] = sum;
  }
  return phi;
}

void amLeadFields::Snap(const amP1Assembly& fem, const std::vector<unsigned char>& onSurface,
  const std::vector<double>& positions, std::vector<vtkIdType>& nodes, std::vector<double>& distances)
{
  nodes.clear();
  distances.clear();
  const vtkIdType n = static_cast<vtkIdType>(fem.Points.size());
  for (std::size_t e = 0; e + 2 < positions.size(); e += 3)
  {
    vtkIdType best = -1;
    double bestD = 1e300;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (!onSurface[i])
        continue;
      double d2 = 0;
      for (int c = 0; c < 3; ++c)
        d2 += (fem.Points[i][c] - positions[e + c]) * (fem.Points[i][c] - positions[e + c]);
      if (d2 < bestD)
      {
        bestD = d2;
        best = i;
      }
    }
    nodes.push_back(best);
    distances.push_back(best < 0 ? -1.0 : std::sqrt(bestD));
  }
}
