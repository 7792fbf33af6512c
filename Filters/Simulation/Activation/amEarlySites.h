/**
 * @class   amEarlySites
 * @brief   Where the conduction system first reaches the ventricles (Durrer et al. 1970): the
 *          septal endocardium of both ventricles, mid-way from apex to base.
 *
 * Durrer's isolated human hearts activate first at the left septal surface and at high anterior
 * and low posterior para-septal sites of the LV, within 5 ms of each other, and the RV's septal
 * surface near the anterior papillary muscle a few ms later. The sites here: the LV endocardial
 * nodes that face the RV (the SeptalFraction of them nearest the RV endocardium) between
 * apico-basal levels Lowest and Highest, at time 0, and the RV endocardial nodes facing the LV in the
 * same band, at RightDelay. The fast endocardial layer spreads from them.
 *
 * Reference: D. Durrer et al., Total excitation of the isolated human heart, Circulation 41:899-912, 1970.
 */
#ifndef amEarlySites_h
#define amEarlySites_h

#include "vtkType.h"

#include <array>
#include <utility>
#include <vector>

class amEarlySites
{
public:
  double SeptalFraction = 0.3;
  double Lowest = 0.3, Highest = 0.6; // apico-basal band (0 apex, 1 base)
  double RightDelay = 5.0;            // ms

  /// points: positions; lv, rv: the endocardial nodes of each ventricle; apicoBasal: per node.
  std::vector<std::pair<vtkIdType, double>> Find(const std::vector<std::array<double, 3>>& points,
    const std::vector<vtkIdType>& lv, const std::vector<vtkIdType>& rv, const std::vector<double>& apicoBasal) const;
};

#endif
