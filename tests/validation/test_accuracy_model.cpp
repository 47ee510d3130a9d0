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

// damping_mass: contact (issue 16): the same landings with the dashpot on the contact point's
// mass, stepped exactly, take their own table (kCubesContactMass): bounded at the printed step too.
TEST_CASE("accuracy model: a contact-mass cube scene's printed error bounds its landings at its step", "[validation][step_accuracy]") {
  ContactParams config = law(kKn, kEn);
  config.damping_contact_mass = true;
  const ImpactModel model = scene_model(config, cube_shape(kCubeSide, kCubeRounding));
  CHECK((model.polyhedra && model.contact_mass && !model.exact && !model.friction && !model.hertz));
  for (double f : kFractions) {
    const double printed = printed_error(f, model);
    const double flat = cube_flat_error(f, 8, true), tilted = cube_tilted_error(f, 8, true),
                 corner = cube_corner_error(f, true, true);
    std::printf("contact-mass cube at %.3g x critical: printed %.1e; flat %.2e, tilted %.2e, corner %.2e\n", f,
                printed, flat, tilted, corner);
    INFO("dt = " << f << " x critical");
    CHECK(flat <= printed);
    CHECK(tilted <= printed);
    CHECK(corner <= printed);
  }
}

// dt: auto under damping_mass: contact: the step of 1e-3 by the contact-mass landings, about
// twice the pair's-mass 0.0654, and the landings run at that step stay within 1e-3: the tilted
// cube against its landing at 0.002 x critical, the corner against the rigid body integrated with
// the law (corner_reference.hpp), the flat one against en.
TEST_CASE("accuracy model: dt: auto under damping_mass: contact keeps the cube landings within 1e-3", "[validation][step_accuracy]") {
  ContactParams config = law(kKn, kEn);
  config.damping_contact_mass = true;
  const Shape cube = cube_shape(kCubeSide, kCubeRounding);
  const Scene scene = base_scene(config, true);
  const TimeStepEstimate t = Simulation(scene, library({cube}), {body(cube.name.c_str(), {0, 0, 0.1})}).time_step();
  const double f = t.chosen / t.critical;
  const ImpactModel pair_mass{.polyhedra = true};
  std::printf("contact-mass cube: dt: auto %.4g x critical (pair's mass %.4g)\n", f, auto_fraction(pair_mass));
  CHECK(t.model.contact_mass);
  CHECK(expected_restitution_error(f, t.model) == Approx(kAutoAccuracy).epsilon(1e-9));
  CHECK(f > 1.5 * auto_fraction(pair_mass));  // the corner no longer binds: the tilted cube does, later
  const double flat = cube_flat_error(f, 8, true), tilted = cube_tilted_error(f, 8, true), corner = cube_corner_error(f, true, true);
  std::printf("  at it: flat %.3e, tilted %.3e, corner %.3e\n", flat, tilted, corner);
  CHECK(flat <= kAutoAccuracy);
  CHECK(tilted <= kAutoAccuracy);
  CHECK(corner <= kAutoAccuracy);
}

// The model takes the contact-mass landings only where every law the cubes' contacts take has
// damping_mass: contact and the exact step: two cubes over a floor with it in config alone, in
// config_driver alone, in both, and under Hertz. The pair's-mass scene keeps 0.0654.
TEST_CASE("accuracy model: the contact-mass landings only where every law the polyhedra take has it", "[validation][step_accuracy]") {
  const Shape cube = cube_shape(kCubeSide, kCubeRounding);
  auto two_cubes = [&](bool particle, bool driver, bool hertz) {
    Scene scene = base_scene(hertz ? hertz_law(kEn) : law(kKn, kEn), true);
    scene.forces.contact.config.damping_contact_mass = particle;
    scene.forces.contact.config_driver.damping_contact_mass = driver;
    return Simulation(scene, library({cube}), {body(cube.name.c_str(), {0, 0, 0.1}), body(cube.name.c_str(), {0, 0, 0.2})})
        .time_step();
  };
  const TimeStepEstimate both = two_cubes(true, true, false), pair = two_cubes(false, false, false);
  CHECK(both.model.contact_mass);
  CHECK(!pair.model.contact_mass);
  CHECK(!two_cubes(true, false, false).model.contact_mass);
  CHECK(!two_cubes(false, true, false).model.contact_mass);
  CHECK(!two_cubes(true, true, true).model.contact_mass);  // Hertz's dashpot is not stepped exactly
  CHECK(pair.chosen / pair.critical == Approx(0.0654).margin(0.0005));
  CHECK(both.chosen / both.critical > 1.5 * pair.chosen / pair.critical);
}
