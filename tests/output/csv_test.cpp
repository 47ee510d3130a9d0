// CsvSeries: header once, rows that parse back to the same bits, flushed at once, append mode.
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "output/csv.hpp"
#include "output_test_util.hpp"
#include "polydem/error.hpp"
#include "polydem/math.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::istringstream in(read_all(path));
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::strtod(cell.c_str(), nullptr));
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

const std::vector<std::string> kColumns{"time", "kinetic", "contacts"};

}  // namespace

TEST_CASE("csv: rows parse back bit for bit", "[output][csv]") {
  const TempDir tmp("csv_exact");
  const std::string path = tmp.path + "/energy.csv";
  const std::vector<std::vector<double>> rows{
      {0.1, 1.0 / 3.0, 12},
      {std::nextafter(1.0, 2.0), -0.0, 4.9406564584124654e-324},  // one ulp, signed zero, smallest subnormal
      {std::numeric_limits<double>::max(), -kPi, std::numeric_limits<double>::infinity()},
      {1e-300 / 7.0, 123456789.123456789, 2.2250738585072014e-308}};
  {
    CsvSeries csv(path, kColumns);
    for (const auto& r : rows) csv.row(r);
  }
  const std::vector<std::string> lines = lines_of(path);
  REQUIRE(lines.size() == rows.size() + 1);
  CHECK(lines[0] == "time,kinetic,contacts");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::vector<double> back = parse_row(lines[k + 1]);
    REQUIRE(back.size() == 3);
    for (std::size_t c = 0; c < 3; ++c) CHECK(same_bits(back[c], rows[k][c]));
  }
}

TEST_CASE("csv: each row is on disk as soon as it is written", "[output][csv]") {
  const TempDir tmp("csv_flush");
  const std::string path = tmp.path + "/energy.csv";
  CsvSeries csv(path, kColumns);
  CHECK(lines_of(path).size() == 1);
  csv.row({1, 2, 3});
  CHECK(lines_of(path).size() == 2);  // a crash from here on keeps the row
}

TEST_CASE("csv: append continues the file with one header", "[output][csv]") {
  const TempDir tmp("csv_append");
  const std::string path = tmp.path + "/energy.csv";
  {
    CsvSeries csv(path, kColumns, true);  // missing file: append still writes the header
    csv.row({0, 1, 2});
  }
  {
    CsvSeries csv(path, kColumns, true);
    csv.row({0.5, 3, 4});
  }
  std::vector<std::string> lines = lines_of(path);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "time,kinetic,contacts");
  CHECK(parse_row(lines[2]) == std::vector<double>{0.5, 3, 4});
  {
    CsvSeries csv(path, kColumns);  // not appending: a fresh file
  }
  CHECK(lines_of(path).size() == 1);
}

TEST_CASE("csv: wrong use is reported", "[output][csv]") {
  const TempDir tmp("csv_errors");
  const std::string dir = tmp.path;
  { CsvSeries csv(dir + "/energy.csv", kColumns); }
  CHECK_THROWS_WITH(CsvSeries(dir + "/energy.csv", {"time", "elastic"}, true),
                    Catch::Contains("energy.csv") && Catch::Contains("time,kinetic,contacts"));
  CsvSeries csv(dir + "/energy.csv", kColumns);
  CHECK_THROWS_AS(csv.row({1, 2}), std::logic_error);
  CHECK_THROWS_AS(CsvSeries(dir + "/no_folder/x.csv", kColumns), RunError);
}
