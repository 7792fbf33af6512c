#include "amEikonal.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace
{
using Vec = std::array<double, 3>;

double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

// min over the segment y0 + s e, s in [0, 1], of T0 + s (T1 - T0) + |y - y0 - s e|, interior only:
// +infinity when the stationary point is outside the segment or the time gradient is too steep.
double EdgeInterior(const Vec& y, const Vec& y0, double t0, const Vec& y1, double t1)
{
  const Vec e = Sub(y1, y0);
  const double length = std::sqrt(Dot(e, e));
  if (!(length > 0))
    return std::numeric_limits<double>::infinity();
  const Vec u = { e[0] / length, e[1] / length, e[2] / length };
  const double g = (t1 - t0) / length;
  if (std::fabs(g) >= 1.0)
    return std::numeric_limits<double>::infinity();
  const Vec w = Sub(y, y0);
  const double along = Dot(w, u);
  const double h = std::sqrt(std::max(0.0, Dot(w, w) - along * along));
  const double sigma = along - g * h / std::sqrt(1.0 - g * g);
  if (sigma < 0 || sigma > length)
    return std::numeric_limits<double>::infinity();
  return t0 + g * sigma + std::sqrt(h * h + (along - sigma) * (along - sigma));
}

// The same over the triangle (y0, y1, y2): its interior stationary point only.
double FaceInterior(const Vec& y, const Vec& y0, double t0, const Vec& y1, double t1, const Vec& y2, double t2)
{
  const Vec e1 = Sub(y1, y0), e2 = Sub(y2, y0);
  const double a = Dot(e1, e1), b = Dot(e1, e2), c = Dot(e2, e2);
  const double det = a * c - b * b;
  if (!(det > 1e-12 * a * c))
    return std::numeric_limits<double>::infinity();
  // The in-plane gradient G = alpha e1 + beta e2 with G.e1 = t1 - t0, G.e2 = t2 - t0.
  const double d1 = t1 - t0, d2 = t2 - t0;
  const double alpha = (c * d1 - b * d2) / det, beta = (a * d2 - b * d1) / det;
  const Vec G = { alpha * e1[0] + beta * e2[0], alpha * e1[1] + beta * e2[1], alpha * e1[2] + beta * e2[2] };
  const double g2 = Dot(G, G);
  if (g2 >= 1.0)
    return std::numeric_limits<double>::infinity();
  // The projection q of y on the plane, as barycentric coordinates (s1, s2) over e1, e2.
  const Vec w = Sub(y, y0);
  const double w1 = Dot(w, e1), w2 = Dot(w, e2);
  const double q1 = (c * w1 - b * w2) / det, q2 = (a * w2 - b * w1) / det;
  const Vec q = { y0[0] + q1 * e1[0] + q2 * e2[0], y0[1] + q1 * e1[1] + q2 * e2[1], y0[2] + q1 * e1[2] + q2 * e2[2] };
  const Vec n = Sub(y, q);
  const double h = std::sqrt(Dot(n, n));
  const double shift = h / std::sqrt(1.0 - g2);
  // p = q - G shift, in the same coordinates.
  const double p1 = q1 - alpha * shift, p2 = q2 - beta * shift;
  if (p1 < 0 || p2 < 0 || p1 + p2 > 1)
    return std::numeric_limits<double>::infinity();
  const double tq = t0 + q1 * d1 + q2 * d2;
  return tq + h * std::sqrt(1.0 - g2);
}

Vec Apply(const std::array<double, 9>& m, const std::array<double, 3>& x)
{
  return { m[0] * x[0] + m[1] * x[1] + m[2] * x[2], m[3] * x[0] + m[4] * x[1] + m[5] * x[2],
    m[6] * x[0] + m[7] * x[1] + m[8] * x[2] };
}
}

void amEikonal::AddElement(const std::array<vtkIdType, 4>& nodes, const double f[3], double along, double across)
{
  // D^-1/2 = f f^T / v_f + (I - f f^T) / v_t.
  const double n2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
  const double a = n2 > 0 ? 1.0 / along : 1.0 / across, b = 1.0 / across;
  std::array<double, 9> m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m[3 * i + j] = (i == j ? b : 0.0) + (n2 > 0 ? (a - b) * f[i] * f[j] / n2 : 0.0);
  this->Nodes.push_back(nodes);
  this->Transform.push_back(m);
}

std::vector<double> amEikonal::Solve(const std::vector<std::pair<vtkIdType, double>>& sources) const
{
  const double inf = std::numeric_limits<double>::infinity();
  const vtkIdType n = static_cast<vtkIdType>(this->Points.size());
  // Elements of each node.
  std::vector<vtkIdType> start(n + 1, 0);
  for (const auto& e : this->Nodes)
    for (vtkIdType v : e)
      if (v >= 0)
        ++start[v + 1];
  for (vtkIdType i = 0; i < n; ++i)
    start[i + 1] += start[i];
  std::vector<vtkIdType> elements(start[n]), fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < this->Nodes.size(); ++k)
    for (vtkIdType v : this->Nodes[k])
      if (v >= 0)
        elements[fill[v]++] = static_cast<vtkIdType>(k);

  std::vector<double> T(n, inf);
  using Entry = std::pair<double, vtkIdType>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (const auto& s : sources)
    if (s.first >= 0 && s.first < n && s.second < T[s.first])
    {
      T[s.first] = s.second;
      heap.push({ s.second, s.first });
    }
  while (!heap.empty())
  {
    const Entry top = heap.top();
    heap.pop();
    if (top.first > T[top.second])
      continue;
    const vtkIdType from = top.second;
    for (vtkIdType q = start[from]; q < start[from + 1]; ++q)
    {
      const vtkIdType k = elements[q];
      const auto& nodes = this->Nodes[k];
      const auto& m = this->Transform[k];
      const int count = nodes[3] >= 0 ? 4 : 3;
      Vec y[4];
      for (int a = 0; a < count; ++a)
        y[a] = Apply(m, this->Points[nodes[a]]);
      for (int target = 0; target < count; ++target)
      {
        const vtkIdType node = nodes[target];
        if (node == from)
          continue;
        // The others: the face (tetrahedron) or the edge (triangle) opposite the target.
        int other[3], known = 0;
        for (int a = 0; a < count; ++a)
          if (a != target && T[nodes[a]] < inf)
            other[known++] = a;
        double best = T[node];
        for (int i = 0; i < known; ++i)
        {
          const int a = other[i];
          const Vec d = Sub(y[target], y[a]);
          best = std::min(best, T[nodes[a]] + std::sqrt(Dot(d, d)));
          for (int j = i + 1; j < known; ++j)
          {
            const int b = other[j];
            best = std::min(best, EdgeInterior(y[target], y[a], T[nodes[a]], y[b], T[nodes[b]]));
          }
        }
        if (known == 3)
          best = std::min(best,
            FaceInterior(y[target], y[other[0]], T[nodes[other[0]]], y[other[1]], T[nodes[other[1]]], y[other[2]],
              T[nodes[other[2]]]));
        if (best < T[node] - 1e-12 * (1.0 + std::fabs(best)))
        {
          T[node] = best;
          heap.push({ best, node });
        }
      }
    }
  }
  return T;
}
