// The label-preserving Gaussian regularisation: the argmax of the smoothed indicators (ITK).
#include "amLabelCleaning.h"

#include "vtkSMPTools.h"

#include <itkSmoothingRecursiveGaussianImageFilter.h>

#include <algorithm>
#include <array>

void amLabelCleaning::Smooth(
  const Grid& grid, double sigma, std::vector<unsigned char>& out, const std::function<void(double)>& progress)
{
  const int* dims = grid.Dims;
  const double* spacing = grid.Spacing;
  const vtkIdType n = static_cast<vtkIdType>(out.size());
  std::array<vtkIdType, 256> present{};
  for (unsigned char v : out)
    ++present[v];
  using FloatImage = itk::Image<float, 3>;
  FloatImage::RegionType region;
  FloatImage::SizeType size = { { static_cast<itk::SizeValueType>(dims[0]), static_cast<itk::SizeValueType>(dims[1]),
    static_cast<itk::SizeValueType>(dims[2]) } };
  region.SetSize(size);
  FloatImage::SpacingType sp;
  for (int a = 0; a < 3; ++a)
    sp[a] = spacing[a];
  std::vector<float> best(static_cast<size_t>(n), -1.0f);
  std::vector<unsigned char> bestLabel(out);
  auto indicator = FloatImage::New();
  indicator->SetRegions(region);
  indicator->SetSpacing(sp);
  indicator->Allocate();
  int done = 0;
  const int total = static_cast<int>(std::count_if(present.begin(), present.end(), [](vtkIdType c) { return c > 0; }));
  for (int l = 0; l < 256; ++l)
  {
    if (!present[l])
      continue;
    float* ind = indicator->GetBufferPointer();
    for (vtkIdType i = 0; i < n; ++i)
      ind[i] = out[i] == l ? 1.0f : 0.0f;
    auto smooth = itk::SmoothingRecursiveGaussianImageFilter<FloatImage, FloatImage>::New();
    smooth->SetInput(indicator);
    smooth->SetSigma(sigma);
    smooth->Update();
    const float* s = smooth->GetOutput()->GetBufferPointer();
    vtkSMPTools::For(0, n, [&](vtkIdType b, vtkIdType e) {
      for (vtkIdType i = b; i < e; ++i)
        if (s[i] > best[i] + 1e-6f || (s[i] >= best[i] - 1e-6f && out[i] == l))
        {
          best[i] = s[i];
          bestLabel[i] = static_cast<unsigned char>(l);
        }
    });
    if (progress)
      progress(static_cast<double>(++done) / total);
  }
  out.swap(bestLabel);
}
