#include "shape/shp_io.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "polydem/error.hpp"
#include "shape/mass.hpp"
#include "shape/suggest.hpp"

namespace polydem {
namespace {

struct Token {
  std::string text;
  int line = 0;
};

const std::vector<std::string> kShpKeys = {
    "name",   "radius",       "preCompDone", "nv",           "ne",         "nf",     "volume",
    "I/m",    "position",     "orientation", "obb.extent",   "obb.center", "obb.e1", "obb.e2",
    "obb.e3", "OBBtreeLevel", "MCnstep",     "fibObbOption", "isSurface",  "na"};

bool is_key(const std::string& word) {
  return word == "<" || word == ">" || std::find(kShpKeys.begin(), kShpKeys.end(), word) != kShpKeys.end();
}

std::vector<Token> tokenize(std::istream& in) {
  std::vector<Token> tokens;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      if (w[0] == '#' || w[0] == '/' || w[0] == '!') break;  // Rockable's comment marks
      tokens.push_back({w, n});
    }
  }
  return tokens;
}

// What one block says, before the shape is finished.
struct Block {
  Shape shape;
  std::vector<int> edge_lines;  // line of each edge, for the duplicate warning
  int line = 0;
  bool has_name = false, has_radius = false, precomputed = false;
  bool has_volume = false, has_inertia = false;
};

class BlockParser {
 public:
  BlockParser(const std::vector<Token>& tokens, size_t pos, std::string file, std::vector<std::string>& warnings)
      : tokens_(tokens), pos_(pos), file_(std::move(file)), warnings_(warnings) {}

  size_t position() const { return pos_; }

  Block parse(int open_line) {
    Block b;
    b.line = open_line;
    for (;;) {
      const Token& t = next("", "a key or '>'", open_line);
      if (t.text == ">") return b;
      if (t.text == "<")
        throw InputError(input_message(file_, t.line, "",
                                       "'<' inside the shape block opened at line " +
                                           std::to_string(open_line) + " (a '>' is missing)"));
      key(b, t);
    }
  }

 private:
  const Token& next(const std::string& key, const std::string& what, int line) {
    if (pos_ >= tokens_.size())
      throw InputError(input_message(
          file_, line, key, "end of file where " + what + " was expected (a shape block ends with '>')"));
    return tokens_[pos_++];
  }

  double number(const std::string& key, int line) {
    const Token& t = next(key, "a number", line);
    char* end = nullptr;
    const double v = std::strtod(t.text.c_str(), &end);
    if (end == t.text.c_str() || *end != '\0' || !std::isfinite(v))
      throw InputError(input_message(file_, t.line, key, "'" + t.text + "' is not a number"));
    return v;
  }

  int count(const std::string& key, int line, long max) {
    const Token& t = next(key, "a count", line);
    char* end = nullptr;
    const long v = std::strtol(t.text.c_str(), &end, 10);
    if (end == t.text.c_str() || *end != '\0' || v < 0 || v > max)
      throw InputError(input_message(file_, t.line, key,
                                     "'" + t.text + "' is not an integer in 0.." + std::to_string(max)));
    return static_cast<int>(v);
  }

  Vec3 vec3(const std::string& key, int line) {
    const double x = number(key, line), y = number(key, line);
    return Vec3(x, y, number(key, line));
  }

  // Rockable skips what it does not know: so do we, with a warning, up to the next key.
  void key(Block& b, const Token& t) {
    if (header_key(b, t) || geometry_key(b, t) || property_key(b, t) || ignored_key(b, t)) return;
    warnings_.push_back(input_message(file_, t.line, t.text,
                                      "unknown key in a shape block, ignored" + did_you_mean(t.text, kShpKeys)));
    while (pos_ < tokens_.size() && !is_key(tokens_[pos_].text)) ++pos_;
  }

  bool header_key(Block& b, const Token& t) {
    const std::string& k = t.text;
    if (k == "name") {
      b.shape.name = next(k, "a name", t.line).text;
      b.has_name = true;
    } else if (k == "radius") {
      b.shape.radius = number(k, t.line);
      b.has_radius = true;
    } else if (k == "preCompDone") {
      const Token& v = next(k, "y or n", t.line);
      if (v.text != "y" && v.text != "n")
        throw InputError(input_message(file_, v.line, k, "'" + v.text + "' must be y or n"));
      b.precomputed = v.text == "y";
    } else {
      return false;
    }
    return true;
  }

  bool geometry_key(Block& b, const Token& t) {
    Shape& s = b.shape;
    const std::string& k = t.text;
    constexpr long kMaxCount = 10000000;
    if (k == "nv") {
      const int n = count(k, t.line, kMaxCount);
      for (int i = 0; i < n; ++i) s.vertices.push_back(vec3(k, t.line));
    } else if (k == "ne") {
      const int n = count(k, t.line, kMaxCount);
      for (int i = 0; i < n; ++i) {
        const int a = count(k, t.line, kMaxCount);
        s.edges.push_back({a, count(k, t.line, kMaxCount)});
        b.edge_lines.push_back(tokens_[pos_ - 1].line);
      }
    } else if (k == "nf") {
      const int n = count(k, t.line, kMaxCount);
      for (int i = 0; i < n; ++i) {
        std::vector<int> face(count(k, t.line, 100000));
        for (int& v : face) v = count(k, t.line, kMaxCount);
        s.faces.push_back(face);
      }
    } else {
      return false;
    }
    return true;
  }

  bool property_key(Block& b, const Token& t) {
    const std::string& k = t.text;
    if (k == "volume") {
      b.shape.volume = number(k, t.line);
      b.has_volume = true;
    } else if (k == "I/m") {
      b.shape.inertia_per_mass = vec3(k, t.line);
      b.has_inertia = true;
    } else if (k == "position") {
      b.shape.input_center = vec3(k, t.line);
    } else if (k == "orientation") {
      const double w = number(k, t.line);  // Rockable writes a quaternion as "s vx vy vz"
      const Vec3 v = vec3(k, t.line);
      b.shape.input_rotation = Quat(w, v.x(), v.y(), v.z());
    } else {
      return false;
    }
    return true;
  }

  // Keys Rockable writes that polydem rebuilds (bounding box) or does not use (its settings),
// and isSurface.
  bool ignored_key(Block& b, const Token& t) {
    const std::string& k = t.text;
    if (k == "obb.extent" || k == "obb.center" || k == "obb.e1" || k == "obb.e2" || k == "obb.e3") {
      vec3(k, t.line);
    } else if (k == "OBBtreeLevel" || k == "MCnstep" || k == "fibObbOption" || k == "na") {
      number(k, t.line);  // na: exaDEM's count of extra data, 0 in its libraries
    } else if (k == "isSurface") {
      b.shape.surface = true;
      if (pos_ < tokens_.size() && (tokens_[pos_].text == "0" || tokens_[pos_].text == "1"))
        b.shape.surface = tokens_[pos_++].text == "1";  // a flag, or a flag with its value
    } else {
      return false;
    }
    return true;
  }

  const std::vector<Token>& tokens_;
  size_t pos_;
  std::string file_;
  std::vector<std::string>& warnings_;
};

// Edges listed twice (a b, or b a) are merged, with a warning naming the line of the repeat.
void merge_duplicate_edges(Block& b, const std::string& file, std::vector<std::string>& warnings) {
  std::vector<std::array<int, 2>> kept;
  for (std::size_t e = 0; e < b.shape.edges.size(); ++e) {
    const auto& edge = b.shape.edges[e];
    const bool repeated = std::any_of(kept.begin(), kept.end(), [&](const std::array<int, 2>& k) {
      return std::min(k[0], k[1]) == std::min(edge[0], edge[1]) && std::max(k[0], k[1]) == std::max(edge[0], edge[1]);
    });
    if (!repeated) {
      kept.push_back(edge);
      continue;
    }
    warnings.push_back(input_message(file, b.edge_lines[e], "ne",
                                     "shape '" + b.shape.name + "': edge " + std::to_string(edge[0]) + " " +
                                         std::to_string(edge[1]) + " is listed twice, merged"));
  }
  b.shape.edges = std::move(kept);
}

Shape finish(Block b, const std::string& file, std::vector<std::string>& warnings) {
  Shape& s = b.shape;
  merge_duplicate_edges(b, file, warnings);
  if (!b.has_name) throw InputError(input_message(file, b.line, "name", "missing in this shape block"));
  const std::string where = "shape '" + s.name + "': ";
  if (!b.has_radius || !(s.radius > 0.0))
    throw InputError(
        input_message(file, b.line, "radius", where + "missing or not > 0 (a Minkowski radius, m)"));
  if (s.vertices.empty()) throw InputError(input_message(file, b.line, "nv", where + "no vertex"));
  try {
    if (b.precomputed && b.has_volume && b.has_inertia) {
      if (!(s.volume > 0.0)) throw InputError(where + "volume must be > 0");
      s.input_rotation.normalize();
      compute_derived_geometry(s);
    } else {
      compute_mass_properties(s);
    }
  } catch (const InputError& e) {
    throw InputError(input_message(file, b.line, "", e.what()));
  }
  return s;
}

}  // namespace

std::vector<Shape> read_shp(std::istream& in, const std::string& file, std::vector<std::string>* warnings) {
  const std::vector<Token> tokens = tokenize(in);
  std::vector<std::string> own;
  std::vector<std::string>& said = warnings ? *warnings : own;
  std::vector<Shape> shapes;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].text != "<") continue;  // Rockable skips anything between blocks
    BlockParser parser(tokens, i + 1, file, said);
    shapes.push_back(finish(parser.parse(tokens[i].line), file, said));
    i = parser.position() - 1;
  }
  if (!warnings)
    for (const std::string& w : own) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return shapes;
}

std::vector<Shape> read_shp_file(const std::string& path, std::vector<std::string>* warnings) {
  std::ifstream in(path);
  if (!in) throw InputError(input_message(path, 0, "", "cannot open the shape file"));
  return read_shp(in, path, warnings);
}

void write_shp(std::ostream& out, const std::vector<Shape>& shapes) {
  const auto old_precision = out.precision(std::numeric_limits<double>::max_digits10);
  auto vec = [&](const Vec3& v) { out << v.x() << ' ' << v.y() << ' ' << v.z(); };
  for (const Shape& s : shapes) {
    Vec3 lo = s.vertices[0], hi = s.vertices[0];
    for (const Vec3& v : s.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    out << "<\nname " << s.name << "\nradius " << s.radius << "\npreCompDone y\nvolume " << s.volume;
    out << "\nI/m ";
    vec(s.inertia_per_mass);
    out << "\nobb.extent ";  // principal-frame box, enlarged by the radius as Rockable does
    vec(0.5 * (hi - lo) + Vec3::Constant(s.radius));
    out << "\nobb.e1 1 0 0\nobb.e2 0 1 0\nobb.e3 0 0 1\nobb.center ";
    vec(0.5 * (hi + lo));
    out << "\nposition ";
    vec(s.input_center);
    const Quat& q = s.input_rotation;
    out << "\norientation " << q.w() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z();
    if (s.surface) out << "\nisSurface";  // a flag, as Rockable writes it
    out << "\nnv " << s.vertices.size() << '\n';
    for (const Vec3& v : s.vertices) {
      vec(v);
      out << '\n';
    }
    out << "ne " << s.edges.size() << '\n';
    for (const auto& e : s.edges) out << e[0] << ' ' << e[1] << '\n';
    out << "nf " << s.faces.size() << '\n';
    for (const auto& f : s.faces) {
      out << f.size();
      for (int i : f) out << ' ' << i;
      out << '\n';
    }
    out << ">\n";
  }
  out.precision(old_precision);
}

void write_shp_file(const std::string& path, const std::vector<Shape>& shapes) {
  std::ofstream out(path);
  if (!out) throw InputError(input_message(path, 0, "", "cannot open for writing"));
  write_shp(out, shapes);
  if (!out) throw InputError(input_message(path, 0, "", "write failed"));
}

}  // namespace polydem
