#include "output/appended.hpp"

#include <bit>

#include "output/file.hpp"

namespace polydem {

std::string AppendedData::add(std::string_view type, std::string_view name, int components,
                              std::shared_ptr<const void> data, std::uint64_t bytes, std::string_view extra) {
  std::string xml = "<DataArray type=\"" + std::string(type) + "\" Name=\"" + xml_escape(name) + "\"";
  if (components != 1) xml += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  xml += std::string(extra) + " format=\"appended\" offset=\"" + std::to_string(offset_) + "\"/>\n";
  blocks_.push_back({std::move(data), bytes});
  offset_ += sizeof(std::uint64_t) + bytes;
  return xml;
}

std::string AppendedData::array(std::string_view name, std::vector<Vec3> values) {
  const std::uint64_t bytes = values.size() * sizeof(Vec3);
  auto owned = std::make_shared<std::vector<Vec3>>(std::move(values));
  return add("Float64", name, 3, std::shared_ptr<const void>(owned, owned->data()), bytes);
}

std::string AppendedData::field_array(std::string_view name, std::vector<Vec3> values) {
  const std::string extra = " NumberOfTuples=\"" + std::to_string(values.size()) + "\"";
  const std::uint64_t bytes = values.size() * sizeof(Vec3);
  auto owned = std::make_shared<std::vector<Vec3>>(std::move(values));
  return add("Float64", name, 3, std::shared_ptr<const void>(owned, owned->data()), bytes, extra);
}

std::string AppendedData::strings(std::string_view name, const std::vector<std::string>& values) {
  auto packed = std::make_shared<std::string>();
  for (const std::string& s : values) packed->append(s.c_str(), s.size() + 1);
  const std::string extra = " NumberOfTuples=\"" + std::to_string(values.size()) + "\"";
  return add("String", name, 1, std::shared_ptr<const void>(packed, packed->data()), packed->size(), extra);
}

void AppendedData::write_file(const std::string& path, std::string_view type, std::string_view content) const {
  const char* order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + std::string(type) +
                     "\" version=\"1.0\" byte_order=\"" + order + "\" header_type=\"UInt64\">\n<" +
                     std::string(type) + ">\n";
  head += content;
  head += "</" + std::string(type) + ">\n<AppendedData encoding=\"raw\">\n_";
  OutputFile f(path);
  f.write(head);
  for (const Block& b : blocks_) {
    f.write(&b.bytes, sizeof(b.bytes));
    f.write(b.data.get(), b.bytes);
  }
  f.write("\n</AppendedData>\n</VTKFile>\n");
  f.close();
}

void CellTopology::add_cell(std::span<const int> indices, std::int64_t base) {
  for (int k : indices) connectivity.push_back(base + k);
  offsets.push_back(std::int64_t(connectivity.size()));
}

std::string topology_xml(AppendedData& data, CellTopology cells) {
  std::string xml = data.array("connectivity", std::move(cells.connectivity));
  return xml + data.array("offsets", std::move(cells.offsets));
}

std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace polydem
