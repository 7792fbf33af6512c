#include "amXdmfGrid.h"

#include "amHdf5Datasets.h"
#include "amTextOutput.h"

#include <sstream>

namespace
{
/// A DataItem: inline values, or a reference into the HDF5 file.
template<typename T>
void Item(amTextOutput& out, const std::vector<T>& values, std::size_t rows, int columns, const char* numberType,
  const std::string& hdf5Name, const std::string& dataset)
{
  out << "        <DataItem Dimensions=\"" << rows;
  if (columns > 1)
    out << " " << columns;
  out << "\" NumberType=\"" << numberType << "\" Precision=\"8\" Format=\"" << (hdf5Name.empty() ? "XML" : "HDF")
      << "\">";
  if (!hdf5Name.empty())
  {
    out << hdf5Name << ":/" << dataset << "</DataItem>\n";
    return;
  }
  out << "\n";
  for (std::size_t r = 0; r < rows; ++r)
  {
    for (int c = 0; c < columns; ++c)
    {
      if (c)
        out << " ";
      out << values[r * columns + c];
    }
    out << "\n";
  }
  out << "        </DataItem>\n";
}
}

bool amXdmfGrid::Make(const std::string& hdf5Name, std::string& xdmf, std::string& hdf5, std::string& why) const
{
  const std::size_t elements = this->Topology.size() / this->NodesPerElement;
  const std::size_t points = this->Geometry->size() / 3;
  if (!hdf5Name.empty())
  {
    amHdf5Datasets h5;
    h5.Write("topology", this->Topology.data(), elements, this->NodesPerElement);
    h5.Write("geometry", this->Geometry->data(), points, 3);
    for (const Attribute& a : this->Attributes)
    {
      if (a.Integers.empty())
        h5.Write(a.Name, a.Reals.data(), elements, a.Components);
      else
        h5.Write(a.Name, a.Integers.data(), elements, a.Components);
    }
    if (!h5.Finish(hdf5, why))
      return false;
  }
  std::ostringstream stream;
  amTextOutput out(stream);
  out << "<?xml version=\"1.0\"?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<!-- Anatomesh: lengths in mm, patient frame LPS; tags: regions, 1000 x higher + lower per interface "
         "(0: outside) -->\n"
      << "<Xdmf Version=\"3.0\">\n  <Domain>\n    <Grid Name=\"" << this->Name << "\" GridType=\"Uniform\">\n";
  out << "      <Information Name=\"Information\" Value=\"" << this->TagNames.size() << "\"><![CDATA[<main>";
  for (const auto& kv : this->TagNames)
    out << "<map key=\"" << kv.second << "\" dim=\"" << (kv.first >= 1000 || kv.first == 0 ? 2 : 3) << "\">" << kv.first
        << "</map>";
  out << "</main>]]></Information>\n";
  out << "      <Topology TopologyType=\"" << this->TopologyType << "\" NumberOfElements=\"" << elements
      << "\" NodesPerElement=\"" << this->NodesPerElement << "\">\n";
  Item(out, this->Topology, elements, this->NodesPerElement, "Int", hdf5Name, "topology");
  out << "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
  Item(out, *this->Geometry, points, 3, "Float", hdf5Name, "geometry");
  out << "      </Geometry>\n";
  for (const Attribute& a : this->Attributes)
  {
    out << "      <Attribute Name=\"" << a.Name << "\" AttributeType=\"" << (a.Components == 1 ? "Scalar" : "Vector")
        << "\" Center=\"Cell\">\n";
    if (a.Integers.empty())
      Item(out, a.Reals, elements, a.Components, "Float", hdf5Name, a.Name);
    else
      Item(out, a.Integers, elements, a.Components, "Int", hdf5Name, a.Name);
    out << "      </Attribute>\n";
  }
  out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  out.Flush();
  xdmf = stream.str();
  return true;
}
