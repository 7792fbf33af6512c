// Rule-based fibres: on a truncated prolate-spheroidal LV, whose transmural Laplace field is known in
// closed form, the helix angle follows the rule's profile within 5 degrees; on the phantom's heart the
// surfaces are tagged from the labels and the fibres turn from right- to left-handed across the wall.
#include "amBoxMesh.h"
#include "amRuleBasedFibres.h"
#include "amSimulationTestUtilities.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomModel.h"
#include "amVentricularFibres.h"
#include "amVentricularTags.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A thick truncated prolate spheroid between the confocal surfaces mu = MuEndo and mu = MuEpi (focal
// distance F), from the equator (the base, z = 0) to nu = Pi - NuCut (a small hole round the apex's
// axis keeps every element well shaped; its surface is a nu-surface, across which the closed-form
// field has no flux, as across the base).
struct ProlateLV
{
  static constexpr double F = 15.0, MuEndo = 0.45, MuEpi = 0.7327, NuCut = 0.2;
  static constexpr int NMu = 8, NNu = 24, NTheta = 48;
  amP1Assembly Fem;
  std::vector<unsigned char> Tag;
  std::vector<double> Mu; // per node

  static double Q0(double mu) { return std::log(1.0 / std::tanh(0.5 * mu)); }
  // phi_LV in closed form: 1 on the endocardium, 0 on the epicardium.
  static double Phi(double mu) { return (Q0(mu) - Q0(MuEpi)) / (Q0(MuEndo) - Q0(MuEpi)); }

  ProlateLV()
  {
    auto id = [](int i, int j, int k) {
      return static_cast<vtkIdType>((k % NTheta) * (NNu + 1) * (NMu + 1) + j * (NMu + 1) + i);
    };
    for (int k = 0; k < NTheta; ++k)
      for (int j = 0; j <= NNu; ++j)
        for (int i = 0; i <= NMu; ++i)
        {
          const double mu = MuEndo + (MuEpi - MuEndo) * i / NMu;
          const double nu = 0.5 * Pi + (0.5 * Pi - NuCut) * j / NNu;
          const double th = 2 * Pi * k / NTheta;
          this->Fem.Points.push_back({ F * std::sinh(mu) * std::sin(nu) * std::cos(th),
            F * std::sinh(mu) * std::sin(nu) * std::sin(th), F * std::cosh(mu) * std::cos(nu) });
          this->Mu.push_back(mu);
          this->Tag.push_back(
            i == 0 ? amVentricularTags::LVEndocardium : (i == NMu ? amVentricularTags::Epicardium : 0));
        }
    // Kuhn's six tetrahedra per cell, conforming between cells (and across theta's seam).
    const int perm[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
    for (int k = 0; k < NTheta; ++k)
      for (int j = 0; j < NNu; ++j)
        for (int i = 0; i < NMu; ++i)
          for (const auto& p : perm)
          {
            int c[3] = { i, j, k };
            std::array<vtkIdType, 4> tet;
            tet[0] = id(c[0], c[1], c[2]);
            for (int s = 0; s < 3; ++s)
            {
              ++c[p[s]];
              tet[s + 1] = id(c[0], c[1], c[2]);
            }
            this->Fem.Tetrahedra.push_back(tet);
          }
  }
};
}

TEST(RuleBasedFibres, HelixFollowsTheRuleOnAProlateLV)
{
  const ProlateLV lv;
  amRuleBasedFibres fibres;
  amRuleBasedFibres::Parameters p; // +60 to -60 degrees, axis +z (apex below the base)
  ASSERT_TRUE(fibres.Compute(lv.Fem, lv.Tag, p)) << fibres.Error;

  // The transmural depth against the closed form.
  double worstDepth = 0;
  for (std::size_t i = 0; i < lv.Mu.size(); ++i)
    worstDepth = std::max(worstDepth, std::fabs(fibres.TransmuralDepth[i] - (1 - ProlateLV::Phi(lv.Mu[i]))));
  EXPECT_LT(worstDepth, 0.01);

  // The helix angle in the spheroid's own frame (outward normal, axis) against alpha(d(mu)).
  double worstInterior = 0, worstAll = 0, sumEndo = 0, sumEpi = 0;
  int nEndo = 0, nEpi = 0;
  for (std::size_t k = 0; k < lv.Fem.Tetrahedra.size(); ++k)
  {
    const auto& tet = lv.Fem.Tetrahedra[k];
    double mu = 0, x[3] = { 0, 0, 0 };
    bool boundary = false;
    for (vtkIdType v : tet)
    {
      mu += 0.25 * lv.Mu[v];
      boundary |= lv.Tag[v] != 0;
      for (int c = 0; c < 3; ++c)
        x[c] += 0.25 * lv.Fem.Points[v][c];
    }
    // The outward normal of the mu-surface through x: the gradient of mu, along
    // (x / sinh^2 mu, y / sinh^2 mu, z / cosh^2 mu) up to a factor.
    const double s = std::sinh(mu), c = std::cosh(mu);
    double normal[3] = { x[0] / (s * s), x[1] / (s * s), x[2] / (c * c) };
    const double len = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (double& q : normal)
      q /= len;
    const double axis[3] = { 0, 0, 1 };
    const double measured = amRuleBasedFibres::HelixAngle(fibres.Fibres[k].data(), normal, axis);
    const double d = 1 - ProlateLV::Phi(mu);
    const double expected = 60 - 120 * d;
    const double error = std::fabs(measured - expected);
    worstAll = std::max(worstAll, error);
    if (!boundary)
      worstInterior = std::max(worstInterior, error);
    if (d < 0.1)
    {
      sumEndo += measured;
      ++nEndo;
    }
    if (d > 0.9)
    {
      sumEpi += measured;
      ++nEpi;
    }
  }
  std::cout << "[ figures  ] helix error: interior " << worstInterior << " deg, all " << worstAll << " deg; depth "
            << worstDepth << "\n";
  EXPECT_LT(worstInterior, 5.0);
  EXPECT_LT(worstAll, 8.0);
  ASSERT_GT(nEndo, 0);
  ASSERT_GT(nEpi, 0);
  EXPECT_GT(sumEndo / nEndo, 50.0);
  EXPECT_LT(sumEpi / nEpi, -50.0);
  // Sheets: unit, normal to the fibres.
  for (std::size_t k = 0; k < fibres.Fibres.size(); k += 97)
  {
    const auto& f = fibres.Fibres[k];
    const auto& s = fibres.Sheets[k];
    EXPECT_NEAR(f[0] * f[0] + f[1] * f[1] + f[2] * f[2], 1.0, 1e-9);
    EXPECT_NEAR(s[0] * s[0] + s[1] * s[1] + s[2] * s[2], 1.0, 1e-9);
    EXPECT_NEAR(f[0] * s[0] + f[1] * s[1] + f[2] * s[2], 0.0, 1e-9);
  }
}

TEST(RuleBasedFibres, RefusesAHeartWithoutEndocardium)
{
  const ProlateLV lv;
  std::vector<unsigned char> tag(lv.Tag.size(), 0);
  for (std::size_t i = 0; i < tag.size(); ++i)
    tag[i] = lv.Tag[i] ? amVentricularTags::Epicardium : 0;
  amRuleBasedFibres fibres;
  EXPECT_FALSE(fibres.Compute(lv.Fem, tag, amRuleBasedFibres::Parameters()));
  EXPECT_NE(fibres.Error.find("no LV endocardium"), std::string::npos) << fibres.Error;
}

namespace
{
// The phantom's heart and its surroundings as 3 mm tetrahedra labelled at their centroids.
vtkSmartPointer<vtkUnstructuredGrid> PhantomHeartBox()
{
  static const amThoraxPhantomModel model;
  double c[3];
  model.GetOrganCenter(amThoraxPhantomModel::LeftVentricleBlood, c);
  const int n[3] = { 36, 36, 36 };
  const double origin[3] = { c[0] - 60, c[1] - 54, c[2] - 54 }, size[3] = { 108, 108, 108 };
  return amTest::BoxMesh(n, origin, size, [](const double* x) { return static_cast<int>(model.LabelAt(x)); });
}
}

TEST(VentricularFibres, TagsAndFibresOfThePhantomHeart)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = PhantomHeartBox();
  vtkNew<amVentricularFibres> filter;
  filter->SetInputData(mesh);
  filter->Update();
  // The phantom's heart is closed: no base.
  for (int t = 1; t <= 3; ++t)
    EXPECT_GT(filter->GetNumberOfTaggedTriangles(t), 50) << amVentricularTags::Name(t);
  EXPECT_EQ(filter->GetNumberOfTaggedTriangles(4), 0);
  vtkUnstructuredGrid* out = filter->GetOutput();
  vtkDataArray* fibres = out->GetCellData()->GetArray("Fibers");
  vtkDataArray* sheets = out->GetCellData()->GetArray("Sheets");
  vtkDataArray* regions = out->GetCellData()->GetArray("Region");
  vtkDataArray* depth = out->GetPointData()->GetArray("TransmuralDepth");
  ASSERT_TRUE(fibres && sheets && regions && depth);
  vtkPolyData* tags = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1));
  ASSERT_TRUE(tags);
  ASSERT_TRUE(tags->GetCellData()->GetArray("VentricularTag"));
  EXPECT_EQ(tags->GetNumberOfCells(),
    filter->GetNumberOfTaggedTriangles(1) + filter->GetNumberOfTaggedTriangles(2) +
      filter->GetNumberOfTaggedTriangles(3) + filter->GetNumberOfTaggedTriangles(4));

  // The axis found from the LV endocardium and the base (the aorta): the phantom's long axis points
  // from the apex (left, anterior, low) to the base (right, posterior, high).
  double sumEndo = 0, sumEpi = 0;
  int nEndo = 0, nEpi = 0, heart = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    double f[3];
    fibres->GetTuple(c, f);
    const double norm = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (regions->GetComponent(c, 0) != amThoraxPhantomModel::Myocardium)
    {
      EXPECT_EQ(norm, 0.0);
      continue;
    }
    ++heart;
    EXPECT_NEAR(norm, 1.0, 1e-6);
    double s[3], d = 0;
    sheets->GetTuple(c, s);
    const vtkIdType* ids;
    vtkIdType npts;
    out->GetCellPoints(c, npts, ids);
    for (int a = 0; a < 4; ++a)
      d += 0.25 * depth->GetComponent(ids[a], 0);
    const double helix = amRuleBasedFibres::HelixAngle(f, s, filter->GetUsedApexToBase());
    if (d < 0.2)
    {
      sumEndo += helix;
      ++nEndo;
    }
    else if (d > 0.8)
    {
      sumEpi += helix;
      ++nEpi;
    }
  }
  EXPECT_EQ(heart, filter->GetNumberOfHeartCells());
  ASSERT_GT(nEndo, 100);
  ASSERT_GT(nEpi, 100);
  EXPECT_GT(sumEndo / nEndo, 35.0);
  EXPECT_LT(sumEpi / nEpi, -35.0);
  // Without a base, the axis turns towards the patient's right, back and head.
  const double* axis = filter->GetUsedApexToBase();
  EXPECT_NEAR(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2], 1.0, 1e-9);
  EXPECT_GT(-axis[0] + axis[1] + axis[2], 0.5);
}

TEST(VentricularFibres, AHoleInTheWallIsAWarning)
{
  // The myocardium's cells beside the LV blood in one corner of the pool become soft tissue.
  vtkSmartPointer<vtkUnstructuredGrid> mesh = PhantomHeartBox();
  static const amThoraxPhantomModel model;
  double c[3];
  model.GetOrganCenter(amThoraxPhantomModel::LeftVentricleBlood, c);
  vtkDataArray* regions = mesh->GetCellData()->GetArray("Region");
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    double x[3] = { 0, 0, 0 }, p[3];
    const vtkIdType* ids;
    vtkIdType npts;
    mesh->GetCellPoints(cell, npts, ids);
    for (int a = 0; a < 4; ++a)
    {
      mesh->GetPoint(ids[a], p);
      for (int d = 0; d < 3; ++d)
        x[d] += 0.25 * p[d];
    }
    if (regions->GetComponent(cell, 0) == amThoraxPhantomModel::Myocardium && x[2] > c[2] + 20)
      regions->SetComponent(cell, 0, amThoraxPhantomModel::SoftTissue);
  }
  vtkNew<amVentricularFibres> filter;
  filter->SetInputData(mesh);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(filter);
  filter->Update();
  EXPECT_GT(filter->GetNumberOfWallHoles(), 0);
  ASSERT_FALSE(errors->Warnings.empty());
  EXPECT_NE(errors->Warnings[0].find("the heart wall has holes: blood region 6 touches region 1"), std::string::npos)
    << errors->Warnings[0];
}

TEST(VentricularFibres, RefusesAMeshWithoutVentricles)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = PhantomHeartBox();
  vtkNew<amVentricularFibres> filter;
  filter->SetInputData(mesh);
  filter->RemoveAllLVBloodRegions();
  filter->AddLVBloodRegion(42);
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(filter);
  filter->Update();
  EXPECT_TRUE(errors->ErrorContains("no LV endocardium")) << errors->AllErrors();

  vtkNew<amVentricularFibres> noHeart;
  noHeart->SetInputData(mesh);
  noHeart->RemoveAllHeartRegions();
  noHeart->AddHeartRegion(99);
  vtkNew<amTest::ErrorCatcher> errors2;
  errors2->Watch(noHeart);
  noHeart->Update();
  EXPECT_TRUE(errors2->ErrorContains("no heart")) << errors2->AllErrors();
}
