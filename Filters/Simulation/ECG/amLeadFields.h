/**
 * @class   amLeadFields
 * @brief   The lead fields of a torso: per electrode, the weights that turn the heart's
 *          transmembrane voltage into that electrode's potential, by reciprocity.
 *
 * The bidomain's extracellular potential in the heart and the torso solves
 *   div(sigma_b grad phi) = -div(sigma_i grad Vm),   zero flux on the body surface,
 * sigma_b = sigma_i + sigma_e in the heart and the tissue's conductivity elsewhere. In P1 elements
 * A phi = -K_i Vm (A with sigma_b, K_i with sigma_i on the heart's tetrahedra). With the ground
 * node held at 0, the reciprocal problem A Z_k = e_k (a unit current into electrode k) gives
 * phi_k = Z_k . A phi = -(K_i Z_k) . Vm: one torso solve per electrode, then each lead at each time
 * is a dot product with the weights W_k = -K_i Z_k (non-zero on the heart's nodes only). The same
 * discretisation as a direct current-source solve at every time step, at the cost of one solve per
 * electrode instead of one per frame.
 *
 * Reference: D. B. Geselowitz, On the theory of the electrocardiogram, Proc. IEEE 77(6), 1989;
 * the lead-field approach of A. Neic et al., J. Comput. Phys. 346, 2017.
 */
#ifndef amLeadFields_h
#define amLeadFields_h

#include "amP1Assembly.h"

#include <array>
#include <string>
#include <vector>

class amLeadFields
{
public:
  /// fem: the whole mesh; bulk: sigma_b per tetrahedron; heart: the tetrahedra of the heart (indices
  /// into fem) and 'intracellular' their sigma_i; electrodes: the electrodes' nodes; ground: a node
  /// held at 0. False with Error when the torso matrix cannot be factored.
  bool Compute(const amP1Assembly& fem, const std::vector<std::array<double, 6>>& bulk,
    const std::vector<vtkIdType>& heart, const std::vector<std::array<double, 6>>& intracellular,
    const std::vector<vtkIdType>& electrodes, vtkIdType ground);

  /// The nodes where some weight is not zero, and per electrode the weights on them.
  std::vector<vtkIdType> Nodes;
  std::vector<std::vector<double>> Weights;
  /// Each electrode's potential (against the ground) for a voltage given on Nodes.
  std::vector<double> Potentials(const std::vector<double>& vmOnNodes) const;

  /// The body-surface node nearest each position (x y z triples) and its distance (mm).
  static void Snap(const amP1Assembly& fem, const std::vector<unsigned char>& onSurface,
    const std::vector<double>& positions, std::vector<vtkIdType>& nodes, std::vector<double>& distances);

  std::string Error;
};

#endif
