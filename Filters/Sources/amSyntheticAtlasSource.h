/**
 * @class   amSyntheticAtlasSource
 * @brief   A synthetic many-label map (an "atlas"): random Voronoi cells inside an ellipsoid, with
 *          optional thin sheets between the cells and label noise, of a chosen integer type.
 *
 * For testing the surface and mesh filters on inputs with many labels, junctions everywhere,
 * one-voxel-thin parts, noise as a classification leaves it, and anisotropic voxels. Labels
 * 1..NumberOfLabels are the cells, NumberOfLabels + 1 the sheets (SheetWidth > 0), 0 outside.
 * The same parameters give the same bytes whatever the thread count. Field data "Seeds" holds the
 * cells' seed points (mm).
 *
 * @sa amSyntheticAtlas amThoraxPhantomSource amLabelSurface
 */
#ifndef amSyntheticAtlasSource_h
#define amSyntheticAtlasSource_h

#include "AnatomeshFiltersSourcesModule.h" // export macro
#include "vtkImageAlgorithm.h"

class ANATOMESHFILTERSSOURCES_EXPORT amSyntheticAtlasSource : public vtkImageAlgorithm
{
public:
  static amSyntheticAtlasSource* New();
  vtkTypeMacro(amSyntheticAtlasSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of Voronoi cells (default 50).
  vtkSetClampMacro(NumberOfLabels, int, 1, 100000);
  vtkGetMacro(NumberOfLabels, int);
  ///@}

  ///@{
  /// Voxels along x, y, z (default 96 96 96).
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /// Voxel size, mm (default 1 1 1); the image starts at the origin.
  vtkSetVector3Macro(Spacing, double);
  vtkGetVector3Macro(Spacing, double);
  ///@}

  ///@{
  /// Width of the sheets between cells, mm (default 0: none).
  vtkSetClampMacro(SheetWidth, double, 0.0, 1e6);
  vtkGetMacro(SheetWidth, double);
  ///@}

  ///@{
  /// Fraction of the voxels that take a face neighbour's label (default 0).
  vtkSetClampMacro(NoiseFraction, double, 0.0, 1.0);
  vtkGetMacro(NoiseFraction, double);
  ///@}

  ///@{
  /// Seed of the random cells and noise (default 1).
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /// Scalar type of the labels: VTK_SHORT (4, default), VTK_UNSIGNED_CHAR (3), VTK_UNSIGNED_SHORT
  /// (5) or VTK_INT (6). Labels that do not fit are an error.
  vtkSetMacro(OutputScalarType, int);
  vtkGetMacro(OutputScalarType, int);
  ///@}

protected:
  amSyntheticAtlasSource();
  ~amSyntheticAtlasSource() override = default;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfLabels;
  int Dimensions[3];
  double Spacing[3];
  double SheetWidth;
  double NoiseFraction;
  int Seed;
  int OutputScalarType;

private:
  amSyntheticAtlasSource(const amSyntheticAtlasSource&) = delete;
  void operator=(const amSyntheticAtlasSource&) = delete;
};

#endif
