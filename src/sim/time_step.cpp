#include "sim/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Eigenvalues>

#include "driver/drivers.hpp"
#include "contact/contact_lists.hpp"
#include "sim/step_accuracy.hpp"

namespace polydem {

namespace {

// 1/kg and 1/(kg m^2), the largest compliances a contact on one body offers.
struct Compliance {
  double normal = 0.0;      // 1/m + max (r x n)^T I^-1 (r x n)
  double tangential = 0.0;  // 1/m + max (r x t)^T I^-1 (r x t), t perpendicular to n
  double rolling = 0.0;     // largest eigenvalue of I^-1: a moment about the softest axis
};

// 1/(kg m^2), largest eigenvalue of I^-1 (diagonal, principal frame) in the plane normal to v.
double plane_compliance(const Mat3& inv_inertia, const Vec3& v) {
  const Vec3 e1 = v.unitOrthogonal(), e2 = v.normalized().cross(e1);
  Eigen::Matrix2d plane;
  plane << e1.dot(inv_inertia * e1), e1.dot(inv_inertia * e2), e2.dot(inv_inertia * e1), e2.dot(inv_inertia * e2);
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(plane).eigenvalues().maxCoeff();
}

// A contact point is r = p + R n, p on the core (the quadratic forms below are convex in p,
// so a vertex v is the worst point of its faces and edges), n the unit normal, R the rounding.
// Normal force: r x n = v x n, perpendicular to v, so (r x n)^T I^-1 (r x n) <= |v|^2 lp(v),
// lp the largest eigenvalue of I^-1 in the plane normal to v (reached when v x n spans it).
// Tangential force t: r x t = v x t + R n x t; the first term lies in the plane normal to v,
// the second anywhere, so by Cauchy-Schwarz in the I^-1 norm
// (r x t)^T I^-1 (r x t) <= (|v| sqrt(lp(v)) + R sqrt(l_max))^2, reached when n is along v
// (then |r| = |v| + R); a sphere (v = 0) gives 1/m + R^2/I = 3.5/m.
Compliance body_compliance(const Shape& shape, double scale, double mass, const Vec3& inertia) {
  const Mat3 inv_inertia = inertia.cwiseInverse().asDiagonal();
  const double l_max = inertia.cwiseInverse().maxCoeff();  // 1/(kg m^2)
  const double rounding = shape.radius * scale;            // m
  Compliance c;
  c.rolling = l_max;
  double normal = 0.0, tangential = rounding * rounding * l_max;  // 1/kg, rotational parts
  for (const Vec3& vertex : shape.vertices) {
    const Vec3 v = vertex * scale;
    if (v.squaredNorm() == 0.0) continue;  // a sphere's centre: no core lever
    const double lp = plane_compliance(inv_inertia, v);
    normal = std::max(normal, v.squaredNorm() * lp);
    const double lever = v.norm() * std::sqrt(lp) + rounding * std::sqrt(l_max);  // sqrt(1/kg)
    tangential = std::max(tangential, lever * lever);
  }
  c.normal = 1.0 / mass + normal;
  c.tangential = 1.0 / mass + tangential;
  return c;
}

struct Limit {
  double dt = std::numeric_limits<double>::infinity();  // s
  StepMode mode = StepMode::kNormal;
  void take(double candidate, StepMode m) {
    if (candidate < dt) { dt = candidate; mode = m; }
  }
};

// The limits of one law on the smallest masses m_n, m_t (kg) and inertia i_r (kg m^2) its
// contacts meet. Normal: the damped limit 2/w0 (sqrt(1 + a^2) - a), w0 = sqrt(kn/m_n).
// Tangential: the spring kt on m_t (the Coulomb cap only softens it), active only with
// friction (mu > 0), with the dashpot 2 alpha_t sqrt(kt m) of damp_tangential (m the pair's
// mass, kg) acting on m_t: ratio alpha_t sqrt(m/m_t); 2 sqrt(m_t/kt) without it. Rolling: the
// spring kr (N m/rad) on i_r, no dashpot: 2 sqrt(i_r/kr). `normal` keeps the normal mode alone
// (polydem check).
// What the normal part stiffens to at the expected impact (N/m, normal and tangential).
struct Stiffness {
  double normal, tangential;
};

// The normal part's stiffness at an impact of mass m (kg) at v (m/s) with curvature r_star (m).
Stiffness impact_stiffness(const LawParams& law, double m, double v, double r_star) {
  return with_normal(law, [&](auto parts) {
    using Normal = typename decltype(parts)::Normal;
    return Stiffness{Normal::impact_stiffness(law, m, v, r_star), Normal::impact_tangential_stiffness(law, m, v, r_star)};
  });
}

void take_law(Limit& limit, Limit& normal, const LawParams& law, const Stiffness& k, double m, double m_n, double m_t,
              double i_r) {
  if (k.normal > 0.0) normal.take(critical_time_step(k.normal, m_n, law.alpha_n), StepMode::kNormal);
  limit.take(normal.dt, StepMode::kNormal);
  if (k.tangential > 0.0 && law.mu > 0.0)
    limit.take(critical_time_step(k.tangential, m_t, law.alpha_t * std::sqrt(m / m_t)), StepMode::kTangential);
  if (law.rolling) limit.take(critical_time_step(law.kr, i_r), StepMode::kRolling);
}

}  // namespace

const char* step_mode_name(StepMode mode) {
  switch (mode) {
    case StepMode::kNormal: return "normal";
    case StepMode::kTangential: return "tangential";
    case StepMode::kRolling: return "rolling";
  }
  return "normal";
}

TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt, double impact_speed,
                                    std::optional<double> accuracy, ImpactModel model) {
  Compliance worst;
  double lightest = std::numeric_limits<double>::infinity();  // kg
  double heaviest = 0.0, rounding = 0.0;  // kg, m (largest rounding radius: the stiffest Hertz contact)
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Compliance c = body_compliance(shapes[bodies.shape[b]], bodies.scale[b], bodies.mass[b], bodies.inertia[b]);
    worst.normal = std::max(worst.normal, c.normal);
    worst.tangential = std::max(worst.tangential, c.tangential);
    worst.rolling = std::max(worst.rolling, c.rolling);
    lightest = std::min(lightest, bodies.mass[b]);
    heaviest = std::max(heaviest, bodies.mass[b]);
    rounding = std::max(rounding, shapes[bodies.shape[b]].radius * bodies.scale[b]);
  }
  const double m_n = 1.0 / worst.normal, m_t = 1.0 / worst.tangential, i_r = 1.0 / worst.rolling;
  Limit limit, normal;
  TimeStepEstimate e;
  // The deepest impact: the heaviest bodies at the expected speed; two of them close at twice
  // it, with half the mass and the largest rounding halved (R* = r/2).
  const Stiffness k_particle = impact_stiffness(particle, 0.5 * heaviest, 2.0 * impact_speed, 0.5 * rounding);
  const Stiffness k_driver = driver ? impact_stiffness(*driver, heaviest, impact_speed, rounding) : Stiffness{};
  // Two bodies of the smallest mass in contact: the relative motion meets half of it.
  if (bodies.size() > 1) take_law(limit, normal, particle, k_particle, 0.5 * lightest, 0.5 * m_n, 0.5 * m_t, 0.5 * i_r);
  if (driver) take_law(limit, normal, *driver, k_driver, lightest, m_n, m_t, i_r);  // a driver has infinite mass
  e.impact_speed = impact_speed;
  e.kn_particle = k_particle.normal;
  e.kn_driver = driver ? k_driver.normal : k_particle.normal;
  e.m_eff = m_n;
  e.m_tangential = m_t;
  e.critical = limit.dt;
  e.critical_normal = normal.dt;
  e.mode = limit.mode;
  e.model = model;
  if (given_dt)
    e.chosen = *given_dt;
  else
    e.chosen = (accuracy ? accuracy_fraction(*accuracy, model) : auto_fraction(model)) * limit.dt;
  return e;
}

std::string unsafe_step_warning(const TimeStepEstimate& t) {
  if (!(t.chosen > kUnsafeFraction * t.critical)) return "";
  char line[400];
  std::snprintf(line, sizeof(line),
                "warning: dt = %.3g s is %.2g x the critical step %.3g s (above %.2g): the run may be "
                "inaccurate or blow up; use dt: auto or dt <= %.3g s",
                t.chosen, t.chosen / t.critical, t.critical, kUnsafeFraction, kAutoFraction * t.critical);
  return line;
}

double expected_impact_speed(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers,
                             const Vec3& gravity) {
  double fastest = 0.0;  // m/s
  const double g = gravity.norm();  // m/s^2
  const Vec3 down = g > 0.0 ? Vec3(gravity / g) : Vec3::Zero();
  double low = std::numeric_limits<double>::infinity(), high = -low;  // m, along `down`
  auto extend = [&](const Vec3& x) { low = std::min(low, x.dot(down)); high = std::max(high, x.dot(down)); };
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    fastest = std::max(fastest, bodies.velocity[b].norm() + bodies.angular_velocity[b].norm() *
                                                                shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
    extend(bodies.position[b]);
  }
  for (std::uint32_t j = 0; j < drivers.size(); ++j) extend(drivers.center(j));
  const double height = high > low ? high - low : 0.0;  // m
  return std::max(fastest + std::sqrt(2.0 * g * height), kMinImpactSpeed);
}


double inscribed_radius(const Shape& shape, double scale) {
  double core = shape.faces.empty() ? 0.0 : std::numeric_limits<double>::infinity();  // m
  for (std::size_t f = 0; f < shape.faces.size(); ++f)
    core = std::min(core, shape.face_normals[f].dot(shape.vertices[shape.faces[f][0]]));
  return (shape.radius + std::max(core, 0.0)) * scale;
}

namespace {

// m/s, fastest point of body b's surface.
double surface_speed(const Bodies& bodies, const std::vector<Shape>& shapes, std::size_t b) {
  return bodies.velocity[b].norm() + bodies.angular_velocity[b].norm() * shapes[bodies.shape[b]].bounding_radius * bodies.scale[b];
}

// m/s, speed driver j's motion will give its surface at point x (its velocity is set only
// once it advances): translation plus rotation about its axis.
double driver_speed_at(const MotionSettings& m, const Vec3& x) {
  const Vec3 spin = m.rotates ? Vec3(m.omega * m.rotation_axis) : Vec3::Zero();  // rad/s
  return (m.velocity + spin.cross(x - m.rotation_center)).norm();
}

std::string format(const char* fmt, auto... args) {
  char buf[640];
  std::snprintf(buf, sizeof(buf), fmt, args...);
  return buf;
}

}  // namespace

std::string fast_impact_warning(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers,
                                double kn_particle, double kn_driver, double dt) {
  const std::size_t n = bodies.size();
  std::vector<double> speed(n);
  double top = 0.0, second = 0.0;  // m/s, the two fastest bodies: the partner of the fastest is the second
  for (std::size_t b = 0; b < n; ++b) {
    speed[b] = surface_speed(bodies, shapes, b);
    second = std::max(second, std::min(top, speed[b]));
    top = std::max(top, speed[b]);
  }
  double worst = 1.0;  // closing speed / allowed speed
  std::string message;
  for (std::size_t b = 0; b < n; ++b) {
    const double other = speed[b] == top ? second : top;  // m/s
    double driver_speed = 0.0;                              // m/s, the fastest driver surface at the body
    long driver = -1;
    for (std::uint32_t j = 0; j < drivers.size(); ++j) {
      const double v = driver_speed_at(drivers.motion(j), bodies.position[b]);
      if (drivers[j].active && (driver < 0 || v > driver_speed)) { driver_speed = v; driver = j; }
    }
    const bool by_driver = driver >= 0 && (n == 1 || driver_speed >= other);
    const double closing = speed[b] + (by_driver ? driver_speed : (n > 1 ? other : 0.0));
    const double kn = by_driver ? kn_driver : kn_particle;
    const double r_in = inscribed_radius(shapes[bodies.shape[b]], bodies.scale[b]);
    const double by_overlap = kOverlapFraction * r_in * std::sqrt(kn / bodies.mass[b]), by_step = r_in / dt;  // m/s
    const double allowed = std::min(by_overlap, by_step);
    if (closing <= worst * allowed) continue;
    worst = closing / allowed;
    const std::string who = format("warning: body %u (shape '%s') may hit %s at %.3g m/s", bodies.id[b], shapes[bodies.shape[b]].name.c_str(),
                                   by_driver ? ("driver '" + drivers.name(std::uint32_t(driver)) + "'").c_str()
                                                            : "another body", closing);
    if (by_overlap <= by_step) {
      const double kn_needed = bodies.mass[b] * std::pow(closing / (kOverlapFraction * r_in), 2);  // N/m
      message = who + format(": above %.3g m/s its overlap v sqrt(m/kn) exceeds %.2g x its inscribed radius %.3g mm "
                             "(unphysical; it may pass through a thin STL sheet): use kn >= %.3g N/m or lower speeds",
                             by_overlap, kOverlapFraction, 1e3 * r_in, kn_needed);
    } else {
      message = who + format(": above %.3g m/s it moves its inscribed radius %.3g mm in one step of %.3g s and may pass "
                             "through a thin STL sheet: use dt <= %.3g s or lower speeds",
                             by_step, 1e3 * r_in, dt, r_in / closing);
    }
  }
  return message;
}

OverlapWatch::OverlapWatch(const Bodies& bodies, const std::vector<Shape>& shapes)
    : radius_(bodies.size()), id_(bodies.id) {
  for (std::size_t b = 0; b < bodies.size(); ++b) radius_[b] = inscribed_radius(shapes[bodies.shape[b]], bodies.scale[b]);
}

std::string OverlapWatch::check(const PairList& body_pairs, const PairList& driver_pairs, const Drivers& drivers,
                                double kn_particle, double kn_driver, double time) {
  if (warned_) return "";
  const std::optional<Deep> deep = first_deep(body_pairs, driver_pairs, drivers, kn_particle, kn_driver, time);
  if (!deep) return "";
  warned_ = true;
  return deep->warning;
}

std::optional<OverlapWatch::Deep> OverlapWatch::first_deep(const PairList& body_pairs, const PairList& driver_pairs,
                                                           const Drivers& drivers, double kn_particle,
                                                           double kn_driver, double time, Local local) const {
  for (const PairList* list : {&body_pairs, &driver_pairs}) {
    const bool with_driver = list == &driver_pairs;
    for (std::size_t k = 0; k < list->size(); ++k) {
      const BodyPair p = list->pairs[k];
      if (local.ghost && (*local.ghost)[p.i]) continue;
      const std::uint32_t i = local.global_id ? (*local.global_id)[p.i] : p.i;
      const std::uint32_t j = local.global_id && !with_driver ? (*local.global_id)[p.j] : p.j;
      const double r = with_driver ? radius_[i] : std::min(radius_[i], radius_[j]);  // m
      for (std::uint32_t s = list->slot_begin[k]; s < list->slot_begin[k + 1]; ++s) {
        if (!list->active[s]) continue;  // only an active slot has a state in a sparse list
        const double overlap = -list->history(s).gap;  // m
        if (overlap <= kOverlapFraction * r) continue;
        const std::string partner = with_driver ? "driver '" + drivers.name(j) + "'" : format("body %u", id_[j]);
        return Deep{{(std::uint64_t(with_driver) << 32) | i, j},
                    format("warning: t = %.4g s: an overlap of %.3g mm between body %u and %s exceeds %.2g x the "
                           "inscribed radius %.3g mm: the impact is too fast for kn = %.3g N/m (unphysical; raise kn "
                           "or lower the speeds)",
                           time, 1e3 * overlap, id_[i], partner.c_str(), kOverlapFraction, 1e3 * r,
                           with_driver ? kn_driver : kn_particle)};
      }
    }
  }
  return std::nullopt;
}

}  // namespace polydem
