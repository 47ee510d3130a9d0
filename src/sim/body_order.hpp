#pragma once
// Where each body sits in the run's arrays (issue 19): in space order, so the bodies a pair
// loop meets together are near in memory, or in the scene's order. An order lists, per index
// of the arrays, the body's user id (its place in the scene's body list, what files and
// messages name it by); it is made once, when a fresh run builds its bodies, and a checkpoint
// keeps it (sim/checkpoint.cpp), so a resumed run continues in the same order.
#include <cstdint>
#include <vector>

#include "io/scene_settings.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape_library.hpp"

namespace polydem {

// The user ids sorted by cell (cubes of the largest body's bounding diameter), z then y then
// x, then by id: the same order for any thread or rank count.
std::vector<std::uint32_t> spatial_order(const std::vector<BodySpec>& specs, const ShapeLibrary& library);

// 0, 1, ..., n - 1: the scene's order.
std::vector<std::uint32_t> identity_order(std::size_t n);

// Whether `order` holds each of 0 .. n - 1 once.
bool is_order_of(const std::vector<std::uint32_t>& order, std::size_t n);

// specs[order[0]], specs[order[1]], ...
std::vector<BodySpec> in_order(std::vector<BodySpec> specs, const std::vector<std::uint32_t>& order);

// The indices `of` sorted by user id (all bodies: Bodies::by_user_id).
std::vector<std::uint32_t> by_user_id(const Bodies& bodies, std::vector<std::uint32_t> of);

}  // namespace polydem
