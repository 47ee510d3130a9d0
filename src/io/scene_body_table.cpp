// `- file: bodies.csv` in `bodies:`: one body a row, columns named by the header, SI units.
// A YAML list costs ~260,000 instructions a body to read (yaml-cpp); a table ~1,800.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "io/scene_body_table.hpp"
#include "polydem/error.hpp"

namespace polydem {
namespace {

const std::vector<std::string> kColumns = {"shape", "x",  "y",  "z",  "qw", "qx", "qy", "qz", "vx",
                                           "vy",    "vz", "wx", "wy", "wz", "density", "scale", "group"};
enum Col { kShape, kX, kY, kZ, kQw, kQx, kQy, kQz, kVx, kVy, kVz, kWx, kWy, kWz, kDensity, kScale, kGroup };
// Columns that come together: a position, a quaternion, a velocity, an angular velocity.
const std::vector<std::vector<Col>> kTogether = {{kX, kY, kZ}, {kQw, kQx, kQy, kQz}, {kVx, kVy, kVz}, {kWx, kWy, kWz}};

// "shape, x, y, z (required), qw, ...": the columns a header may name.
std::string column_list() {
  std::string out;
  for (std::size_t c = 0; c < kColumns.size(); ++c)
    out.append(c ? ", " : "").append(kColumns[c]).append(c == kZ ? " (required)" : "");
  return out;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Splits a row at commas into `cells` (views into `row`).
void split_row(std::string_view row, std::vector<std::string_view>& cells) {
  cells.clear();
  for (std::size_t start = 0;;) {
    const std::size_t comma = row.find(',', start);
    cells.push_back(trimmed(row.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return;
    start = comma + 1;
  }
}

bool skipped(std::string_view row) {
  const std::string_view t = trimmed(row);
  return t.empty() || t.front() == '#';
}

// The header's column index of each known column name (-1: absent).
class Header {
 public:
  Header(std::string_view row, const SourceLoc& at) {
    std::vector<std::string_view> cells;
    split_row(row, cells);
    index_.assign(kColumns.size(), -1);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string name(cells[c]);
      const auto known = std::find(kColumns.begin(), kColumns.end(), name);
      if (known == kColumns.end())
        throw InputError(input_message(at.file, at.line, name.empty() ? "header" : name,
                                       "unknown column" + did_you_mean(name, kColumns) + "; columns: " + column_list()));
      int& slot = index_[std::size_t(known - kColumns.begin())];
      if (slot >= 0) throw InputError(input_message(at.file, at.line, name, "column given twice"));
      slot = static_cast<int>(c);
    }
    width_ = cells.size();
    if (!has(kShape)) throw InputError(input_message(at.file, at.line, "shape", "missing column"));
    for (const auto& group : kTogether) check_together(group, at);
  }
  bool has(Col c) const { return index_[c] >= 0; }
  int column(Col c) const { return index_[c]; }
  std::size_t width() const { return width_; }

 private:
  void check_together(const std::vector<Col>& group, const SourceLoc& at) const {
    const bool required = group[0] == kX;
    const bool any = std::any_of(group.begin(), group.end(), [&](Col c) { return has(c); });
    for (Col c : group)
      if (!has(c) && (required || any))
        throw InputError(input_message(at.file, at.line, kColumns[c],
                                       "missing column (" + kColumns[group[0]] + " and its companions come together)"));
  }
  std::vector<int> index_;
  std::size_t width_ = 0;
};

class RowReader {
 public:
  RowReader(const Header& header, const std::vector<std::string_view>& cells, const SourceLoc& at)
      : header_(header), cells_(cells), at_(at) {}

  bool has(Col c) const { return header_.has(c); }
  std::string_view text(Col c) const { return cells_[std::size_t(header_.column(c))]; }
  double number(Col c) const {
    const std::string_view s = text(c);
    double v = 0.0;
    const char* begin = s.data() + (!s.empty() && s.front() == '+');
    const auto [ptr, ec] = std::from_chars(begin, s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
      fail(c, "expected a finite number (SI units), got '" + std::string(s) + "'");
    return v;
  }
  double number(Col c, double fallback) const { return has(c) ? number(c) : fallback; }
  double positive(Col c, double fallback) const {
    const double v = number(c, fallback);
    if (!(v > 0.0)) fail(c, "must be > 0, got " + std::string(text(c)));
    return v;
  }
  Vec3 vec3(Col first) const {  // the column and the two after it
    if (!has(first)) return Vec3::Zero();
    return {number(first), number(Col(first + 1)), number(Col(first + 2))};
  }
  [[noreturn]] void fail(Col c, const std::string& message) const {
    throw InputError(input_message(at_.file, at_.line, kColumns[c], message));
  }

 private:
  const Header& header_;
  const std::vector<std::string_view>& cells_;
  const SourceLoc& at_;
};

Quat orientation(const RowReader& row) {
  if (!row.has(kQw)) return Quat::Identity();
  const Quat q(row.number(kQw), row.number(kQx), row.number(kQy), row.number(kQz));
  if (!(q.norm() > 0.0)) row.fail(kQw, "the quaternion must not be zero (identity: 1, 0, 0, 0)");
  return q.normalized();
}

BodySpec read_row(const RowReader& row, const BodySpec& defaults) {
  BodySpec b = defaults;
  b.shape = std::string(row.text(kShape));
  if (b.shape.empty()) row.fail(kShape, "empty shape name");
  b.position = row.vec3(kX);
  b.orientation = orientation(row);
  b.velocity = row.vec3(kVx);
  b.angular_velocity = row.vec3(kWx);
  b.density = row.positive(kDensity, defaults.density);
  b.scale = row.positive(kScale, defaults.scale);
  const double group = row.number(kGroup, defaults.group);
  if (group != std::floor(group) || group < 0 || group > 1e9)
    row.fail(kGroup, "expected an integer >= 0, got " + std::string(row.text(kGroup)));
  b.group = static_cast<int>(group);
  return b;
}

}  // namespace

void read_body_table(const YamlMap& entry, const std::string& folder, std::vector<BodySpec>& out) {
  const std::string path = resolve_input_file(entry, "file", folder, "body table");
  BodySpec defaults;
  defaults.density = check_positive(entry, "density", entry.quantity("density", Dimension::density, defaults.density));
  defaults.scale = check_positive(entry, "scale", entry.quantity("scale", Dimension::dimensionless, defaults.scale));
  defaults.group = static_cast<int>(entry.integer("group", 0, 0));
  std::ifstream in(path);
  std::string line;
  SourceLoc at{path, 0};
  std::optional<Header> header;
  std::vector<std::string_view> cells;
  while (std::getline(in, line)) {
    ++at.line;
    if (skipped(line)) continue;
    if (!header) {
      header.emplace(line, at);
      continue;
    }
    split_row(line, cells);
    if (cells.size() != header->width())
      throw InputError(input_message(at.file, at.line, "row", "has " + std::to_string(cells.size()) +
                                                                  " cells, the header " + std::to_string(header->width())));
    out.push_back(read_row(RowReader(*header, cells, at), defaults));
    out.back().loc = at;
  }
  if (!header) entry.fail("file", "'" + path + "' has no header row (shape, x, y, z, ...)");
}

}  // namespace polydem
