// The brute-force reference: every feature pair of two bodies through the contact kernels.
#include <cstddef>
#include <cstdint>

#include "geometry/features.hpp"

namespace polydem {
namespace {

template <typename Visit>
void for_each_feature_pair(const Shape& a, const Shape& b, Visit visit) {
  const auto nva = a.vertices.size(), nvb = b.vertices.size();
  for (std::size_t i = 0; i < nva; ++i)
    for (std::size_t j = 0; j < nvb; ++j) visit(PairType::vertex_vertex, i, j);
  for (std::size_t i = 0; i < nva; ++i)
    for (std::size_t j = 0; j < b.edges.size(); ++j) visit(PairType::vertex_edge, i, j);
  for (std::size_t i = 0; i < a.edges.size(); ++i)
    for (std::size_t j = 0; j < nvb; ++j) visit(PairType::edge_vertex, i, j);
  for (std::size_t i = 0; i < nva; ++i)
    for (std::size_t j = 0; j < b.faces.size(); ++j) visit(PairType::vertex_face, i, j);
  for (std::size_t i = 0; i < a.faces.size(); ++i)
    for (std::size_t j = 0; j < nvb; ++j) visit(PairType::face_vertex, i, j);
  for (std::size_t i = 0; i < a.edges.size(); ++i)
    for (std::size_t j = 0; j < b.edges.size(); ++j) visit(PairType::edge_edge, i, j);
}

}  // namespace

std::vector<std::pair<FeaturePair, ContactPoint>> brute_force_contacts(const PosedBody& A, const PosedBody& B) {
  std::vector<std::pair<FeaturePair, ContactPoint>> contacts;
  for_each_feature_pair(*A.shape, *B.shape, [&](PairType type, std::size_t i, std::size_t j) {
    const FeaturePair pair{type, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(j)};
    ContactPoint c;
    if (feature_contact(A, B, pair, 0.0, c)) contacts.emplace_back(pair, c);
  });
  return contacts;
}

}  // namespace polydem
