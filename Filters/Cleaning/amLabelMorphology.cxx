// One label's morphology, small components and holes, on the box around it (ITK).
#include "amLabelCleaning.h"

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryDilateImageFilter.h>
#include <itkBinaryErodeImageFilter.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryMorphologicalClosingImageFilter.h>
#include <itkBinaryMorphologicalOpeningImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkRelabelComponentImageFilter.h>

#include <algorithm>
#include <cmath>

namespace
{
using Mask = itk::Image<unsigned char, 3>;
using Ball = itk::BinaryBallStructuringElement<unsigned char, 3>;

struct Box
{
  int Lo[3], Hi[3];
  int Size(int a) const { return this->Hi[a] - this->Lo[a] + 1; }
};

template<typename FilterType>
Mask::Pointer Morph(Mask* in, const Ball& ball)
{
  auto f = FilterType::New();
  f->SetInput(in);
  f->SetKernel(ball);
  f->SetForegroundValue(1);
  f->Update();
  return f->GetOutput();
}
}

bool amLabelCleaning::CleanLabel(const Grid& grid, const Settings& s, int label, std::vector<unsigned char>& out,
  std::vector<Removed>& removed, std::string& why)
{
  const int* dims = grid.Dims;
  const double* spacing = grid.Spacing;
  const vtkIdType n = static_cast<vtkIdType>(out.size());
  const vtkIdType sz = static_cast<vtkIdType>(dims[0]) * dims[1];
  const double voxelVolume = spacing[0] * spacing[1] * spacing[2];
  const bool morph = s.Operation != None && s.Radius > 0;
  int r[3];
  for (int a = 0; a < 3; ++a)
    r[a] = morph ? static_cast<int>(std::lround(s.Radius / spacing[a])) : 0;
  const int pad = std::max(r[0], std::max(r[1], r[2])) + 2;
  Box box{ { dims[0], dims[1], dims[2] }, { -1, -1, -1 } };
  for (vtkIdType id = 0; id < n; ++id)
    if (out[id] == label)
    {
      const int ijk[3] = { static_cast<int>(id % dims[0]), static_cast<int>((id / dims[0]) % dims[1]),
        static_cast<int>(id / sz) };
      for (int a = 0; a < 3; ++a)
      {
        box.Lo[a] = std::min(box.Lo[a], ijk[a]);
        box.Hi[a] = std::max(box.Hi[a], ijk[a]);
      }
    }
  if (box.Hi[0] < 0)
    return true; // not present
  for (int a = 0; a < 3; ++a)
  {
    box.Lo[a] = std::max(0, box.Lo[a] - pad);
    box.Hi[a] = std::min(dims[a] - 1, box.Hi[a] + pad);
  }
  auto mask = Mask::New();
  Mask::RegionType region;
  Mask::SizeType size = { { static_cast<itk::SizeValueType>(box.Size(0)), static_cast<itk::SizeValueType>(box.Size(1)),
    static_cast<itk::SizeValueType>(box.Size(2)) } };
  region.SetSize(size);
  mask->SetRegions(region);
  Mask::SpacingType sp;
  for (int a = 0; a < 3; ++a)
    sp[a] = spacing[a];
  mask->SetSpacing(sp);
  mask->Allocate();
  auto roiId = [&](int i, int j, int k) { return (static_cast<size_t>(k) * box.Size(1) + j) * box.Size(0) + i; };
  auto globalId = [&](int i, int j, int k) {
    return (static_cast<vtkIdType>(k + box.Lo[2]) * dims[1] + (j + box.Lo[1])) * dims[0] + (i + box.Lo[0]);
  };
  for (int k = 0; k < box.Size(2); ++k)
    for (int j = 0; j < box.Size(1); ++j)
      for (int i = 0; i < box.Size(0); ++i)
        mask->GetBufferPointer()[roiId(i, j, k)] = out[globalId(i, j, k)] == label ? 1 : 0;

  Mask::Pointer result = mask;
  try
  {
    if (morph)
    {
      Ball ball;
      Ball::SizeType radius;
      for (int a = 0; a < 3; ++a)
        radius[a] = static_cast<itk::SizeValueType>(r[a]);
      ball.SetRadius(radius);
      ball.CreateStructuringElement();
      switch (s.Operation)
      {
        case amLabelCleaning::Erode:
          result = Morph<itk::BinaryErodeImageFilter<Mask, Mask, Ball>>(result, ball);
          break;
        case amLabelCleaning::Dilate:
          result = Morph<itk::BinaryDilateImageFilter<Mask, Mask, Ball>>(result, ball);
          break;
        case amLabelCleaning::Open:
          result = Morph<itk::BinaryMorphologicalOpeningImageFilter<Mask, Mask, Ball>>(result, ball);
          break;
        case amLabelCleaning::Close:
          result = Morph<itk::BinaryMorphologicalClosingImageFilter<Mask, Mask, Ball>>(result, ball);
          break;
        default:
          break;
      }
    }
    if (s.MinimumComponentVolume > 0 || s.KeepLargestComponent)
    {
      using LabelImage = itk::Image<unsigned int, 3>;
      auto cc = itk::ConnectedComponentImageFilter<Mask, LabelImage>::New();
      cc->SetInput(result);
      cc->SetFullyConnected(false);
      auto relabel = itk::RelabelComponentImageFilter<LabelImage, LabelImage>::New();
      relabel->SetInput(cc->GetOutput());
      relabel->Update();
      const auto& sizes = relabel->GetSizeOfObjectsInPixels();
      std::vector<char> drop(sizes.size() + 1, 0);
      for (size_t c = 0; c < sizes.size(); ++c)
        if ((s.KeepLargestComponent && c > 0) || sizes[c] * voxelVolume < s.MinimumComponentVolume)
        {
          drop[c + 1] = 1;
          removed.push_back({ label, static_cast<double>(sizes[c]), sizes[c] * voxelVolume });
        }
      auto filtered = Mask::New();
      filtered->SetRegions(region);
      filtered->SetSpacing(sp);
      filtered->Allocate();
      const unsigned* c = relabel->GetOutput()->GetBufferPointer();
      for (size_t i = 0; i < region.GetNumberOfPixels(); ++i)
        filtered->GetBufferPointer()[i] = (c[i] && !drop[c[i]]) ? 1 : 0;
      result = filtered;
    }
    if (s.FillHoles)
    {
      auto fill = itk::BinaryFillholeImageFilter<Mask>::New();
      fill->SetInput(result);
      fill->SetForegroundValue(1);
      fill->SetFullyConnected(false);
      fill->Update();
      result = fill->GetOutput();
    }
  }
  catch (const itk::ExceptionObject& e)
  {
    why = "Cleaning label " + std::to_string(label) + " failed: " + e.GetDescription();
    return false;
  }
  // Apply: grow only into unlabelled voxels; hand what is given up to the neighbours.
  std::vector<vtkIdType> released;
  const unsigned char* m = result->GetBufferPointer();
  for (int k = 0; k < box.Size(2); ++k)
    for (int j = 0; j < box.Size(1); ++j)
      for (int i = 0; i < box.Size(0); ++i)
      {
        const vtkIdType g = globalId(i, j, k);
        const bool keep = m[roiId(i, j, k)] != 0;
        if (out[g] == label && !keep)
          released.push_back(g);
        else if (out[g] == 0 && keep)
          out[g] = static_cast<unsigned char>(label);
      }
  HandOver(dims, out, released, label);
  return true;
}
