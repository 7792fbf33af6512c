#include "amOpenCARPReader.h"

#include "amInputCheck.h"
#include "amOpenCARPWriter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>

vtkStandardNewMacro(amOpenCARPReader);

namespace
{
// A text file read line by line, with the line number for messages.
struct Lines
{
  std::ifstream In;
  std::string Path;
  long long Number = 0;
  std::string Text;
  bool Next()
  {
    ++this->Number;
    return static_cast<bool>(std::getline(this->In, this->Text));
  }
  std::string Where() const { return "'" + this->Path + "' line " + std::to_string(this->Number); }
};

// The count on a file's first line.
bool Count(Lines& lines, long long& count, std::string& why)
{
  if (!lines.Next())
  {
    why = "'" + lines.Path + "' is empty";
    return false;
  }
  std::istringstream in(lines.Text);
  if (!(in >> count) || count < 0)
  {
    why = lines.Where() + ": no count";
    return false;
  }
  return true;
}
}

amOpenCARPReader::amOpenCARPReader()
  : FileName(nullptr)
  , CoordinateScale(1000.0)
{
  this->SetNumberOfInputPorts(0);
}

amOpenCARPReader::~amOpenCARPReader()
{
  this->SetFileName(nullptr);
}

int amOpenCARPReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const std::string base = amOpenCARPWriter::BaseName(this->FileName);
  std::string why;
  for (const char* ending : { ".pts", ".elem" })
    if (!amInputCheck::ReadableFile(base + ending, false, why))
    {
      vtkErrorMacro("Cannot read the openCARP mesh: " << why);
      return 0;
    }
  Lines pts{ std::ifstream(base + ".pts"), base + ".pts" };
  Lines elem{ std::ifstream(base + ".elem"), base + ".elem" };
  if (!pts.In || !elem.In)
  {
    vtkErrorMacro("Cannot read '" << (pts.In ? elem.Path : pts.Path) << "': no such readable file.");
    return 0;
  }
  long long np = 0, ne = 0;
  if (!Count(pts, np, why) || !Count(elem, ne, why))
  {
    vtkErrorMacro("Cannot read the openCARP mesh: " << why << ".");
    return 0;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(np);
  for (long long i = 0; i < np; ++i)
  {
    double x[3];
    if (!pts.Next())
    {
      vtkErrorMacro("Cannot read " << pts.Where() << ": the file ends after " << i << " of " << np << " points.");
      return 0;
    }
    std::istringstream in(pts.Text);
    if (!(in >> x[0] >> x[1] >> x[2]) || !std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      vtkErrorMacro("Cannot read " << pts.Where() << ": not three finite numbers.");
      return 0;
    }
    points->SetPoint(i, x[0] / this->CoordinateScale, x[1] / this->CoordinateScale, x[2] / this->CoordinateScale);
  }
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIntArray> regions;
  regions->SetName("Region");
  for (long long c = 0; c < ne; ++c)
  {
    if (!elem.Next())
    {
      vtkErrorMacro("Cannot read " << elem.Where() << ": the file ends after " << c << " of " << ne << " elements.");
      return 0;
    }
    std::istringstream in(elem.Text);
    std::string type;
    long long ids[4], region = 0;
    if (!(in >> type) || type != "Tt")
    {
      vtkErrorMacro(
        "Cannot read " << elem.Where() << ": element type '" << type << "'; only tetrahedra (Tt) are read.");
      return 0;
    }
    if (!(in >> ids[0] >> ids[1] >> ids[2] >> ids[3]))
    {
      vtkErrorMacro("Cannot read " << elem.Where() << ": not four node indices.");
      return 0;
    }
    in >> region;
    vtkIdType cell[4];
    for (int a = 0; a < 4; ++a)
    {
      if (ids[a] < 0 || ids[a] >= np)
      {
        vtkErrorMacro(
          "Cannot read " << elem.Where() << ": node " << ids[a] << " is not one of the " << np << " points.");
        return 0;
      }
      cell[a] = static_cast<vtkIdType>(ids[a]);
    }
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (cell[a] == cell[b])
        {
          vtkErrorMacro(
            "Cannot read " << elem.Where() << ": node " << cell[a] << " appears twice: a degenerate tetrahedron.");
          return 0;
        }
    cells->InsertNextCell(4, cell);
    regions->InsertNextValue(static_cast<int>(region));
  }
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);
  output->GetCellData()->AddArray(regions);

  struct stat st;
  if (::stat((base + ".lon").c_str(), &st) == 0)
  {
    Lines lon{ std::ifstream(base + ".lon"), base + ".lon" };
    long long directions = 0;
    if (!Count(lon, directions, why) || (directions != 1 && directions != 2))
    {
      vtkErrorMacro("Cannot read " << lon.Where() << ": the first line says 1 or 2 directions per element.");
      return 0;
    }
    vtkNew<vtkDoubleArray> fibres, sheets;
    fibres->SetName("Fibers");
    sheets->SetName("Sheets");
    fibres->SetNumberOfComponents(3);
    sheets->SetNumberOfComponents(3);
    for (long long c = 0; c < ne; ++c)
    {
      double v[6] = { 0, 0, 0, 0, 0, 0 };
      if (!lon.Next())
      {
        vtkErrorMacro("Cannot read " << lon.Where() << ": the file ends after " << c << " of " << ne << " elements.");
        return 0;
      }
      std::istringstream in(lon.Text);
      for (int k = 0; k < 3 * directions; ++k)
        if (!(in >> v[k]))
        {
          vtkErrorMacro("Cannot read " << lon.Where() << ": not " << 3 * directions << " numbers.");
          return 0;
        }
      fibres->InsertNextTuple(v);
      if (directions == 2)
        sheets->InsertNextTuple(v + 3);
    }
    output->GetCellData()->AddArray(fibres);
    if (directions == 2)
      output->GetCellData()->AddArray(sheets);
  }
  return 1;
}

void amOpenCARPReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "CoordinateScale: " << this->CoordinateScale << "\n";
}
