#pragma once
// VTK XML plumbing shared by the .vtu/.vtp writers: arrays stored raw in one <AppendedData>
// block (header_type UInt64, machine byte order), each prefixed by its byte count.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "polydem/math.hpp"

namespace polydem {

template <class T> struct VtkScalar;
template <> struct VtkScalar<double> { static constexpr const char* kName = "Float64"; };
template <> struct VtkScalar<std::int64_t> { static constexpr const char* kName = "Int64"; };
template <> struct VtkScalar<std::int32_t> { static constexpr const char* kName = "Int32"; };
template <> struct VtkScalar<std::uint8_t> { static constexpr const char* kName = "UInt8"; };

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are written as packed Float64 triples");

class AppendedData {
 public:
  // Takes ownership of `values` (no copy) and returns its <DataArray .../> element.
  template <class T>
  std::string array(std::string_view name, std::vector<T> values, int components = 1) {
    const std::uint64_t bytes = values.size() * sizeof(T);
    auto owned = std::make_shared<std::vector<T>>(std::move(values));
    return add(VtkScalar<T>::kName, name, components, std::shared_ptr<const void>(owned, owned->data()), bytes);
  }
  std::string array(std::string_view name, std::vector<Vec3> values);
  // A vector array in <FieldData>, which VTK reads only with its tuple count stated.
  std::string field_array(std::string_view name, std::vector<Vec3> values);
  // A String array: the strings back to back, each ended by '\0', as VTK itself writes them.
  std::string strings(std::string_view name, const std::vector<std::string>& values);

  // Writes a whole VTK XML file of `type` ("UnstructuredGrid", "PolyData"): `content` goes
  // inside <type>...</type>, followed by this appended block.
  void write_file(const std::string& path, std::string_view type, std::string_view content) const;

 private:
  struct Block {
    std::shared_ptr<const void> data;
    std::uint64_t bytes;
  };
  std::string add(std::string_view type, std::string_view name, int components, std::shared_ptr<const void> data,
                  std::uint64_t bytes, std::string_view extra = {});
  std::vector<Block> blocks_;
  std::uint64_t offset_ = 0;  // bytes from the '_' marker to the next block's header
};

// Polygon (or line) topology as VTK stores it: indices back to back and the end offset of each cell.
struct CellTopology {
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  void add_cell(std::span<const int> indices, std::int64_t base);
};

// The <connectivity/> and <offsets/> DataArray elements of `cells`, consumed.
std::string topology_xml(AppendedData& data, CellTopology cells);

// Escapes &, <, >, " for an XML attribute value.
std::string xml_escape(std::string_view text);

}  // namespace polydem
