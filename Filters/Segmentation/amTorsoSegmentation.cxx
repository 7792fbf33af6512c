#include "amTorsoSegmentation.h"

#include "Torso/amTorsoLabels.h"
#include "amInputCheck.h"
#include "amIntensityClassifier.h"
#include "amIntensityWindow.h"
#include "amProvenance.h"
#include "amThoraxPhantomModel.h"
#include "amThreading.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

vtkStandardNewMacro(amTorsoSegmentation);

amTorsoSegmentation::amTorsoSegmentation()
  : AutomaticClasses(true)
  , MaximumNoise(25.0)
  , BodyGapClosing(-1.0)
  , LungOpening(-1.0)
  , MinimumComponentVolume(50.0)
  , FindAorta(true)
  , FindPatientTable(true)
  , FindAirway(true)
  , BloodPoolLabels{ amThoraxPhantomModel::LeftVentricleBlood, amThoraxPhantomModel::RightVentricleBlood }
  , MaximumWallThickness(40.0)
  , WallThickness(10.0)
  , RightVentricleWallThickness(4.0)
  , MinimumWallThickness(3.0)
  , WallSmoothingSigma(2.0)
  , MinimumWallContrast(5.0)
{
  this->InputWindow[0] = this->InputWindow[1] = 0.0;
  this->SetNumberOfInputPorts(2);
  amThreading::Initialize();
}

amTorsoSegmentation::~amTorsoSegmentation() = default;

void amTorsoSegmentation::SetBloodPoolLabels(int lv, int rv)
{
  this->BloodPoolLabels = { lv, rv };
  this->Modified();
}

void amTorsoSegmentation::AddBloodPoolLabel(int label)
{
  this->BloodPoolLabels.push_back(label);
  this->Modified();
}

void amTorsoSegmentation::RemoveAllBloodPoolLabels()
{
  if (!this->BloodPoolLabels.empty())
  {
    this->BloodPoolLabels.clear();
    this->Modified();
  }
}

int amTorsoSegmentation::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int amTorsoSegmentation::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0), VTK_UNSIGNED_CHAR, 1);
  return 1;
}

namespace
{
// The organ map of input 1 as labels 0..254, or an error message.
bool OrganLabels(vtkImageData* ct, vtkImageData* organs, std::vector<std::uint8_t>& out, std::string& why)
{
  if (!organs)
    return true;
  int a[3], b[3];
  ct->GetDimensions(a);
  organs->GetDimensions(b);
  if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
  {
    std::ostringstream s;
    s << "The organ label map (input 1) is " << b[0] << "x" << b[1] << "x" << b[2] << " voxels, the CT " << a[0] << "x"
      << a[1] << "x" << a[2] << ": they must share one grid.";
    why = s.str();
    return false;
  }
  vtkDataArray* scalars = amInputCheck::ScalarImage(organs, why);
  if (!scalars)
  {
    why = "The organ label map (input 1): " + why;
    return false;
  }
  if (!amInputCheck::LabelBytes(scalars, 254, out, why))
  {
    why = "The organ label map (input 1): " + why;
    return false;
  }
  return true;
}

// The CT in HU (a windowed scan's 0..255 mapped back through its window), or false with 'why':
// values outside a window's 0..255, a non-finite voxel, or (automatic classes) no air or lung.
bool HounsfieldUnits(vtkDataArray* scalars, const double window[2], bool automatic, vtkFloatArray* hu, std::string& why)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  const bool windowed = window[0] > 0.0;
  std::ostringstream message;
  if (windowed)
  {
    double range[2];
    scalars->GetRange(range, 0);
    if (range[0] < 0.0 || range[1] > 255.0)
    {
      message << "InputWindow says the CT is windowed to 0..255, but its values span " << range[0] << " .. " << range[1]
              << ".";
      why = message.str();
      return false;
    }
  }
  const double lowest = window[1] - 0.5 * window[0];
  hu->SetName("HU");
  hu->SetNumberOfTuples(n);
  // On the threads; the first non-finite voxel (the smallest index) is the one named.
  const double width = window[0];
  const vtkIdType bad = amThreading::FirstFailure(0, n, [&](vtkIdType i) {
    const double v = scalars->GetComponent(i, 0);
    if (!std::isfinite(v))
      return false;
    double h = v;
    if (windowed)
      h = v <= 0.0 ? -1000.0 : v >= 255.0 ? 1000.0 : lowest + v * width / 255.0;
    hu->SetValue(i, static_cast<float>(h));
    return true;
  });
  if (bad < n)
  {
    message << "The CT has a non-finite value (" << scalars->GetComponent(bad, 0) << ") at voxel " << bad
            << ": cannot segment it.";
    why = message.str();
    return false;
  }
  // A chest CT shows air and lung below -500 HU; none at all is a scan in other units (a CT stored
  // unsigned without its rescale, an MR).
  const auto darkest = std::min_element(hu->GetPointer(0), hu->GetPointer(0) + n);
  if (automatic && *darkest > -500.0f)
  {
    message << "The scan has no air or lung: its darkest value is " << *darkest
            << ", not below -500 HU. It is not a chest CT in HU (a CT stored unsigned needs its rescale "
               "intercept, usually -1024; a windowed scan needs InputWindow).";
    why = message.str();
    return false;
  }
  return true;
}

// What the tissue step reads off the scan's classes and its orientation.
amTorso::TissueParameters TissueParametersFor(vtkDataArray* classTable, vtkMatrix3x3* direction, const float* hu)
{
  amTorso::TissueParameters p;
  // The patient's head is world +z (LPS and RAS alike): gas under the lungs is found along the
  // index axis closest to it, and the axial slices lie across it.
  p.SuperiorAxis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::fabs(direction->GetElement(2, a)) > std::fabs(direction->GetElement(2, p.SuperiorAxis)))
      p.SuperiorAxis = a;
  p.SuperiorSign = direction->GetElement(2, p.SuperiorAxis) > 0 ? 1 : -1;
  // Where the scan tells aerated lung from gas, gas (stomach, bowel) is never lung.
  p.GasIsNotLung = classTable && classTable->GetComponent(amTorso::LungClass, 4) != 0.0;
  if (classTable && classTable->GetComponent(amTorso::SoftClass, 4) != 0.0)
  {
    // Enclosed by cortex and a deviation brighter than soft tissue's centre is trabecular bone (an
    // old patient's marrow reads 80-120 HU at 3 mm); the spinal canal's fluid and cord are darker.
    p.HU = hu;
    p.TrabecularLevel =
      classTable->GetComponent(amTorso::SoftClass, 1) + classTable->GetComponent(amTorso::SoftClass, 2);
    if (classTable->GetComponent(amTorso::BoneClass, 4) != 0.0)
      // Half-way to cortical bone (700 HU at least in an adult); a lower centre is a soft kernel's,
      // a higher one a window's ceiling or dense cortex, neither of which moves a thin bone's edge.
      p.BonePartialLevel = 0.5 *
        (classTable->GetComponent(amTorso::SoftClass, 1) +
          std::min(700.0, classTable->GetComponent(amTorso::BoneClass, 1)));
  }
  return p;
}

// The output's field data: the label names and volumes, what the myocardium was told by, the
// classes read from the scan, its noise and the patient table left out (mm^3).
void AddFieldData(vtkImageData* output, const std::vector<double>& volume, const std::vector<bool>& organ,
  const amTorso::WallReport& heart, vtkDataArray* classTable, double noise, double noiseSmoothing, double tableVolume)
{
  int top = amThoraxPhantomModel::NumberOfLabels - 1;
  for (int l = 0; l < 255; ++l)
    if (volume[l] > 0)
      top = std::max(top, l);
  vtkNew<vtkStringArray> names;
  names->SetName("LabelNames");
  for (int l = 0; l <= top; ++l)
    names->InsertNextValue(l < amThoraxPhantomModel::NumberOfLabels ? amThoraxPhantomModel::LabelName(l)
        : l == amTorso::Atria                                       ? "Atria"
        : l == amTorso::AirwayLabel && !organ[l]                    ? "Airway"
                                                                    : "Organ");
  output->GetFieldData()->AddArray(names);
  vtkNew<vtkDoubleArray> volumes;
  volumes->SetName("LabelVolumes");
  volumes->SetNumberOfComponents(2);
  volumes->SetComponentName(0, "Label");
  volumes->SetComponentName(1, "Volume_mm3");
  for (int l = 1; l < 255; ++l)
    if (volume[l] > 0)
    {
      const double row[2] = { static_cast<double>(l), volume[l] };
      volumes->InsertNextTuple(row);
    }
  output->GetFieldData()->AddArray(volumes);
  vtkNew<vtkDoubleArray> levels;
  levels->SetName("MyocardiumLevels");
  for (double v : { heart.WallLevel, heart.SurroundingLevel, heart.Threshold, heart.Noise, heart.Contrast ? 1.0 : 0.0,
         heart.PoolLevel, heart.Sigma })
    levels->InsertNextValue(v);
  output->GetFieldData()->AddArray(levels);
  if (classTable)
    output->GetFieldData()->AddArray(classTable);
  vtkNew<vtkDoubleArray> noiseArray;
  noiseArray->SetName("Noise");
  noiseArray->SetNumberOfComponents(2);
  noiseArray->SetComponentName(0, "Noise_HU");
  noiseArray->SetComponentName(1, "Smoothing_mm");
  const double noiseRow[2] = { noise, noiseSmoothing };
  noiseArray->InsertNextTuple(noiseRow);
  vtkNew<vtkDoubleArray> table;
  table->SetName("PatientTable");
  table->InsertNextValue(tableVolume);
  output->GetFieldData()->AddArray(table);
  output->GetFieldData()->AddArray(noiseArray);
}

// The classes a chest CT shows that the scan does not (a window's floor clips those below it).
std::vector<std::string> ClassWarnings(vtkDataArray* classTable, bool windowed, double lowest)
{
  std::vector<std::string> warnings;
  if (!classTable)
    return warnings;
  // Classes a chest CT shows; a window's floor clips those below it.
  const char* what[] = { nullptr, "lung", "fat", nullptr, nullptr, "bone" };
  const double below[] = { 0, -850, -100, 0, 0, 700 };
  for (int c : { 1, 2, 5 })
    if (classTable->GetComponent(c, 4) == 0.0 && !(windowed && below[c] < lowest))
    {
      std::ostringstream text;
      text << "The scan shows no " << what[c] << " intensity class (no peak of the body's histogram near " << below[c]
           << " HU): " << (c == 1 ? "is it a chest CT?" : "")
           << (c == 2 ? "a very lean patient, or not a CT in HU?" : "")
           << (c == 5 ? "the field of view holds no bone, or its bone is too thin at these voxels to show one (bone "
                        "then starts half-way to cortical bone)."
                      : "");
      warnings.push_back(text.str());
    }
  return warnings;
}

// Bone stands further above everything else than any noise the smoothing is for reaches, and the
// smoothing takes thin bones (ribs) below its bound: where the scan was smoothed, bone is read from
// the unsmoothed intensities (above the bone class's lower bound, and at least five noise deviations
// above the class below it; also where the smoothed histogram shows no bone peak), with the voxels
// beside it brighter than half-way from soft tissue to its median (partial volume: a voxel more than
// half bone), the other classes from the smoothed ones. A voxel the smoothing put in the bone class
// that is not bone unsmoothed goes to the class below.
void BoneFromUnsmoothed(const amVoxelGrid& g, vtkDataArray* classTable, const std::vector<float>& hu, double noise,
  std::vector<std::uint8_t>& classes)
{
  if (!classTable)
    return;
  const int below = classTable->GetComponent(amTorso::BloodClass, 4) != 0.0 ? amTorso::BloodClass : amTorso::SoftClass;
  const double bound = std::max(classTable->GetComponent(below, 5), classTable->GetComponent(below, 1) + 5.0 * noise);
  amVoxelMask bone(classes.size());
  std::vector<float> boneValues;
  for (std::size_t v = 0; v < classes.size(); ++v)
    if ((bone[v] = hu[v] > bound))
      boneValues.push_back(hu[v]);
  if (boneValues.empty())
    return;
  // A voxel half bone, half soft tissue beside bone is bone (its centre lies in the bone).
  std::nth_element(boneValues.begin(), boneValues.begin() + boneValues.size() / 2, boneValues.end());
  const double edge = 0.5 * (classTable->GetComponent(amTorso::SoftClass, 1) + boneValues[boneValues.size() / 2]);
  amVoxelMask grown = bone;
  for (std::size_t v = 0; v < classes.size(); ++v)
    if (!bone[v] && hu[v] > edge)
      g.AllNeighbours(v, [&](std::size_t w) { grown[v] = grown[v] || bone[w]; });
  for (std::size_t v = 0; v < classes.size(); ++v)
    if (grown[v])
      classes[v] = amTorso::BoneClass;
    else if (classes[v] == amTorso::BoneClass)
      classes[v] = static_cast<std::uint8_t>(below);
}

// Half-way from gas to soft tissue (HU): where a lumen's partial volume ends.
double GasHalfWay(vtkDataArray* classTable)
{
  return 0.5 * (classTable->GetComponent(amTorso::AirClass, 1) + classTable->GetComponent(amTorso::SoftClass, 1));
}

// A voxel between lung and tissue (the fat class's partial-volume sheets) is lung only when more
// than half of it is air: brighter than half-way from the lung's class to soft tissue's, it goes to
// the tissue beside it; and darker than soft tissue, it holds no bone.
std::function<bool(std::size_t, std::uint8_t)> PartialVolumeRefusals(vtkDataArray* classTable, const float* values)
{
  if (!classTable || classTable->GetComponent(amTorso::LungClass, 4) == 0.0 ||
    classTable->GetComponent(amTorso::SoftClass, 4) == 0.0)
    return nullptr;
  const float soft = static_cast<float>(classTable->GetComponent(amTorso::SoftClass, 1));
  const float halfAir = 0.5f * (static_cast<float>(classTable->GetComponent(amTorso::LungClass, 1)) + soft);
  const float halfGas = static_cast<float>(GasHalfWay(classTable));
  return [values, halfAir, halfGas, soft](std::size_t v, std::uint8_t l) {
    using Phantom = amThoraxPhantomModel;
    return ((l == Phantom::RightLung || l == Phantom::LeftLung) && values[v] > halfAir) ||
      (l == amTorso::AirwayLabel && values[v] > halfGas) ||
      ((l == Phantom::Spine || l == Phantom::Ribs) && values[v] < soft);
  };
}

// Where the scan shows contrast blood and the organ map seeds its pools, the blood connected to
// them (brighter than half a deviation below the blood class's centre) is never bone; where the
// window's ceiling lies below cortical bone (700 HU at least in an adult), bone is its cortex
// (brighter than two deviations above the blood's centre) and the marrow it reaches (ClippedBone).
void ContrastBone(const amVoxelGrid& g, vtkDataArray* classTable, const float* hu,
  const std::vector<std::uint8_t>& organs, const std::vector<int>& poolLabels, double ceiling, amVoxelMask& vessels,
  amTorso::TissueParameters& p)
{
  if (!classTable || !p.HU || classTable->GetComponent(amTorso::BloodClass, 4) == 0.0 || organs.empty())
    return;
  amVoxelMask pools(organs.size(), 0);
  bool any = false;
  for (std::size_t v = 0; v < organs.size(); ++v)
    if (organs[v] && std::find(poolLabels.begin(), poolLabels.end(), organs[v]) != poolLabels.end())
      any = pools[v] = 1;
  if (!any)
    return;
  const double centre = classTable->GetComponent(amTorso::BloodClass, 1);
  const double spread = classTable->GetComponent(amTorso::BloodClass, 2);
  vessels = amTorso::ContrastVessels(g, hu, static_cast<float>(centre - 0.5 * spread), pools);
  p.Vessels = &vessels;
  p.BoneClipped = ceiling < 700.0;
  p.CortexLevel = centre + 2.0 * spread;
  p.MarrowLevel = centre - 0.5 * spread;
}

// World x of voxel (i, j, k): worldX[0] i + worldX[1] j + worldX[2] k + worldX[3].
// Below a window that starts above fat's -100 HU (fatReadsAsAir), fat reads as air: what is not
// lung is fat, the body wall shows as muscle and bone with gaps, and fat lies beside the lungs as a
// thinner layer. The gap closing and the lung opening (negative: automatic) follow.
void AirBelowTheWindow(bool fatReadsAsAir, double gap, double opening, amTorso::TissueParameters& p)
{
  p.BodyGap = gap >= 0.0 ? gap : fatReadsAsAir ? 15.0 : 0.0;
  p.LungOpening = opening >= 0.0 ? opening : fatReadsAsAir ? 12.0 : 0.0;
  p.LeftoverAirIsFat = fatReadsAsAir;
}

// The organs written over the tissues; organ[l]: label l is one of them.
std::vector<bool> PasteOrgans(const std::vector<std::uint8_t>& organs, std::vector<std::uint8_t>& labels)
{
  std::vector<bool> organ(256, false);
  for (std::size_t v = 0; v < organs.size(); ++v)
    if (organs[v])
    {
      labels[v] = organs[v];
      organ[organs[v]] = true;
    }
  return organ;
}

// The contrast blood outside every organ, bone and lung: within half the pools' contrast of the
// seeded blood pools' level (pools at least 50 HU brighter than soft tissue: a phase whose blood the
// histogram does not part from soft tissue still has it; a vein still full of the denser bolus is
// brighter), or without pools the blood class where the scan shows one. Empty where there is no
// contrast.
amVoxelMask ContrastOutsideOrgans(vtkDataArray* classTable, const std::vector<std::uint8_t>& classes, const float* hu,
  const std::vector<int>& poolLabels, const std::vector<std::uint8_t>& labels)
{
  const std::size_t n = labels.size();
  amVoxelMask contrast(n, 0);
  std::vector<float> pool;
  for (std::size_t v = 0; v < n; ++v)
    if (std::find(poolLabels.begin(), poolLabels.end(), labels[v]) != poolLabels.end())
      pool.push_back(hu[v]);
  const double soft = classTable ? classTable->GetComponent(amTorso::SoftClass, 1) : 40.0;
  double level = 1e30, reach = 0.0;
  if (!pool.empty())
  {
    std::nth_element(pool.begin(), pool.begin() + pool.size() / 2, pool.end());
    level = pool[pool.size() / 2];
    if (level - soft < 50.0)
      return contrast;
    reach = 0.5 * (level - soft);
  }
  else if (classTable && classTable->GetComponent(amTorso::BloodClass, 4) == 0.0)
    return contrast;
  for (std::size_t v = 0; v < n; ++v)
    contrast[v] = (pool.empty() ? classes[v] == amTorso::BloodClass : std::fabs(hu[v] - level) < reach) &&
      (labels[v] == amThoraxPhantomModel::SoftTissue || labels[v] == amVoxel::Pending);
  return contrast;
}

// The aorta where the scan shows contrast (amTorso::AortaFromContrast), of the contrast outside the
// organs: where clicks give the aorta, their snake may stop short of its descending part (its
// region ends MaximumDistance from the clicks), and the tube in front of the spine completes it.
// Then its ascending part where the atria's label took it (amTorso::AortaOutOfAtria). Labels it
// Aorta in place; true when found.
bool CompleteAorta(vtkImageData* image, const amVoxelGrid& g, const amVoxelMask& contrast,
  const amTorso::TissueParameters& tissues, std::vector<std::uint8_t>& labels)
{
  const int superiorAxis = tissues.SuperiorAxis;
  double world[3][4];
  const double* spacing = image->GetSpacing();
  for (int r = 0; r < 3; ++r)
  {
    for (int a = 0; a < 3; ++a)
      world[r][a] = image->GetDirectionMatrix()->GetElement(r, a) * spacing[a];
    world[r][3] = image->GetOrigin()[r];
  }
  amTorso::AortaReport report;
  const amVoxelMask aorta =
    amTorso::AortaFromContrast(g, contrast, labels, world, superiorAxis, amTorso::AortaParameters(), report);
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (aorta[v])
      labels[v] = amThoraxPhantomModel::Aorta;
  amTorso::AortaOutOfAtria(g, superiorAxis, tissues.SuperiorSign, amTorso::AscendingAortaParameters(), labels);
  return report.Found;
}

void WorldXRow(vtkImageData* image, double worldX[4])
{
  const double* spacing = image->GetSpacing();
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  for (int a = 0; a < 3; ++a)
    worldX[a] = direction->GetElement(0, a) * spacing[a];
  worldX[3] = image->GetOrigin()[0];
}

// The lumen's partial volume reaches half-way from the gas to the soft tissue of its wall.
amTorso::AirwayParameters AirwaySettings(vtkDataArray* classTable, const float* hu)
{
  amTorso::AirwayParameters p;
  if (classTable && classTable->GetComponent(amTorso::SoftClass, 4) != 0.0)
  {
    p.HU = hu;
    p.LumenLevel = GasHalfWay(classTable);
  }
  return p;
}

// What the lungs' step could not do, in words.
std::vector<std::string> LungWarnings(const amTorso::TissueReport& tissues, double minimumVolume)
{
  std::vector<std::string> warnings;
  std::ostringstream text;
  if (tissues.LungComponents == 0)
  {
    text << "No lungs: no air inside the body of at least " << minimumVolume << " mm^3.";
    warnings.push_back(text.str());
  }
  else if (tissues.LungsSplitAtMidPlane)
    warnings.push_back("The lungs are one component that no depth parts in two (joined more widely than at the "
                       "trachea or bronchi): they are split at the body's mid-plane into right and left lung.");
  return warnings;
}

// The myocardium step's settings, from the filter's, and the heart's base where the atria or the
// aorta show it (the RV's pool ended there).
amTorso::WallParameters WallSettings(
  amTorsoSegmentation* filter, const amVoxelGrid& grid, std::vector<std::uint8_t>& labels)
{
  amTorso::WallParameters wall;
  wall.PoolLabels.clear();
  for (int i = 0; i < filter->GetNumberOfBloodPoolLabels(); ++i)
    wall.PoolLabels.push_back(filter->GetBloodPoolLabel(i));
  wall.MaximumThickness = filter->GetMaximumWallThickness();
  wall.Thickness = filter->GetWallThickness();
  wall.RightThickness = filter->GetRightVentricleWallThickness();
  wall.MinimumThickness = filter->GetMinimumWallThickness();
  wall.Sigma = filter->GetWallSmoothingSigma();
  wall.MinimumContrast = filter->GetMinimumWallContrast();
  if (wall.PoolLabels.size() > 1)
  {
    wall.Base = amTorso::FindValvePlane(grid, labels, wall.PoolLabels[0]);
    amTorso::EndVentriclesAtValves(grid, wall.Base, wall.PoolLabels[1], wall.BaseMargin, labels);
  }
  return wall;
}

// What the myocardium's step could not do, in words.
std::vector<std::string> WallWarnings(const amTorso::WallReport& heart, const amTorso::WallParameters& wall)
{
  std::vector<std::string> warnings;
  std::ostringstream text;
  if (!heart.PoolVoxels)
    warnings.push_back(
      "No blood pool (labels of BloodPoolLabels in the organ map): the segmentation has no myocardium.");
  else if (heart.PoolLevel < heart.WallLevel + wall.MinimumContrast)
  {
    text
      << "The blood pools (median " << heart.PoolLevel << " HU) are not brighter than the tissue around them ("
      << heart.WallLevel
      << " HU): a scan without contrast, or a seed outside the blood pool; the myocardium around them is unreliable.";
    warnings.push_back(text.str());
  }
  if (heart.PoolsAtBorder)
    warnings.push_back("A blood pool reaches the border of the image: the scan may cut the heart, and the myocardium "
                       "stops there.");
  if (heart.PoolVoxels && !heart.Contrast)
  {
    text.str("");
    text << "The myocardium cannot be told from the tissue around it by intensity (wall " << heart.WallLevel
         << " HU, surroundings " << heart.SurroundingLevel << " HU, noise " << heart.Noise
         << " HU): it is the soft tissue within " << wall.Thickness << " mm of the blood pools";
    if (wall.PoolLabels.size() > 1)
      text << " (" << wall.RightThickness << " mm of the RV's)";
    text << ".";
    warnings.push_back(text.str());
  }
  return warnings;
}

// Updates an inner filter and returns its errors' messages (empty when it ran), so that the outer
// filter says them once, as its own.
std::string UpdateQuietly(vtkAlgorithm* inner)
{
  std::string errors;
  vtkNew<vtkCallbackCommand> keep;
  keep->SetClientData(&errors);
  keep->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    // VTK's text is "ERROR: In file, line N\nclass (address): message": keep the message.
    std::string text = callData ? static_cast<const char*>(callData) : "";
    const auto start = text.find("): ");
    if (start != std::string::npos)
      text = text.substr(start + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
      text.pop_back();
    *static_cast<std::string*>(clientData) += text;
  });
  inner->AddObserver(vtkCommand::ErrorEvent, keep);
  vtkNew<vtkCallbackCommand> quiet; // the executive's "returned failure" adds nothing
  inner->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  inner->Update();
  return errors;
}
}

int amTorsoSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* organInput = vtkImageData::GetData(inputVector[1], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  std::string why;
  vtkDataArray* scalars = amInputCheck::ScalarImage(input, why);
  if (!scalars)
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  std::vector<std::uint8_t> organs;
  if (!OrganLabels(input, organInput, organs, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  // InputWindow, or the window the image carries (amImageReader's IntensityWindow).
  double window[2] = { this->InputWindow[0], this->InputWindow[1] };
  if (!(window[0] > 0.0))
    amIntensityWindow::Of(input, window);
  const bool windowed = window[0] > 0.0;
  const double lowest = window[1] - 0.5 * window[0];
  vtkNew<vtkFloatArray> hu;
  if (!HounsfieldUnits(scalars, window, this->AutomaticClasses != 0, hu, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }
  amVoxelGrid grid;
  input->GetDimensions(grid.N);
  input->GetSpacing(grid.Spacing);
  for (int a = 0; a < 3; ++a)
    grid.Spacing[a] = std::fabs(grid.Spacing[a]);
  // A scan noisier than MaximumNoise (low dose, thin slices) is smoothed until its noise is four
  // fifths of it (a margin, so a scan just above the bound is not left just below it): voxel by
  // voxel, 60 HU of noise leaves fat and soft tissue one population, and the wall's average too
  // noisy to tell.
  const double noise = amVoxel::NoiseLevel(grid, hu->GetPointer(0), -500.0f);
  double noiseSmoothing = 0.0;
  std::vector<float> unsmoothed;
  if (noise > this->MaximumNoise)
  {
    noiseSmoothing = amVoxel::GaussianForNoise(grid, noise, 0.8 * this->MaximumNoise);
    unsmoothed.assign(hu->GetPointer(0), hu->GetPointer(0) + n);
    std::vector<float> smoothed(hu->GetPointer(0), hu->GetPointer(0) + n);
    amVoxel::Gaussian(grid, smoothed, noiseSmoothing);
    std::copy(smoothed.begin(), smoothed.end(), hu->GetPointer(0));
  }
  vtkNew<vtkImageData> huImage;
  huImage->CopyStructure(input);
  huImage->GetPointData()->SetScalars(hu);
  vtkNew<amIntensityClassifier> classifier;
  classifier->SetInputData(huImage);
  classifier->SetMode(this->AutomaticClasses ? amIntensityClassifier::Automatic : amIntensityClassifier::Ranges);
  const std::string classifierError = UpdateQuietly(classifier);
  vtkDataArray* classArray = classifier->GetOutput()->GetPointData()->GetScalars();
  if (!classArray || !classifierError.empty())
  {
    vtkErrorMacro("Classifying the CT by intensity failed: " << (classifierError.empty() ? std::string("no classes")
                                                                                         : classifierError));
    return 0;
  }
  vtkDataArray* classTable = classifier->GetOutput()->GetFieldData()->GetArray("TissueClasses");
  for (const std::string& warning : ClassWarnings(classTable, windowed, lowest))
    vtkWarningMacro(<< warning);
  this->UpdateProgress(0.2);

  std::vector<std::uint8_t> classes(static_cast<std::uint8_t*>(classArray->GetVoidPointer(0)),
    static_cast<std::uint8_t*>(classArray->GetVoidPointer(0)) + n);
  if (!unsmoothed.empty())
    BoneFromUnsmoothed(grid, classTable, unsmoothed, noise, classes);
  double worldX[4];
  WorldXRow(input, worldX);
  const std::size_t minimumVoxels =
    static_cast<std::size_t>(std::ceil(this->MinimumComponentVolume / grid.VoxelVolume()));

  std::vector<std::uint8_t> labels;
  amTorso::TissueParameters tissueParameters =
    TissueParametersFor(classTable, input->GetDirectionMatrix(), hu->GetPointer(0));
  tissueParameters.MinimumVoxels = minimumVoxels;
  tissueParameters.FindTable = this->FindPatientTable;
  AirBelowTheWindow(windowed && lowest > -100.0, this->BodyGapClosing, this->LungOpening, tissueParameters);
  amVoxelMask vessels;
  ContrastBone(grid, classTable, hu->GetPointer(0), organs, this->BloodPoolLabels,
    windowed ? window[1] + 0.5 * window[0] : 1e30, vessels, tissueParameters);
  const amTorso::TissueReport tissues = amTorso::Tissues(grid, classes, worldX, tissueParameters, labels);
  for (const std::string& warning : LungWarnings(tissues, this->MinimumComponentVolume))
    vtkWarningMacro(<< warning);
  // The trachea and the main bronchi, where the scan tells gas from aerated lung.
  if (this->FindAirway && tissueParameters.GasIsNotLung && !tissueParameters.LeftoverAirIsFat)
    amTorso::Airway(grid, classes, tissueParameters.SuperiorAxis, tissueParameters.SuperiorSign, minimumVoxels,
      AirwaySettings(classTable, hu->GetPointer(0)), labels);
  this->UpdateProgress(0.4);

  std::vector<bool> organ = PasteOrgans(organs, labels);

  if (this->FindAorta &&
    CompleteAorta(input, grid,
      ContrastOutsideOrgans(classTable, classes, hu->GetPointer(0), this->BloodPoolLabels, labels), tissueParameters,
      labels))
    organ[amThoraxPhantomModel::Aorta] = true;

  const amTorso::WallParameters wall = WallSettings(this, grid, labels);
  const amTorso::WallReport heart = amTorso::MyocardiumWall(grid, hu->GetPointer(0), classes, wall, labels);
  for (const std::string& warning : WallWarnings(heart, wall))
    vtkWarningMacro(<< warning);
  this->UpdateProgress(0.7);

  amVoxel::HandOver(grid, labels, PartialVolumeRefusals(classTable, hu->GetPointer(0)));
  // Organs are one piece each; the ribs, fat and soft tissue are many, and so are the vertebrae
  // once the ribs joining them are parted from them.
  std::vector<bool> single(256, false);
  for (int l = 1; l < 255; ++l)
    single[l] = l != amThoraxPhantomModel::SoftTissue && l != amThoraxPhantomModel::Fat &&
      l != amThoraxPhantomModel::Ribs && l != amThoraxPhantomModel::Spine;
  amVoxel::DropSmallComponents(grid, labels, minimumVoxels, single);
  this->UpdateProgress(0.9);

  std::vector<double> volume(256, 0.0);
  for (const auto l : labels)
    volume[l] += grid.VoxelVolume();
  if (heart.PoolVoxels && volume[amThoraxPhantomModel::Myocardium] == 0.0)
    vtkWarningMacro("The myocardium is empty: nothing around the blood pools is soft tissue.");
  for (int l = 1; l < 255; ++l)
    if (organ[l] && volume[l] == 0.0)
      vtkWarningMacro("Label " << l << " of the organ map is lost (smaller than MinimumComponentVolume).");

  output->CopyStructure(input);
  vtkNew<vtkUnsignedCharArray> out;
  out->SetName("Labels");
  out->SetNumberOfTuples(n);
  std::copy(labels.begin(), labels.end(), out->GetPointer(0));
  output->GetPointData()->SetScalars(out);

  AddFieldData(
    output, volume, organ, heart, classTable, noise, noiseSmoothing, tissues.TableVoxels * grid.VoxelVolume());

  amProvenance::Record(output, input, "TorsoSegmentation", this->SettingsText(window));
  this->UpdateProgress(1.0);
  return 1;
}

std::string amTorsoSegmentation::SettingsText(const double window[2]) const
{
  std::ostringstream p;
  p << "AutomaticClasses=" << this->AutomaticClasses << " MaximumNoise=" << this->MaximumNoise
    << " InputWindow=" << window[0] << "," << window[1] << " BodyGapClosing=" << this->BodyGapClosing
    << " LungOpening=" << this->LungOpening << " MinimumComponentVolume=" << this->MinimumComponentVolume
    << " FindAorta=" << this->FindAorta << " FindPatientTable=" << this->FindPatientTable
    << " FindAirway=" << this->FindAirway << " BloodPoolLabels=";
  for (const int l : this->BloodPoolLabels)
    p << l << ",";
  p << " MaximumWallThickness=" << this->MaximumWallThickness << " WallThickness=" << this->WallThickness
    << " RightVentricleWallThickness=" << this->RightVentricleWallThickness
    << " MinimumWallThickness=" << this->MinimumWallThickness << " WallSmoothingSigma=" << this->WallSmoothingSigma
    << " MinimumWallContrast=" << this->MinimumWallContrast;
  return p.str();
}

void amTorsoSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputWindow: " << this->InputWindow[0] << " " << this->InputWindow[1] << "\n";
  os << indent << "AutomaticClasses: " << this->AutomaticClasses << "\n";
  os << indent << "MaximumNoise: " << this->MaximumNoise << "\n";
  os << indent << "BodyGapClosing: " << this->BodyGapClosing << "\n";
  os << indent << "LungOpening: " << this->LungOpening << "\n";
  os << indent << "FindAorta: " << this->FindAorta << "\n";
  os << indent << "FindPatientTable: " << this->FindPatientTable << "\n";
  os << indent << "FindAirway: " << this->FindAirway << "\n";
  os << indent << "MinimumComponentVolume: " << this->MinimumComponentVolume << "\n";
  os << indent << "BloodPoolLabels:";
  for (const int l : this->BloodPoolLabels)
    os << " " << l;
  os << "\n" << indent << "MaximumWallThickness: " << this->MaximumWallThickness << "\n";
  os << indent << "WallThickness: " << this->WallThickness << "\n";
  os << indent << "RightVentricleWallThickness: " << this->RightVentricleWallThickness << "\n";
  os << indent << "MinimumWallThickness: " << this->MinimumWallThickness << "\n";
  os << indent << "WallSmoothingSigma: " << this->WallSmoothingSigma << "\n";
  os << indent << "MinimumWallContrast: " << this->MinimumWallContrast << "\n";
}
