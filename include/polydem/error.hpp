#pragma once
// Errors the user can fix (exit code 1) apart from failures during a run (exit code 2).
#include <stdexcept>
#include <string>

namespace polydem {

// Bad input: a one-line message "FILE:LINE: key 'KEY': what is wrong (suggestion)".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The run itself failed (non-finite state, I/O failure while writing results).
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "FILE:LINE: key 'KEY': MESSAGE"; parts that are empty or 0 are left out.
inline std::string input_message(const std::string& file, int line, const std::string& key,
                                 const std::string& message) {
  std::string s = file;  // appended piecewise: GCC 12 misreports `a + b + c` (PR105651)
  if (line > 0) s.append(":").append(std::to_string(line));
  if (!s.empty()) s.append(": ");
  if (!key.empty()) s.append("key '").append(key).append("': ");
  return s.append(message);
}

}  // namespace polydem
