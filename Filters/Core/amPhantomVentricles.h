/**
 * @class   amPhantomVentricles
 * @brief   The thorax phantom's anatomical ventricles: a truncated prolate left ventricle with a
 *          10 mm wall and a crescent right ventricle with a 4 mm free wall wrapped round its
 *          right-anterior side, both cut by one base plane.
 *
 * In the heart's frame (rows of Axes: u from base to apex, v from the LV towards the RV, w = u x v;
 * millimetres at HeartScale 1, about Center):
 * - the LV cavity is the ellipsoid of semi-axes 50 (along u) and 23 mm centred at (-10, -8, 0),
 *   cut by the base plane u = -32 (a cavity 72 mm long, 90 mL); the LV wall is the ellipsoid
 *   10 mm larger on every semi-axis about the same centre, cut 8 mm further up (the base's cap of
 *   muscle, where the valves and atria would be);
 * - the RV cavity is the ellipsoid of semi-axes 40 (u), 14 (v) and 30 mm (w) centred at
 *   (-5, 31, 0), cut by the same base plane, less the LV wall (so the septum is the LV's wall and
 *   the RV cavity a crescent round it); the RV's free wall is that ellipsoid 4 mm larger.
 * Thin walls and an apex that points down as well as left-anterior are what a heart shows: the
 * activation crosses a 10 mm wall, not a 20 mm one, and the QRS axis points down and left.
 *
 * Plain C++ (amThoraxPhantomModel's heart with HeartShape = Ventricles).
 */
#ifndef amPhantomVentricles_h
#define amPhantomVentricles_h

#include "AnatomeshFiltersCoreModule.h" // export macro

class ANATOMESHFILTERSCORE_EXPORT amPhantomVentricles
{
public:
  /// center: the frame's origin (mm, world); axes: rows u, v, w (orthonormal); scale: HeartScale.
  amPhantomVentricles(const double center[3], const double axes[3][3], double scale);
  amPhantomVentricles() = default;

  /// The heart (LV wall with the RV's free wall, cavities included).
  bool InsideHeart(const double x[3]) const;
  /// The LV cavity.
  bool InsideLeftVentricle(const double x[3]) const;
  /// The RV cavity: outside the LV's wall.
  bool InsideRightVentricle(const double x[3]) const;

  /// Points well inside the LV cavity, the RV cavity and the LV's free wall (half-way through it).
  void LeftVentricleCenter(double x[3]) const;
  void RightVentricleCenter(double x[3]) const;
  void FreeWallCenter(double x[3]) const;

  /// Closed-form volume of the LV cavity (mm^3).
  double LeftVentricleVolume() const;

private:
  void ToLocal(const double x[3], double local[3]) const;
  void ToWorld(const double local[3], double x[3]) const;

  double Center[3] = { 0, 0, 0 };
  double Axes[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  double Scale = 1.0;
};

#endif
