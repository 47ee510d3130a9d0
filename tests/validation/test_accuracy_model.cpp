// The error `polydem check` prints at a step (sim/step_accuracy.cpp, under the model the engine
// picks for the scene) bounds the errors of the accuracy cases run at that step: the cube
// landings for polyhedra, the oblique impact for friction, Hertz's sphere-wall impacts for Hertz
// (tools/bench/accuracy). At fractions on the model's points and between them: 0.1 (dt: auto
// but for frictionless spheres), 0.181 (theirs), 0.25-0.27 (the samples': 0.251, 0.266), 0.3 (the cap).
#include <catch2/catch.hpp>

#include <string>

#include "cube_flat_cases.hpp"
#include "sim/step_accuracy.hpp"

using namespace polydem;
using namespace polydem::validation;
using namespace polydem::validation::accuracy;

namespace {

constexpr double kFractions[] = {0.1, 0.12, 0.181, 0.25, 0.251, 0.266, 0.27, 0.3};

// The model the engine picks for one body of `shape` over a floor under `config`.
ImpactModel scene_model(const ContactParams& config, const Shape& shape) {
  const Scene scene = base_scene(config, true);
  return Simulation(scene, library({shape}), {body(shape.name.c_str(), {0, 0, 0.1})}).time_step().model;
}

// The error printed at dt = fraction x critical, as `polydem check` prints it.
double printed_error(double fraction, ImpactModel model) {
  const std::string note = impact_error_note(fraction, 1.0, model);
  return std::stod(note.substr(note.find(": ") + 2));
}

}  // namespace

TEST_CASE("accuracy model: a cube scene's printed error bounds the cube landings at its step", "[validation][step_accuracy]") {
  const ImpactModel model = scene_model(law(kKn, kEn), cube_shape(kCubeSide, kCubeRounding));
  CHECK((model.polyhedra && !model.exact && !model.friction && !model.hertz));
  for (double f : kFractions) {
    const double printed = printed_error(f, model);
    const double flat = cube_flat_error(f), tilted = cube_tilted_error(f), corner = cube_corner_error(f, false, true);
    std::printf("cube at %.3g x critical: printed %.1e; flat %.2e, tilted %.2e, corner %.2e\n", f, printed, flat,
                tilted, corner);
    INFO("dt = " << f << " x critical");
    CHECK(flat <= printed);
    CHECK(tilted <= printed);
    CHECK(corner <= printed);
  }
}

TEST_CASE("accuracy model: a frictional sphere scene's printed error bounds the oblique impact at its step", "[validation][step_accuracy]") {
  const ImpactModel model = scene_model(law(kKn, kEn, 0.3, kKn), sphere_shape(kRadius));
  CHECK((model.exact && model.friction && !model.polyhedra));
  for (double f : kFractions) {
    const double printed = printed_error(f, model), oblique = oblique_impact_worst_phase(f);
    const double normal = binary_impact_worst_phase(f, kEn);
    std::printf("oblique at %.3g x critical: printed %.1e; worst touch place %.2e, normal %.2e\n", f, printed, oblique,
                normal);
    INFO("dt = " << f << " x critical");
    CHECK(oblique <= printed);
    CHECK(normal <= printed);
  }
  // Its error spikes (up to 2x, narrower than 1e-4 x critical) between the table's points:
  // every 0.0013 x critical from 0.05 to 0.3 (off the points' 0.005 grid), 193 steps of 16 impacts.
  for (int k = 0; k <= 192; ++k) {
    const double f = 0.05 + 0.0013 * k;
    INFO("dt = " << f << " x critical");
    CHECK(oblique_impact_worst_phase(f) <= printed_error(f, model));
  }
}

TEST_CASE("accuracy model: a Hertz scene's printed error bounds its sphere-wall impacts at its step", "[validation][step_accuracy]") {
  const ImpactModel model = scene_model(hertz_law(kEn), sphere_shape(kRadius));
  CHECK((model.hertz && !model.exact && !model.friction));
  for (double f : kFractions)
    for (double en : {0.1, 0.5, 0.9}) {
      const double printed = printed_error(f, model), error = hertz_impact(f, en);
      std::printf("Hertz en %.1f at %.3g x critical: printed %.1e, worst touch place %.2e\n", en, f, printed, error);
      INFO("dt = " << f << " x critical, en = " << en);
      CHECK(error <= printed);
    }
}
