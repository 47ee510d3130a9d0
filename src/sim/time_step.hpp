#pragma once
// The critical time step of the contact law and the step a run uses.
#include <optional>
#include <vector>

#include "contact/law.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"

namespace polydem {

struct TimeStepEstimate {
  double critical = 0.0;  // s, stability limit of the stiffest damped contact on the lightest mass
  double chosen = 0.0;    // s, the step the run uses
  double m_eff = 0.0;     // kg, smallest effective mass at a contact point (rotational included)
};

// A fraction of the critical step: w0 dt <= 0.2 on the lightest contact-point mass, less on
// heavier contacts; the half-step dashpot velocity then costs 1-3% of restitution on a single
// impact (tools/bench/accuracy: 1% needs 0.03-0.07). A given step above kUnsafeFraction draws a warning.
constexpr double kAutoFraction = 0.1;
constexpr double kUnsafeFraction = 0.3;

// The smallest mass a contact force meets at any vertex of any body (a vertex far from the
// centre is lighter than the body); pairs of bodies halve it.
TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt);

}  // namespace polydem
