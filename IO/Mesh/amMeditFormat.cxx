#include "amMeditFormat.h"

#include "amMessage.h"

#include "amTextOutput.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>

namespace
{
// Whitespace-separated tokens with '#' comments, keeping track of line numbers for messages.
class Tokens
{
public:
  explicit Tokens(std::istream& in)
    : In(in)
  {
  }
  bool Next(std::string& token)
  {
    token.clear();
    int c;
    while ((c = this->In.get()) != EOF)
    {
      if (c == '\n')
        ++this->Line;
      if (c == '#')
      {
        while ((c = this->In.get()) != EOF && c != '\n')
          ;
        if (c == '\n')
          ++this->Line;
        continue;
      }
      if (!std::isspace(c))
        break;
    }
    if (c == EOF)
      return false;
    token.push_back(static_cast<char>(c));
    while ((c = this->In.peek()) != EOF && !std::isspace(c) && c != '#')
      token.push_back(static_cast<char>(this->In.get()));
    return true;
  }
  bool Integer(long long& v, std::string& error, const char* what)
  {
    std::string t;
    if (!this->Next(t))
      return this->Fail(error, std::string("unexpected end of file, expected ") + what);
    char* end = nullptr;
    errno = 0;
    v = std::strtoll(t.c_str(), &end, 10);
    if (*end || errno)
      return this->Fail(error, std::string("expected ") + what + ", found '" + t + "'");
    return true;
  }
  bool Real(double& v, std::string& error, const char* what)
  {
    std::string t;
    if (!this->Next(t))
      return this->Fail(error, std::string("unexpected end of file, expected ") + what);
    char* end = nullptr;
    v = std::strtod(t.c_str(), &end);
    if (*end)
      return this->Fail(error, std::string("expected ") + what + ", found '" + t + "'");
    if (!std::isfinite(v))
      return this->Fail(error, std::string("non-finite ") + what + " '" + t + "'");
    return true;
  }
  bool Fail(std::string& error, const std::string& what) const
  {
    error = "line " + std::to_string(this->Line) + ": " + what;
    return false;
  }
  int Line = 1;

private:
  std::istream& In;
};

bool ReadCount(Tokens& t, long long& n, std::string& error, const std::string& section)
{
  if (!t.Integer(n, error, ("the number of " + section).c_str()))
    return false;
  if (n < 0 || n > 2000000000LL)
    return t.Fail(error, "invalid number of " + section + ": " + std::to_string(n));
  return true;
}
}

namespace
{
// Entries reserved before a section is read, whatever count it announces.
constexpr long long FirstReservation = 1 << 16;

// VTK component index of each Medit component of a symmetric tensor.
constexpr int MeditToVTK[6] = { 0, 3, 1, 5, 4, 2 };
}

void amMeditFormat::MeditToVTKTensor(const double medit[6], double vtk[6])
{
  for (int i = 0; i < 6; ++i)
    vtk[MeditToVTK[i]] = medit[i];
}

void amMeditFormat::VTKToMeditTensor(const double vtk[6], double medit[6])
{
  for (int i = 0; i < 6; ++i)
    medit[i] = vtk[MeditToVTK[i]];
}

std::string amMeditFormat::SolutionPathFor(const std::string& meshPath)
{
  std::string sol = meshPath;
  const auto dot = sol.find_last_of('.');
  if (dot != std::string::npos && sol.find('/', dot) == std::string::npos)
    sol.resize(dot);
  return sol + ".sol";
}

int amMeditFormat::NodesOf(const std::string& keyword)
{
  if (keyword == "Edges")
    return 2;
  if (keyword == "Triangles")
    return 3;
  if (keyword == "Quadrilaterals" || keyword == "Tetrahedra")
    return 4;
  if (keyword == "Hexahedra")
    return 8;
  return 0;
}

bool amMeditFormat::ReadMesh(std::istream& in, Mesh& mesh, std::string& error)
{
  Tokens t(in);
  std::string key;
  mesh = Mesh();
  bool sawVersion = false, sawVertices = false, sawEnd = false;
  std::string last = "MeshVersionFormatted";
  while (t.Next(key))
  {
    long long n = 0;
    if (key != "End")
      last = key;
    if (key == "MeshVersionFormatted")
    {
      if (!t.Integer(n, error, "a version number"))
        return false;
      if (n < 1 || n > 4)
        return t.Fail(error, "unsupported MeshVersionFormatted " + std::to_string(n));
      mesh.Version = static_cast<int>(n);
      sawVersion = true;
    }
    else if (key == "Dimension")
    {
      if (!t.Integer(n, error, "the dimension"))
        return false;
      if (n != 2 && n != 3)
        return t.Fail(error, "Dimension must be 2 or 3, found " + std::to_string(n));
      if (sawVertices && n != mesh.Dimension)
        return t.Fail(error,
          "Dimension " + std::to_string(n) + " after the vertices were read in dimension " +
            std::to_string(mesh.Dimension));
      mesh.Dimension = static_cast<int>(n);
    }
    else if (key == "Vertices")
    {
      // A second list would renumber the vertices the elements read so far refer to.
      if (sawVertices)
        return t.Fail(error, "a second Vertices section");
      if (!ReadCount(t, n, error, "vertices"))
        return false;
      // The count is only a claim: storage grows with what is read, so a short file announcing
      // billions of vertices fails at its end instead of allocating for them first.
      mesh.Points.clear();
      mesh.PointRefs.clear();
      mesh.Points.reserve(static_cast<size_t>(std::min(n, FirstReservation)) * 3);
      mesh.PointRefs.reserve(static_cast<size_t>(std::min(n, FirstReservation)));
      for (long long i = 0; i < n; ++i)
      {
        double x[3] = { 0, 0, 0 };
        for (int d = 0; d < mesh.Dimension; ++d)
          if (!t.Real(x[d], error, "a vertex coordinate"))
            return false;
        long long ref;
        if (!t.Integer(ref, error, "a vertex reference"))
          return false;
        mesh.Points.insert(mesh.Points.end(), x, x + 3);
        mesh.PointRefs.push_back(static_cast<int>(ref));
      }
      sawVertices = true;
    }
    else if (int nodes = NodesOf(key))
    {
      if (!sawVertices)
        return t.Fail(error, "section " + key + " before Vertices");
      if (!ReadCount(t, n, error, key))
        return false;
      Block b;
      b.Keyword = key;
      b.NodesPerCell = nodes;
      b.Connectivity.reserve(static_cast<size_t>(std::min(n, FirstReservation)) * nodes);
      b.Refs.reserve(static_cast<size_t>(std::min(n, FirstReservation)));
      const long long nv = static_cast<long long>(mesh.PointRefs.size());
      for (long long i = 0; i < n; ++i)
      {
        for (int k = 0; k < nodes; ++k)
        {
          long long id;
          if (!t.Integer(id, error, "a vertex index"))
            return false;
          if (id < 1 || id > nv)
            return t.Fail(error,
              key + " #" + std::to_string(i + 1) + " uses vertex " + std::to_string(id) + " (the mesh has " +
                std::to_string(nv) + ")");
          b.Connectivity.push_back(id - 1);
        }
        // An element naming one vertex twice has no area or volume: no solver can use it.
        const auto first = b.Connectivity.end() - nodes;
        for (auto a = first; a != b.Connectivity.end(); ++a)
          if (std::find(a + 1, b.Connectivity.end(), *a) != b.Connectivity.end())
            return t.Fail(error,
              key + " #" + std::to_string(i + 1) + " uses vertex " + std::to_string(*a + 1) +
                " twice: a degenerate element");
        long long ref;
        if (!t.Integer(ref, error, "an element reference"))
          return false;
        b.Refs.push_back(static_cast<int>(ref));
      }
      mesh.Blocks.push_back(std::move(b));
    }
    else if (key == "Corners" || key == "Ridges" || key == "RequiredVertices" || key == "RequiredEdges")
    {
      if (!ReadCount(t, n, error, key))
        return false;
      for (long long i = 0; i < n; ++i)
      {
        long long id;
        if (!t.Integer(id, error, "an index"))
          return false;
      }
    }
    else if (key == "End")
    {
      sawEnd = true;
      break;
    }
    else
      return t.Fail(error, "unknown or unsupported section '" + amMessage::Printable(key) + "'");
  }
  if (!sawVersion)
    return t.Fail(error, "not a Medit mesh: no MeshVersionFormatted keyword");
  if (!sawVertices)
    return t.Fail(error, "no Vertices section");
  // Without End, a file cut between two sections (before its Tetrahedra, say) would read as a
  // valid smaller mesh: every writer (Medit, Mmg, Gmsh, TetGen, CGAL, ours) ends with End.
  if (!sawEnd)
    return t.Fail(error,
      "the file ends without its End keyword after the " + last +
        " section: it is cut short, or not a complete Medit mesh");
  return true;
}

bool amMeditFormat::ReadSolution(std::istream& in, Mesh& mesh, std::string& error)
{
  Tokens t(in);
  std::string key;
  int dim = mesh.Dimension;
  bool sawSol = false;
  while (t.Next(key))
  {
    long long n = 0;
    if (key == "MeshVersionFormatted")
    {
      if (!t.Integer(n, error, "a version number"))
        return false;
    }
    else if (key == "Dimension")
    {
      if (!t.Integer(n, error, "the dimension"))
        return false;
      dim = static_cast<int>(n);
      if (dim != mesh.Dimension)
        return t.Fail(error, "solution dimension " + std::to_string(dim) + " differs from the mesh's");
    }
    else if (key == "SolAtVertices")
    {
      if (!ReadCount(t, n, error, "solution values"))
        return false;
      if (static_cast<size_t>(n) != mesh.PointRefs.size())
        return t.Fail(error,
          "SolAtVertices has " + std::to_string(n) + " values for " + std::to_string(mesh.PointRefs.size()) +
            " vertices");
      long long k;
      if (!t.Integer(k, error, "the number of solution fields"))
        return false;
      if (k < 1 || k > 64)
        return t.Fail(error, "invalid number of solution fields " + std::to_string(k));
      std::vector<Field> fields(static_cast<size_t>(k));
      for (auto& f : fields)
      {
        long long type;
        if (!t.Integer(type, error, "a solution type"))
          return false;
        if (type < 1 || type > 3)
          return t.Fail(error, "unsupported solution type " + std::to_string(type) + " (1, 2 or 3 expected)");
        f.Type = static_cast<int>(type);
        f.Values.reserve(static_cast<size_t>(std::min(n, FirstReservation)) * f.Components(dim));
      }
      for (long long i = 0; i < n; ++i)
        for (auto& f : fields)
        {
          const int c = f.Components(dim);
          for (int j = 0; j < c; ++j)
          {
            double v;
            if (!t.Real(v, error, "a solution value"))
              return false;
            f.Values.push_back(v);
          }
        }
      for (auto& f : fields)
        mesh.Fields.push_back(std::move(f));
      sawSol = true;
    }
    else if (key == "End")
      break;
    else
      return t.Fail(error, "unknown or unsupported section '" + amMessage::Printable(key) + "' in a .sol file");
  }
  if (!sawSol)
    return t.Fail(error, "no SolAtVertices section");
  return true;
}

bool amMeditFormat::WriteMesh(std::ostream& stream, const Mesh& mesh)
{
  amTextOutput out(stream);
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << mesh.PointRefs.size() << "\n";
  for (size_t i = 0; i < mesh.PointRefs.size(); ++i)
    out << mesh.Points[3 * i] << " " << mesh.Points[3 * i + 1] << " " << mesh.Points[3 * i + 2] << " "
        << mesh.PointRefs[i] << "\n";
  for (const Block& b : mesh.Blocks)
  {
    out << "\n" << b.Keyword << "\n" << b.Refs.size() << "\n";
    for (size_t i = 0; i < b.Refs.size(); ++i)
    {
      for (int k = 0; k < b.NodesPerCell; ++k)
        out << b.Connectivity[i * b.NodesPerCell + k] + 1 << " ";
      out << b.Refs[i] << "\n";
    }
  }
  out << "\nEnd\n";
  return out.Flush();
}

bool amMeditFormat::WriteSolution(std::ostream& stream, const Mesh& mesh)
{
  amTextOutput out(stream);
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n"
      << mesh.PointRefs.size() << "\n"
      << mesh.Fields.size();
  for (const Field& f : mesh.Fields)
    out << " " << f.Type;
  out << "\n";
  for (size_t i = 0; i < mesh.PointRefs.size(); ++i)
  {
    bool first = true;
    for (const Field& f : mesh.Fields)
    {
      const int c = f.Components(3);
      for (int j = 0; j < c; ++j)
      {
        out << (first ? "" : " ") << f.Values[i * c + j];
        first = false;
      }
    }
    out << "\n";
  }
  out << "\nEnd\n";
  return out.Flush();
}
