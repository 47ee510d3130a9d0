#pragma once
// Byte-level decoding of VTK XML data arrays: base64, the block header, zlib blocks, and the
// conversion of typed values to double. Errors are std::runtime_error with a plain message;
// the reader adds the file and the array name.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace polydem {

// Decodes base64 text 4 characters at a time, skipping whitespace. A '=' padded quantum ends
// one encoded stream and the next starts afresh: VTK encodes a compressed array's header and
// its data as separate streams.
std::vector<std::uint8_t> decode_base64(std::string_view text);

struct VtkBinaryLayout {
  int header_bytes = 4;           // UInt32 (VTK's default) or UInt64
  bool zlib = false;              // vtkZLibDataCompressor blocks
};

// The payload of one binary array: `data` starts at its header; the result is the array's
// raw bytes (decompressed). `consumed` receives the bytes of `data` the array occupies.
std::vector<std::uint8_t> decode_binary_array(std::string_view data, const VtkBinaryLayout& layout,
                                              std::size_t* consumed = nullptr);

// Little-endian values of VTK type `type` ("Float32", "Int64", ...) converted to double.
std::vector<double> to_doubles(const std::vector<std::uint8_t>& bytes, const std::string& type);

// Whether `type` is a numeric VTK type to_doubles accepts.
bool is_numeric_type(const std::string& type);

}  // namespace polydem
