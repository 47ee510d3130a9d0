#pragma once
// CSV time series (energy.csv and others): header once, rows appended and flushed at once so a
// crashed run keeps every row, doubles in full precision (%.17g round-trips exactly).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "output/file.hpp"

namespace polydem {

class CsvSeries {
 public:
  // append: continue an existing file (resumed run); its header must equal `columns`, and its
  // rows later than `keep_until` (s, first column) are dropped first, with any partial last
  // line (a run killed after its checkpoint wrote them). A missing or empty file gets the
  // header in either mode.
  CsvSeries(std::string path, std::vector<std::string> columns, bool append = false,
            double keep_until = std::numeric_limits<double>::infinity());
  // values.size() must equal the number of columns.
  void row(const std::vector<double>& values);

 private:
  std::vector<std::string> columns_;
  std::optional<OutputFile> file_;
};

}  // namespace polydem
