#include "fuzz_targets.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "field/vti_reader.hpp"
#include "io/generate.hpp"
#include "io/scene.hpp"
#include "polydem/error.hpp"
#include "polydem/shape_library.hpp"
#include "shape/point_sources.hpp"
#include "shape/shp_io.hpp"
#include "sim/checkpoint.hpp"

namespace polydem::fuzz {

namespace {

namespace fs = std::filesystem;

// A folder of this process: ROOT/a/b/ holds the input, so a scene's "../../shapes/X.shp"
// (as in the samples) finds the shipped library and "meshes/X.stl" the samples' meshes.
struct WorkFolder {
  fs::path root = fs::temp_directory_path() / ("polydem_fuzz_" + std::to_string(::getpid()));
  fs::path input = root / "a" / "b";
  WorkFolder() {
    const fs::path source = POLYDEM_SOURCE_DIR;
    fs::create_directories(input / "meshes");
    std::error_code ignored;
    fs::create_directory_symlink(source / "shapes", root / "shapes", ignored);
    for (const char* sample : {"hopper", "silo"})
      for (const auto& mesh : fs::directory_iterator(source / "samples" / sample / "meshes"))
        fs::create_symlink(mesh.path(), input / "meshes" / mesh.path().filename(), ignored);
  }
  ~WorkFolder() {
    std::error_code ignored;
    fs::remove_all(root, ignored);
  }
};

const fs::path& work_folder() {
  static const WorkFolder folder;
  return folder.input;
}

std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const fs::path path = work_folder() / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path.string();
}

// Runs one read; InputError is the wanted answer to bad input, anything else escapes.
template <class Read>
void expect_clean(Read read) {
  try {
    read();
  } catch (const InputError&) {
  }
}

void scene(const std::uint8_t* data, std::size_t size) {
  const std::string path = write_input("scene.yaml", data, size);
  expect_clean([&] { load_scene(path); });
}

// The input is a body table (`- file: table.csv`) of a fixed scene that names the shipped
// library, its bodies expanded against it (so unknown shapes are reached too).
void body_table(const std::uint8_t* data, std::size_t size) {
  static const std::string scene_path = [] {
    const std::string text =
        "simulation: {duration: 1, dt: \"1 us\"}\nshapes: [../../shapes/platonic.shp]\n"
        "bodies:\n  - {file: table.csv, density: 2000}\n";
    return write_input("table_scene.yaml", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }();
  static const ShapeLibrary library =
      load_shape_library({std::string(POLYDEM_SOURCE_DIR) + "/shapes/platonic.shp"});
  write_input("table.csv", data, size);
  expect_clean([&] { expand_bodies(load_scene(scene_path), library); });
}

void shp(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  expect_clean([&] { read_shp(in, "fuzz.shp"); });
}

void stl(const std::uint8_t* data, std::size_t size) {
  const std::string path = write_input("mesh.stl", data, size);
  expect_clean([&] { read_stl(path); });
}

void vti(const std::uint8_t* data, std::size_t size) {
  const std::string path = write_input("grid.vti", data, size);
  expect_clean([&] { read_vti(path); });
}

// The checkpoint reader needs the simulation of its scene: tests/fuzz/checkpoint_scene.yaml
// (a few bodies, every driver kind with state: servo, rotation, removal); the corpus holds
// checkpoints of it.
void checkpoint(const std::uint8_t* data, std::size_t size) {
  static const Scene scene_ = load_scene(std::string(POLYDEM_SOURCE_DIR) + "/tests/fuzz/checkpoint_scene.yaml");
  static const ShapeLibrary library = load_shape_library(scene_.shape_files);
  static const std::vector<BodySpec> specs = expand_bodies(scene_, library);
  const std::string path = write_input("checkpoint.bin", data, size);
  Simulation sim(scene_, library, specs);
  OutputProgress progress;
  expect_clean([&] { read_checkpoint(path, sim, progress); });
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"scene", scene}, {"body_table", body_table}, {"shp", shp}, {"stl", stl}, {"vti", vti}, {"checkpoint", checkpoint}};
  return all;
}

const Target& target(const std::string& name) {
  for (const Target& t : targets())
    if (t.name == name) return t;
  throw std::out_of_range("no fuzz target '" + name + "'");
}

}  // namespace polydem::fuzz
