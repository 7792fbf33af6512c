/**
 * @class   amVolumeOffsets
 * @brief   One normal offset per interface that gives every region its target volume to first
 *          order: the offsets of smallest area-weighted norm (not wrapped).
 *
 * An interface (a sheet) lies between labels Lo and Hi; moving its vertices by an offset o along
 * their normals (pointing out of Lo into Hi) changes Lo's volume by +Sensitivity * o and Hi's by
 * -Sensitivity * o. The offsets minimise sum(Area * o^2) subject to every region with an error
 * getting it back: (B W^-1 B^T) y = error, o = W^-1 B^T y, with B[region][sheet] = +-Sensitivity
 * and W = Area, a sparse system of regions x regions (a region coupled to its neighbours). A
 * label without an error entry (the outside, a region without a target) takes up what the
 * others need. A region that no sheet can move (or enclosed by regions that cannot give way)
 * makes the system singular: a small diagonal term leaves its share at zero. Offsets are clamped
 * to +-limit. Shared by the surface remeshing and the tetrahedral mesh's volume correction.
 */
#ifndef amVolumeOffsets_h
#define amVolumeOffsets_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <map>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amVolumeOffsets
{
public:
  struct Sheet
  {
    int Lo = -1, Hi = -1;   // the labels on either side (the normal points out of Lo)
    double Sensitivity = 0; // d(volume of Lo) / d(offset), mm^2
    double Area = 0;        // the weight of the sheet's offset, mm^2
    bool Valid() const { return this->Lo != this->Hi && this->Area > 0 && this->Sensitivity > 0; }
  };

  /// error: target minus current volume (mm^3) for each label to correct. Returns one offset
  /// per sheet (mm; 0 for invalid sheets), or an empty vector when nothing can be solved.
  static std::vector<double> Solve(const std::vector<Sheet>& sheets, const std::map<int, double>& error, double limit);
};

#endif
