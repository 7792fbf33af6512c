// amLabelOverlap compares label maps in world coordinates, whatever their grids.
#include "amLabelOverlap.h"
#include "amTestUtilities.h"
#include "amThoraxPhantomSource.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

namespace
{
vtkSmartPointer<vtkImageData> PhantomLabels(double spacing)
{
  vtkNew<amThoraxPhantomSource> src;
  src->SetSpacing(spacing, spacing, spacing);
  src->Update();
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->DeepCopy(src->GetOutputDataObject(1));
  return img;
}
}

TEST(LabelOverlap, SameAnatomyOnAFlippedGridMatchesExactly)
{
  auto a = PhantomLabels(4.0);
  // The same voxels stored with the x axis reversed: direction diag(-1, 1, 1), origin at the far end.
  auto b = vtkSmartPointer<vtkImageData>::New();
  b->DeepCopy(a);
  int d[3];
  a->GetDimensions(d);
  auto* src = vtkUnsignedCharArray::SafeDownCast(a->GetPointData()->GetScalars());
  auto* dst = vtkUnsignedCharArray::SafeDownCast(b->GetPointData()->GetScalars());
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
        dst->SetValue((k * d[1] + j) * d[0] + i, src->GetValue((k * d[1] + j) * d[0] + (d[0] - 1 - i)));
  const double dir[9] = { -1, 0, 0, 0, 1, 0, 0, 0, 1 };
  b->SetDirectionMatrix(dir);
  double far[3];
  a->TransformContinuousIndexToPhysicalPoint(d[0] - 1, 0, 0, far);
  b->SetOrigin(far);

  vtkNew<amLabelOverlap> overlap;
  overlap->SetInputData(0, a);
  overlap->SetReferenceData(b);
  overlap->Update();
  vtkTable* t = overlap->GetOutput();
  ASSERT_EQ(t->GetNumberOfRows(), 11); // labels 1..10 (background excluded) and the foreground row
  for (vtkIdType r = 0; r < t->GetNumberOfRows(); ++r)
    EXPECT_DOUBLE_EQ(t->GetValueByName(r, "Dice").ToDouble(), 1.0) << "label " << t->GetValueByName(r, "Label").ToInt();

  // Without the direction, the comparison would be mirrored: the lungs swap sides.
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  b->SetDirectionMatrix(identity);
  b->SetOrigin(a->GetOrigin());
  overlap->Modified();
  overlap->Update();
  EXPECT_LT(overlap->GetDice(3), 0.2);
}

TEST(LabelOverlap, DifferentResolutionsAndBinaryMasks)
{
  auto coarse = PhantomLabels(4.0), fine = PhantomLabels(2.0);
  vtkNew<amLabelOverlap> overlap;
  overlap->SetInputData(0, coarse);
  overlap->SetReferenceData(fine);
  overlap->Update();
  for (int l : { 3, 4, 5 })
    EXPECT_GT(overlap->GetDice(l), 0.9) << "label " << l;
  EXPECT_GT(overlap->GetDice(-1), 0.99);
  EXPECT_EQ(overlap->GetDice(77), -1.0);

  // A 0/1 mask of the LV blood as reference, against the multi-label map.
  auto mask = vtkSmartPointer<vtkImageData>::New();
  mask->DeepCopy(coarse);
  vtkDataArray* m = mask->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < m->GetNumberOfTuples(); ++i)
    m->SetComponent(i, 0, m->GetComponent(i, 0) == 6 ? 1 : 0);
  vtkNew<amLabelOverlap> binary;
  binary->SetInputData(0, coarse);
  binary->SetReferenceData(mask);
  binary->BinaryReferenceOn();
  binary->Update();
  EXPECT_DOUBLE_EQ(binary->GetDice(6), 1.0);
}

TEST(LabelOverlap, MissingReferenceIsAnError)
{
  vtkNew<amLabelOverlap> overlap;
  vtkNew<amTest::ErrorCatcher> errors;
  errors->Watch(overlap);
  overlap->SetInputData(0, PhantomLabels(8.0));
  overlap->Update();
  EXPECT_TRUE(errors->HasError());
}
