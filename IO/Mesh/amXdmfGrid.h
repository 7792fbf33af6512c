/**
 * @class   amXdmfGrid
 * @brief   One XDMF 3 file of one uniform grid (topology, geometry, attributes), its heavy data inline
 *          as text or in an HDF5 file beside it: the plain core of amXdmfWriter.
 *
 * Inline ("XML"), numbers are written in their shortest form that reads back to the same value. In HDF5
 * each array is a dataset of the .h5 file ("/topology", "/geometry", "/NAME" per attribute), referenced
 * from the .xdmf by the .h5 file's name (relative: the two files move together). FEniCSx's XDMFFile opens
 * NAME.h5 beside NAME.xdmf whatever the format, so a grid meant for it is written as HDF5.
 */
#ifndef amXdmfGrid_h
#define amXdmfGrid_h

#include <cstdint>
#include <map>
#include <string>
#include <vector>

struct amXdmfGrid
{
  struct Attribute
  {
    std::string Name;
    int Components = 1;                 // 1: a scalar, 3: a vector
    std::vector<std::int64_t> Integers; // or
    std::vector<double> Reals;
  };
  std::string Name;         // the grid's name ("mesh", "facet_tags")
  std::string TopologyType; // "Tetrahedron", "Triangle"
  int NodesPerElement = 4;
  std::vector<std::int64_t> Topology;            // point indices, NodesPerElement per element
  const std::vector<double>* Geometry = nullptr; // x y z per point, mm
  std::vector<Attribute> Attributes;             // cell-centred
  std::map<long long, std::string> TagNames;     // tag -> name, written as the grid's Information (meshio's field data)

  /// The .xdmf text and, when 'hdf5Name' (the .h5 file's name, as the .xdmf refers to it) is not empty,
  /// the bytes of the .h5 file with the heavy data, for the caller to write. False with 'why'.
  bool Make(const std::string& hdf5Name, std::string& xdmf, std::string& hdf5, std::string& why) const;
};

#endif
