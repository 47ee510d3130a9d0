#include "field/vti_decode.hpp"

#include <zlib.h>

#include <array>
#include <cstring>
#include <stdexcept>

namespace polydem {

namespace {

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

std::uint64_t read_word(std::string_view data, std::size_t at, int bytes) {
  if (at + std::size_t(bytes) > data.size()) throw std::runtime_error("data ends inside the array header");
  if (bytes == 4) {
    std::uint32_t v;
    std::memcpy(&v, data.data() + at, 4);
    return v;
  }
  std::uint64_t v;
  std::memcpy(&v, data.data() + at, 8);
  return v;
}

constexpr std::array<const char*, 10> kTypes = {"Float32", "Float64", "Int8",  "UInt8",  "Int16",
                                                 "UInt16",  "Int32",   "UInt32", "Int64", "UInt64"};

template <class T>
void convert(const std::vector<std::uint8_t>& bytes, std::vector<double>& out) {
  out.resize(bytes.size() / sizeof(T));
  for (std::size_t k = 0; k < out.size(); ++k) {
    T v;
    std::memcpy(&v, bytes.data() + k * sizeof(T), sizeof(T));
    out[k] = double(v);
  }
}

}  // namespace

std::vector<std::uint8_t> decode_base64(std::string_view text) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  int quantum[4], n = 0, pad = 0;
  for (char c : text) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '=') {
      quantum[n++] = 0;
      ++pad;
    } else {
      const int v = base64_value(c);
      if (v < 0 || pad > 0) throw std::runtime_error(std::string("invalid base64 character '") + c + "'");
      quantum[n++] = v;
    }
    if (n < 4) continue;
    const std::uint32_t bits = (quantum[0] << 18) | (quantum[1] << 12) | (quantum[2] << 6) | quantum[3];
    const std::uint8_t bytes[3] = {std::uint8_t(bits >> 16), std::uint8_t(bits >> 8), std::uint8_t(bits)};
    if (pad > 2) throw std::runtime_error("invalid base64 padding");
    out.insert(out.end(), bytes, bytes + 3 - pad);
    n = pad = 0;
  }
  if (n != 0) throw std::runtime_error("base64 data ends in the middle of a 4-character group");
  return out;
}

std::vector<std::uint8_t> decode_binary_array(std::string_view data, const VtkBinaryLayout& layout,
                                              std::size_t* consumed) {
  const int h = layout.header_bytes;
  std::vector<std::uint8_t> out;
  if (!layout.zlib) {
    const std::uint64_t bytes = read_word(data, 0, h);
    if (bytes > data.size() - std::size_t(h)) throw std::runtime_error("array data is shorter than its header says");
    out.assign(data.begin() + h, data.begin() + h + std::ptrdiff_t(bytes));
    if (consumed) *consumed = std::size_t(h) + bytes;
    return out;
  }
  // [blocks, block size, last block size (0: full), compressed size of each block], then the blocks
  const std::uint64_t blocks = read_word(data, 0, h), block = read_word(data, h, h), last = read_word(data, 2 * h, h);
  if (blocks > data.size() / std::size_t(h)) throw std::runtime_error("corrupt compression header");
  std::size_t at = std::size_t(3 + blocks) * std::size_t(h);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t packed = read_word(data, std::size_t(3 + b) * std::size_t(h), h);
    uLongf size = uLongf((b + 1 == blocks && last != 0) ? last : block);
    if (packed > data.size() - at || size > (std::uint64_t(1) << 34))
      throw std::runtime_error("compressed array data is shorter than its header says");
    const std::size_t start = out.size();
    out.resize(start + size);
    if (uncompress(out.data() + start, &size, reinterpret_cast<const Bytef*>(data.data() + at), uLong(packed)) != Z_OK)
      throw std::runtime_error("zlib cannot decompress the array data (corrupt file?)");
    out.resize(start + size);
    at += std::size_t(packed);
  }
  if (consumed) *consumed = at;
  return out;
}

bool is_numeric_type(const std::string& type) {
  for (const char* t : kTypes)
    if (type == t) return true;
  return false;
}

std::vector<double> to_doubles(const std::vector<std::uint8_t>& bytes, const std::string& type) {
  std::vector<double> out;
  if (type == "Float32") convert<float>(bytes, out);
  else if (type == "Float64") convert<double>(bytes, out);
  else if (type == "Int8") convert<std::int8_t>(bytes, out);
  else if (type == "UInt8") convert<std::uint8_t>(bytes, out);
  else if (type == "Int16") convert<std::int16_t>(bytes, out);
  else if (type == "UInt16") convert<std::uint16_t>(bytes, out);
  else if (type == "Int32") convert<std::int32_t>(bytes, out);
  else if (type == "UInt32") convert<std::uint32_t>(bytes, out);
  else if (type == "Int64") convert<std::int64_t>(bytes, out);
  else if (type == "UInt64") convert<std::uint64_t>(bytes, out);
  else throw std::runtime_error("unsupported data type " + type);
  return out;
}

}  // namespace polydem
