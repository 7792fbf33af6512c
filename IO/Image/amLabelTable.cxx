#include "amLabelTable.h"

#include "amAtomicFile.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdio>
#include <functional>

namespace
{
std::string Stem(const std::string& imagePath)
{
  return imagePath.substr(0, imagePath.size() - amAtomicFile::Extension(imagePath).size());
}

/// One table file, written atomically: the header, then one line per label value (its name and
/// colour given to 'line'); false with 'why' when it cannot be written whole.
bool WriteTable(const std::string& path, const std::string& header, vtkStringArray* names,
  const std::function<std::string(int, const std::string&, const unsigned char*)>& line, std::string& why)
{
  amAtomicFile file(path);
  FILE* f = std::fopen(file.TemporaryPath().c_str(), "wb");
  if (!f)
  {
    why = "cannot create the label table " + path + " beside it";
    return false;
  }
  bool ok = std::fputs(header.c_str(), f) >= 0;
  for (vtkIdType v = 0; v < names->GetNumberOfValues(); ++v)
  {
    unsigned char rgb[3];
    amLabelTable::Colour(static_cast<int>(v), rgb);
    ok = ok && std::fputs(line(static_cast<int>(v), names->GetValue(v), rgb).c_str(), f) >= 0;
  }
  ok = std::fflush(f) == 0 && ok;
  ok = std::fclose(f) == 0 && ok;
  if (!ok)
  {
    std::remove(file.TemporaryPath().c_str());
    why = "the label table " + path + " beside it is incomplete; is the disk full?";
    return false;
  }
  return file.Commit(why);
}

/// The name with the characters a format cannot hold replaced.
std::string Clean(std::string name, const std::string& bad, char by)
{
  for (char& c : name)
    if (bad.find(c) != std::string::npos)
      c = by;
  return name;
}
}

std::string amLabelTable::PathFor(const std::string& imagePath)
{
  return Stem(imagePath) + ".ctbl";
}

std::string amLabelTable::ItkSnapPathFor(const std::string& imagePath)
{
  return Stem(imagePath) + ".itksnap.txt";
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
  const std::string file = imagePath.substr(imagePath.find_last_of('/') + 1);
  // 3D Slicer's colour table (FreeSurfer's LUT layout): "value name R G B A", no spaces in names.
  const bool slicer = WriteTable(
    PathFor(imagePath), "# Anatomesh label table of " + file + ": value name R G B A\n", names,
    [](int v, const std::string& name, const unsigned char* rgb) {
      char line[512];
      std::snprintf(line, sizeof(line), "%d %s %d %d %d %d\n", v,
        name.empty() ? "unnamed" : Clean(name, " \t", '_').c_str(), rgb[0], rgb[1], rgb[2], v == 0 ? 0 : 255);
      return std::string(line);
    },
    why);
  // ITK-SNAP's label description: IDX R G B A(0-1) VIS MSH "LABEL"; 0 is its "Clear Label".
  return slicer &&
    WriteTable(
      ItkSnapPathFor(imagePath),
      "################################################\n"
      "# ITK-SnAP Label Description File\n"
      "# Anatomesh labels of " +
        file +
        "\n"
        "# Fields: IDX -R- -G- -B- -A-- VIS MSH LABEL\n"
        "################################################\n",
      names,
      [](int v, const std::string& name, const unsigned char* rgb) {
        char line[512];
        std::snprintf(line, sizeof(line), "%5d %5d %4d %4d %8d %2d %2d    \"%s\"\n", v, rgb[0], rgb[1], rgb[2],
          v == 0 ? 0 : 1, v == 0 ? 0 : 1, v == 0 ? 0 : 1,
          v == 0 ? "Clear Label" : (name.empty() ? "unnamed" : Clean(name, "\"\n\r", '\'').c_str()));
        return std::string(line);
      },
      why);
}
