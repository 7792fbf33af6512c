// The analytic thorax: labels at organ centres, containment and disjointness that make the
// closed-form volumes exact, and those volumes against a fine sampling.
#include "amThoraxPhantomModel.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using M = amThoraxPhantomModel;

TEST(ThoraxPhantomModel, OrganCentresCarryTheirLabel)
{
  const M model;
  for (int label = 0; label < M::NumberOfLabels; ++label)
  {
    double c[3];
    model.GetOrganCenter(label, c);
    EXPECT_EQ(model.LabelAt(c), label) << M::LabelName(label) << " at " << c[0] << " " << c[1] << " " << c[2];
  }
}

TEST(ThoraxPhantomModel, NamesAndUnits)
{
  EXPECT_STREQ(M::LabelName(M::LeftVentricleBlood), "LeftVentricleBlood");
  EXPECT_STREQ(M::LabelName(99), "Unknown");
  EXPECT_DOUBLE_EQ(M::HounsfieldUnits(M::Background), -1000.0);
  EXPECT_GT(M::HounsfieldUnits(M::LeftVentricleBlood), M::HounsfieldUnits(M::Myocardium) + 200.0);
  EXPECT_LT(M::HounsfieldUnits(M::LeftLung), -800.0);
}

TEST(ThoraxPhantomModel, BloodPoolsAreWalledInsideTheHeart)
{
  // Every point of each pool's surface, pushed 3 mm further out, is still inside the heart:
  // the myocardial wall is at least 3 mm thick, so the pools' volumes are exact.
  const M model;
  const double pi = 3.14159265358979;
  for (int pool : { M::LeftVentricleBlood, M::RightVentricleBlood })
  {
    double c[3];
    model.GetOrganCenter(pool, c);
    int checked = 0;
    for (int a = 0; a < 48; ++a)
      for (int b = 1; b < 24; ++b)
      {
        const double th = 2 * pi * a / 48, ph = pi * b / 24;
        const double d[3] = { std::cos(th) * std::sin(ph), std::sin(th) * std::sin(ph), std::cos(ph) };
        // March out to the pool's surface along d.
        double t = 0;
        double x[3] = { c[0], c[1], c[2] };
        while (true)
        {
          const double y[3] = { c[0] + (t + 0.1) * d[0], c[1] + (t + 0.1) * d[1], c[2] + (t + 0.1) * d[2] };
          const bool inside =
            pool == M::LeftVentricleBlood ? model.InsideLeftVentricle(y) : model.InsideRightVentricle(y);
          if (!inside)
            break;
          t += 0.1;
        }
        for (int i = 0; i < 3; ++i)
          x[i] = c[i] + (t + 3.0) * d[i];
        EXPECT_TRUE(model.InsideHeart(x))
          << M::LabelName(pool) << " wall thinner than 3 mm towards " << d[0] << " " << d[1] << " " << d[2];
        ++checked;
      }
    EXPECT_EQ(checked, 48 * 23);
  }
}

TEST(ThoraxPhantomModel, ExactVolumesMatchFineSampling)
{
  // Count 0.5 mm lattice points in the boxes around the pools and the aorta.
  const M model;
  struct Case
  {
    int Label;
    double Box[6];
  };
  const Case cases[] = {
    { M::LeftVentricleBlood, { -30, 70, -80, 20, -70, 20 } },
    { M::RightVentricleBlood, { -50, 40, -90, 10, -70, 20 } },
    { M::Spine, { -15, 15, 50, 82, -75, 75 } },
  };
  const double h = 0.5;
  for (const Case& cs : cases)
  {
    long count = 0;
    for (double z = cs.Box[4] + h / 2; z < cs.Box[5]; z += h)
      for (double y = cs.Box[2] + h / 2; y < cs.Box[3]; y += h)
        for (double x = cs.Box[0] + h / 2; x < cs.Box[1]; x += h)
        {
          const double p[3] = { x, y, z };
          count += model.LabelAt(p) == cs.Label;
        }
    const double sampled = count * h * h * h, exact = model.ExactVolume(cs.Label);
    EXPECT_NEAR(sampled / exact, 1.0, 0.005) << M::LabelName(cs.Label) << ": sampled " << sampled << " exact " << exact;
  }
}

TEST(ThoraxPhantomModel, BodyContainsEveryOrgan)
{
  const M model;
  double b[6];
  model.GetBodyBounds(b);
  EXPECT_DOUBLE_EQ(b[1], 150.0);
  const double outside[3] = { 0.0, 0.0, b[5] + 1.0 };
  EXPECT_EQ(model.LabelAt(outside), 0);
  const double top[3] = { 0.0, 0.0, b[5] - 0.5 };
  EXPECT_NE(model.LabelAt(top), 0);
  EXPECT_GT(model.BodyVolume(), 8.0e6); // mm^3: a thorax of about 8.5 litres
  EXPECT_LT(model.BodyVolume(), 9.0e6);
  EXPECT_LT(model.ExactVolume(M::RightLung), 0.0); // not closed-form
}

TEST(ThoraxPhantomModel, HabitusScalesTheHeartAndThickensTheFat)
{
  const amThoraxPhantomModel usual;
  amThoraxPhantomModel::Habitus build;
  build.FatThickness = 30.0;
  build.HeartScale = 1.2;
  build.HeartAngle = -45.0;
  const amThoraxPhantomModel other(build);
  // The heart's shapes scale by k: volumes by k^3; the body grows by the fat over the same inner body.
  for (int label : { amThoraxPhantomModel::LeftVentricleBlood, amThoraxPhantomModel::RightVentricleBlood })
    EXPECT_NEAR(other.ExactVolume(label), 1.2 * 1.2 * 1.2 * usual.ExactVolume(label), 1e-6 * usual.ExactVolume(label));
  double a[6], b[6];
  usual.GetBodyBounds(a);
  other.GetBodyBounds(b);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(std::fabs(b[i]) - std::fabs(a[i]), 18.0, 1e-9) << i;
  // A click in the default LV lands in the other's LV, the frame's round trip is exact to rounding.
  const double click[3] = { 29.4, -24.1, -28.0 };
  double frame[3], there[3], back[3];
  usual.WorldToHeartFrame(click, frame);
  other.HeartFrameToWorld(frame, there);
  EXPECT_EQ(other.LabelAt(there), amThoraxPhantomModel::LeftVentricleBlood);
  usual.HeartFrameToWorld(frame, back);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(back[i], click[i], 1e-12);
  // The default build is the usual phantom.
  const amThoraxPhantomModel same{ amThoraxPhantomModel::Habitus() };
  for (int label = 1; label < amThoraxPhantomModel::NumberOfLabels; ++label)
    EXPECT_EQ(same.ExactVolume(label), usual.ExactVolume(label)) << label;
}

TEST(ThoraxPhantomModel, TheVentriclesHaveAHeartsWallsAndItsApexPointsDown)
{
  amThoraxPhantomModel::Habitus build;
  build.HeartShape = M::Ventricles;
  const M model(build);
  for (int label : { M::Myocardium, M::LeftVentricleBlood, M::RightVentricleBlood })
  {
    double c[3];
    model.GetOrganCenter(label, c);
    EXPECT_EQ(model.LabelAt(c), label) << M::LabelName(label);
  }
  // Across the LV's lateral wall and the RV's free wall, along the frame's axis to the RV (at the
  // cavities' centre level): 10 mm and 4 mm of muscle.
  auto run = [&](double u, double v0, double step, int label) {
    double t = 0;
    for (;; t += 0.05)
    {
      const double frame[3] = { u, v0 + step * t, 0.0 };
      double x[3];
      model.HeartFrameToWorld(frame, x);
      if (model.LabelAt(x) != label)
        break;
    }
    return t;
  };
  EXPECT_NEAR(run(-10.0, -31.05, -1.0, M::Myocardium), 10.0, 0.1);
  EXPECT_NEAR(run(-5.0, 45.05, 1.0, M::Myocardium), 4.0, 0.1);
  // On a 1 mm lattice: the pools lie inside the muscle (no pool point beside anything else), the
  // LV's volume is its closed form, the muscle an adult's ventricles' (150-220 cm3), and the LV's
  // long axis (from the cavity's centroid to its farthest point, the apex) points left, forwards
  // and down.
  long lv = 0, muscle = 0, exposed = 0;
  std::vector<std::array<double, 3>> cavity;
  const double h = 1.0;
  for (double z = -110.5; z < 20; z += h)
    for (double y = -100.5; y < 40; y += h)
      for (double x = -50.5; x < 100; x += h)
      {
        const double p[3] = { x, y, z };
        const int l = model.LabelAt(p);
        lv += l == M::LeftVentricleBlood;
        muscle += l == M::Myocardium;
        if (l == M::LeftVentricleBlood)
          cavity.push_back({ x, y, z });
        if (l != M::LeftVentricleBlood && l != M::RightVentricleBlood)
          continue;
        for (int a = 0; a < 3; ++a)
          for (int s : { -1, 1 })
          {
            double q[3] = { x, y, z };
            q[a] += s * h;
            const int m = model.LabelAt(q);
            exposed += m != M::Myocardium && m != M::LeftVentricleBlood && m != M::RightVentricleBlood;
          }
      }
  EXPECT_EQ(exposed, 0);
  EXPECT_NEAR(lv * h * h * h / model.ExactVolume(M::LeftVentricleBlood), 1.0, 0.01);
  EXPECT_NEAR(model.ExactVolume(M::LeftVentricleBlood), 89.6e3, 0.1e3);
  EXPECT_GT(muscle * h * h * h, 150e3);
  EXPECT_LT(muscle * h * h * h, 220e3);
  double c[3] = { 0, 0, 0 }, axis[3] = { 0, 0, 0 }, far = 0;
  for (const auto& p : cavity)
    for (int a = 0; a < 3; ++a)
      c[a] += p[a] / cavity.size();
  for (const auto& p : cavity)
  {
    const double d = std::hypot(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
    if (d > far)
    {
      far = d;
      for (int a = 0; a < 3; ++a)
        axis[a] = (p[a] - c[a]) / d;
    }
  }
  EXPECT_GT(far, 40.0);
  EXPECT_GT(axis[0], 0.6);
  EXPECT_LT(axis[1], -0.3);
  EXPECT_LT(axis[2], -0.3);
  // The RV's crescent and the muscle are not closed-form; the default shape is unchanged.
  EXPECT_LT(model.ExactVolume(M::RightVentricleBlood), 0.0);
  EXPECT_LT(model.ExactVolume(M::Myocardium), 0.0);
  EXPECT_GT(M().ExactVolume(M::Myocardium), 0.0);
}
