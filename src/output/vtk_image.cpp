#include "output/vtk_image.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>

#include "output/appended.hpp"
#include "output/file.hpp"

namespace polydem {

namespace {

std::string triple(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%.17g %.17g %.17g", v.x(), v.y(), v.z());
  return buf;
}

}  // namespace

void write_image_vti(const std::string& path, const Vec3& origin, const Vec3& spacing,
                     const Eigen::Vector3i& cells, const std::vector<ImageArray>& arrays) {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  const std::string extent = "0 " + std::to_string(cells.x()) + " 0 " + std::to_string(cells.y()) + " 0 " +
                             std::to_string(cells.z());
  std::string xml = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"") +
                    order + "\" header_type=\"UInt64\">\n<ImageData WholeExtent=\"" + extent + "\" Origin=\"" +
                    triple(origin) + "\" Spacing=\"" + triple(spacing) + "\">\n<Piece Extent=\"" + extent +
                    "\">\n<CellData>\n";
  std::uint64_t offset = 0;
  for (const ImageArray& a : arrays) {
    xml += "<DataArray type=\"Float64\" Name=\"" + xml_escape(a.name) + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + a.values.size() * sizeof(double);
  }
  xml += "</CellData>\n</Piece>\n</ImageData>\n<AppendedData encoding=\"raw\">\n_";
  OutputFile f(path);
  f.write(xml);
  for (const ImageArray& a : arrays) {
    const std::uint64_t bytes = a.values.size() * sizeof(double);
    f.write(&bytes, sizeof(bytes));
    f.write(a.values.data(), bytes);
  }
  f.write("\n</AppendedData>\n</VTKFile>\n");
  f.close();
}

}  // namespace polydem
