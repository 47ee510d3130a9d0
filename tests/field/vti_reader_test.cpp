// The .vti reader on hand-written files: ASCII cell and point data, inline base64, and the
// one-line errors for files that are missing, of the wrong kind, lack a field or have a
// non-positive spacing. tests/field/vti_formats.sh checks the files python vtk writes
// (base64, appended raw and base64, zlib).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>
#include <zlib.h>

#include "field/fluid_source.hpp"
#include "field/vti_decode.hpp"
#include "field/vti_reader.hpp"
#include "polydem/error.hpp"

using namespace polydem;

namespace {

struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& text)
      : path((std::filesystem::temp_directory_path() / ("polydem_field_" + std::to_string(::getpid()) + name)).string()) {
    std::ofstream(path) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
};

// A 2 x 1 x 1 cell image with origin (1, 2, 3) and spacing (0.5, 1, 2); `data` holds the arrays.
std::string image(const std::string& data, const std::string& spacing = "0.5 1 2",
                  const std::string& type = "ImageData") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + type + "\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
         "<ImageData WholeExtent=\"0 2 0 1 0 1\" Origin=\"1 2 3\" Spacing=\"" + spacing + "\">\n"
         "<Piece Extent=\"0 2 0 1 0 1\">\n" + data + "</Piece>\n</ImageData>\n</VTKFile>\n";
}

const std::string kCells =
    "<CellData>\n<DataArray type=\"Float64\" Name=\"U\" NumberOfComponents=\"3\" format=\"ascii\">\n"
    "1 2 3 4 5 6\n</DataArray>\n<DataArray type=\"Float32\" Name=\"p\" format=\"ascii\">10 20</DataArray>\n"
    "</CellData>\n";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

FieldSettings::FluidField settings(const std::string& file) {
  FieldSettings::FluidField f;
  f.file = file;
  f.file_loc = {"scene.yaml", 14};
  return f;
}

}  // namespace

TEST_CASE("ASCII cell data: values, origin and spacing", "[field]") {
  const TempFile t("a.vti", image(kCells));
  const FluidGrid g = make_fluid_grid(settings(t.path), {.U = true, .p = true});
  CHECK(g.cells == Index3(2, 1, 1));
  CHECK(g.origin == Vec3(1, 2, 3));
  CHECK(g.spacing == Vec3(0.5, 1, 2));
  CHECK(g.U[1] == Vec3(4, 5, 6));
  CHECK(g.p[1] == 20.0);
}

TEST_CASE("Point data: each point is a cell centre", "[field]") {
  const TempFile t("p.vti", image("<PointData>\n<DataArray type=\"Int32\" Name=\"p\" format=\"ascii\">"
                                  "0 1 2 3 4 5 6 7 8 9 10 11</DataArray>\n</PointData>\n"));
  const FluidGrid g = make_fluid_grid(settings(t.path), {.p = true});
  CHECK(g.cells == Index3(3, 2, 2));
  CHECK(g.origin == Vec3(0.75, 1.5, 2.0));  // half a spacing before the first point
  CHECK(g.p[g.index({2, 1, 1})] == 11.0);
}

TEST_CASE("Inline base64 arrays decode, header and data as separate streams", "[field]") {
  // "AQAAAA==" is the UInt32 header 1 as its own padded stream, then "Kg==" the byte 42:
  // VTK pads a compressed array's header apart from its data.
  const auto bytes = decode_base64("AQAAAA==\nKg==");
  REQUIRE(bytes.size() == 5);
  CHECK(bytes[0] == 1);
  CHECK(bytes[4] == 42);
  // Two Float64 values 0.5 and -2 (16 bytes) after a UInt32 byte count of 16.
  const std::string b64 = "EAAAAAAAAAAAAOA/AAAAAAAAAMA=";
  const TempFile t("b.vti", image("<CellData>\n<DataArray type=\"Float64\" Name=\"p\" format=\"binary\">" + b64 +
                                  "</DataArray>\n</CellData>\n"));
  const FluidGrid g = make_fluid_grid(settings(t.path), {.p = true});
  CHECK(g.p == std::vector<double>{0.5, -2.0});
}

TEST_CASE("Bad grid files: one line naming the scene key and the file", "[field]") {
  const std::string where = "scene.yaml:14: key 'file': ";
  CHECK(error_of([] { make_fluid_grid(settings("/nonexistent/flow.vti"), {}); }) ==
        where + "/nonexistent/flow.vti: cannot open the fluid grid file");
  const TempFile kind("k.vti", image(kCells, "0.5 1 2", "UnstructuredGrid"));
  CHECK(error_of([&] { make_fluid_grid(settings(kind.path), {}); })
            .find(where + kind.path + ": is a VTK UnstructuredGrid file, expected ImageData") == 0);
  const TempFile spacing("s.vti", image(kCells, "0.5 0 2"));
  CHECK(error_of([&] { make_fluid_grid(settings(spacing.path), {}); })
            .find(where + spacing.path + ": Spacing must be positive") == 0);
  // Extents beyond int (found by tools/fuzz.sh: a float-to-int overflow), fractional, or too many points.
  for (const std::string extent : {"0 2 0 1 0 4e33", "0 2.5 0 1 0 1", "-2e9 0 0 1 0 1"}) {
    std::string text = image(kCells);
    text.replace(text.find("0 2 0 1 0 1"), 11, extent);
    const TempFile bad("e.vti", text);
    CHECK(error_of([&] { make_fluid_grid(settings(bad.path), {}); })
              .find(where + bad.path + ": WholeExtent must hold whole numbers within +-1e9") == 0);
  }
  std::string huge = image(kCells);
  huge.replace(huge.find("0 2 0 1 0 1"), 11, "0 2000 0 2000 0 2000");
  const TempFile big("h.vti", huge);
  CHECK(error_of([&] { make_fluid_grid(settings(big.path), {}); }).find("holds more than 1e9 points") != std::string::npos);
  const TempFile plain("t.vti", "U p rho nu\n1 2 3 4\n");
  CHECK(error_of([&] { make_fluid_grid(settings(plain.path), {}); }).find("not a VTK XML file") != std::string::npos);
  const TempFile ok("m.vti", image(kCells));
  CHECK(error_of([&] { make_fluid_grid(settings(ok.path), {.rho = true}); }) ==
        where + ok.path + ": no array 'rho' in its CellData (arrays: U, p); or give the density in fluid_field (rho: 1000)");
  auto with_rho = settings(ok.path);
  with_rho.rho = 1000.0;  // the scene's constant fills in
  CHECK(make_fluid_grid(with_rho, {.rho = true}).rho == std::vector<double>{1000.0, 1000.0});
  const TempFile short_array("n.vti", image("<CellData><DataArray type=\"Float64\" Name=\"p\" format=\"ascii\">1"
                                            "</DataArray></CellData>"));
  CHECK(error_of([&] { make_fluid_grid(settings(short_array.path), {}); }).find("array 'p' has 1 values, expected 2") !=
        std::string::npos);
}

TEST_CASE("Appended raw zlib data, and every truncation of the file is a clean error", "[field]") {
  // One zlib block: UInt32 header [blocks = 1, block size, last block size, compressed size].
  const std::vector<double> p = {1.5, -2.25};
  uLongf packed_size = compressBound(sizeof(double) * 2);
  std::vector<Bytef> packed(packed_size);
  REQUIRE(compress(packed.data(), &packed_size, reinterpret_cast<const Bytef*>(p.data()), sizeof(double) * 2) == Z_OK);
  const std::uint32_t header[4] = {1, 16, 16, std::uint32_t(packed_size)};
  std::string raw(reinterpret_cast<const char*>(header), sizeof(header));
  raw.append(reinterpret_cast<const char*>(packed.data()), packed_size);
  std::string text = image("<CellData><DataArray type=\"Float64\" Name=\"p\" format=\"appended\" offset=\"0\"/></CellData>\n");
  text.replace(text.find("</VTKFile>"), 10, "<AppendedData encoding=\"raw\">_" + raw + "\n</AppendedData></VTKFile>\n");
  text.replace(text.find("byte_order"), 10, "compressor=\"vtkZLibDataCompressor\" byte_order");
  const TempFile whole("z.vti", text);
  CHECK(make_fluid_grid(settings(whole.path), {.p = true}).p == p);
  int errors = 0;
  for (std::size_t n = 0; n < text.size(); ++n) {  // no crash, no hang: a value or an InputError
    const TempFile cut("cut.vti", text.substr(0, n));
    try {
      make_fluid_grid(settings(cut.path), {.p = true});
    } catch (const InputError&) {
      ++errors;
    }
  }
  CHECK(errors > 0.9 * double(text.size()));
}

TEST_CASE("A non-finite value in the grid is an error", "[field]") {
  const TempFile t("nan.vti", image("<CellData><DataArray type=\"Float64\" Name=\"p\" format=\"ascii\">1 nan"
                                    "</DataArray></CellData>"));
  CHECK(error_of([&] { make_fluid_grid(settings(t.path), {.p = true}); }).find("array 'p' holds a non-finite value") !=
        std::string::npos);
}
