// The parallel VTK files of a distributed run: one .pvtu naming each rank's piece, so ParaView
// opens the pieces as one data set. Only the arrays' names, types and components are stated;
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

}  // namespace

void write_bodies_pvtu(const std::string& path, const std::vector<std::string>& pieces) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  std::string xml = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
                                "byte_order=\"") + order + "\" header_type=\"UInt64\">\n"
                    "<PUnstructuredGrid GhostLevel=\"0\">\n<PPoints>\n" +
                    declarations("PDataArray", {{"Points", "Float64", 3}}) +
                    "</PPoints>\n<PCellData Scalars=\"id\" Vectors=\"velocity\">\n" +
                    declarations("PDataArray", {{"id", "Int64", 1}, {"group", "Int32", 1}, {"radius", "Float64", 1},
                                                {"velocity", "Float64", 3}, {"angular_velocity", "Float64", 3}}) +
                    "</PCellData>\n";
  for (const std::string& piece : pieces) xml += "<Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  replace_file(path, xml + "</PUnstructuredGrid>\n</VTKFile>\n");
}

}  // namespace polydem
