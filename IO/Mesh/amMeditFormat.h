// Internal: the Medit ASCII format (.mesh and .sol), as plain C++ so it can be tested on its own.
//
// .mesh: "MeshVersionFormatted 1|2", "Dimension 3", then sections "Vertices N" (x y z ref),
// "Edges N" (2 ids + ref), "Triangles N" (3 + ref), "Quadrilaterals N" (4 + ref),
// "Tetrahedra N" (4 + ref), "Hexahedra N" (8 + ref), 1-based ids, and "End". Sections listing
// only ids (Corners, Ridges, RequiredVertices, RequiredEdges) are read and ignored.
// .sol: "SolAtVertices N", then "k t1..tk" (type 1 scalar, 2 vector, 3 symmetric tensor), then
// N lines of values. Symmetric tensors are stored in Medit order m11 m21 m22 m31 m32 m33.
#ifndef amMeditFormat_h
#define amMeditFormat_h

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

class amMeditFormat
{
public:
  struct Block
  {
    std::string Keyword; // "Triangles", ...
    int NodesPerCell = 0;
    std::vector<int64_t> Connectivity; // 0-based
    std::vector<int> Refs;
  };
  struct Field
  {
    int Type = 1;               // 1 scalar, 2 vector, 3 symmetric tensor
    std::vector<double> Values; // per vertex, Components() each
    int Components(int dim) const { return this->Type == 1 ? 1 : this->Type == 2 ? dim : dim * (dim + 1) / 2; }
  };
  struct Mesh
  {
    int Version = 2;
    int Dimension = 3;
    std::vector<double> Points; // 3 per vertex (z = 0 in 2-D)
    std::vector<int> PointRefs;
    std::vector<Block> Blocks;
    std::vector<Field> Fields;
  };

  /// Symmetric 3x3 tensors: Medit order m11 m21 m22 m31 m32 m33 <-> VTK order XX YY ZZ XY YZ XZ.
  static void MeditToVTKTensor(const double medit[6], double vtk[6]);
  static void VTKToMeditTensor(const double vtk[6], double medit[6]);

  /// The .sol file that goes with a .mesh file ("a/b.mesh" -> "a/b.sol").
  static std::string SolutionPathFor(const std::string& meshPath);

  /// Nodes per element of a section keyword; 0 if the keyword is not an element section.
  static int NodesOf(const std::string& keyword);

  /// Parse a .mesh stream. On failure returns false and sets 'error' ("line L: problem").
  static bool ReadMesh(std::istream& in, Mesh& mesh, std::string& error);
  /// Parse a .sol stream into mesh.Fields (vertex count must match). Same error convention.
  static bool ReadSolution(std::istream& in, Mesh& mesh, std::string& error);
  /// Write .mesh / .sol with full double precision (a round trip keeps every number).
  static bool WriteMesh(std::ostream& out, const Mesh& mesh);
  static bool WriteSolution(std::ostream& out, const Mesh& mesh);
};

#endif
