#pragma once
// Builds the fluid grid a scene asks for: read from a .vti file or filled from the analytic
// fields of `fluid_field`, with the derived fields its operators need.
#include "field/fluid_grid.hpp"
#include "field/field_settings.hpp"

namespace polydem {

struct FluidNeeds {
  bool U = false, p = false, rho = false, nu = false;  // arrays the operators read
  bool grad_p = false, div_tau = false;                // derived fields
};

// What the scene's operators read from the fluid.
FluidNeeds fluid_needs(const FieldSettings& forces);

// Throws InputError "SCENE:LINE: key 'file': PATH: what is wrong" for a bad file or a missing
// array. A .vti's CellData are cell values; PointData points are taken as cell centres (the
// grid extends half a spacing beyond the outer points). rho and nu given in the scene fill in
// for arrays the file lacks.
FluidGrid make_fluid_grid(const FieldSettings::FluidField& settings, const FluidNeeds& needs);

}  // namespace polydem
