#pragma once
// The critical time step of the contact law and the step a run uses.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "contact/law.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"
#include "sim/step_accuracy.hpp"

namespace polydem {

// Which oscillator of the contact law sets the critical step.
enum class StepMode { kNormal, kTangential, kRolling };
const char* step_mode_name(StepMode mode);  // "normal", "tangential", "rolling"

struct TimeStepEstimate {
  double critical = 0.0;      // s, stability limit of the fastest contact oscillator (normal, tangential, rolling)
  double critical_normal = 0.0;  // s, the limit of the normal spring-dashpot alone
  double chosen = 0.0;        // s, the step the run uses
  double m_eff = 0.0;         // kg, smallest effective mass of a normal force at a contact point (rotation included)
  double m_tangential = 0.0;  // kg, smallest effective mass of a tangential force (lever to the rounded surface)
  StepMode mode = StepMode::kNormal;
  double impact_speed = 0.0;  // m/s, the fastest impact expected (expected_impact_speed)
  double kn_particle = 0.0, kn_driver = 0.0;  // N/m, normal stiffness the limits took (Hertz: at that impact)
  ImpactModel model;  // which measured impacts bound the scene's (step_accuracy.hpp)
};

// m/s, the fastest impact a scene expects, for laws whose stiffness grows with the overlap
// (Hertz): the fastest body surface at the start plus a free fall over the scene's height
// along gravity (body centres and driver reference points), at least kMinImpactSpeed.
constexpr double kMinImpactSpeed = 0.1;  // m/s: a scene at rest still gets a finite step
class Drivers;
double expected_impact_speed(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers,
                             const Vec3& gravity);

// A fraction of the critical step: w0 dt <= 0.2 on the lightest contact-point mass, less on
// heavier contacts; a single impact's restitution is then 0.1-0.25% off (tools/bench/accuracy).
// Where every contact takes the linear law's exact step, spheres meet under Hertz, or a body is
// a polyhedron, `dt: auto` takes the step of kAutoAccuracy instead, and simulation: accuracy picks another fraction (sim/step_accuracy.hpp).
// A given step above kUnsafeFraction draws a warning, and `accuracy` never picks more.
constexpr double kAutoFraction = 0.1;
constexpr double kUnsafeFraction = 0.3;

// The smallest of the velocity Verlet limits of the normal spring-dashpot, the tangential
// spring and the rolling spring, each on the smallest mass (or inertia) it meets at any
// contact point of any body; pairs of bodies halve it, a driver does not. Each law's normal
// part gives its stiffness at an impact at `impact_speed` (m/s; two bodies close at twice it).
// The step: given_dt, else the fraction of the limit whose expected restitution error is
// within `accuracy` under `model` (accuracy_fraction), else auto_fraction(model) of the limit.
TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt, double impact_speed = kMinImpactSpeed,
                                    std::optional<double> accuracy = std::nullopt, ImpactModel model = {});

// A warning line ("" when none) for a given step above kUnsafeFraction of the critical one.
std::string unsafe_step_warning(const TimeStepEstimate& t);

// Impacts too fast for the contact law: a body hitting at speed v overlaps about
// v sqrt(m/kn) (the undamped bound, m_eff <= m); beyond kOverlapFraction of its inscribed
// radius the contact is unphysical (tools/stress: a sphere of radius 5 mm at 100 m/s overlaps
// 8.5 mm) and a body past its centre goes through a thin STL sheet.
constexpr double kOverlapFraction = 0.5;

// m, radius of the largest ball centred at the centre of mass inside the rounded body:
// the rounding plus the distance to the nearest face plane (0 for a body without faces).
double inscribed_radius(const Shape& shape, double scale);

struct PairList;

// A start-up warning line ("" when none) for the body whose closing speed is furthest above
// the speed its contacts allow: its surface speed |v| + |w| r_bound plus the fastest other
// body or the driver surface at its centre. Allowed: kOverlapFraction r_in sqrt(kn/m)
// (overlap), and r_in/dt (the body moves its inscribed radius in one step: nothing stops it
// before its centre is past a thin sheet).
std::string fast_impact_warning(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers,
                                double kn_particle, double kn_driver, double dt);

// The run-time watch: scans the active contacts (every output row, not every step) and
// reports once an overlap deeper than kOverlapFraction of the smaller inscribed radius.
class OverlapWatch {
 public:
  // A too-deep contact: where it comes in one process's scan (body pairs, then driver pairs,
  // each by (i, j) in global ids) and its warning line.
  struct Deep {
    std::array<std::uint64_t, 2> key;
    std::string warning;
  };
  // A rank's lists: its local ids' global ids, and which are ghosts (pairs whose lower body is
  // a ghost are its owner's to check).
  struct Local {
    const std::vector<std::uint32_t>* global_id;
    const std::vector<std::uint8_t>* ghost;
  };

  OverlapWatch(const Bodies& bodies, const std::vector<Shape>& shapes);
  // A warning line the first time an active contact of the lists is too deep, else "".
  std::string check(const PairList& body_pairs, const PairList& driver_pairs, const Drivers& drivers, double kn_particle,
                    double kn_driver, double time);
  // The first too-deep active contact of the lists, if any (whether warned or not).
  std::optional<Deep> first_deep(const PairList& body_pairs, const PairList& driver_pairs, const Drivers& drivers,
                                 double kn_particle, double kn_driver, double time, Local local = {}) const;
  bool warned() const { return warned_; }
  void set_warned() { warned_ = true; }

 private:
  std::vector<double> radius_;  // m, inscribed radius per body
  std::vector<std::uint32_t> id_;  // the user id per body (the warning names it)
  bool warned_ = false;
};

}  // namespace polydem
