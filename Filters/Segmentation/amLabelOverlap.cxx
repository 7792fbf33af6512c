#include "amLabelOverlap.h"

#include "amInputCheck.h"
#include "amUnits.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(amLabelOverlap);

amLabelOverlap::amLabelOverlap()
  : BinaryReference(false)
{
  this->SetNumberOfInputPorts(2);
}

amLabelOverlap::~amLabelOverlap() = default;

int amLabelOverlap::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1); // so a missing reference gets our own message
  return 1;
}

int amLabelOverlap::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The two maps live on different grids: each must come whole (the default would hand the
  // first input's extent to the second).
  for (int port = 0; port < 2; ++port)
    if (vtkInformation* in = inputVector[port]->GetInformationObject(0))
      if (in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
        in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
          in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  return 1;
}

double amLabelOverlap::GetDice(int label)
{
  vtkTable* t = this->GetOutput();
  if (!t || t->GetNumberOfRows() == 0)
    return -1.0;
  for (vtkIdType r = 0; r < t->GetNumberOfRows(); ++r)
    if (t->GetValueByName(r, "Label").ToInt() == label)
      return t->GetValueByName(r, "Dice").ToDouble();
  return -1.0;
}

int amLabelOverlap::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* a = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* b = vtkImageData::GetData(inputVector[1], 0);
  vtkTable* output = vtkTable::GetData(outputVector, 0);
  std::string why;
  vtkDataArray* la = amInputCheck::ScalarImage(a, why);
  if (!la)
  {
    vtkErrorMacro("Label map: " << why);
    return 0;
  }
  vtkDataArray* lb = b ? amInputCheck::ScalarImage(b, why) : nullptr;
  if (!lb)
  {
    vtkErrorMacro("Reference: " << (b ? why : std::string("no reference label map on input port 1.")));
    return 0;
  }
  int da[3], db[3], eb[6];
  a->GetDimensions(da);
  b->GetDimensions(db);
  b->GetExtent(eb);
  int ea[6];
  a->GetExtent(ea);
  const double voxel = a->GetSpacing()[0] * a->GetSpacing()[1] * a->GetSpacing()[2];

  // Reference label at each voxel centre of the evaluated map (nearest voxel, 0 outside). On the
  // same grid that voxel is the one of the same index (the transforms' rounding stays far below
  // half a voxel), read directly.
  bool sameGrid = true;
  for (int d = 0; d < 6; ++d)
    sameGrid = sameGrid && ea[d] == eb[d];
  for (int d = 0; d < 3; ++d)
    sameGrid = sameGrid && a->GetOrigin()[d] == b->GetOrigin()[d] && a->GetSpacing()[d] == b->GetSpacing()[d];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      sameGrid = sameGrid && a->GetDirectionMatrix()->GetElement(r, c) == b->GetDirectionMatrix()->GetElement(r, c);
  auto reference = [&](vtkIdType id, int i, int j, int k) {
    if (sameGrid)
      return static_cast<int>(lb->GetComponent(id, 0));
    double x[3], c[3];
    a->TransformContinuousIndexToPhysicalPoint(i + ea[0], j + ea[2], k + ea[4], x);
    b->TransformPhysicalPointToContinuousIndex(x, c);
    int ijk[3];
    for (int d = 0; d < 3; ++d)
    {
      ijk[d] = static_cast<int>(std::floor(c[d] + 0.5)) - eb[2 * d];
      if (ijk[d] < 0 || ijk[d] >= db[d])
        return 0;
    }
    return static_cast<int>(lb->GetComponent((static_cast<vtkIdType>(ijk[2]) * db[1] + ijk[1]) * db[0] + ijk[0], 0));
  };

  // Voxel counts per label, slab by slab on the threads: whole numbers, so their sum is the same
  // whatever the number of threads and the order the slabs are added in.
  struct Counts
  {
    std::array<long long, 257> A{}, B{}, Both{};
    long long FA = 0, FB = 0, FBoth = 0;
  };
  vtkSMPThreadLocal<Counts> local;
  vtkSMPTools::For(0, da[2], [&](vtkIdType k0, vtkIdType k1) {
    Counts& n = local.Local();
    for (vtkIdType k = k0; k < k1; ++k)
      for (int j = 0; j < da[1]; ++j)
        for (int i = 0; i < da[0]; ++i)
        {
          const vtkIdType id = (k * da[1] + j) * static_cast<vtkIdType>(da[0]) + i;
          const int p = static_cast<int>(la->GetComponent(id, 0)), q = reference(id, i, j, static_cast<int>(k));
          const int pa = std::min(256, std::max(0, p)), qb = std::min(256, std::max(0, q));
          ++n.A[pa];
          if (this->BinaryReference)
            n.Both[pa] += q != 0 && p != 0;
          else
          {
            ++n.B[qb];
            n.Both[pa] += p == q;
          }
          n.FA += p != 0;
          n.FB += q != 0;
          n.FBoth += p != 0 && q != 0;
        }
  });
  Counts sum;
  for (const Counts& n : local)
  {
    for (int l = 0; l < 257; ++l)
    {
      sum.A[l] += n.A[l];
      sum.B[l] += n.B[l];
      sum.Both[l] += n.Both[l];
    }
    sum.FA += n.FA;
    sum.FB += n.FB;
    sum.FBoth += n.FBoth;
  }
  // A binary reference: every label is compared with the reference's whole foreground.
  if (this->BinaryReference)
    for (int l = 1; l < 257; ++l)
      sum.B[l] = sum.A[l] ? sum.FB : 0;

  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  vtkNew<vtkDoubleArray> volume, refVolume, dice, jaccard;
  volume->SetName("Volume");
  refVolume->SetName("ReferenceVolume");
  amUnits::Set(volume, "mm3");
  amUnits::Set(refVolume, "mm3");
  dice->SetName("Dice");
  jaccard->SetName("Jaccard");
  auto row = [&](int l, double x, double y, double z) {
    label->InsertNextValue(l);
    volume->InsertNextValue(x * voxel);
    refVolume->InsertNextValue(y * voxel);
    dice->InsertNextValue(x + y > 0 ? 2.0 * z / (x + y) : 1.0);
    jaccard->InsertNextValue(x + y - z > 0 ? z / (x + y - z) : 1.0);
  };
  for (int l = 1; l < 257; ++l)
    if (sum.A[l] > 0 || sum.B[l] > 0)
      row(l, static_cast<double>(sum.A[l]), static_cast<double>(sum.B[l]), static_cast<double>(sum.Both[l]));
  row(-1, static_cast<double>(sum.FA), static_cast<double>(sum.FB), static_cast<double>(sum.FBoth));
  output->AddColumn(label);
  output->AddColumn(volume);
  output->AddColumn(refVolume);
  output->AddColumn(dice);
  output->AddColumn(jaccard);
  return 1;
}

void amLabelOverlap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BinaryReference: " << this->BinaryReference << "\n";
}
