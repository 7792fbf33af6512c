#include "amVentricularTags.h"

#include "amTetraFaces.h"

const char* amVentricularTags::Name(int tag)
{
  switch (tag)
  {
    case LVEndocardium:
      return "LVEndocardium";
    case RVEndocardium:
      return "RVEndocardium";
    case Epicardium:
      return "Epicardium";
    case Base:
      return "Base";
    default:
      return "None";
  }
}

std::vector<amVentricularTags::Triangle> amVentricularTags::Find(const double* points,
  const std::vector<std::array<vtkIdType, 4>>& tetrahedra, const std::vector<int>& labels,
  std::map<std::pair<int, int>, vtkIdType>* holes) const
{
  // Every heart region one label, so faces between two heart regions are interior.
  std::vector<int> merged(labels);
  const int heartLabel = this->Heart.empty() ? 0 : *this->Heart.begin();
  for (int& l : merged)
    if (this->Heart.count(l))
      l = heartLabel;
  std::vector<Triangle> out;
  for (const amTetraFaces::Face& f : amTetraFaces::Find(points, tetrahedra, merged.data()))
  {
    const bool firstIsHeart = f.First == heartLabel && this->Heart.count(labels[f.FirstTetra]);
    const bool secondIsHeart = f.SecondTetra >= 0 && f.Second == heartLabel && this->Heart.count(labels[f.SecondTetra]);
    if (holes && !firstIsHeart && !secondIsHeart)
    {
      auto may = [&](int l) { return this->LVBlood.count(l) || this->RVBlood.count(l) || this->BaseRegions.count(l); };
      for (const auto& pair : { std::make_pair(f.First, f.Second), std::make_pair(f.Second, f.First) })
        if ((this->LVBlood.count(pair.first) || this->RVBlood.count(pair.first)) && !may(pair.second))
          ++(*holes)[pair];
    }
    if (firstIsHeart == secondIsHeart)
      continue;
    Triangle t;
    t.Points = f.Points;
    if (firstIsHeart)
    {
      t.Tetra = f.FirstTetra;
      t.Across = f.SecondTetra >= 0 ? labels[f.SecondTetra] : amTetraFaces::Outside();
    }
    else
    {
      // The normal points from First into Second: turn it to point out of the heart.
      std::swap(t.Points[1], t.Points[2]);
      t.Tetra = f.SecondTetra;
      t.Across = labels[f.FirstTetra];
    }
    if (this->LVBlood.count(t.Across))
      t.Tag = LVEndocardium;
    else if (this->RVBlood.count(t.Across))
      t.Tag = RVEndocardium;
    else if (this->BaseRegions.count(t.Across))
      t.Tag = Base;
    else
      t.Tag = Epicardium;
    out.push_back(t);
  }
  return out;
}
