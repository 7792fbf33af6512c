/**
 * @class   amCardiacLandmarks
 * @brief   The landmarks a heart simulation needs, computed from a segmented thorax: the left
 *          ventricle's long axis, apex and base, a stimulus site, and the standard 12-lead ECG
 *          electrodes on the segmented skin, so a new scan needs no typed coordinates.
 *
 * Input: a label map in the thorax phantom's scheme (amTorsoSegmentation's output: 0 outside,
 * 3/4 lungs, 5 myocardium, 6 LV blood). Output: a point set (one vertex per point) whose point
 * data "Name" (strings) says what each is: RA, LA, LL, V1..V6 (in amTorsoPotential's
 * ElectrodePositions order), LVApexEndocardium, LVApexEpicardium, LVBase, Stimulus, and Sternum
 * where the bone shows it; field data
 * "LongAxis" (unit vector, base to apex) and "LongAxisLength" (mm). amTorsoPotential takes the
 * electrodes and amFitzHughNagumoSolver the stimulus from this output on their Landmarks inputs.
 *
 * The rules (anatomical, in world LPS millimetres, whatever the voxels' storage order):
 * - the long axis runs from the LV's base, where its pool meets the atria or the aortic root (labels
 *   11, 8), to the pool's voxel farthest from there; where it meets neither, it is the principal
 *   axis of the ventricles (myocardium and LV pool), pointed to the patient's left, front and feet;
 *   the endocardial apex is the LV pool's farthest voxel along it,
 *   the epicardial apex the myocardium's beyond it within 15 mm of the axis, the base the centre of the pool's last 5
 * mm at the other end (the valve plane), the stimulus half-way between the apices (mid-wall);
 * - the electrodes lie on the trunk's skin: the body is cut into the basins of its depth (parts
 *   joined to the rest by a neck at least 10 mm thinner than their own deepest point), the trunk
 *   is the basin that holds the LV's pool, its skin its voxels beside the outside or another basin
 *   (arms in the field, apart from the trunk or lying against it, carry none);
 * - V4 is where the line from the apex straight forward meets the skin (the apex beat, 5th
 *   intercostal space, mid-clavicular line); V1 and V2 one intercostal space (25 mm) higher, on
 *   the front at the sternum's right and left borders: the bone (labels 9, 10) in front of the
 *   heart that spans the skin's mid-line within 12.5 mm of that level (of the bone within 30 mm of
 *   the mid-line, the run along x that holds it, 10-60 mm wide; its centre is the Sternum point);
 *   where no bone spans the mid-line there, 25 mm right and left of it; V6 the skin's leftmost point at V4's level
 *   (mid-axillary), V5 half-way round from V4 to V6, V3 half-way round from V2 to V4; RA and LA
 *   below the clavicles (the lungs' top, 60 % of the way from the mid-line to the side, on the
 *   front), LL on the left lower front 50 mm below the lungs (Mason-Likar's torso placement).
 * Errors name what is missing: no LV blood pool, no myocardium, no lungs, no skin, or no skin in
 * front of the apex (a field of view that cuts the chest).
 *
 * References: Mason and Likar, Am Heart J 71 (1966) 196 (limb electrodes on the torso); AHA
 * recommendations for the standardization of the ECG (Kligfield et al., Circulation 2007).
 */
#ifndef amCardiacLandmarks_h
#define amCardiacLandmarks_h

#include "AnatomeshFiltersSegmentationModule.h" // export macro
#include "vtkPolyDataAlgorithm.h"

class ANATOMESHFILTERSSEGMENTATION_EXPORT amCardiacLandmarks : public vtkPolyDataAlgorithm
{
public:
  static amCardiacLandmarks* New();
  vtkTypeMacro(amCardiacLandmarks, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  amCardiacLandmarks();
  ~amCardiacLandmarks() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  amCardiacLandmarks(const amCardiacLandmarks&) = delete;
  void operator=(const amCardiacLandmarks&) = delete;
};

#endif
