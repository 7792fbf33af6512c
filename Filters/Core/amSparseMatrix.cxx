#include "amSparseMatrix.h"

#include "amThreading.h"
#include "vtkSMPTools.h"

#include <algorithm>

void amSparseMatrix::BuildPattern(vtkIdType n, const std::vector<std::array<vtkIdType, 4>>& tetrahedra)
{
  // Node -> tetrahedra (CSR), then each row is the sorted union of its tetrahedra's nodes.
  std::vector<vtkIdType> start(n + 1, 0);
  for (const auto& t : tetrahedra)
    for (vtkIdType v : t)
      ++start[v + 1];
  for (vtkIdType i = 0; i < n; ++i)
    start[i + 1] += start[i];
  std::vector<vtkIdType> fill(start.begin(), start.end() - 1), cells(start[n]);
  for (std::size_t c = 0; c < tetrahedra.size(); ++c)
    for (vtkIdType v : tetrahedra[c])
      cells[fill[v]++] = static_cast<vtkIdType>(c);

  std::vector<std::vector<vtkIdType>> rows(n);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      auto& row = rows[i];
      row.push_back(i);
      for (vtkIdType k = start[i]; k < start[i + 1]; ++k)
        for (vtkIdType v : tetrahedra[cells[k]])
          row.push_back(v);
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
    }
  });
  this->RowStart.assign(n + 1, 0);
  for (vtkIdType i = 0; i < n; ++i)
    this->RowStart[i + 1] = this->RowStart[i] + static_cast<vtkIdType>(rows[i].size());
  this->Columns.resize(this->RowStart[n]);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      std::copy(rows[i].begin(), rows[i].end(), this->Columns.begin() + this->RowStart[i]);
      std::vector<vtkIdType>().swap(rows[i]);
    }
  });
  this->Values.assign(this->Columns.size(), 0.0);
}

vtkIdType amSparseMatrix::Find(vtkIdType i, vtkIdType j) const
{
  const auto first = this->Columns.begin() + this->RowStart[i];
  const auto last = this->Columns.begin() + this->RowStart[i + 1];
  const auto it = std::lower_bound(first, last, j);
  return (it != last && *it == j) ? static_cast<vtkIdType>(it - this->Columns.begin()) : -1;
}

void amSparseMatrix::Multiply(const double* x, double* y) const
{
  const vtkIdType* rs = this->RowStart.data();
  const vtkIdType* cols = this->Columns.data();
  const double* vals = this->Values.data();
  amThreading::For(0, this->Size(), [=](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      double sum = 0.0;
      for (vtkIdType k = rs[i]; k < rs[i + 1]; ++k)
        sum += vals[k] * x[cols[k]];
      y[i] = sum;
    }
  });
}

std::vector<double> amSparseMatrix::Diagonal() const
{
  std::vector<double> d(this->Size(), 0.0);
  for (vtkIdType i = 0; i < this->Size(); ++i)
  {
    const vtkIdType k = this->Find(i, i);
    d[i] = k >= 0 ? this->Values[k] : 0.0;
  }
  return d;
}

void amSparseMatrix::Combine(double a, const amSparseMatrix& A, double b, const amSparseMatrix& B)
{
  this->RowStart = A.RowStart;
  this->Columns = A.Columns;
  this->Values.resize(A.Values.size());
  for (std::size_t k = 0; k < this->Values.size(); ++k)
    this->Values[k] = a * A.Values[k] + b * B.Values[k];
}
