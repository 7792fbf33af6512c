// The improvement's objective and its report's one line.
#include "amTetraImproveOptions.h"

#include "amTetraGeometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amTetraImprove
{
using Vec = amTetraGeometry::Vec;

double Objective(const double* a, const double* b, const double* c, const double* d)
{
  const double volume = amTetraGeometry::SignedVolume(a, b, c, d);
  if (!(volume > 0))
    return -1.0;
  using G = amTetraGeometry;
  const Vec ab = G::Sub(b, a), ac = G::Sub(c, a), ad = G::Sub(d, a), bc = G::Sub(c, b), bd = G::Sub(d, b),
            cd = G::Sub(d, c);
  // Twice the area of the face opposite each vertex.
  const double fa = G::Norm(G::Cross(bc, bd)), fb = G::Norm(G::Cross(ac, ad)), fc = G::Norm(G::Cross(ab, ad)),
               fd = G::Norm(G::Cross(ab, ac));
  const double lab = G::Norm(ab), lac = G::Norm(ac), lad = G::Norm(ad), lbc = G::Norm(bc), lbd = G::Norm(bd),
               lcd = G::Norm(cd);
  const double longest = std::max({ lab, lac, lad, lbc, lbd, lcd });
  const double inradius = 6.0 * volume / (fa + fb + fc + fd);
  const double inverseQ = 2.0 * std::sqrt(6.0) * inradius / longest;
  // sin of the dihedral angle at edge ij = 3 V l_ij / (2 A_k A_l) (faces k, l opposite the
  // other two vertices); the regular tetrahedron's is sqrt(8)/3.
  const double minSine = 6.0 * volume *
    std::min({ lab / (fc * fd), lac / (fb * fd), lad / (fb * fc), lbc / (fa * fd), lbd / (fa * fc), lcd / (fa * fb) });
  return std::min(inverseQ, minSine * 3.0 / std::sqrt(8.0));
}

std::string Report::Describe() const
{
  std::ostringstream os;
  os << "worst Q " << this->WorstBefore << " -> " << this->WorstAfter << ", mean " << this->MeanBefore << " -> "
     << this->MeanAfter << " (" << this->EdgeRemovals << " edge removals, " << this->Flips23 << " 2-3 flips, "
     << this->EdgeSplits << " edge splits, " << this->FaceSplits << " face splits, " << this->Moves << " vertex moves";
  if (this->VolumeMoves > 0)
    os << "; " << this->VolumeMoves << " surface vertex moves, at most " << this->VolumeDisplacement
       << " mm, for the regions' volumes";
  if (this->SurfaceMoves + this->Relabels + this->SurfaceSplits + this->SurfaceCollapses > 0)
    os << "; around slivers " << this->SurfaceMoves << " surface vertex slides, " << this->Relabels
       << " region changes, " << this->SurfaceSplits << " surface edge splits, " << this->SurfaceCollapses
       << " surface edge collapses: the surface moved by " << this->SurfaceDeviation << " mm";
  os << "; " << this->Slivers << " slivers left)";
  return os.str();
}
}
