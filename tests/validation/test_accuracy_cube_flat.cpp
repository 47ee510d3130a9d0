// The cube-flat rows of issue 16's table (cube_flat_cases.hpp): a cube landing flat on a wall
// against en (face-face, no rotation) and landing tilted 1e-3 rad against the same landing at
// 0.002 x critical, each the worst of 8 places of the touch in its step, at 0.1 and 0.3 x
// critical (the goals: 0.3% and 1.5%) and the observed order between 0.1 and 0.05 (goal 1.8).
// The cube takes its default step (the pair's mass, the end-of-step dashpot).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "cube_flat_cases.hpp"

using namespace polydem::validation::accuracy;

TEST_CASE("accuracy: cube landing flat rebounds at en, at 0.1 and 0.3 x critical, second order", "[validation][second_order]") {
  const double at_auto = cube_flat_error(0.1), at_03 = cube_flat_error(0.3), at_005 = cube_flat_error(0.05);
  const double order = std::log2(at_auto / at_005);
  std::printf("cube flat, worst of 8 touch places: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", at_auto, at_03, order);
  // Measured 3.1e-4 at 0.1, 4.7e-3 at 0.3, order 2.29, the same at each of the 8 touch places.
  CHECK(at_auto <= 3e-3);
  CHECK(at_03 <= 0.015);
  CHECK(order >= 1.8);
  CHECK(cube_flat_error(0.01) < 1e-5);  // measured 2.2e-6: en itself, not a nearby value
}

TEST_CASE("accuracy: cube landing tilted 1e-3 rad against its converged landing, at 0.1 and 0.3 x critical", "[validation][second_order]") {
  // The answer converges: 0.001 against 0.002 x critical differ by 7e-7 of v0 (vz' and spin).
  const CubeRebound fine = cube_face_landing(0.001, kTilt, kTiltSpeed, 0.5), ref = cube_face_landing(0.002, kTilt, kTiltSpeed, 0.0);
  CHECK(std::abs(fine.vz - ref.vz) < 1e-5 * kTiltSpeed);
  CHECK(0.5 * kCubeSide * std::abs(fine.spin - ref.spin) < 1e-5 * kTiltSpeed);
  // The tilt turns a share of the landing into spin: the centre rebounds below en v0.
  CHECK(ref.vz < 0.95 * kEn * kTiltSpeed);
  CHECK(ref.spin > 1.0);  // rad/s, measured 4.12
  const double at_auto = cube_tilted_error(0.1), at_03 = cube_tilted_error(0.3), at_005 = cube_tilted_error(0.05);
  const double order = std::log2(at_auto / at_005);
  std::printf("cube tilted 1e-3 rad, worst of 8 touch places: error %.2e at 0.1, %.2e at 0.3, order %.2f\n", at_auto,
              at_03, order);
  // Measured 8.23e-4 at 0.1, 7.08e-3 at 0.3, order 1.98 (the patch's pushes, patch_push.hpp;
  // acc20's onsets alone: 8.16e-4, 7.39e-3, order 1.78).
  CHECK(at_auto <= 3e-3);
  CHECK(at_03 <= 0.015);
  CHECK(order >= 1.8);
}

TEST_CASE("accuracy: under damping_mass: contact a cube landing flat rebounds at en too", "[validation][second_order]") {
  // The four corners act as one patch (one spring kn): their dashpot takes the mass at the
  // patch's centre, the whole cube's. Each corner's own point mass (m/4) rebounded at 0.672.
  const double at_auto = cube_flat_error(0.1, 8, true), at_03 = cube_flat_error(0.3, 8, true);
  std::printf("cube flat, damping_mass: contact: error %.2e at 0.1, %.2e at 0.3\n", at_auto, at_03);
  CHECK(at_auto <= 3e-3);
  CHECK(at_03 <= 0.015);
  CHECK(cube_flat_error(0.01, 2, true) < 1e-4);
}

TEST_CASE("accuracy: a cube landing almost flat, its far edge joining mid-contact, is second order against the RK4 patch", "[validation][second_order]") {
  // The far edge's two vertices join the near edge's patch within a step of the touch (kJoinGap):
  // their start is no onset of the patch's force, but each share moves (patch_push.hpp).
  const double at_auto = cube_join_error(0.1), at_005 = cube_join_error(0.05), at_0025 = cube_join_error(0.025);
  const double at_03 = cube_join_error(0.3);
  const double order = std::log2(at_auto / at_005), order_fine = std::log2(at_005 / at_0025);
  std::printf("cube joining edge, worst of 8 touch places: error %.2e at 0.1, %.2e at 0.05, %.2e at 0.025, order %.2f, %.2f; %.2e at 0.3\n",
              at_auto, at_005, at_0025, order, order_fine, at_03);
  // Measured 9.90e-4 at 0.1, 3.09e-4 at 0.05, 7.34e-5 at 0.025: order 1.68, then 2.07 (acc20's
  // onsets alone: 1.44e-3, 5.04e-4, 1.03e-4, order 1.51). patch_push.hpp integrates the moving
  // shares' impulse; still open (issue 16): the cube turns within the join step, which the drift
  // at v(n+1/2) misses, a first-order angle error ~ lag x touch time (orders 1.2-1.4 at gaps of
  // 5e-8 to 1e-7 m). The 1.8 waits for a position correction of the join step.
  CHECK(at_auto <= 3e-3);
  CHECK(at_03 <= 0.015);  // the cube rows' goal; measured 3.99e-3
  CHECK(order >= 1.6);
  CHECK(order_fine >= 1.8);
}
