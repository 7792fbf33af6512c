/**
 * @file    amSurfaceCurvature.h
 * @brief   The principal curvatures of a labelled triangle surface and the sizes they ask for (not
 *          wrapped): the plain core of amCurvatureMetric.
 *
 * At every vertex, on every interface it lies on, a quadric height function is fitted by least
 * squares to the interface's vertices within Radius (reached through that interface's triangles)
 * and at least its Rings-ring; the interface of the largest curvature gives the vertex's. With
 * ScaleAdaptive, the fit is made again over the size the last fit asks for (the median over the
 * vertex's 2-ring, from Radius to three times it), three times, so that ripples shorter than the
 * triangles average out. Curvatures in 1/mm, signed (bending away from the normal positive);
 * deterministic on any number of threads.
 */
#ifndef amSurfaceCurvature_h
#define amSurfaceCurvature_h

#include <functional>
#include <vector>

class amSurfaceMesh;

namespace amSurfaceCurvature
{
struct Principal
{
  double K1 = 0, K2 = 0; // K1 >= K2
  double D1[3] = { 1, 0, 0 }, D2[3] = { 0, 1, 0 }, N[3] = { 0, 0, 1 };
};

/// amCurvatureMetric's properties: Radius is the resolved NeighborhoodRadius (mm, 0: rings only).
struct Settings
{
  double Radius = 0;
  int Rings = 2;
  bool ScaleAdaptive = true;
  double Tolerance = 0.2, MinimumSize = 0.5, MaximumSize = 20.0; // mm
};

/// The principal curvatures and directions at every vertex; progress(fraction) between passes.
std::vector<Principal> Estimate(
  const amSurfaceMesh& mesh, const Settings& settings, const std::function<void(double)>& progress = nullptr);

/// The edge length whose chord deviates by Tolerance from a circle of curvature k,
/// sqrt(6 Tolerance / |k|), within MinimumSize..MaximumSize (MaximumSize where k is 0).
double Size(double k, const Settings& settings);

/// Grades a size field along the surface's edges: no vertex larger than a neighbour's size plus
/// slope times their distance (the smallest sizes spread first).
void Grade(const amSurfaceMesh& mesh, double slope, std::vector<double>& field);
}

#endif
