#pragma once
// Rolling part (SPEC "rolling resistance"): a moment spring mr (history, N m) grows by
// -kr_w w_rel dt, capped at mur l fp (l the lever from i's centre to the contact, m).
// Coefficients: LawParams::kr (N m/rad), mur (-); on when both > 0. Stored: |mr|^2/(2 kr_w);
// slip dissipates. Stability: 2 sqrt(I/kr) on the smallest inertia (sim/time_step.cpp).
#include "contact/law/tangential_spring.hpp"

namespace polydem {

// N m, the rolling moment on i after this step, loaded over `on` (s: the step, or the time since
// the touch where it starts); adds the slip (J) to `slip`. fp_at_slip(): the compressive force
// (N) to take where the spring passes the cap fp gives (capped_spring).
template <class AtSlip, class OnSlip>
[[gnu::always_inline]] inline void rolling_spring(const LawParams& law, const ContactKinematics& k, double fp,
                                                  double on, ContactHistory& h, double& slip, const AtSlip& fp_at_slip,
                                                  const OnSlip& on_slip) {
  const double kr_w = k.weight * law.kr;
  const double lever_mu = law.mur * k.lever;  // m
  slip = capped_spring(h.mr, -kr_w * on * k.w_rel, kr_w, lever_mu * fp, [&](double) { return lever_mu * fp_at_slip(); },
                       on_slip);
}

}  // namespace polydem
