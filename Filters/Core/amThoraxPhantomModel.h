/**
 * @class   amThoraxPhantomModel
 * @brief   Analytic description of a synthetic thorax (the embedded default input).
 *
 * In the spirit of the NCAT phantom used by the CEMRACS 2004 paper, the thorax is built from
 * analytic shapes so that every surface, volume and label is known exactly:
 *
 * | label | organ            | shape                                                   | HU    |
 * |-------|------------------|---------------------------------------------------------|-------|
 * | 0     | background (air) | outside the body                                        | -1000 |
 * | 1     | soft tissue      | inside the inner body, not in an organ                  | 40    |
 * | 2     | fat              | shell between the outer and inner body superquadrics    | -100  |
 * | 3     | right lung       | ellipsoid (patient right = -x)                          | -850  |
 * | 4     | left lung        | ellipsoid                                               | -850  |
 * | 5     | myocardium       | rotated ellipsoid minus the two blood pools             | 50    |
 * | 6     | LV blood pool    | rotated ellipsoid inside the myocardium                 | 300   |
 * | 7     | RV blood pool    | rotated ellipsoid inside the myocardium                 | 300   |
 * | 8     | aorta            | ascending tube, half-torus arch, descending tube        | 300   |
 * | 9     | spine            | capped cylinder                                         | 700   |
 * | 10    | ribs             | tilted elliptic tubes, 7 pairs                          | 700   |
 *
 * Coordinates are millimetres in the patient LPS frame (x to the patient's left, y posterior,
 * z superior), centred on the origin. Organs are clipped by the inner body, and where two organs
 * overlap the one listed later wins (heart over lungs, aorta over everything soft).
 * The geometry is designed so that the body, fat, myocardium, blood pools, aorta and spine do not
 * overlap anything of higher precedence: their volumes are closed-form (ExactVolume()).
 * Contrast-enhanced blood (300 HU) is what a cardiac CT shows.
 *
 * Plain C++ so tests can query the truth (LabelAt, SignedDistance-free inside tests, volumes)
 * without a pipeline.
 */
#ifndef amThoraxPhantomModel_h
#define amThoraxPhantomModel_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include "amPhantomVentricles.h"

#include <string>
#include <vector>

class ANATOMESHFILTERSCORE_EXPORT amThoraxPhantomModel
{
public:
  enum Label : unsigned char
  {
    Background = 0,
    SoftTissue = 1,
    Fat = 2,
    RightLung = 3,
    LeftLung = 4,
    Myocardium = 5,
    LeftVentricleBlood = 6,
    RightVentricleBlood = 7,
    Aorta = 8,
    Spine = 9,
    Ribs = 10,
    NumberOfLabels = 11
  };

  /// The heart's shape: Ellipsoidal (the default), one ellipsoid of muscle 12-20 mm thick round two
  /// ellipsoidal blood pools, its long axis in the axial plane; Ventricles (amPhantomVentricles),
  /// a truncated LV with a 10 mm wall and a crescent RV with a 4 mm free wall, the apex also
  /// pointing 25 degrees down, as a heart's does.
  enum HeartShapes
  {
    Ellipsoidal = 0,
    Ventricles = 1
  };

  /// The patient's build: the subcutaneous fat's thickness (mm, over an inner body of fixed size,
  /// so a larger patient has a larger body), the heart's size (a scale of every heart shape about
  /// its centre) and its long axis's angle in the axial plane (degrees from the patient's left, the
  /// default -30 turning it towards the left-anterior side; -45 more horizontal, -15 more vertical
  /// in a frontal chest film's sense is not modelled: the tilt stays in the axial plane) and its
  /// shape (HeartShapes).
  struct Habitus
  {
    double FatThickness = 12.0;
    double HeartScale = 1.0;
    double HeartAngle = -30.0;
    int HeartShape = Ellipsoidal;
  };

  amThoraxPhantomModel();
  explicit amThoraxPhantomModel(const Habitus& habitus);

  /// A point in the heart's frame, in units of the heart's scale (the frame turns and scales with
  /// Habitus), and back: a click placed on one heart lands at the same place of another's with
  /// other.HeartFrameToWorld(one.WorldToHeartFrame(click)).
  void WorldToHeartFrame(const double world[3], double frame[3]) const;
  void HeartFrameToWorld(const double frame[3], double world[3]) const;

  /// Label of the point x (mm, LPS). Pure function of x: deterministic and thread-safe.
  unsigned char LabelAt(const double x[3]) const;

  /// Nominal CT value of a label (Hounsfield units).
  static double HounsfieldUnits(int label);
  /// Human-readable organ name ("Myocardium", ...); "Unknown" outside the range.
  static const char* LabelName(int label);

  /// Exact volume (mm^3) of the region that carries this label, when it is closed-form;
  /// a negative value when it is not (lungs, soft tissue, ribs).
  double ExactVolume(int label) const;
  /// Exact volume (mm^3) of the whole body (every non-zero label together).
  double BodyVolume() const;

  /// Axis-aligned bounds (mm) that contain the whole body: {xmin,xmax,ymin,ymax,zmin,zmax}.
  void GetBodyBounds(double bounds[6]) const;

  /// Inside tests of the individual analytic shapes, before precedence is applied
  /// (tests measure surface errors against these).
  bool InsideBody(const double x[3]) const;
  bool InsideInnerBody(const double x[3]) const;
  bool InsideLung(const double x[3], bool left) const;
  bool InsideHeart(const double x[3]) const;
  bool InsideLeftVentricle(const double x[3]) const;
  bool InsideRightVentricle(const double x[3]) const;
  bool InsideAorta(const double x[3]) const;
  bool InsideSpine(const double x[3]) const;
  bool InsideRib(const double x[3]) const;

  /// Centre points well inside each blood pool / organ (seeds for segmentation tests).
  void GetOrganCenter(int label, double center[3]) const;

  /// Electrode positions of the standard 12-lead ECG on this body (mm, LPS), in the order RA, LA,
  /// LL (limb electrodes moved onto the torso as in the Mason-Likar placement), V1..V6 (fourth and
  /// fifth intercostal spaces around the heart). Positions lie on or near the body surface; ECG
  /// filters snap each to the closest surface node.
  static void StandardElectrodes(double positions[9][3]);

  /// A rotated ellipsoid: centre, semi-axes and a rotation (rows = ellipsoid axes in world).
  struct Ellipsoid
  {
    double Center[3];
    double Radii[3];
    double Axes[3][3];
    bool Inside(const double x[3]) const;
    double Volume() const;
  };

private:
  // Body: |x/a|^2 + |y/b|^2 + |z/c|^q <= 1 (a flattened, round-ended elliptic cylinder).
  double BodyRadii[3];
  double FatThickness;
  double HeartScale;
  double BodyExponent;
  Ellipsoid Lungs[2];
  Ellipsoid Heart;
  Ellipsoid LeftVentricle;
  Ellipsoid RightVentricle;
  // HeartShape Ventricles: the heart's frame is Heart's (its Axes tilted apex-down).
  int HeartShape;
  amPhantomVentricles AnatomicalVentricles;
  // Aorta: half torus of major radius ArchRadius in the y-z plane centred at ArchCenter, tubes
  // of radius AortaRadius going down from both ends (ascending ends at AscendingBottom,
  // descending at DescendingBottom).
  double ArchCenter[3];
  double ArchRadius;
  double AortaRadius;
  double AscendingBottom;
  double DescendingBottom;
  // Spine: cylinder along z.
  double SpineCenter[2];
  double SpineRadius;
  double SpineZ[2];
  // Ribs.
  int NumberOfRibPairs;
  double RibRadius;
  double RibRing[2];
  double RibZTop;
  double RibSpacing;
  double RibTilt;
  // Per rib pair: its height and the semi-axes of its ring (derived in the constructor).
  std::vector<double> RibHeight, RibA, RibB;

  static bool InsideSuperquadric(const double x[3], const double radii[3], double q);
  static double SuperquadricVolume(const double radii[3], double q);
};

#endif
