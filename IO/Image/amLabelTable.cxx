#include "amLabelTable.h"

#include "amAtomicFile.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdio>

std::string amLabelTable::PathFor(const std::string& imagePath)
{
  const std::string ext = amAtomicFile::Extension(imagePath);
  return imagePath.substr(0, imagePath.size() - ext.size()) + ".ctbl";
}

void amLabelTable::Colour(int value, unsigned char rgb[3])
{
  if (value == 0)
  {
    rgb[0] = rgb[1] = rgb[2] = 0;
    return;
  }
  // Hues a golden angle apart: neighbouring labels differ; saturation and value alternate a little.
  const double h = std::fmod(value * 137.50776405, 360.0) / 60.0;
  const double s = value % 2 ? 0.65 : 0.85, v = value % 3 ? 0.95 : 0.8;
  const int sector = static_cast<int>(h) % 6;
  const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double table[6][3] = { { v, t, p }, { q, v, p }, { p, v, t }, { p, q, v }, { t, p, v }, { v, p, q } };
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(std::lround(255.0 * table[sector][c]));
}

bool amLabelTable::Write(vtkImageData* image, const std::string& imagePath, std::string& why)
{
  auto* names = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("LabelNames"));
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  // A label map: its scalars are "Labels" (a scan beside it may carry the same field data).
  if (!names || names->GetNumberOfValues() == 0 || !scalars || !scalars->GetName() ||
    std::string(scalars->GetName()) != "Labels")
    return true;
  amAtomicFile file(PathFor(imagePath));
  FILE* f = std::fopen(file.TemporaryPath().c_str(), "wb");
  if (!f)
  {
    why = "cannot create the label table beside it";
    return false;
  }
  bool ok = std::fprintf(f, "# Anatomesh label table of %s: value name R G B A\n",
              imagePath.substr(imagePath.find_last_of('/') + 1).c_str()) > 0;
  for (vtkIdType v = 0; v < names->GetNumberOfValues(); ++v)
  {
    std::string name = names->GetValue(v);
    for (char& c : name)
      if (c == ' ' || c == '\t')
        c = '_';
    unsigned char rgb[3];
    Colour(static_cast<int>(v), rgb);
    ok = ok &&
      std::fprintf(f, "%lld %s %d %d %d %d\n", static_cast<long long>(v), name.empty() ? "unnamed" : name.c_str(),
        rgb[0], rgb[1], rgb[2], v == 0 ? 0 : 255) > 0;
  }
  ok = std::fflush(f) == 0 && ok;
  ok = std::fclose(f) == 0 && ok;
  if (!ok)
  {
    std::remove(file.TemporaryPath().c_str());
    why = "the label table beside it is incomplete; is the disk full?";
    return false;
  }
  return file.Commit(why);
}
