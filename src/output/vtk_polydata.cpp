#include <stdexcept>

#include "output/appended.hpp"
#include "output/vtk.hpp"

namespace polydem {

namespace {

enum class CellKind { lines, polys };

// The opening of a PolyData <Piece>: counts, points and the line or polygon topology.
std::string polydata_piece(AppendedData& data, std::vector<Vec3> points, CellTopology cells, CellKind kind) {
  const std::string n_cells = std::to_string(cells.offsets.size());
  const bool lines = kind == CellKind::lines;
  std::string xml = "<Piece NumberOfPoints=\"" + std::to_string(points.size()) + "\" NumberOfVerts=\"0\"" +
                    " NumberOfLines=\"" + (lines ? n_cells : "0") + "\" NumberOfStrips=\"0\"" +
                    " NumberOfPolys=\"" + (lines ? "0" : n_cells) + "\">\n<Points>\n";
  xml += data.array("Points", std::move(points));
  const std::string tag = lines ? "Lines" : "Polys";
  xml += "</Points>\n<" + tag + ">\n";
  xml += topology_xml(data, std::move(cells));
  return xml + "</" + tag + ">\n";
}

void check_polygon(const DriverMesh& d, const std::vector<int>& polygon) {
  for (int k : polygon)
    if (k < 0 || std::size_t(k) >= d.points.size())
      throw std::out_of_range("write_drivers_vtp: driver '" + d.name + "' has a polygon with point index " +
                              std::to_string(k) + " of " + std::to_string(d.points.size()));
}

}  // namespace

void write_drivers_vtp(const std::string& path, const std::vector<DriverMesh>& drivers) {
  std::vector<Vec3> points;
  CellTopology cells;
  std::vector<std::int32_t> driver;
  std::vector<std::string> names;
  for (std::size_t d = 0; d < drivers.size(); ++d) {
    const DriverMesh& m = drivers[d];
    const std::int64_t base = std::int64_t(points.size());
    points.insert(points.end(), m.points.begin(), m.points.end());
    for (const std::vector<int>& polygon : m.polygons) {
      check_polygon(m, polygon);
      cells.add_cell(polygon, base);
    }
    driver.insert(driver.end(), m.polygons.size(), std::int32_t(d));
    names.push_back(m.name);
  }
  AppendedData data;
  std::string xml = "<FieldData>\n";
  xml += data.strings("driver_names", names);
  xml += "</FieldData>\n";
  xml += polydata_piece(data, std::move(points), std::move(cells), CellKind::polys);
  xml += "<CellData Scalars=\"driver\">\n";
  xml += data.array("driver", std::move(driver));
  xml += "</CellData>\n</Piece>\n";
  data.write_file(path, "PolyData", xml);
}

void write_contacts_vtp(const std::string& path, const std::vector<ContactOut>& contacts) {
  const std::size_t n = contacts.size();
  std::vector<Vec3> points, force, point;
  std::vector<double> fn, ft, overlap;
  std::vector<std::int64_t> i, j;
  std::vector<std::int32_t> type;
  CellTopology cells;
  constexpr int kLine[] = {0, 1};
  points.reserve(2 * n);
  for (auto* v : {&force, &point}) v->reserve(n);
  for (auto* v : {&fn, &ft, &overlap}) v->reserve(n);
  for (auto* v : {&i, &j, &cells.offsets}) v->reserve(n);
  cells.connectivity.reserve(2 * n);
  type.reserve(n);
  for (const ContactOut& c : contacts) {
    cells.add_cell(kLine, std::int64_t(points.size()));
    points.push_back(c.from);
    points.push_back(c.to);
    force.push_back(c.force);
    point.push_back(c.point);
    fn.push_back(c.fn);
    ft.push_back(c.ft);
    overlap.push_back(c.overlap);
    i.push_back(c.i);
    j.push_back(c.j);
    type.push_back(c.type);
  }
  AppendedData data;
  std::string xml = polydata_piece(data, std::move(points), std::move(cells), CellKind::lines);
  xml += "<CellData Scalars=\"fn\" Vectors=\"force\">\n";
  xml += data.array("force", std::move(force));
  xml += data.array("fn", std::move(fn));
  xml += data.array("ft", std::move(ft));
  xml += data.array("overlap", std::move(overlap));
  xml += data.array("point", std::move(point));
  xml += data.array("i", std::move(i));
  xml += data.array("j", std::move(j));
  xml += data.array("type", std::move(type));
  xml += "</CellData>\n</Piece>\n";
  data.write_file(path, "PolyData", xml);
}

}  // namespace polydem
