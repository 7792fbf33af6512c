/**
 * @class   amEikonal
 * @brief   Activation times of an anisotropic eikonal equation on tetrahedra and triangles:
 *          sqrt(grad T . D grad T) = 1, D = V V^T the squared conduction velocity tensor.
 *
 * Elements are tetrahedra (the myocardium) and triangles (a fast conducting sheet such as the
 * endocardium, standing in for the Purkinje network); each has its own velocity tensor
 * D = v_f^2 f f^T + v_t^2 (I - f f^T). In an element the travel time between two points is the
 * distance in the metric D^-1, so in coordinates y = D^-1/2 x the element is isotropic with unit
 * speed. The local update of a node from the opposite face (or edge) is the exact minimum of
 * T(p) + |y - p| over that face, T linear on it: the face's interior stationary point (closed form),
 * else its edges' (closed form), else its vertices. The nodes are settled by a label-correcting
 * Dijkstra order (a heap by time, a node updated again whenever a neighbour's time drops), which
 * converges to the discrete solution for any anisotropy; the result does not depend on threads.
 *
 * References: Z. Fu, R. M. Kirby, R. T. Whitaker, A fast iterative method for solving the eikonal
 * equation on tetrahedral domains, SIAM J. Sci. Comput. 35(5), 2013; the local solver's closed form
 * is theirs, applied in the transformed coordinates.
 */
#ifndef amEikonal_h
#define amEikonal_h

#include "vtkType.h"

#include <array>
#include <utility>
#include <vector>

class amEikonal
{
public:
  /// The nodes' positions (mm).
  std::vector<std::array<double, 3>> Points;

  /// Adds a tetrahedron or a triangle (the fourth node -1) with its fibre direction f (unit; zero:
  /// isotropic) and the speeds along and across it (mm/ms).
  void AddElement(const std::array<vtkIdType, 4>& nodes, const double f[3], double along, double across);

  /// The earliest time of every node from the sources (node, time); +infinity where unreached.
  std::vector<double> Solve(const std::vector<std::pair<vtkIdType, double>>& sources) const;

  std::size_t NumberOfElements() const { return this->Nodes.size(); }

private:
  std::vector<std::array<vtkIdType, 4>> Nodes;
  std::vector<std::array<double, 9>> Transform; // D^-1/2, row-major
};

#endif
