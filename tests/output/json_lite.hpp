#pragma once
// A minimal JSON reader for the output of read_vtk.py (tests only): numbers go through strtod,
// which reads Python's shortest round-trip repr back to the same double.
#include <cctype>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace polydem::test {

struct Json {
  enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
  double number = 0.0;
  std::string text;
  std::vector<Json> items;
  std::map<std::string, Json> fields;

  const Json& operator[](const std::string& key) const {
    auto it = fields.find(key);
    if (it == fields.end()) throw std::runtime_error("JSON has no key '" + key + "'");
    return it->second;
  }
  const Json& operator[](std::size_t k) const { return items.at(k); }
  std::size_t size() const { return items.size(); }
  bool has(const std::string& key) const { return fields.count(key) > 0; }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& s) : s_(s) {}
  Json parse() {
    Json v = value();
    skip();
    if (p_ != s_.size()) fail("trailing characters");
    return v;
  }

 private:
  [[noreturn]] void fail(const char* what) {
    throw std::runtime_error("JSON " + std::string(what) + " at " + std::to_string(p_));
  }
  void skip() { while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_; }
  bool eat(char c) { skip(); if (p_ < s_.size() && s_[p_] == c) { ++p_; return true; } return false; }
  bool word(const char* w) {
    const std::string t(w);
    if (s_.compare(p_, t.size(), t) != 0) return false;
    p_ += t.size();
    return true;
  }
  Json value() {
    skip();
    Json v;
    if (p_ >= s_.size()) fail("ended early");
    const char c = s_[p_];
    if (c == '{') return object();
    if (c == '[') return array();
    if (c == '"') { v.kind = Json::Kind::string; v.text = string(); return v; }
    if (word("null")) return v;
    if (word("true")) { v.kind = Json::Kind::boolean; v.number = 1.0; return v; }
    if (word("false")) { v.kind = Json::Kind::boolean; return v; }
    char* end = nullptr;
    v.kind = Json::Kind::number;
    v.number = std::strtod(s_.c_str() + p_, &end);  // also reads NaN/Infinity as Python writes them
    if (end == s_.c_str() + p_) fail("unexpected character");
    p_ = std::size_t(end - s_.c_str());
    return v;
  }
  std::string string() {
    std::string out;
    ++p_;
    while (p_ < s_.size() && s_[p_] != '"') {
      if (s_[p_] == '\\') ++p_;  // tests use plain ASCII names: keep the escaped character
      out += s_[p_++];
    }
    ++p_;
    return out;
  }
  Json array() {
    Json v;
    v.kind = Json::Kind::array;
    ++p_;
    if (eat(']')) return v;
    do v.items.push_back(value()); while (eat(','));
    if (!eat(']')) fail("expected ]");
    return v;
  }
  Json object() {
    Json v;
    v.kind = Json::Kind::object;
    ++p_;
    if (eat('}')) return v;
    do {
      skip();
      const std::string key = string();
      if (!eat(':')) fail("expected :");
      v.fields[key] = value();
    } while (eat(','));
    if (!eat('}')) fail("expected }");
    return v;
  }
  const std::string& s_;
  std::size_t p_ = 0;
};

}  // namespace polydem::test
