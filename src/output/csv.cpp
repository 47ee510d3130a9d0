#include "output/csv.hpp"

#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <fstream>
#include <stdexcept>

#include "polydem/error.hpp"

namespace polydem {

namespace {

std::string header_line(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t k = 0; k < columns.size(); ++k) line += (k ? "," : "") + columns[k];
  return line;
}

// The first line of `path`, or nullopt if the file is missing or empty.
std::optional<std::string> existing_header(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return std::nullopt;
  return line;
}

// Rewrites `path` (atomically) without the rows whose time is later than `keep_until` and
// without a last line cut short; leaves it alone when nothing is to go.
void drop_rows_after(const std::string& path, double keep_until) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t keep = text.find('\n');  // the header stays
  if (keep == std::string::npos) return;
  ++keep;
  while (keep < text.size()) {
    const std::size_t end = text.find('\n', keep);
    if (end == std::string::npos) break;  // a partial last line
    if (!(std::strtod(text.c_str() + keep, nullptr) <= keep_until)) break;  // rows are in time order
    keep = end + 1;
  }
  if (keep < text.size()) replace_file(path, std::string_view(text).substr(0, keep));
}

}  // namespace

CsvSeries::CsvSeries(std::string path, std::vector<std::string> columns, bool append, double keep_until)
    : columns_(std::move(columns)) {
  const std::string header = header_line(columns_);
  const std::optional<std::string> old = append ? existing_header(path) : std::nullopt;
  if (old && *old != header)
    throw RunError("cannot append to '" + path + "': its columns are '" + *old + "' but this run writes '" + header +
                   "' (remove the file or write to another output folder)");
  if (old) drop_rows_after(path, keep_until);
  file_.emplace(std::move(path), append ? "ab" : "wb");
  if (!old) {
    file_->write(header + "\n");
    file_->flush();
  }
}

void CsvSeries::row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw std::logic_error("CsvSeries::row: " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns in '" + file_->path() + "'");
  std::string line;
  char buf[32];
  for (std::size_t k = 0; k < values.size(); ++k) {
    const int n = std::snprintf(buf, sizeof(buf), k ? ",%.17g" : "%.17g", values[k]);
    line.append(buf, std::size_t(n));
  }
  line += '\n';
  file_->write(line);
  file_->flush();
}

}  // namespace polydem
