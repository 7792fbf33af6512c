/**
 * @class   amRuleBasedFibres
 * @brief   Rule-based myocardial fibres and sheets on a ventricular tetrahedral mesh, from
 *          Laplace-Dirichlet transmural fields (after Bayer et al. 2012).
 *
 * Two Laplace problems on the heart: phi_LV = 1 on the LV endocardium, 0 on the RV endocardium and
 * the epicardium; phi_RV = 1 on the RV endocardium, 0 on the LV endocardium and the epicardium (the
 * base is free: zero flux). Each tetrahedron belongs to the ventricle whose field is larger there,
 * and its transmural depth is d = 1 - phi of that ventricle: 0 on its endocardium, 1 on the
 * epicardium, and, in the septum, 1 on the other ventricle's endocardium up to where both fields
 * meet (d = 1/2 on either side). The local frame per tetrahedron:
 *   e_t = -grad phi / |grad phi|                      transmural, endocardium to epicardium,
 *   e_l = the apex-to-base axis without its e_t part   longitudinal,
 *   e_c = e_l x e_t                                    circumferential (anticlockwise seen from the base),
 * and the fibre is e_c turned about e_t by the helix angle alpha(d) = alpha_endo + (alpha_epi -
 * alpha_endo) d: f = cos(alpha) e_c + sin(alpha) e_l, positive angles a right-handed helix about the
 * apex-to-base axis. The sheet is e_t turned about f by the transverse angle beta(d) (0 by default).
 * The longitudinal direction is the given long axis rather than the gradient of an apico-basal
 * Laplace field (Bayer's psi), and the two ventricles' frames are picked, not blended by bislerp:
 * in the septum, where the pick changes, both frames give alpha near 0 along the same line, so the
 * fibres stay continuous up to their sign.
 *
 * Also per node: TransmuralDepth (d), ApicoBasal (0 at the heart's most apical node, 1 at its most
 * basal, along the axis) and the ventricle (0 LV, 1 RV), the coordinates that action-potential
 * gradients use.
 *
 * Reference: J. D. Bayer, R. C. Blake, G. Plank, N. A. Trayanova, A novel rule-based algorithm for
 * assigning myocardial fiber orientation to computational heart models, Ann. Biomed. Eng. 40(10),
 * 2012.
 */
#ifndef amRuleBasedFibres_h
#define amRuleBasedFibres_h

#include "amP1Assembly.h"

#include <array>
#include <string>
#include <vector>

class amRuleBasedFibres
{
public:
  struct Parameters
  {
    double HelixEndocardium = 60.0;     // degrees
    double HelixEpicardium = -60.0;     // degrees
    double TransverseEndocardium = 0.0; // degrees
    double TransverseEpicardium = 0.0;  // degrees
    std::array<double, 3> ApexToBase{ 0, 0, 1 };
  };

  /// The fields and frames of the heart 'fem' (its nodes, its tetrahedra) whose boundary nodes are
  /// given per node as 'tag' (amVentricularTags::Tag, 0 where a node is on no tagged triangle; a
  /// node on the endocardium and another surface counts as endocardium). False with Error when
  /// there is no LV or RV endocardium, no epicardium, or a field cannot be solved.
  bool Compute(const amP1Assembly& fem, const std::vector<unsigned char>& tag, const Parameters& parameters);

  std::vector<std::array<double, 3>> Fibres, Sheets; // per tetrahedron, unit
  std::vector<double> TransmuralDepth;               // per node
  std::vector<double> ApicoBasal;                    // per node
  std::vector<unsigned char> Ventricle;              // per node: 0 LV, 1 RV
  std::string Error;

  /// The helix angle (degrees) of fibre f in the frame of transmural t and apex-to-base axis a,
  /// in (-90, 90]: the measure of the rule, for tests and reports.
  static double HelixAngle(const double f[3], const double t[3], const double a[3]);
};

#endif
