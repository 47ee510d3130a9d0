#include "shape/point_sources.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "polydem/error.hpp"

namespace polydem {
namespace {

std::ifstream open(const std::string& path, std::ios::openmode mode = std::ios::in) {
  std::ifstream in(path, mode);
  if (!in) throw InputError(input_message(path, 0, "", "cannot open the file"));
  return in;
}

[[noreturn]] void bad_line(const std::string& path, int line, const std::string& what) {
  throw InputError(input_message(path, line, "", what));
}

// Three numbers and nothing else from `words`.
Vec3 read_xyz(std::istringstream& words, const std::string& path, int line) {
  Vec3 p;
  std::string extra;
  if (!(words >> p.x() >> p.y() >> p.z()) || (words >> extra))
    bad_line(path, line, "expected three numbers 'x y z'");
  if (!p.allFinite()) bad_line(path, line, "a coordinate is not finite");
  return p;
}

std::string lower_extension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Collects vertices, welding identical points into one index.
class Welder {
 public:
  int add(const Vec3& p) {
    auto [it, inserted] = index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(p);
    return it->second;
  }
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const std::array<int, 3> t{add(a), add(b), add(c)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
  }
  TriangleMesh mesh;

 private:
  std::map<std::array<double, 3>, int> index_;
};

TriangleMesh read_binary_stl(const std::string& bytes, const std::string& path) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  Welder welder;
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* record = bytes.data() + 84 + 50 * static_cast<size_t>(i);
    float xyz[12];  // normal, then the three vertices (little-endian IEEE floats)
    std::memcpy(xyz, record, sizeof xyz);
    auto vertex = [&](int k) { return Vec3(xyz[3 + 3 * k], xyz[4 + 3 * k], xyz[5 + 3 * k]); };
    if (!vertex(0).allFinite() || !vertex(1).allFinite() || !vertex(2).allFinite())  // NaN would weld with anything
      throw InputError(input_message(path, 0, "", "triangle " + std::to_string(i + 1) + " has a coordinate that is not finite"));
    welder.triangle(vertex(0), vertex(1), vertex(2));
  }
  return welder.mesh;
}

TriangleMesh read_ascii_stl(const std::string& bytes, const std::string& path) {
  std::istringstream in(bytes);
  std::string line;
  std::vector<Vec3> corners;
  Welder welder;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    std::istringstream words(line);
    std::string word;
    if (!(words >> word)) continue;
    if (word == "vertex") {
      corners.push_back(read_xyz(words, path, n));
    } else if (word == "endfacet") {
      if (corners.size() != 3)
        bad_line(path, n, "a facet needs 3 vertices, it has " + std::to_string(corners.size()));
      welder.triangle(corners[0], corners[1], corners[2]);
      corners.clear();
    }
  }
  if (!corners.empty()) bad_line(path, n, "the last facet has no 'endfacet'");
  return welder.mesh;
}

// What the binary header says, for a file read as neither: a truncated binary STL is told apart.
std::string binary_size_note(const std::string& bytes) {
  if (bytes.size() < 84) return "; " + std::to_string(bytes.size()) + " bytes, shorter than a binary STL header";
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  return "; as binary it announces " + std::to_string(count) + " triangles, " +
         std::to_string(84 + 50 * std::uint64_t(count)) + " bytes, but has " + std::to_string(bytes.size()) +
         " (truncated?)";
}

}  // namespace

std::vector<Vec3> read_point_list(const std::string& path) {
  std::ifstream in = open(path);
  std::vector<Vec3> points;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string probe;
    if (!(std::istringstream(line) >> probe)) continue;
    points.push_back(read_xyz(words, path, n));
  }
  if (points.empty()) throw InputError(input_message(path, 0, "", "no point in the file"));
  return points;
}

std::vector<Vec3> read_obj_points(const std::string& path) {
  std::ifstream in = open(path);
  std::vector<Vec3> points;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag) || tag != "v") continue;
    Vec3 p;
    if (!(words >> p.x() >> p.y() >> p.z()) || !p.allFinite())  // an optional w may follow
      bad_line(path, n, "a 'v' line needs three numbers 'v x y z'");
    points.push_back(p);
  }
  if (points.empty()) throw InputError(input_message(path, 0, "", "no 'v' vertex line in the OBJ file"));
  return points;
}

TriangleMesh read_stl(const std::string& path) {
  std::ifstream in = open(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<size_t>(count)) return read_binary_stl(bytes, path);
  }
  if (bytes.compare(0, 5, "solid") != 0)
    throw InputError(input_message(path, 0, "",
                                   "not an STL file (neither 'solid ...' text nor a binary of 84 + 50 n bytes" +
                                       binary_size_note(bytes) + ")"));
  TriangleMesh mesh = read_ascii_stl(bytes, path);
  if (mesh.triangles.empty())
    throw InputError(input_message(path, 0, "", "no facet in the STL file (read as text" + binary_size_note(bytes) + ")"));
  return mesh;
}

std::vector<Vec3> read_points(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == "stl") return read_stl(path).vertices;
  if (ext == "obj") return read_obj_points(path);
  return read_point_list(path);
}

}  // namespace polydem
