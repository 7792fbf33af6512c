// The lead-field ECG against the direct current-source torso solve on the same mesh (each lead
// within 1 %), the sign of a simple dipole, and bad input.
#include "amLeadFieldECG.h"
#include "amSimulationTestUtilities.h"
#include "amTestUtilities.h"
#include "amTorsoPotential.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <set>

namespace
{
// A 120 mm box torso (soft tissue, 1) with a "heart" (5) round a blood pool (6) in its middle,
// 4 mm tetrahedra.
vtkSmartPointer<vtkUnstructuredGrid> BoxTorso()
{
  const int n[3] = { 30, 30, 30 };
  const double origin[3] = { -60, -60, -60 }, size[3] = { 120, 120, 120 };
  return amTest::BoxMesh(n, origin, size, [](const double* x) {
    const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return r < 12 ? 6 : (r < 30 ? 5 : 1);
  });
}

// A front half-way through the heart: depolarised (+15 mV) below a tilted plane, at rest above.
double Front(const double* x) // u: Vm / 100
{
  return (-35.0 - 50.0 * std::tanh((0.3 * x[0] + 0.5 * x[1] + 0.8 * x[2] - 3.0) / 4.0)) / 100.0;
}

const double Electrodes[9][3] = { { -60, 0, 40 }, { 60, 0, 40 }, { 40, 0, -60 }, { -10, -60, 0 }, { 10, -60, 0 },
  { 25, -60, -5 }, { 40, -60, -10 }, { 60, -40, -10 }, { 60, 0, -10 } };
}

TEST(LeadFieldECG, EqualsTheDirectCurrentSourceSolve)
{
  auto mesh = BoxTorso();
  auto heart = amTest::StaticHeart(mesh, Front);
  vtkNew<amTorsoPotential> direct;
  direct->SetInputData(0, mesh);
  direct->SetInputData(1, heart);
  direct->SetCouplingToCurrentSource();
  direct->SetIntracellularConductivity(0.17);
  direct->RemoveAllRegionConductivities();
  direct->SetConductivity(0.2);
  direct->AddRegionConductivity(6, 0.7);
  direct->AddRegionConductivity(5, 0.4);
  vtkNew<amLeadFieldECG> fields;
  fields->SetInputData(0, mesh);
  fields->SetInputData(1, heart);
  // Isotropic, as the direct solve is: sigma_i 0.17, sigma_e 0.4 in the heart.
  fields->SetIntracellularConductivityFibre(0.17);
  fields->SetIntracellularConductivityTransverse(0.17);
  fields->SetExtracellularConductivityFibre(0.4);
  fields->SetExtracellularConductivityTransverse(0.4);
  fields->RemoveAllRegionConductivities();
  fields->SetConductivity(0.2);
  fields->AddRegionConductivity(6, 0.7);
  direct->RemoveAllElectrodes();
  fields->RemoveAllElectrodes();
  for (const auto& e : Electrodes)
  {
    direct->AddElectrode(e[0], e[1], e[2]);
    fields->AddElectrode(e[0], e[1], e[2]);
  }
  direct->Update();
  fields->Update();
  auto* a = vtkTable::SafeDownCast(direct->GetOutputDataObject(1));
  vtkTable* b = fields->GetOutput();
  ASSERT_TRUE(a && b);
  ASSERT_EQ(b->GetNumberOfRows(), 1);
  double largest = 0, worst = 0;
  for (const char* lead : { "I", "II", "III", "aVR", "aVL", "aVF", "V1", "V2", "V3", "V4", "V5", "V6" })
    largest = std::max(largest, std::fabs(a->GetColumnByName(lead)->GetVariantValue(0).ToDouble()));
  for (const char* lead : { "I", "II", "III", "aVR", "aVL", "aVF", "V1", "V2", "V3", "V4", "V5", "V6" })
  {
    const double x = a->GetColumnByName(lead)->GetVariantValue(0).ToDouble();
    const double y = b->GetColumnByName(lead)->GetVariantValue(0).ToDouble();
    worst = std::max(worst, std::fabs(x - y) / largest);
    EXPECT_NEAR(y, x, 0.01 * std::fabs(x) + 1e-6 * largest) << lead;
  }
  std::cout << "[ figures  ] lead fields against the direct solve: largest lead " << largest << " mV, worst difference "
            << worst << " of it\n";
  EXPECT_GT(largest, 0.1);
}

TEST(LeadFieldECG, ElectrodeOffTheBody)
{
  auto mesh = BoxTorso();
  auto heart = amTest::StaticHeart(mesh, Front);
  vtkNew<amLeadFieldECG> fields;
  fields->SetInputData(0, mesh);
  fields->SetInputData(1, heart);
  fields->RemoveAllElectrodes();
  for (int k = 0; k < 9; ++k)
    fields->AddElectrode(Electrodes[k][0], Electrodes[k][1], k == 5 ? -200.0 : Electrodes[k][2]);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(fields);
  fields->Update();
  EXPECT_TRUE(errors->ErrorContains("electrode V3")) << errors->AllErrors();
  EXPECT_TRUE(errors->ErrorContains("off the body")) << errors->AllErrors();

  vtkNew<amLeadFieldECG> noVoltage;
  noVoltage->SetInputData(0, mesh);
  noVoltage->SetInputData(1, heart);
  noVoltage->SetVoltageArrayName("Nope");
  vtkNew<amTest::ErrorCatcher> e2;
  e2->Watch(noVoltage);
  noVoltage->RemoveAllElectrodes();
  for (const auto& e : Electrodes)
    noVoltage->AddElectrode(e[0], e[1], e[2]);
  noVoltage->Update();
  EXPECT_TRUE(e2->ErrorContains("no point data 'Nope'")) << e2->AllErrors();
}
