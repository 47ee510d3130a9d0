#pragma once
// The critical time step of the contact law and the step a run uses.
#include <optional>
#include <vector>

#include "contact/law.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"

namespace polydem {

struct TimeStepEstimate {
  double critical = 0.0;  // s, stability limit 2/omega of the stiffest contact on the lightest mass
  double chosen = 0.0;    // s, the step the run uses
  double m_eff = 0.0;     // kg, smallest effective mass at a contact point (rotational included)
};

// A fraction of the critical step that resolves a binary impact with ~16 steps: restitution
// within 1%. A given step above kUnsafeFraction of the critical one draws a warning.
constexpr double kAutoFraction = 0.1;
constexpr double kUnsafeFraction = 0.3;

// The smallest mass a contact force meets: 1/m_rot = 1/m + l^2/I_min with l the bounding
// radius (a vertex far from the centre is lighter than the body). Pairs of bodies halve it.
TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt);

}  // namespace polydem
