#include "field/vti_reader.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <stdexcept>

#include "field/fluid_grid.hpp"  // kMaxGridCells
#include "field/vti_decode.hpp"
#include "polydem/error.hpp"

namespace polydem {

namespace {

constexpr double kMaxIndex = 1e9;   // WholeExtent bounds: point counts stay within int
constexpr double kMaxPoints = 1e9;  // a grid beyond holds 8 GB per scalar array

// One XML start tag: its attributes and, unless it is self-closing, where its text begins.
struct Tag {
  std::size_t begin = std::string::npos, end = 0;  // '<' and one past '>'
  bool self_closing = false;
  std::string text;                                // the whole tag
  std::string attribute(const std::string& name, const std::string& fallback = "") const {
    const std::string key = " " + name + "=\"";
    const std::size_t at = text.find(key);
    if (at == std::string::npos) return fallback;
    const std::size_t from = at + key.size(), to = text.find('"', from);
    return text.substr(from, to - from);
  }
  bool found() const { return begin != std::string::npos; }
};

Tag find_tag(const std::string& xml, const std::string& name, std::size_t from = 0, std::size_t until = std::string::npos) {
  Tag t;
  for (std::size_t at = xml.find("<" + name, from); at != std::string::npos && at < until;
       at = xml.find("<" + name, at + 1)) {
    const char next = xml[at + name.size() + 1];
    if (next != ' ' && next != '>' && next != '/' && next != '\n' && next != '\t' && next != '\r') continue;
    const std::size_t close = xml.find('>', at);
    if (close == std::string::npos) break;
    t.begin = at;
    t.end = close + 1;
    t.self_closing = xml[close - 1] == '/';
    t.text = xml.substr(at, close - at);
    for (char& c : t.text) if (c == '\n' || c == '\t' || c == '\r') c = ' ';
    return t;
  }
  return t;
}

template <int N>
Eigen::Matrix<double, N, 1> numbers(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  Eigen::Matrix<double, N, 1> v;
  for (int k = 0; k < N; ++k)
    if (!(in >> v[k])) throw std::runtime_error(what + " needs " + std::to_string(N) + " numbers, got '" + text + "'");
  return v;
}

struct Context {
  const std::string& xml;
  VtkBinaryLayout layout;
  std::size_t appended = std::string::npos, appended_end = 0;  // after the '_' marker
  bool appended_base64 = false;
};

// Decodes base64 text holding one binary array (header first), and anything after it.
std::vector<double> base64_values(std::string_view text, const VtkBinaryLayout& layout, const std::string& type) {
  const std::vector<std::uint8_t> bytes = decode_base64(text);
  return to_doubles(decode_binary_array({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, layout), type);
}

std::vector<double> read_values(const Context& c, const Tag& tag, const std::string& name) {
  const std::string format = tag.attribute("format", "ascii"), type = tag.attribute("type");
  if (!is_numeric_type(type)) throw std::runtime_error("array '" + name + "' has unsupported type '" + type + "'");
  const std::size_t text_end = tag.self_closing ? tag.end : c.xml.find('<', tag.end);  // or <InformationKey>
  if (text_end == std::string::npos) throw std::runtime_error("array '" + name + "' is not closed (truncated file?)");
  const std::string_view text(c.xml.data() + tag.end, text_end - tag.end);
  if (format == "ascii") {
    std::vector<double> v;
    const std::string s(text);
    char* end = nullptr;
    for (const char* at = s.c_str();; at = end) {
      while (std::isspace(static_cast<unsigned char>(*at))) ++at;
      if (!*at) return v;
      v.push_back(std::strtod(at, &end));  // also reads nan and inf: refused later with their cell
      if (end == at) throw std::runtime_error("array '" + name + "' holds text that is not a number");
    }
  }
  if (format == "binary") return base64_values(text, c.layout, type);
  if (format != "appended") throw std::runtime_error("array '" + name + "' has unknown format '" + format + "'");
  if (c.appended == std::string::npos) throw std::runtime_error("array '" + name + "' is appended but there is no AppendedData");
  const std::size_t at = c.appended + std::stoull(tag.attribute("offset", "0"));
  if (at > c.appended_end) throw std::runtime_error("array '" + name + "' offset lies past the AppendedData");
  const std::string_view rest(c.xml.data() + at, c.appended_end - at);
  if (!c.appended_base64) return to_doubles(decode_binary_array(rest, c.layout), type);
  return base64_values(rest.substr(0, rest.find_first_of("< \n")), c.layout, type);  // and the arrays after it
}

// The DataArrays between `section`'s start and end tags.
std::map<std::string, VtiArray> read_section(const Context& c, const std::string& section) {
  std::map<std::string, VtiArray> arrays;
  const Tag open = find_tag(c.xml, section);
  if (!open.found() || open.self_closing) return arrays;
  const std::size_t close = c.xml.find("</" + section + ">", open.end);
  for (Tag t = find_tag(c.xml, "DataArray", open.end, close); t.found(); t = find_tag(c.xml, "DataArray", t.end, close)) {
    const std::string name = t.attribute("Name");
    VtiArray a;
    a.components = std::stoi(t.attribute("NumberOfComponents", "1"));
    a.values = read_values(c, t, name);
    arrays[name] = std::move(a);
  }
  return arrays;
}

VtiImage parse(const std::string& xml) {
  const Tag file = find_tag(xml, "VTKFile");
  if (!file.found()) throw std::runtime_error("not a VTK XML file (no <VTKFile> element); expected image data (.vti)");
  if (file.attribute("type") != "ImageData")
    throw std::runtime_error("is a VTK " + file.attribute("type") + " file, expected ImageData (.vti): resample the fluid onto an image in ParaView (Resample To Image)");
  if (file.attribute("byte_order", "LittleEndian") != "LittleEndian")
    throw std::runtime_error("big-endian files are not supported; save it again on this machine");
  const std::string compressor = file.attribute("compressor");
  if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
    throw std::runtime_error("compressor " + compressor + " is not supported; save with zlib or no compression");
  Context c{xml, {file.attribute("header_type", "UInt32") == "UInt64" ? 8 : 4, !compressor.empty()}};
  const Tag image = find_tag(xml, "ImageData");
  if (!image.found()) throw std::runtime_error("has no <ImageData> element");
  VtiImage img;
  const auto extent = numbers<6>(image.attribute("WholeExtent"), "WholeExtent");
  img.origin = numbers<3>(image.attribute("Origin", "0 0 0"), "Origin");
  img.spacing = numbers<3>(image.attribute("Spacing", "1 1 1"), "Spacing");
  const std::string direction = image.attribute("Direction", "1 0 0 0 1 0 0 0 1");
  if (numbers<9>(direction, "Direction") != Eigen::Matrix<double, 9, 1>(1, 0, 0, 0, 1, 0, 0, 0, 1))
    throw std::runtime_error("a rotated image (Direction " + direction + ") is not supported: the grid must be axis-aligned");
  for (int a = 0; a < 3; ++a) {
    if (!(img.spacing[a] > 0.0)) throw std::runtime_error("Spacing must be positive on every axis, got '" + image.attribute("Spacing") + "'");
    const double low = extent[2 * a], high = extent[2 * a + 1];
    if (low != std::floor(low) || high != std::floor(high) || std::abs(low) > kMaxIndex || std::abs(high) > kMaxIndex)
      throw std::runtime_error("WholeExtent must hold whole numbers within +-1e9, got '" + image.attribute("WholeExtent") + "'");
    img.points[a] = int(high - low) + 1;
    if (img.points[a] < 1) throw std::runtime_error("WholeExtent is empty: '" + image.attribute("WholeExtent") + "'");
  }
  if (img.points.cast<double>().prod() > kMaxPoints)
    throw std::runtime_error("WholeExtent '" + image.attribute("WholeExtent") + "' holds more than 1e9 points");
  const Tag piece = find_tag(xml, "Piece");
  if (piece.found() && numbers<6>(piece.attribute("Extent"), "Piece Extent") != extent)
    throw std::runtime_error("holds several pieces; save it as one piece (the whole extent)");
  if (find_tag(xml, "Piece", piece.end).found()) throw std::runtime_error("holds several pieces; save it as one piece");
  const Tag app = find_tag(xml, "AppendedData");
  if (app.found()) {
    c.appended = xml.find('_', app.end) + 1;
    c.appended_end = xml.rfind("</AppendedData>");
    c.appended_base64 = app.attribute("encoding") == "base64";
    if (c.appended == 0 || c.appended_end == std::string::npos || c.appended_end < c.appended)
      throw std::runtime_error("AppendedData is truncated");
  }
  img.origin += Vec3(extent[0], extent[2], extent[4]).cwiseProduct(img.spacing);
  img.arrays = read_section(c, "CellData");
  img.cell_data = !img.arrays.empty();
  if (!img.cell_data) img.arrays = read_section(c, "PointData");
  const Eigen::Vector3i cells = (img.points - Eigen::Vector3i::Ones()).cwiseMax(1);
  const long long tuples = img.cell_data ? cells.cast<long long>().prod() : img.points.cast<long long>().prod();
  if (double(tuples) > kMaxGridCells)
    throw std::runtime_error("the extent holds " + std::to_string(tuples) + " cells, more than the limit of " +
                             std::to_string((long long)kMaxGridCells));
  for (const auto& [name, a] : img.arrays)
    if (a.components < 1 || (long long)a.values.size() != tuples * a.components)
      throw std::runtime_error("array '" + name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                               std::to_string(tuples * a.components));
  return img;
}

}  // namespace

VtiImage read_vti(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the fluid grid file");
  const std::string xml{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  try {
    return parse(xml);
  } catch (const std::bad_alloc&) {
    throw InputError(path + ": an array header asks for more memory than there is (corrupt file?)");
  } catch (const std::invalid_argument&) {
    throw InputError(path + ": a number in an attribute cannot be read");
  } catch (const std::out_of_range&) {
    throw InputError(path + ": a number in an attribute is out of range");
  } catch (const std::runtime_error& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace polydem
