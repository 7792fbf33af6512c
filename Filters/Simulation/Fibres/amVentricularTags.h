/**
 * @class   amVentricularTags
 * @brief   The ventricles' surfaces tagged from the labels around them: LV endocardium, RV
 *          endocardium, epicardium and base, as triangles of the heart's boundary.
 *
 * Every face of a heart tetrahedron that the heart does not share with another heart tetrahedron
 * is a heart boundary triangle. Its tag is read from the region across it: a left-ventricular blood
 * region gives the LV endocardium, a right-ventricular one the RV endocardium, a base region (the
 * outflow tracts and atria: aorta, pulmonary artery, atrial blood) the base; anything else (lung,
 * fat, the outside of the mesh) the epicardium. A mesh of the heart alone (no blood meshed) has
 * only the outside across its boundary: the caller then tags the triangles itself.
 *
 * Plain C++ over amTetraFaces; the triangles keep the project's orientation (normal from the
 * heart outwards).
 */
#ifndef amVentricularTags_h
#define amVentricularTags_h

#include "vtkType.h"

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

class amVentricularTags
{
public:
  enum Tag : unsigned char
  {
    LVEndocardium = 1,
    RVEndocardium = 2,
    Epicardium = 3,
    Base = 4
  };
  static const char* Name(int tag);

  struct Triangle
  {
    std::array<vtkIdType, 3> Points; // mesh point ids, normal out of the heart
    vtkIdType Tetra;                 // the heart tetrahedron it bounds
    int Across;                      // the region across it (amTetraFaces::Outside() outside the mesh)
    unsigned char Tag;
  };

  std::set<int> Heart, LVBlood, RVBlood, BaseRegions;

  /// The heart's boundary triangles of a tetrahedral mesh (points x y z, tetrahedra, one label each).
  /// 'holes', when given, counts the triangles where ventricular blood touches a region other than
  /// the heart, the other pool or the base (a hole in the segmented wall), per (blood, other) pair.
  std::vector<Triangle> Find(const double* points, const std::vector<std::array<vtkIdType, 4>>& tetrahedra,
    const std::vector<int>& labels, std::map<std::pair<int, int>, vtkIdType>* holes = nullptr) const;
};

#endif
