#include "amRemeshSurface.h"

#include <limits>

namespace amRemesh
{
void Surface::Neighbours(int v, std::vector<int>& out) const
{
  out.clear();
  for (int t : this->VT[v])
    for (int k = 0; k < 3; ++k)
      if (this->T[t].V[k] != v)
        out.push_back(this->T[t].V[k]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void Surface::EdgeTriangles(int a, int b, std::vector<int>& out) const
{
  out.clear();
  for (int t : this->VT[a])
  {
    const int* v = this->T[t].V;
    if (v[0] == b || v[1] == b || v[2] == b)
      out.push_back(t);
  }
}

bool Surface::IsFeature(int a, int b) const
{
  std::vector<int> edge;
  this->EdgeTriangles(a, b, edge);
  return this->IsFeature(edge);
}

bool Surface::ComponentAtMost(int v, size_t n) const
{
  std::vector<int> seen{ v }, next;
  for (size_t i = 0; i < seen.size(); ++i)
  {
    this->Neighbours(seen[i], next);
    for (int w : next)
      if (std::find(seen.begin(), seen.end(), w) == seen.end())
      {
        seen.push_back(w);
        if (seen.size() > n)
          return false;
      }
  }
  return true;
}

int Surface::AddVertex(const Vec3& x, const Mat3& m, unsigned char kind, int anchor)
{
  const int v = static_cast<int>(this->P.size());
  this->P.push_back(x);
  this->M.push_back(m);
  this->Kind.push_back(kind);
  this->Anchor.push_back(anchor);
  this->Merged.emplace_back();
  this->VAlive.push_back(1);
  this->Held.push_back(0);
  this->VT.emplace_back();
  this->Cluster.emplace_back();
  return v;
}

void Surface::SizeDirty()
{
  if (this->Dirty.size() < this->P.size())
    this->Dirty.resize(this->P.size(), 1);
  if (this->FlipDirty.size() < this->P.size())
    this->FlipDirty.resize(this->P.size(), 1);
}

void Surface::AngleSummary(long long& small, double& smallest, double& shortest) const
{
  small = 0;
  smallest = M_PI;
  shortest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : this->T)
    if (t.Alive)
    {
      const Vec3 &a = this->P[t.V[0]], &b = this->P[t.V[1]], &c = this->P[t.V[2]];
      const double angle = MinAngle(a, b, c);
      small += angle < SmallAngle;
      smallest = std::min(smallest, angle);
      shortest = std::min({ shortest, (b - a).norm(), (c - b).norm(), (a - c).norm() });
    }
}
}
