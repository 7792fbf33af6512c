/**
 * @file    amTetraImproveOptions.h
 * @brief   What the element improvement is asked (Options), what it reports (Report) and what its
 *          operations maximise (Objective): shared by its front end (amTetraMeshOptimizer) and its
 *          operations (amTetraImproveMesh.h), not wrapped.
 */
#ifndef amTetraImproveOptions_h
#define amTetraImproveOptions_h

#include <map>
#include <string>

namespace amTetraImprove
{
struct Options
{
  int Passes = 4; // rounds of flips + smoothing
  // Thresholds in Q, applied to the objective (1/Q or the dihedral term, whichever is worse):
  double FlipQuality = 1.6;   // elements above this get flips
  double SearchQuality = 2.5; // the vertices of elements above this get the local search
  int MaxRing = 7;            // largest edge ring the edge removal triangulates
  double SplitQuality = 5;    // elements with Q above this that no flip mends get an edge split
  // Slivers: elements with Q above SliverQuality or a dihedral angle below SliverDihedral
  // (degrees) that the rounds above leave. Where interfaces meet at a junction curve at a small
  // angle, or a surface triangle lies almost flat on another, no element there can be better
  // than the surface allows. When MaximumSurfaceDeviation (mm) is positive, the surface may
  // move that far to free them (amTetraImproveSlivers.cxx): their surface vertices slide, those
  // still bad take the region across a surface face (or leave the mesh at its boundary), a
  // surface edge of the rest (where its dihedral angle is smallest, else the longest) is split
  // at its midpoint, and the flips and moves run again around them, for up to SliverRounds
  // rounds. The deviation is measured (two-sided, against the surface as it was) and kept
  // within the bound; the attempts, their order and budgets: amTetraImproveSchedule.h.
  double SliverQuality = 10;
  double SliverDihedral = 10;
  double MaximumSurfaceDeviation = 0;
  int SliverRounds = 4;
  // Region volumes: where TargetVolumes (label -> mm^3) is not empty and MaximumVolumeOffset
  // (mm) positive, the surface vertices inside one interface first move along their normals,
  // by at most that distance, until each region has its target (amTetraImproveVolumes.cxx),
  // where no element falls below Q SearchQuality (or its star's worst) and the boundary does
  // not run into itself. Junction curves stay.
  std::map<int, double> TargetVolumes;
  double MaximumVolumeOffset = 0;
  int VolumeRounds = 4;
};
struct Report
{
  double WorstBefore = 0, WorstAfter = 0, MeanBefore = 0, MeanAfter = 0;
  long Flips23 = 0, EdgeRemovals = 0, EdgeSplits = 0, FaceSplits = 0, Moves = 0;
  long Relabels = 0;             // elements that changed region (or left the mesh)
  long SurfaceSplits = 0;        // surface edges split at their midpoints near slivers
  long SurfaceCollapses = 0;     // surface edges of slivers collapsed along their interface or curve
  long SurfaceMoves = 0;         // slides of surface vertices
  long VolumeMoves = 0;          // surface vertex moves that gave regions their volume
  double VolumeDisplacement = 0; // the farthest those moved a vertex (mm)
  double SurfaceDeviation = 0;   // the largest displacement of the surface they caused (mm)
  long Slivers = 0;              // elements still above SliverQuality or below SliverDihedral
  /// One line for provenance: worst and mean Q before -> after, and the operations done.
  std::string Describe() const;
};

/// What the operations maximise, in (0, 1] (1: regular), -1 when inverted or flat: the smaller
/// of 1/Q and the smallest sine of the dihedral angles over that of the regular tetrahedron, so
/// that no operation trades a dihedral angle for Q (slivers have both small).
double Objective(const double* a, const double* b, const double* c, const double* d);
}

#endif
