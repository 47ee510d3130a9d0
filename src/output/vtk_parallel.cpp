// The parallel VTK files of a distributed run: a .pvtu (bodies) or .pvtp (contacts) naming each
// rank's piece, so ParaView opens the pieces as one data set. Only the arrays' names, types and components are stated;
// the data stays in the pieces.
#include <bit>
#include <initializer_list>

#include "output/appended.hpp"
#include "output/file.hpp"
#include "output/vtk.hpp"

namespace polydem {

namespace {

struct ArrayDeclaration {
  const char* name;
  const char* type;
  int components;
};

std::string declarations(const char* element, std::initializer_list<ArrayDeclaration> arrays) {
  std::string xml;
  for (const ArrayDeclaration& a : arrays)
    xml += std::string("<") + element + " type=\"" + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\"/>\n";
  return xml;
}

// The parallel file of `type` ("PUnstructuredGrid", "PPolyData"): Float64 points, the cell
// arrays `cells` (with `attributes`, as the pieces state them), then one <Piece> per file.
void write_parallel_file(const std::string& path, const std::string& type, const char* attributes,
                         std::initializer_list<ArrayDeclaration> cells, const std::vector<std::string>& pieces) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + type + "\" version=\"1.0\" byte_order=\"" + order +
                    "\" header_type=\"UInt64\">\n<" + type + " GhostLevel=\"0\">\n<PPoints>\n" +
                    declarations("PDataArray", {{"Points", "Float64", 3}}) + "</PPoints>\n<PCellData " + attributes +
                    ">\n" + declarations("PDataArray", cells) + "</PCellData>\n";
  for (const std::string& piece : pieces) xml += "<Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  replace_file(path, xml + "</" + type + ">\n</VTKFile>\n");
}

}  // namespace

void write_bodies_pvtu(const std::string& path, const std::vector<std::string>& pieces) {
  write_parallel_file(path, "PUnstructuredGrid", "Scalars=\"id\" Vectors=\"velocity\"",
                      {{"id", "Int64", 1}, {"group", "Int32", 1}, {"radius", "Float64", 1}, {"velocity", "Float64", 3},
                       {"angular_velocity", "Float64", 3}},
                      pieces);
}

void write_contacts_pvtp(const std::string& path, const std::vector<std::string>& pieces) {
  write_parallel_file(path, "PPolyData", "Scalars=\"fn\" Vectors=\"force\"",
                      {{"force", "Float64", 3}, {"point", "Float64", 3}, {"fn", "Float64", 1}, {"ft", "Float64", 1},
                       {"overlap", "Float64", 1}, {"i", "Int64", 1}, {"j", "Int64", 1}, {"type", "Int32", 1}},
                      pieces);
}

}  // namespace polydem
