#pragma once
// Rigid-body time integration: velocity Verlet for translation, a symmetric splitting of the
// free rotor (NO_SQUISH, Miller et al. 2002, J. Chem. Phys. 116, 8649) for rotation.
// One engine step: kick(dt/2); drift(dt); compute forces; kick(dt/2).
// Preconditions: mass > 0 and every principal moment > 0 (massless bodies are drivers).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "integrate/free_rotor.hpp"
#include "integrate/pass_turn.hpp"
#include "polydem/bodies.hpp"
#include "polydem/parallel.hpp"
#include "polydem/shape.hpp"

namespace polydem {

// A body's rotation path, chosen once: the drift loop never tests inertia per body.
enum class Rotor {
  sphere,      // nothing reads its orientation: w alone, q the identity, L in the world frame
  isotropic,   // Ix == Iy == Iz: one exact rotation per step
  asymmetric,  // the 3,2,1,2,3 splitting
};

// A group's ids as runs of consecutive indices (a rank's owned bodies, between its ghosts in
// the store): run r holds ids[at[r]] .. ids[at[r + 1] - 1], the indices first[r], first[r] + 1, ...
struct IdRuns {
  std::vector<std::size_t> first, at;  // at: one more than first, at[0] = 0
};
IdRuns runs_of(const std::vector<std::size_t>& ids);

// Bodies sorted once by rotation path.
struct RotorGroups {
  std::vector<std::size_t> spheres;     // Rotor::sphere (only with the shapes known)
  std::vector<std::size_t> isotropic;   // Rotor::isotropic
  std::vector<std::size_t> asymmetric;  // Rotor::asymmetric
  // Each sphere has the same mass and inertia (a bed of equal spheres): the sphere passes read
  // one mass and inertia, not two arrays (32 bytes a body a pass, and h/m made once); in order,
  // spheres[k] == k (one process), they read no ids either.
  bool spheres_alike = false, spheres_in_order = false;
  // in_runs: the passes over a rank's store (not Bodies) walk each group by its runs, reading
  // no ids (with_runs).
  IdRuns sphere_runs, isotropic_runs, asymmetric_runs;
  bool in_runs = false;
};

// `groups` walked by runs (their ids made runs_of).
RotorGroups with_runs(RotorGroups groups);

// True when the principal moments agree within 1e-12 relative (sphere, cube, Platonic solid).
bool is_isotropic(const Vec3& inertia);

// True for a sphere: one vertex, at the centre of mass, and isotropic inertia. Its orientation
// moves nothing (R 0 = 0 for its vertex, R I R^T = I), so it is not integrated: it stays the
// identity, and L (body frame = world frame) is I w (README, "A sphere's orientation").
bool keeps_no_orientation(const Shape& shape, const Vec3& inertia);

// Recompute whenever inertia changes (bodies added or removed). Without the shapes no body
// takes Rotor::sphere (every orientation is integrated).
RotorGroups group_rotors(const Bodies& b);
RotorGroups group_rotors(const Bodies& b, const std::vector<Shape>& shapes);
// Per body, the instructions a step of its opening and closing passes (kicks, drift), by its
// group: what the contact stage's pass cut weighs (ContactEngine::weigh_passes).
std::vector<float> pass_weights(const RotorGroups& groups, std::size_t n);
// The same for the rows `rows` alone of `b` (Bodies, or a rank's LocalStore and its owned
// bodies' rows), in their order.
template <class B>
RotorGroups group_rotors(const B& b, const std::vector<std::uint32_t>& rows, const std::vector<Shape>& shapes);

// Sets the orientation of groups.spheres to the identity, turning L into the world frame
// (L_world = q L_body, w unchanged): at the start and after a state is read (checkpoints of
// polydem before this path kept turning quaternions). Bodies already at the identity keep
// their bits.
template <class B>  // Bodies, or a rank's LocalStore (its rows)
void drop_sphere_orientations(B& b, const RotorGroups& groups) {
  for (std::size_t i : groups.spheres) {
    if (b.orientation[i].coeffs() == Quat::Identity().coeffs()) continue;  // exact: -0 stays -0 in L
    b.angular_momentum[i] = b.orientation[i] * b.angular_momentum[i];
    b.orientation[i] = Quat::Identity();
  }
}

// v += F/m h; L_body += R^T torque h (a half kick with h = dt/2 in velocity Verlet).
void kick(Bodies& b, double h);
// The same by groups: an isotropic body's world w takes torque h / I directly (one rotation
// fewer per body); equal to kick(b, h) up to round-off.
void kick(Bodies& b, double h, const RotorGroups& groups);

// The addresses of the arrays a step's passes read and write, copied into each thread's loop:
// there they stay in registers. Read through Bodies' vectors, each access reloads the vector's
// address (Eigen's SSE stores may alias anything): ~44 instructions a body in start_step.
template <class Mass, class Inertia>
struct BodyArraysOf {
  Vec3* position;             // m
  Quat* orientation;
  Vec3* velocity;             // m/s
  Vec3* angular_velocity;     // rad/s
  Vec3* velocity_end;         // m/s
  Vec3* angular_velocity_end; // rad/s
  Vec3* angular_momentum;     // kg m^2/s, principal frame
  Vec3* force;                // N
  Vec3* torque;               // N m
  Mass mass;                  // kg, [i]
  Inertia inertia;            // kg m^2, [i]
};
using BodyArrays = BodyArraysOf<const double*, const Vec3*>;

// One mass and inertia for every body of a group, indexed as the arrays are (the same bits).
struct SameMass {
  double m;  // kg
  double operator[](std::size_t) const { return m; }
};
struct SameInertia {
  Vec3 inertia;  // kg m^2
  const Vec3& operator[](std::size_t) const { return inertia; }
};
using AlikeArrays = BodyArraysOf<SameMass, SameInertia>;

inline BodyArrays arrays_of(Bodies& b) {
  return {b.position.data(),         b.orientation.data(),      b.velocity.data(), b.angular_velocity.data(),
          b.velocity_end.data(),     b.angular_velocity_end.data(), b.angular_momentum.data(),
          b.force.data(),            b.torque.data(),           b.mass.data(),     b.inertia.data()};
}

// Body `like`'s mass and inertia for all (RotorGroups::spheres_alike); B: Bodies or a rank's
// LocalStore, whatever arrays_of reads.
template <class B>
AlikeArrays alike_arrays_of(B& b, std::size_t like) {
  const BodyArrays a = arrays_of(b);
  return {a.position, a.orientation,      a.velocity, a.angular_velocity,        a.velocity_end,
          a.angular_velocity_end, a.angular_momentum, a.force, a.torque, {b.mass[like]}, {b.inertia[like]}};
}

// The rotor path as a type: body lambdas take it as `auto rotor` and read decltype(rotor)::value.
template <Rotor kRotor>
using RotorPath = std::integral_constant<Rotor, kRotor>;

// How a pass walks a group: by its ids, in order (ids[k] == k, so k is the body), or by its runs.
enum class Walk { ids, in_order, runs };

// Runs body(arrays, i, RotorPath<kRotor>) over the bodies of `ids` (one rotor group, increasing),
// each thread of the team on its share of `cut` with the arrays' addresses in its own registers;
// ends at a barrier when `wait` (the same on every thread). Walk::runs reads `runs` (ids' runs_of).
template <Rotor kRotor, Walk kWalk, class Arrays, class Body>
void over_group(const Arrays& arrays, const std::vector<std::size_t>& ids, const Body& body, bool wait, TeamCut cut,
                const IdRuns* runs = nullptr) {
  const std::size_t n = ids.size();
  if (n == 0) return;  // the same on every thread: no barrier skipped by some only
  in_team(n >= kParallelMinItems, [&] {
    const Arrays a = arrays;
    const Body each = body;  // a copy: what it holds by value stays in registers too
    const std::size_t* id = ids.data();
    for (const auto [first, last] : kWalk == Walk::in_order ? team_shares(n, cut) : team_shares(ids, cut)) {
      if constexpr (kWalk == Walk::runs) {
        if (first == last) continue;
        // Each loop runs at least once (a run is never empty), written so: the body's constants
        // (h/m ...) are then set up once a share, not at each run (~48 instructions, ~200 runs a step).
        const std::size_t* at = runs->at.data();
        std::size_t r = std::size_t(std::upper_bound(runs->at.begin(), runs->at.end(), first) - runs->at.begin()) - 1;
        std::size_t k = first;
        do {
          std::size_t i = runs->first[r] + (k - at[r]);
          const std::size_t i1 = i + (std::min(last, at[r + 1]) - k);
          do each(a, i, RotorPath<kRotor>{});
          while (++i < i1);
          k = at[++r];
        } while (k < last);
      } else {
        for (std::size_t k = first; k < last; ++k) each(a, kWalk == Walk::in_order ? k : id[k], RotorPath<kRotor>{});
      }
    }
    if (wait) {
#pragma omp barrier
    }
  });
}

// body over the three rotor groups: they hold different bodies and body(i) touches body i's
// state only, so only the last group that has bodies ends at a barrier (a pass over a mixed
// scene meets once, not once per group). Equal spheres read one mass and inertia. Each thread
// takes the bodies of its share of `cut` (the contact stage's, or none: static shares).
// B: Bodies (by global id) or a rank's LocalStore (by local index, its groups' runs when
// in_runs), whatever arrays_of and alike_arrays_of read. `wait` false: no barrier at all (the
// caller reads only its own share of `cut` before the region's end).
template <class B, class Body>
void over_rotor_groups(B& b, const RotorGroups& groups, const Body& body, TeamCut cut = {}, bool wait = true) {
  const bool isotropic = !groups.isotropic.empty(), asymmetric = !groups.asymmetric.empty();
  const bool sphere_wait = wait && !isotropic && !asymmetric;
  // A rank's store walks its groups by runs (with_runs); Bodies by ids: more paths there and
  // GCC outlines an Eigen += of one process's joined pass (+2.2% of a sphere bed's step).
  if constexpr (!std::is_same_v<B, Bodies>) {
    if (groups.in_runs) {
      if (groups.spheres_alike)
        over_group<Rotor::sphere, Walk::runs>(alike_arrays_of(b, groups.spheres[0]), groups.spheres, body,
                                              sphere_wait, cut, &groups.sphere_runs);
      else
        over_group<Rotor::sphere, Walk::runs>(arrays_of(b), groups.spheres, body, sphere_wait, cut,
                                              &groups.sphere_runs);
      over_group<Rotor::isotropic, Walk::runs>(arrays_of(b), groups.isotropic, body, wait && !asymmetric, cut,
                                               &groups.isotropic_runs);
      over_group<Rotor::asymmetric, Walk::runs>(arrays_of(b), groups.asymmetric, body, wait, cut,
                                                &groups.asymmetric_runs);
      return;
    }
  }
  if (groups.spheres_alike && groups.spheres_in_order)
    over_group<Rotor::sphere, Walk::in_order>(alike_arrays_of(b, 0), groups.spheres, body, sphere_wait, cut);
  else if (groups.spheres_alike)
    over_group<Rotor::sphere, Walk::ids>(alike_arrays_of(b, groups.spheres[0]), groups.spheres, body, sphere_wait, cut);
  else
    over_group<Rotor::sphere, Walk::ids>(arrays_of(b), groups.spheres, body, sphere_wait, cut);
  over_group<Rotor::isotropic, Walk::ids>(arrays_of(b), groups.isotropic, body, wait && !asymmetric, cut);
  over_group<Rotor::asymmetric, Walk::ids>(arrays_of(b), groups.asymmetric, body, wait, cut);
}

namespace integrate_detail {
// Row i of `b` into the group of its rotation path; shapes null: no sphere path.
template <class B>
void add_rotor(const B& b, std::size_t i, const std::vector<Shape>* shapes, RotorGroups& groups) {
  if (shapes && keeps_no_orientation((*shapes)[b.shape[i]], b.inertia[i]))
    groups.spheres.push_back(i);
  else
    (is_isotropic(b.inertia[i]) ? groups.isotropic : groups.asymmetric).push_back(i);
}

// Sets spheres_alike and spheres_in_order once the groups are made.
template <class B>
void mark_spheres(const B& b, RotorGroups& groups) {
  const std::vector<std::size_t>& s = groups.spheres;
  groups.spheres_alike = groups.spheres_in_order = !s.empty();
  for (std::size_t k = 0; k < s.size(); ++k) {
    groups.spheres_alike &= b.mass[s[k]] == b.mass[s[0]] && b.inertia[s[k]] == b.inertia[s[0]];
    groups.spheres_in_order &= s[k] == k;
  }
}

// v += F h/m; L += R^T T h; w from L (an isotropic body: w += T h / I, w = L / I in any frame;
// a sphere: R the identity). Inlined into the step's passes: a call per body and pass cost ~10%
// of a kick.
template <Rotor kRotor, class Arrays>
[[gnu::always_inline]] inline void kick_body(const Arrays& b, std::size_t i, double h) {
  b.velocity[i] += b.force[i] * (h / b.mass[i]);
  if constexpr (kRotor == Rotor::sphere) {
    const Vec3 dl = b.torque[i] * h;  // N m s, world frame = body frame
    b.angular_momentum[i] += dl;
    b.angular_velocity[i] += dl / b.inertia[i].x();
  } else if constexpr (kRotor == Rotor::isotropic) {
    const Vec3 dl = b.torque[i] * h;  // N m s, world frame
    b.angular_momentum[i] += b.orientation[i].conjugate() * dl;
    b.angular_velocity[i] += dl / b.inertia[i].x();
  } else {
    b.angular_momentum[i] += b.orientation[i].conjugate() * (b.torque[i] * h);
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  }
}

// Translation, then the exact or split free-rotor flow, then w from the new (q, L_body)
// (an isotropic body keeps its w: it turns about L; a sphere does not turn its q at all).
template <Rotor kRotor, class Arrays>
[[gnu::always_inline]] inline void drift_body(const Arrays& b, std::size_t i, double dt) {
  b.position[i] += b.velocity[i] * dt;
  if constexpr (kRotor == Rotor::sphere) {
    return;
  } else if constexpr (kRotor == Rotor::isotropic) {
    // The rotation is about L itself, so the world angular velocity is unchanged: keep it.
    free_rotor::rotate_isotropic(b.orientation[i], b.angular_momentum[i], b.inertia[i], dt);
    free_rotor::renormalize(b.orientation[i]);
  } else {
    free_rotor::rotate_asymmetric(b.orientation[i], b.angular_momentum[i], b.inertia[i], dt);
    free_rotor::renormalize(b.orientation[i]);
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  }
}

// angular_velocity_end of body i from torque t (N m) over h (s).
template <Rotor kRotor, class Arrays>
[[gnu::always_inline]] inline void predict_spin(const Arrays& b, std::size_t i, double h, const Vec3& t) {
  if constexpr (kRotor != Rotor::asymmetric) {
    b.angular_velocity_end[i] = b.angular_velocity[i] + t * (h / b.inertia[i].x());
  } else {
    const Vec3 dl = b.orientation[i].conjugate() * (t * h);  // N m s, principal frame
    b.angular_velocity_end[i] = b.angular_velocity[i] + b.orientation[i] * dl.cwiseQuotient(b.inertia[i]);
  }
}
// kKicked: velocity_end is set (kick_body_twice).
template <Rotor kRotor, bool kKicked = false, class Arrays>
[[gnu::always_inline]] inline void predict_body(const Arrays& b, std::size_t i, double h) {
  if constexpr (!kKicked) b.velocity_end[i] = b.velocity[i] + b.force[i] * (h / b.mass[i]);
  predict_spin<kRotor>(b, i, h, b.torque[i]);
}

// A step's opening for body i: kick(h), drift(dt), predict_end_velocities(h) with the last
// step's force, then force = m gravity and torque = 0 (m/s^2).
// kKicked true: the kick and velocity_end are done (close_and_start_step's kick_body_twice).
template <Rotor kRotor, bool kKicked = false, class Arrays>
[[gnu::always_inline]] inline void start_body(const Arrays& a, std::size_t i, double h, double dt,
                                              const Vec3& gravity) {
  if constexpr (!kKicked) kick_body<kRotor>(a, i, h);
  drift_body<kRotor>(a, i, dt);
  predict_body<kRotor, kKicked>(a, i, h);  // the last step's force: before it is cleared
  a.force[i] = a.mass[i] * gravity;
  a.torque[i].setZero();
}
// The last step's closing kick and this step's opening kick of body i, one after the other, with
// force f (N) and torque t (N m): the same h and orientation, so each shared term (F h/m, R^T T h,
// T h/I) is made once and added twice; an asymmetric body's w is made once, from the twice-kicked
// L. Each kick's bits. velocity_end = v + F h/m (predict_body's) too: the drift leaves v alone.
template <Rotor kRotor, class Arrays>
[[gnu::always_inline]] inline void kick_body_twice(const Arrays& b, std::size_t i, double h, const Vec3& f,
                                                   const Vec3& t) {
  const Vec3 dv = f * (h / b.mass[i]);  // m/s
  b.velocity[i] += dv;
  b.velocity[i] += dv;
  b.velocity_end[i] = b.velocity[i] + dv;
  if constexpr (kRotor == Rotor::asymmetric) {
    const Vec3 dl = b.orientation[i].conjugate() * (t * h);  // N m s, principal frame
    b.angular_momentum[i] += dl;
    b.angular_momentum[i] += dl;
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  } else {
    const Vec3 dl = t * h;  // N m s, world frame
    const Vec3 dl_body = kRotor == Rotor::sphere ? dl : Vec3(b.orientation[i].conjugate() * dl);
    const Vec3 dw = dl / b.inertia[i].x();  // rad/s
    b.angular_momentum[i] += dl_body;
    b.angular_momentum[i] += dl_body;
    b.angular_velocity[i] += dw;
    b.angular_velocity[i] += dw;
  }
}

// close_and_start_step<true>'s pass for body i: its force and torque made in registers, m gravity
// plus before's sum (N, N m), both kicks, the drift, moved(i, x) and the end velocities.
template <Rotor kRotor, class Arrays, class Before, class Moved>
[[gnu::always_inline]] inline void close_and_start_from_gravity(const Arrays& a, std::size_t i, double h, double dt,
                                                                const Vec3& gravity, const Before& before,
                                                                const Moved& moved) {
  Vec3 f = a.mass[i] * gravity, t = Vec3::Zero();  // N, N m
  before.add_to(i, f, t);
  kick_body_twice<kRotor>(a, i, h, f, t);  // the closing kick and start_body's
  drift_body<kRotor>(a, i, dt);
  moved(i, a.position[i]);
  predict_spin<kRotor>(a, i, h, t);  // the last step's torque
}

// close_and_start_step's pass for body i when it turns: the closing kick (kick_after's, with
// before(i)), the turn (turn_body, its work -torque . angle in `turn`), then start_body.
template <Rotor kRotor, class Arrays, class Before>
[[gnu::noinline]] void turn_between_kicks(const Arrays& a, std::size_t i, double h, double dt, const Vec3& gravity,
                                          const Before& before, PassTurn& turn) {
  before(i);
  kick_body<kRotor>(a, i, h);
  const std::optional<Vec3> angle = turn_body(a.orientation[i], a.angular_momentum[i], a.angular_velocity[i],
                                              a.inertia[i], kRotor == Rotor::isotropic, turn.moment);
  if (angle) turn.work = -a.torque[i].dot(*angle);
  start_body<kRotor>(a, i, h, dt, gravity);
}
}  // namespace integrate_detail

template <class B>
RotorGroups group_rotors(const B& b, const std::vector<std::uint32_t>& rows, const std::vector<Shape>& shapes) {
  RotorGroups groups;
  for (std::uint32_t i : rows) integrate_detail::add_rotor(b, i, &shapes, groups);
  integrate_detail::mark_spheres(b, groups);
  return groups;
}

// kick(b, h, groups) with before(i) run on each body just before its kick (a step's closing
// kick: the contact forces summed into force[i]): one pass and one barrier for both (none when
// not `wait`: the region ends after it).
template <class B, class Before>
void kick_after(B& b, double h, const RotorGroups& groups, const Before& before, TeamCut cut = {}, bool wait = true) {
  auto one = [h, before](const auto& a, std::size_t i, auto rotor) __attribute__((always_inline)) {
    before(i);
    integrate_detail::kick_body<decltype(rotor)::value>(a, i, h);
  };
  over_rotor_groups(b, groups, one, cut, wait);
}

// x += v dt; free-rotor rotation of (q, L_body) over dt; angular_velocity = R (L_body / I).
void drift(Bodies& b, double dt, const RotorGroups& groups);

// Same, choosing each body's rotation path on the fly (for callers without RotorGroups).
void drift(Bodies& b, double dt);

// After the drift, before the new forces: velocity_end = v + F h/m and angular_velocity_end =
// w + I_world^-1 T h with the last step's force and torque, h = dt/2: the end-of-step
// velocities to O(dt^2), for the dashpots (a dashpot on the half-step velocity is first order
// in dt). h = 0 copies the velocities (the first force evaluation, at full-step velocities).
void predict_end_velocities(Bodies& b, double h, const RotorGroups& groups);

// A step's start in one pass over the bodies: kick(h), drift(dt), predict_end_velocities(h),
// then force = m gravity and torque = 0 (the new step's forces start from gravity, m/s^2).
// Each body's arithmetic is that of the separate calls: the same bits, one loop instead of four.
void start_step(Bodies& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity, TeamCut cut = {});
// start_step's pass over any B (over_rotor_groups): a rank's local arrays.
template <class B>
void start_pass(B& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity, TeamCut cut = {}) {
  over_rotor_groups(b, groups, [h, dt, gravity](const auto& a, std::size_t i, auto rotor) __attribute__((always_inline)) {
    integrate_detail::start_body<decltype(rotor)::value>(a, i, h, dt, gravity);
  }, cut);
}

// No watch of the positions a pass moves.
struct NoWatch {
  void operator()(std::size_t, const Vec3&) const {}
};

// The last step's closing pass (kick_after(b, h, groups, before)) and start_step in one pass
// over the bodies, body by body: each body's arithmetic is theirs (the same bits), its arrays
// read and written once, not twice. Nothing may read the state between the two (Simulation::step).
// kFromGravity: nothing but gravity and `before`'s sums acts on a body (no drag or fluid force
// added in the step), so each body's force and torque are made in registers, m gravity + sum and
// 0 + sum (the same bits as kept and added to), and its force and torque arrays are neither read
// nor written (48 + 48 bytes a body-step less memory traffic); `before` is then a ForceSums,
// whose gravity_mass closing sets them at a closed step. moved(i, x) sees each body's new
// position (m) while the pass holds it (the rebuild trigger's test: no pass of its own).
// `wait` false: no barrier at the pass's end (over_rotor_groups). `turns`: the last step's turns
// (PassTurns), each applied between its body's closing kick and its opening kick, as
// kick_after, turn_bodies and start_step apply it (the same bits); `before` is then called on
// its body as kick_after calls it (a ForceSums sets m gravity first under kFromGravity).
template <bool kFromGravity = false, class B, class Before, class Moved = NoWatch, class Turns = NoTurns>
void close_and_start_step(B& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity,
                          const Before& before, TeamCut cut = {}, Moved moved = {}, bool wait = true,
                          Turns turns = {}) {
  auto one = [h, dt, gravity, before, moved, turns](const auto& a, std::size_t i, auto rotor)
                 __attribute__((always_inline)) {
    constexpr Rotor kRotor = decltype(rotor)::value;
    if constexpr (Turns::kAny && kRotor != Rotor::sphere) {  // a sphere's orientation stays the identity
      if (PassTurn* turn = turns.at(i)) {  // rare: a patch's shares moved in the last step
        integrate_detail::turn_between_kicks<kRotor>(a, i, h, dt, gravity, before, *turn);
        moved(i, a.position[i]);
        return;
      }
    }
    if constexpr (kFromGravity) {
      integrate_detail::close_and_start_from_gravity<kRotor>(a, i, h, dt, gravity, before, moved);
    } else {
      before(i);
      integrate_detail::kick_body_twice<kRotor>(a, i, h, a.force[i], a.torque[i]);
      integrate_detail::start_body<kRotor, true>(a, i, h, dt, gravity);
    }
  };
  over_rotor_groups(b, groups, one, cut, wait);
}

// angular_velocity from angular_momentum and orientation (after the caller sets them).
void update_angular_velocity(Bodies& b);

// angular_momentum of body i from a world angular velocity; also sets angular_velocity[i].
void set_angular_velocity(Bodies& b, std::size_t i, const Vec3& w_world);

}  // namespace polydem
