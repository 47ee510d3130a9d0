#pragma once
// A file opened for writing whose every failure is a RunError naming the path and errno text.
#include <cstdio>
#include <string>
#include <string_view>

namespace polydem {

class OutputFile {
 public:
  // mode: "wb" to replace, "ab" to append.
  OutputFile(std::string path, const char* mode = "wb");
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(const void* data, std::size_t bytes);
  void write(std::string_view text) { write(text.data(), text.size()); }
  void flush();
  // Closes and reports errors of the final flush (disk full shows up here).
  void close();
  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail(const char* what) const;
  std::string path_;
  std::FILE* file_ = nullptr;
};

// Writes `text` to `path` through `path`.tmp and a rename, so readers never see a half file.
void replace_file(const std::string& path, std::string_view text);

}  // namespace polydem
