#pragma once
// Frees a vector's buffer. `v = {}` does not: it picks the initializer-list assignment, which
// empties the vector and keeps its capacity (a 91k-sphere list's results and records, 41 MB,
// stayed held that way between rebuilds and output steps).
#include <vector>

namespace polydem {

template <class T, class A>
void release(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace polydem
