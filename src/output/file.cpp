#include "output/file.hpp"

#include <cerrno>
#include <cstring>

#include "polydem/error.hpp"

namespace polydem {

OutputFile::OutputFile(std::string path, const char* mode) : path_(std::move(path)) {
  file_ = std::fopen(path_.c_str(), mode);
  if (!file_) fail("cannot open for writing");
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);
}

void OutputFile::fail(const char* what) const {
  throw RunError(std::string(what) + " '" + path_ + "': " + std::strerror(errno));
}

void OutputFile::write(const void* data, std::size_t bytes) {
  if (bytes == 0) return;
  if (std::fwrite(data, 1, bytes, file_) != bytes) fail("cannot write");
}

void OutputFile::flush() {
  if (std::fflush(file_) != 0) fail("cannot write");
}

void OutputFile::close() {
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) fail("cannot write");
}

void replace_file(const std::string& path, std::string_view text) {
  const std::string tmp = path + ".tmp";
  OutputFile f(tmp);
  f.write(text);
  f.close();
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw RunError("cannot replace '" + path + "': " + std::strerror(errno));
}

}  // namespace polydem
