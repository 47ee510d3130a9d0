#include <algorithm>
#include <cstdio>

#include "output/appended.hpp"
#include "output/file.hpp"
#include "output/vtk.hpp"

namespace polydem {

PvdSeries::PvdSeries(std::string path) : path_(std::move(path)) {}

namespace {

// "bodies" for "out/bodies_000012.vtu".
std::string stem_of(const std::string& file) {
  const std::size_t slash = file.find_last_of('/');
  const std::string name = slash == std::string::npos ? file : file.substr(slash + 1);
  return name.substr(0, name.find_last_of('_'));
}

}  // namespace

int PvdSeries::part_of(const std::string& file) {
  const std::string stem = stem_of(file);
  for (std::size_t k = 0; k < stems_.size(); ++k)
    if (stems_[k] == stem) return int(k);
  stems_.push_back(stem);
  return int(stems_.size()) - 1;
}

void PvdSeries::add(double time, const std::vector<std::string>& files) {
  char t[32];
  std::snprintf(t, sizeof(t), "%.17g", time);  // s, exact so frames never collapse in ParaView
  for (const std::string& f : files)
    entries_ += "<DataSet timestep=\"" + std::string(t) + "\" group=\"\" part=\"" + std::to_string(part_of(f)) +
                "\" file=\"" + xml_escape(f) + "\"/>\n";
  replace_file(path_, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n" +
                          entries_ + "</Collection>\n</VTKFile>\n");
}

PvdFiles::PvdFiles(std::string dir) : dir_(std::move(dir)), scene_(dir_ + "/scene.pvd") {}

void PvdFiles::add(double time, const std::vector<std::string>& files) {
  scene_.add(time, files);
  for (const std::string& f : files) {
    const std::string stem = stem_of(f);
    auto part = std::find_if(parts_.begin(), parts_.end(), [&](const auto& p) { return p.first == stem; });
    if (part == parts_.end()) part = parts_.insert(parts_.end(), {stem, PvdSeries(dir_ + "/" + stem + ".pvd")});
    part->second.add(time, {f});
  }
}

}  // namespace polydem
