/**
 * @file    amTorsoLabels.h
 * @brief   The steps of the torso segmentation (amTorsoSegmentation) as plain functions on voxel
 *          arrays: the tissues from the intensity classes, and the myocardium around the blood pools.
 *
 * The label scheme is the thorax phantom's (amThoraxPhantomModel), so a segmentation scores
 * against the phantom's truth label by label and the simulation finds its heart in region 5.
 */
#ifndef amTorsoLabels_h
#define amTorsoLabels_h

#include "amThoraxPhantomModel.h"
#include "amVoxelGrid.h"

#include <cstdint>
#include <vector>

namespace amTorso
{
/// The output labels are the phantom's (amThoraxPhantomModel::Label), and the atria's blood where
/// the organ map holds it (the phantom has no atria).
using Phantom = amThoraxPhantomModel;
constexpr int Atria = 11;
/// The trachea and the main bronchi (Airway), where the scan tells gas from aerated lung.
constexpr int AirwayLabel = 12;

/// The classes of amIntensityClassifier's CT defaults.
enum Class : std::uint8_t
{
  AirClass = 0,
  LungClass = 1,
  FatClass = 2,
  SoftClass = 3,
  BloodClass = 4,
  BoneClass = 5
};

struct TissueReport
{
  std::size_t ExteriorVoxels = 0;
  std::size_t FatPartialVolume = 0;  // fat voxels in sheets one voxel thick, handed to neighbours
  int LungComponents = 0;            // air/lung components inside the body of at least the minimum size
  bool LungsSplit = false;           // one air component held both lungs, parted where they meet
  bool LungsSplitAtMidPlane = false; // ... and they could not be parted there: split at the mid-plane
  int BoneComponents = 0;
  std::size_t RibsJoinedToSpine = 0; // voxels of the largest bone piece parted from its column
  std::size_t GasBelowLungs = 0;     // air voxels under the lungs across tissue: not lung
  std::size_t TableVoxels = 0;       // the patient table's: outside the body
};

struct TissueParameters
{
  std::size_t MinimumVoxels = 0; // smaller components are left Pending
  double BodyGap = 0.0;          // mm: see amTorsoSegmentation::BodyGapClosing
  double MinimumOpening = 400.0; // mm^2: the outside air meets a side of the image over a patch this wide
                                 // (a bronchus's lumen, where the field cuts a lung, over a smaller one)
  bool FindTable = true;         // the patient table is exterior (PatientTable)
  double LungOpening = 0.0;      // mm: the lungs are the air inside the body opened by this ball
  bool LeftoverAirIsFat = false; // air inside the body that is not lung is fat (below the window)
  bool GasIsNotLung = false;     // a component mostly of the air class is gas, not lung (the scan
                                 // tells lung from air)
  // The index axis closest to the patient's head-feet axis (-1: unknown), and +1 when the index
  // grows towards the head: air under the lungs across tissue is not lung (GasBelowLungs).
  int SuperiorAxis = -1;
  int SuperiorSign = 1;
  // Trabecular bone: voxels brighter than TrabecularLevel (HU) that cortical bone encloses in a
  // slice across any index axis, in holes of at most MaximumMarrowArea mm^2.
  const float* HU = nullptr;
  double TrabecularLevel = 1e30;
  double MaximumMarrowArea = 2000.0;
  // Bone's partial volume: voxels brighter than BonePartialLevel (HU) within two voxels of the
  // bone class (where contrast blood pushes the bone class's boundary above thin bones' edges).
  double BonePartialLevel = 1e30;
  // Contrast blood connected to the seeded pools (ContrastVessels; null: none): never bone, nor
  // the two voxels around it (its partial volume).
  const amVoxelMask* Vessels = nullptr;
  // Where the scan's window clips bone below cortical bone's intensity (a window's ceiling under
  // 700 HU), bone cannot be told from contrast by intensity: it is the cortex (brighter than
  // CortexLevel, HU) away from the vessels and not bordered mostly by lung, and the marrow it
  // reaches (brighter than MarrowLevel, within MarrowReach mm; ClippedBone).
  bool BoneClipped = false;
  double CortexLevel = 1e30;
  double MarrowLevel = 1e30;
  double MarrowReach = 12.0;
};

/// The contrast-filled vessels and chambers: the voxels brighter than level connected to the pools
/// (the seeded blood pools) through the mask opened by the 6-neighbour cross (so a vessel touching
/// a bone through a voxel-thin contact does not carry the bone along).
amVoxelMask ContrastVessels(const amVoxelGrid& g, const float* hu, float level, const amVoxelMask& pools);

/// Bone where the window clips it (TissueParameters::BoneClipped): outside the exterior and
/// away from nearVessels.
amVoxelMask ClippedBone(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, const amVoxelMask& exterior,
  const amVoxelMask& nearVessels, const TissueParameters& p);

/// Where the patient table is told from the body (PatientTable), in mm.
struct TableParameters
{
  int MinimumSlices = 20;         // fewer slices cannot tell a table from a body that does not change
  double MinimumLength = 60.0;    // mm along the axis, likewise
  double Constancy = 0.9;         // the share of the slices a table's pixel is dense in
  double MaximumThickness = 12.0; // mm: a shell; the body's constant parts are thicker
  double MinimumExtent = 100.0;   // mm across: a table spans the body's back (half where the image cuts it)
};

/// The patient table (couch): thin plates (shells of the fat's density or more) that lie at the
/// same place in at least Constancy of the slices across axis (the scanner's long axis, within a
/// pixel), at most MaximumThickness thick, at least MinimumExtent long across (half of it where the
/// plane's border cuts them) and beside air in
/// the same share of the slices; and the foam between them (lung-like density, equally constant).
/// The body's outline changes from slice to slice; a table is made along the axis. Returns its
/// voxels (those not of the air class); none when the scan has too few slices to tell.
amVoxelMask PatientTable(
  const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, int axis, const TableParameters& p);

/// Tissue labels from the classes: the exterior air (the air class connected to the sides of the
/// first two index axes) 0; the body SoftTissue; fat (opened: partial-volume sheets are left
/// Pending); the two largest air/lung components inside the body the lungs, right and left by
/// world x against the body's centre (x to the patient's left); bone components the spine (the
/// largest) and ribs. Small components and the air that is not lung are left Pending (or Fat).
/// worldX: x = row[0] i + row[1] j + row[2] k + row[3].
TissueReport Tissues(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, const double worldX[4],
  const TissueParameters& p, std::vector<std::uint8_t>& labels);

/// Parts one air component that holds both lungs where they meet (the trachea, the carina, the
/// main bronchi): the lungs' deepest parts, at the least depth where they fall into two cores of
/// comparable size (the second at least a tenth of the first), and every voxel of the component
/// to the nearer core. side[v] = 1 or 2 for the two parts (0 elsewhere); false when no depth
/// parts it (the component is not two lungs joined by a thinner airway).
bool SplitJoinedLungs(
  const amVoxelGrid& g, const amVoxelMask& lungs, std::size_t minimumVoxels, std::vector<std::uint8_t>& side);

/// The air below the lungs across the diaphragm: the basins of the air's depth (amVoxel::Basins,
/// a dynamic of two voxels) of which more than half lies under air of a larger basin with tissue
/// between, walking down each column along superiorAxis (superiorSign +1: the index grows towards
/// the head). The stomach's and the bowel's gas, and abdominal fat under a window that shows it as
/// air, are joined to a lung only through narrow passages; the lungs lie under no other air.
amVoxelMask GasBelowLungs(const amVoxelGrid& g, const amVoxelMask& air, int superiorAxis, int superiorSign);

/// Where the airway is told from the lungs (Airway), in mm and mm^2.
struct AirwayParameters
{
  // The trachea's section where it leaves the field (an adult's lumen 150-450, a child's from 50).
  double MinimumTracheaArea = 50.0;
  double MaximumTracheaArea = 1000.0;
  double MinimumTracheaDepth = 20.0; // the trachea lies deep in the neck (an adult's 30 mm and more from the skin)
  double LungClosing = 12.0;         // a bronchus inside a lung (its lumen and wall) is narrower than this ball
  // The lumen's partial volume: voxels darker than LumenLevel (HU; half-way from gas to the wall's
  // soft tissue) beside the gas, where HU is given.
  const float* HU = nullptr;
  double LumenLevel = -480.0;
};

/// The trachea and the main bronchi, labelled AirwayLabel: the gas (air class, inside the body) of
/// a component that leaves the field at its top slice along superiorAxis (superiorSign +1: the
/// index grows towards the head) with a section of MinimumTracheaArea to MaximumTracheaArea, part
/// of it deeper in the body than MinimumTracheaDepth (the image's border is not the body's), and
/// enters both lungs, where it lies outside both lungs (each lung's parenchyma, the lung class away from that gas,
/// closed by a ball of LungClosing), with the voxels darker than LumenLevel in two rings round it
/// outside the lungs (the lumen's partial volume). The oesophagus's gas enters no lung; the
/// stomach's and the bowel's leave no field at its top; a field that holds the larynx and the
/// mouth shows no trachea leaving it. Needs the lungs labelled and a scan that tells gas from
/// aerated lung. Returns the voxels labelled.
std::size_t Airway(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, int superiorAxis, int superiorSign,
  std::size_t minimumVoxels, const AirwayParameters& p, std::vector<std::uint8_t>& labels);

/// Where a vertebral column is parted from the ribs joined to it (VertebralColumn), in mm.
struct ColumnParameters
{
  double HalfWidth = 35.0;    // the band either side of the column's centre (a thoracic vertebra's
                              // transverse processes end 25-40 mm from it; the ribs' heads lie inside)
  double Stub = 20.0;         // a piece outside the band that ends within this of it is a process
  double Window = 20.0;       // slices this far above and below place the column's centre
  double Midline = 0.0;       // the body's centre along the left-right axis (world x)
  double MidlineReach = 60.0; // the column's centre lies this near it (the shoulders lie beyond)
};

/// The vertebral column within a skeleton whose ribs are joined to it (the largest bone
/// component of a scan whose voxels join ribs to vertebrae at their joints): the bone within
/// HalfWidth of the column's centre along the patient's left-right axis (world x), slice by slice
/// across superiorAxis, in pieces that hold a vertebral body (bone at least three quarters as deep
/// as the deepest within Window), and the pieces beyond that end within Stub of the band. The centre of a
/// slice is the median x of the deepest bone within MidlineReach of Midline and within Window.
/// Without a superior axis (-1), all of the bone.
amVoxelMask VertebralColumn(
  const amVoxelGrid& g, const amVoxelMask& bone, const double worldX[4], int superiorAxis, const ColumnParameters& p);

/// Where the aorta is found without a click (AortaFromContrast), in mm and mm^3.
struct AortaParameters
{
  double Opening = 3.0;        // the contrast is opened by a ball of this radius first
  double Reach = 45.0;         // its voxels beside the column lie this near the column's centre
  double MinimumLength = 50.0; // ... over at least this length of the column
  double MinimumVolume = 5000.0;
};

struct AortaReport
{
  bool Found = false;
  double Length = 0.0; // mm of the column the chosen piece runs beside
  double Volume = 0.0; // mm^3
};

/// The aorta where the organs hold none: of the contrast blood given (contrast: its voxels outside
/// every organ), opened by the 6-neighbour cross (so a vein touching it, or the partial volume at a
/// chamber's wall, does not join it), the piece with the most voxels in front of the vertebral
/// column (labels Spine; world[1] is y, to the patient's back) within Reach of its centre, slice
/// by slice across superiorAxis: the descending aorta runs down beside the vertebral bodies, the
/// arch and the ascending aorta with it. None when that piece runs beside the column for less than
/// MinimumLength or is smaller than MinimumVolume. world: rows of the voxel-to-world transform.
amVoxelMask AortaFromContrast(const amVoxelGrid& g, const amVoxelMask& contrast,
  const std::vector<std::uint8_t>& labels, const double world[3][4], int superiorAxis, const AortaParameters& p,
  AortaReport& report);

/// How AortaOutOfAtria follows the ascending aorta down through the atria's label.
struct AscendingAortaParameters
{
  double MinimumDiameter = 20.0; // mm: a track starts from an aorta section at least this wide
  double Margin = 1.2;           // the next section lies within this times the tube's radius
  double SmallestArea = 0.5;     // each section's area, as a fraction of the first: at least
  double LargestArea = 1.3;      // ... and at most
};

/// Where the atria's snake took the ascending aorta (its contrast is theirs, and the root touches
/// the left atrium): each of the aorta's sections (in slices across superiorAxis; superiorSign
/// +1 when the slice index grows towards the head) at least MinimumDiameter wide is followed
/// down, the atria's voxels of the next slice under it and within the tube's disk taking the
/// aorta's label while the section stays the tube's size. Returns the voxels relabelled.
std::size_t AortaOutOfAtria(const amVoxelGrid& g, int superiorAxis, int superiorSign, const AscendingAortaParameters& p,
  std::vector<std::uint8_t>& labels);

/// The heart's base: a plane through the LV's pool where it meets the atria or the aorta, its
/// normal (unit) along the LV's long axis towards the apex (the pool's voxel farthest from it).
/// Positions are index times spacing. Found is false where the LV's pool meets neither.
struct ValvePlane
{
  bool Found = false;
  double Point[3] = { 0.0, 0.0, 0.0 };
  double Normal[3] = { 0.0, 0.0, 1.0 };
  /// mm towards the apex (negative above the base).
  double Height(const amVoxelGrid& g, std::size_t v) const;
};
ValvePlane FindValvePlane(const amVoxelGrid& g, const std::vector<std::uint8_t>& labels, int lv);

/// The RV's pool more than margin mm above the base (its label past the tricuspid valve, where the
/// snake ran into the right atrium) goes to the atria. Returns the voxels relabelled.
std::size_t EndVentriclesAtValves(
  const amVoxelGrid& g, const ValvePlane& plane, int rv, double margin, std::vector<std::uint8_t>& labels);

struct WallParameters
{
  std::vector<int> PoolLabels{ Phantom::LeftVentricleBlood, Phantom::RightVentricleBlood };
  double MaximumThickness = 40.0; // mm from the pools
  double Thickness = 10.0;        // mm, where intensity cannot tell the wall
  double RightThickness = 4.0;    // mm, the same for the RV (the second pool label)
  double MinimumThickness = 3.0;  // mm: the soft tissue this near the pools is wall, whatever it reads
  double Sigma = 2.0;             // mm
  double MinimumContrast = 5.0;   // HU
  /// The heart's base: no wall grows more than BaseMargin above it, and below it the fat and lung
  /// within MinimumThickness of a pool are wall (a ventricle's blood lies inside its wall).
  ValvePlane Base;
  double BaseMargin = 10.0; // mm
};

struct WallReport
{
  std::size_t PoolVoxels = 0;
  double PoolLevel = 0.0;        // median intensity of the pools (HU)
  bool PoolsAtBorder = false;    // a pool reaches the image's border: the scan may cut the heart
  double WallLevel = 0.0;        // median smoothed intensity 3-6 mm from the pools
  double SurroundingLevel = 0.0; // median beyond the maximum thickness
  double Noise = 0.0;            // robust spread of the smoothed wall intensity
  double Sigma = 0.0;            // mm: the Gaussian the wall was averaged with
  double Threshold = 0.0;
  bool Contrast = false; // the wall was told from its surroundings by intensity
  std::size_t Voxels = 0;
};

/// The myocardium (see amTorsoSegmentation): soft-tissue voxels connected to the pools, within
/// the maximum thickness, whose intensity averaged over soft tissue alone (away from partial
/// volumes) lies on the wall's side of the half-way level between the wall next to the pools and
/// the tissue beyond the maximum thickness. Labels Myocardium in place.
WallReport MyocardiumWall(const amVoxelGrid& g, const float* hu, const std::vector<std::uint8_t>& classes,
  const WallParameters& p, std::vector<std::uint8_t>& labels);
}

#endif
