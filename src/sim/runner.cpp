#include "sim/runner.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <numeric>
#include <omp.h>
#include <unistd.h>

#include "driver/frame.hpp"
#include "output/csv.hpp"
#include "output/vtk.hpp"
#include "output/vtk_image.hpp"
#include "polydem/error.hpp"
#include "sim/body_order.hpp"
#include "sim/body_rows.hpp"
#include "sim/checkpoint.hpp"
#include "sim/checkpoint_pieces.hpp"
#include "sim/contact_table.hpp"
#include "sim/last_good.hpp"
#include "sim/memory_marks.hpp"
#include "sim/probes.hpp"
#include "sim/run_limits.hpp"
#include "sim/thread_governor.hpp"
#include "sim/time_step.hpp"

namespace polydem {

namespace {

std::atomic<bool> g_interrupted{false};  // SIGINT or SIGTERM: finish the step, write a checkpoint
void on_interrupt(int) { g_interrupted = true; }

using Clock = std::chrono::steady_clock;

// Fires at 0, every, 2 every, ... of simulated time, at the step nearest to each.
class Schedule {
 public:
  Schedule(std::optional<double> every, double now) : every_(every ? *every : 0.0) {
    if (every_ > 0) next_ = std::ceil(now / every_ - 1e-9) * every_;
  }
  // True when due(t, dt) would be, without moving on.
  bool due_at(double t, double dt) const { return every_ > 0 && t >= next_ - 0.5 * dt; }
  bool due(double t, double dt) {
    if (!due_at(t, dt)) return false;
    while (next_ <= t + 0.5 * dt) {
      const double next = next_ + every_;
      if (next == next_)  // check_run_limits keeps intervals above this; a guard, not a hang
        throw RunError("an output interval of " + std::to_string(every_) + " s is below the round-off of t = " +
                       std::to_string(t) + " s");
      next_ = next;
    }
    return true;
  }
  bool enabled() const { return every_ > 0; }

 private:
  double every_, next_ = 0.0;
};

std::string numbered(const char* stem, std::int64_t n, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s_%06lld.%s", stem, static_cast<long long>(n), ext);
  return buf;
}

// One line per touching pair (force chains): body-body from centre to centre, body-driver
// from the centre to the contact point; forces summed over the pair's sub-contacts (ft: the
// sum of their tangential magnitudes).
// `body` and `driver`: pair lists in global ids, as one process's engine holds them.
// `b`: Bodies, or a rank's LocalStore with the lists in its local indices.
template <class Arrays>
std::vector<ContactOut> contact_lines(const PairList& body, const PairList& driver, const Arrays& b) {
  std::vector<ContactOut> out;
  auto add = [&](const PairList& list, bool driver) {
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (!list.touching[k]) continue;
      ContactOut c{};
      double weight = 0.0;
      for (std::uint32_t s = list.slot_begin[k]; s < list.slot_begin[k + 1]; ++s) {
        if (!list.active[s]) continue;
        const SlotRecord& r = list.record(s);  // recorded at the step just made
        c.fn += r.fn;
        c.force += r.force;
        // force = fn n + ft with ft normal to n, so |ft| follows without storing n
        c.ft += std::sqrt(std::max(r.force.squaredNorm() - r.fn * r.fn, 0.0));
        c.overlap = std::max(c.overlap, -list.history(s).gap);
        c.point += r.point * std::max(r.fn, 1e-300);
        weight += std::max(r.fn, 1e-300);
        c.type = int(list.features[s].type);
      }
      c.point /= weight;
      const BodyPair p = list.pairs[k];
      c.i = b.id[p.i];  // user ids
      c.j = driver ? -1 - std::int64_t(p.j) : std::int64_t(b.id[p.j]);
      c.from = b.position[p.i];
      c.to = driver ? c.point : b.position[p.j];
      out.push_back(c);
    }
  };
  add(body, false);
  add(driver, true);
  return out;
}

// A distributed run's rank: the lines of the pairs it answers for (sim/rank_contacts.hpp), from
// its owned bodies and ghosts in its store, which are current after a step.
std::vector<ContactOut> rank_contact_lines(const Simulation& sim) {
  const RankContacts& r = *sim.rank_contacts();
  const LocalStore& store = r.store();
  auto local = [&](bool driver) {  // the pairs in the store's indices
    PairList list = table_of(r.output_slots(sim.engine(), driver));
    for (BodyPair& p : list.pairs) {
      p.i = store.local_of(p.i);
      if (!driver) p.j = store.local_of(p.j);
    }
    return list;
  };
  return contact_lines(local(false), local(true), store);
}

// s: rows of a resumed run's CSV files later than this were written after its checkpoint.
double resumed_at(const Simulation& sim) { return sim.time() + 0.5 * sim.dt(); }

// fluid_NNNNNN.vti: the fluid grid's cell fields and, with void_fraction, the void fraction.
void write_fluid_vti(const std::string& path, const Simulation& sim) {
  const FluidGrid& g = *sim.external()->grid();
  std::vector<ImageArray> arrays;
  auto add = [&](const char* name, const std::vector<double>& v) { if (!v.empty()) arrays.push_back({name, 1, v}); };
  if (!g.U.empty()) arrays.push_back({"U", 3, std::vector<double>(g.U[0].data(), g.U[0].data() + 3 * g.U.size())});
  add("p", g.p);
  add("rho", g.rho);
  add("nu", g.nu);
  if (const auto vf = sim.external()->void_fraction(sim.bodies)) add("void_fraction", vf->alpha);
  write_image_vti(path, g.origin, g.spacing, g.cells, arrays);
}

// fluid.csv: bodies outside the fluid grid (no grid force), the solid volume the alpha_min
// floor refused (m^3), and the mean vertical velocity of each group (m/s).
class FluidSeries {
 public:
  FluidSeries(const Simulation& sim, const std::string& path, bool append) : sim_(sim) {
    std::vector<std::string> columns{"time", "outside", "excess_volume"};
    for (int g : sim.bodies.group)
      if (std::find(groups_.begin(), groups_.end(), g) == groups_.end()) groups_.push_back(g);
    std::sort(groups_.begin(), groups_.end());
    for (int g : groups_) columns.push_back("vz_group_" + std::to_string(g));
    csv_ = std::make_unique<CsvSeries>(path, columns, append, resumed_at(sim));
  }
  // `outside`: Simulation::bodies_outside_grid (a collective every rank takes part in).
  void row(std::size_t outside) {
    const auto vf = sim_.external()->void_fraction(sim_.bodies);
    std::vector<double> values{sim_.time(), double(outside), vf ? vf->excess : 0.0};
    std::vector<double> vz(groups_.size(), 0.0), count(groups_.size(), 0.0);
    for (std::size_t b = 0; b < sim_.bodies.size(); ++b) {
      const auto g = std::lower_bound(groups_.begin(), groups_.end(), sim_.bodies.group[b]) - groups_.begin();
      vz[g] += sim_.bodies.velocity[b].z();
      count[g] += 1.0;
    }
    for (std::size_t g = 0; g < groups_.size(); ++g) values.push_back(vz[g] / count[g]);
    csv_->row(values);
  }

 private:
  const Simulation& sim_;
  std::vector<int> groups_;
  std::unique_ptr<CsvSeries> csv_;
};

// m, the box of every body's bounding sphere; distributed runs: each rank's own bodies' (its
// store's after its first cut, which dropped `bodies`' state), met on rank 0 (a collective).
Box3 bodies_box(const Simulation& sim) {
  Box3 box;
  const RankContacts* r = sim.rank_contacts();
  if (!r) {
    for (std::size_t b = 0; b < sim.bodies.size(); ++b) add_body(box, sim.bodies, b, sim.shapes());
    return box;
  }
  r->with_output_rows(sim.bodies, [&](const auto& a, const std::vector<std::uint32_t>& rows) {
    for (std::uint32_t k : rows) add_body(box, a, k, sim.shapes());
  });
  std::vector<char> mine;
  append_record(mine, box);
  for (const std::vector<char>& from : sim.link()->gather(mine, 0)) {  // min and max: exact in any order
    Box3 theirs;
    std::memcpy(static_cast<void*>(&theirs), from.data(), sizeof theirs);
    box.add(theirs);
  }
  return box;
}

class OutputWriter {
 public:
  // Rank 0 of a distributed run writes; the others only take part in the gathers.
  OutputWriter(Simulation& sim, const RunOptions& o, OutputProgress progress)
      : sim_(sim), dir_(o.out_dir), io_(sim.rank() == 0), progress_(std::move(progress)),
        view_box_(view_box(bodies_box(sim), sim.drivers)) {
    // output.probes: flow.csv, angle.csv (every rank measures its own bodies)
    probes_ = std::make_unique<Probes>(sim, dir_, !o.resume.empty(), io_);
    if (!io_) return;
    pvd_ = std::make_unique<PvdFiles>(dir_);
    for (const OutputFrame& f : progress_.frames) pvd_->add(f.time, f.files);
    if (!sim.scene().output.csv_every) return;
    energy_ = std::make_unique<CsvSeries>(dir_ + "/energy.csv",
        std::vector<std::string>{"time", "kinetic", "rotational", "elastic", "dissipated", "gravity_work",
                                 "driver_work", "contacts", "external_work", "elastic_normal", "elastic_tangential",
                                 "elastic_rolling", "dissipated_dashpot", "dissipated_sliding", "dissipated_rolling",
                                 "patch_work"}, !o.resume.empty(), resumed_at(sim));
    if (sim.external()) fluid_ = std::make_unique<FluidSeries>(sim, dir_ + "/fluid.csv", !o.resume.empty());
    for (std::size_t j = 0; j < sim.drivers.size(); ++j)  // force and torque the particles exert on it
      driver_series_.push_back(std::make_unique<CsvSeries>(dir_ + "/driver_" + sim.drivers.name(std::uint32_t(j)) + ".csv",
          std::vector<std::string>{"time", "fx", "fy", "fz", "tx", "ty", "tz", "x", "y", "z"}, !o.resume.empty(),
          resumed_at(sim)));
  }

  void frame() {
    const bool pieces = sim_.distributed();  // each rank writes its own bodies and contacts
    const bool contacts = sim_.scene().output.contacts;
    const bool fluid = fluid_grid();
    if (fluid) sim_.gather_bodies();  // the void fraction reads every body (rank 0's copy)
    const std::int64_t n = progress_.frame++;  // on every rank: the pieces carry it
    const std::string bodies = numbered("bodies", n, pieces ? "pvtu" : "vtu");
    const std::string lines = numbered("contacts", n, pieces ? "pvtp" : "vtp");
    if (pieces) write_rank_pieces(bodies, contacts ? lines : "");
    if (io_) write_frame(n, bodies, lines, fluid);
    if (fluid) sim_.release_bodies();
  }

  // Returns whether the contact table is whole on this process (one process: check_overlaps).
  bool energy_row() {
    if (!sim_.scene().output.csv_every) return false;
    const bool reads_bodies = sim_.external() != nullptr;
    if (reads_bodies) sim_.gather_bodies();  // fluid.csv reads every body (rank 0's copy)
    sim_.sum_energy();                        // each rank's part of the energies, reduced exactly
    const std::size_t outside = sim_.bodies_outside_grid();  // a collective too
    if (energy_) write_rows(outside);
    probes_->row();                           // each rank's part of the probes, met on rank 0
    if (reads_bodies) sim_.release_bodies();
    return !sim_.distributed();
  }

  std::string checkpoint(Simulation& sim) {
    const std::string path = dir_ + "/" + numbered("checkpoint", sim.step_index(), "bin");
    if (sim.distributed()) write_checkpoint_pieces(path, sim, progress_);  // a collective
    else write_checkpoint(path, sim, progress_);
    sim.force_rebuild(false);  // the resumed run rebuilds here too: same lists, same bits
    return path;
  }

 private:
  bool fluid_grid() const { return sim_.external() && sim_.external()->grid(); }

  // Rank 0's files of frame n: the bodies (one process), drivers, contacts and fluid grid.
  void write_frame(std::int64_t n, const std::string& bodies, const std::string& lines, bool fluid) {
    const bool pieces = sim_.distributed(), contacts = sim_.scene().output.contacts;
    OutputFrame f{sim_.time(), {bodies}};
    if (!pieces)
      write_bodies_vtu(dir_ + "/" + bodies, sim_.bodies, sim_.shapes(), sim_.scene().output.rounded,
                       sim_.scene().forces.gravity);
    if (!sim_.drivers.empty()) {
      f.files.push_back(numbered("drivers", n, "vtp"));
      write_drivers_vtp(dir_ + "/" + f.files.back(), sim_.drivers.meshes(view_frame(sim_.drivers, view_box_)));
    }
    if (contacts) {
      f.files.push_back(lines);
      if (!pieces)
        write_contacts_vtp(dir_ + "/" + lines,
                           contact_lines(sim_.engine().body_pairs(), sim_.engine().driver_pairs(), sim_.bodies));
    }
    if (fluid) {
      f.files.push_back(numbered("fluid", n, "vti"));
      write_fluid_vti(dir_ + "/" + f.files.back(), sim_);
    }
    pvd_->add(f.time, f.files);
    progress_.frames.push_back(f);
  }

  // Rank 0's CSV rows: energy, the fluid's, the drivers'.
  void write_rows(std::size_t outside) {
    const EnergyRow e = sim_.energy();
    if (fluid_) fluid_->row(outside);
    energy_->row({sim_.time(), e.kinetic, e.rotational, e.elastic, e.dissipated, e.gravity_work, e.driver_work,
                  double(e.contacts), e.external_work, e.elastic_parts.normal, e.elastic_parts.tangential,
                  e.elastic_parts.rolling, e.dissipated_dashpot, e.dissipated_sliding, e.dissipated_rolling,
                  e.patch_work});
    for (std::size_t j = 0; j < driver_series_.size(); ++j) {
      const DriverState& d = sim_.drivers[j];
      const Vec3 x = sim_.drivers.center(std::uint32_t(j));
      driver_series_[j]->row({sim_.time(), d.force.x(), d.force.y(), d.force.z(), d.torque.x(), d.torque.y(),
                              d.torque.z(), x.x(), x.y(), x.z()});
    }
  }

  // STEM_NNNNNN_pK.vtu and .vtp: each rank's owned bodies and the contacts it answers for;
  // rank 0 adds the .pvtu and .pvtp (`contacts`: none when empty) naming every piece.
  void write_rank_pieces(const std::string& bodies, const std::string& contacts) {
    auto piece = [&](const std::string& file, int r) {  // bodies_000012.pvtu -> bodies_000012_p3.vtu
      const std::size_t dot = file.rfind('.');
      return file.substr(0, dot) + "_p" + std::to_string(r) + "." + file.substr(dot + 2);
    };
    auto all = [&](const std::string& file) {
      std::vector<std::string> names;
      for (int r = 0; r < sim_.link()->ranks(); ++r) names.push_back(piece(file, r));
      return names;
    };
    on_every_rank(*sim_.link(), [&] {
      sim_.rank_contacts()->with_output_rows(sim_.bodies, [&](const auto& a, const std::vector<std::uint32_t>& rows) {
        const Bodies mine = rows_of(a, rows);  // this rank's bodies alone
        std::vector<std::uint32_t> every(mine.size());
        std::iota(every.begin(), every.end(), 0u);
        write_bodies_piece(dir_ + "/" + piece(bodies, sim_.rank()), mine, by_user_id(mine, std::move(every)),
                           sim_.shapes(), sim_.scene().output.rounded, sim_.scene().forces.gravity);
      });
      if (!contacts.empty()) write_contacts_vtp(dir_ + "/" + piece(contacts, sim_.rank()), rank_contact_lines(sim_));
      if (!io_) return;
      write_bodies_pvtu(dir_ + "/" + bodies, all(bodies));
      if (!contacts.empty()) write_contacts_pvtp(dir_ + "/" + contacts, all(contacts));
    });
  }

  Simulation& sim_;
  std::string dir_;
  bool io_;  // writes the files
  OutputProgress progress_;
  std::unique_ptr<PvdFiles> pvd_;  // scene.pvd and bodies.pvd, drivers.pvd, ...
  std::unique_ptr<CsvSeries> energy_;
  std::vector<std::unique_ptr<CsvSeries>> driver_series_;
  std::unique_ptr<FluidSeries> fluid_;
  std::unique_ptr<Probes> probes_;
  Box3 view_box_;  // m, what the drivers are drawn in: the bodies and drivers at the start
};

std::string format_duration(double s) {
  char buf[32];
  if (s < 60) std::snprintf(buf, sizeof(buf), "%.0fs", s);
  else if (s < 3600) std::snprintf(buf, sizeof(buf), "%dm%02ds", int(s) / 60, int(s) % 60);
  else std::snprintf(buf, sizeof(buf), "%dh%02dm", int(s) / 3600, (int(s) % 3600) / 60);
  return buf;
}

// m/s^2: gravity beyond this (1000 g) is named as the likely cause of a blow-up.
constexpr double kStrongGravity = 1e4;

bool driver_moves(const MotionSettings& m) {
  return m.rotates || m.velocity != Vec3::Zero() || m.force || m.pressure;
}

// What most likely made the state non-finite, among what the scene sets: gravity, a moving
// driver whose reaction is no longer finite, the time step, the checkpoint (first check after
// a resume).
std::string likely_cause(const Simulation& sim, bool first_check_after_resume) {
  char buf[320];
  const TimeStepEstimate& e = sim.time_step();
  if (sim.scene().forces.gravity && sim.scene().forces.gravity->stableNorm() > kStrongGravity) {
    std::snprintf(buf, sizeof(buf), "gravity of %.3g m/s^2", sim.scene().forces.gravity->stableNorm());
    return buf;
  }
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    const DriverState& d = sim.drivers[j];
    if (driver_moves(sim.drivers.motion(std::uint32_t(j))) && !(d.force.allFinite() && d.torque.allFinite()))
      return "the motion of driver '" + sim.drivers.name(std::uint32_t(j)) + "' (its reaction is no longer finite)";
  }
  if (sim.dt() > kUnsafeFraction * e.critical) {
    std::snprintf(buf, sizeof(buf), "the time step dt = %.3g s is %.2g x the critical step %.3g s of the stiffest "
                  "contact (reduce dt or kn, or use dt: auto)", sim.dt(), sim.dt() / e.critical, e.critical);
    return buf;
  }
  if (first_check_after_resume) return "the state of the checkpoint resumed from (damaged, or of another scene)";
  std::snprintf(buf, sizeof(buf), "none of gravity, the drivers or the time step (%.2g x critical) stands out: check "
                "the forces (drag, fluid), the initial velocities and the contact law", sim.dt() / e.critical);
  return buf;
}

// A collective in distributed runs: every rank calls it at the same step (its bodies to rank 0).
[[noreturn]] void fail_non_finite(const Simulation& sim, const std::string& what, const LastGood& last_good,
                                  std::int64_t good_step, const std::string& dir, bool first_check_after_resume) {
  const std::string good = dir + "/bodies_last_good.vtu";
  const LastGood gathered = sim.distributed() ? last_good.gathered(*sim.link()) : LastGood{};
  const LastGood& whole = sim.distributed() ? gathered : last_good;
  if (sim.rank() == 0) write_bodies_vtu(good, whole.with_constants_of(sim.bodies), sim.shapes());
  char msg[256];
  std::snprintf(msg, sizeof(msg), " became non-finite by step %lld (t = %.6g s). Likely cause: ",
                static_cast<long long>(sim.step_index()), sim.time());
  throw RunError(what + msg + likely_cause(sim, first_check_after_resume) + ". Last good state (step " +
                 std::to_string(good_step) + ") written to " + good);
}

std::string body_name(const Simulation& sim, long body) {
  return "body " + std::to_string(sim.bodies.id[body]) + " (shape '" + sim.shapes()[sim.bodies.shape[body]].name + "')";
}

// One process keeps every body; a rank the bodies it owns (before a cut: rank 0 every body).
void keep_last_good(const Simulation& sim, LastGood& last_good) {
  const RankContacts* r = sim.rank_contacts();
  if (!r) return last_good.keep(sim.bodies);
  r->with_output_rows(sim.bodies, [&](const auto& a, const std::vector<std::uint32_t>& rows) {
    last_good.keep(a, rows, r->output_bodies());
  });
}

// What a finiteness check finds: the first body whose state is not finite (-1: none) and, in a
// distributed run, the overlap warning due ("": none; one process checks after, as at rows).
struct StateCheck {
  long bad;
  std::string overlap;
};

// Distributed runs: each rank checks the bodies it owns and the pairs it answers for, and one
// all-gather gives every rank the least id and the first too-deep contact in one process's
// scan order (the same answer as the whole state's, with no state gathered).
StateCheck check_state(const Simulation& sim, const OverlapWatch& watch, double kn, double kn_driver) {
  const RankContacts* r = sim.rank_contacts();
  if (!r) return {first_non_finite_body(sim.bodies), ""};
  std::optional<OverlapWatch::Deep> deep;
  if (sim.scene().forces.contact.present && !watch.warned() && r->lists())
    deep = watch.first_deep(r->lists()->body_pairs(), r->lists()->driver_pairs(), sim.drivers, kn, kn_driver,
                            sim.time(), {&r->store().global_id, &r->store().ghost});
  std::vector<char> mine;
  append_record(mine, std::int64_t(r->first_non_finite_owned()));
  append_record(mine, deep ? deep->key : std::array<std::uint64_t, 2>{~0ull, ~0ull});
  if (deep) mine.insert(mine.end(), deep->warning.begin(), deep->warning.end());
  StateCheck c{-1, ""};
  std::array<std::uint64_t, 2> least{~0ull, ~0ull};
  for (const std::vector<char>& from : sim.link()->all_gather(mine)) {
    std::int64_t bad = -1;
    std::array<std::uint64_t, 2> key{};
    std::memcpy(&bad, from.data(), sizeof bad);
    std::memcpy(key.data(), from.data() + sizeof bad, sizeof key);
    if (bad >= 0 && (c.bad < 0 || bad < c.bad)) c.bad = long(bad);
    if (from.size() > sizeof bad + sizeof key && key < least) {
      least = key;
      c.overlap.assign(from.begin() + std::ptrdiff_t(sizeof bad + sizeof key), from.end());
    }
  }
  return c;
}

// The energy ledger's driver and external work become non-finite while bodies may not.
std::string non_finite_ledger(const EnergyLedger& l) {
  if (!std::isfinite(l.driver_work)) return "the drivers' work";
  if (!std::isfinite(l.external_work)) return "the work of drag and fluid forces";
  if (!std::isfinite(l.dissipated)) return "the dissipated energy";
  return "";
}

// Refuses an --out that is a file, before the filesystem's own message.
void make_output_folder(const std::string& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw InputError("output folder '" + dir + "' is a file (give a folder to --out or output.dir)");
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create the output folder '" + dir + "': " + ec.message());
}

}  // namespace

RunSummary run_simulation(Simulation& sim, const RunOptions& o) {
  const bool io = sim.rank() == 0;  // distributed runs: rank 0 prints
  for (const std::string& w : check_run_limits(sim, o.until))
    if (io) std::fprintf(stderr, "%s\n", w.c_str());
  make_output_folder(o.out_dir);
  OutputProgress progress;
  memory_mark("set-up", sim.rank());
  if (!o.resume.empty()) {
    read_checkpoint(o.resume, sim, progress, o.force);
    memory_mark("resume read", sim.rank());
  }
  const OutputSettings& out = sim.scene().output;
  const double dt = sim.dt();
  const double end_time = o.until ? *o.until : sim.scene().simulation.duration;
  const std::int64_t last_step = std::llround(end_time / dt);  // check_run_limits: <= kMaxSteps
  if (sim.step_index() > last_step)
    throw InputError(o.resume + ": the checkpoint is at t = " + std::to_string(sim.time()) +
                     " s, past the end of this run (" + std::to_string(end_time) + " s); give --until beyond it");
  Schedule vtk(out.vtk_every, sim.time()), csv(out.csv_every, sim.time()), ckpt(out.checkpoint_every, sim.time());
  ckpt.due(sim.time(), dt);  // nothing to save at the start (or we resume from this very checkpoint)
  constexpr std::int64_t kCheckSteps = 100;  // finiteness check and last-good copy period
  OutputWriter writer(sim, o, progress);
  if (o.resume.empty()) {
    if (vtk.due(sim.time(), dt)) writer.frame();
    if (csv.due(sim.time(), dt)) writer.energy_row();
  } else {  // resuming: what is due now was written before the checkpoint
    vtk.due(sim.time(), dt);
    csv.due(sim.time(), dt);
  }
  // What is due now is written: the contacts' records, kept since the set-up's first step (or
  // read from the checkpoint), are freed until a step whose state is written (56 bytes a sphere
  // list's slot); a run with no step left keeps them for its final checkpoint.
  if (sim.step_index() < last_step) sim.engine().record_contacts(false);
  g_interrupted = false;
  auto previous = std::signal(SIGINT, on_interrupt);
  auto previous_term = std::signal(SIGTERM, on_interrupt);  // batch schedulers send it before killing
  LastGood last_good;
  keep_last_good(sim, last_good);
  std::int64_t good_step = sim.step_index();
  bool first_check = !o.resume.empty();  // a blow-up before the first check after a resume blames the checkpoint
  const auto start = Clock::now();
  auto last_print = start;
  const std::int64_t first_step = sim.step_index();
  RunSummary summary;
  const ContactOperator& law = sim.scene().forces.contact;
  const double kn = sim.time_step().kn_particle, kn_driver = sim.time_step().kn_driver;  // N/m
  OverlapWatch overlaps(sim.bodies, sim.shapes());  // warns once when a contact is too deep
  auto check_overlaps = [&]() {  // O(contacts): at each CSV row that gathered the state, one process's checks
    if (!law.present || !io) return;
    const std::string w = overlaps.check(sim.engine().body_pairs(), sim.engine().driver_pairs(), sim.drivers, kn,
                                         kn_driver, sim.time());
    if (!w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
  };
  const int max_threads = omp_get_max_threads();
  ThreadGovernor governor(max_threads, o.adapt_threads);
  int threads = governor.threads();
  omp_set_num_threads(threads);
  double stepping = 0.0;  // s of wall time inside the steps: what the governor compares, output apart
  bool stopping = false;  // interrupted after a step that kept no contact records: one more step, then stop
  sim.open_steps_follow(true);  // an interrupt after an open step: close_step leaves its kick to that extra step
  while (sim.step_index() < last_step) {
    // Contact points and forces are kept only for a step whose state is written after it (the
    // same decision on every rank: an interrupt is seen by all after the step, see below).
    const std::int64_t next = sim.step_index() + 1;
    const double t_next = double(next) * dt;  // s, as sim.time() will be
    const bool recorded = (out.contacts && vtk.due_at(t_next, dt)) || ckpt.due_at(t_next, dt) || next == last_step ||
                          stopping;
    sim.engine().record_contacts(recorded);
    sim.want_driver_reactions(recorded || csv.due_at(t_next, dt));  // the driver CSVs and checkpoints read them
    sim.ask_stop(g_interrupted);
    // Nothing reads the bodies after this step: its closing kick joins the next step's opening pass.
    const bool unread = !recorded && next % kCheckSteps != 0 && !vtk.due_at(t_next, dt) && !csv.due_at(t_next, dt);
    try {
      const auto step_start = Clock::now();
      sim.step(unread);
      stepping += std::chrono::duration<double>(Clock::now() - step_start).count();
    } catch (const RunError&) {  // the neighbour search refuses non-finite positions (every rank alike)
      const long bad = sim.first_non_finite();  // a rank holds only its bodies current: the first over all
      if (bad >= 0) fail_non_finite(sim, body_name(sim, bad), last_good, good_step, o.out_dir, first_check);
      throw;
    }
    if (governor.after_step(stepping) != threads) omp_set_num_threads(threads = governor.threads());
    const std::int64_t s = sim.step_index();
    if (s % kCheckSteps == 0 || s == last_step) {
      const StateCheck c = check_state(sim, overlaps, kn, kn_driver);  // distributed: all stop alike
      if (c.bad >= 0) fail_non_finite(sim, body_name(sim, c.bad), last_good, good_step, o.out_dir, first_check);
      const std::string ledger = non_finite_ledger(sim.ledger);
      if (!ledger.empty()) fail_non_finite(sim, ledger, last_good, good_step, o.out_dir, first_check);
      first_check = false;
      keep_last_good(sim, last_good);
      good_step = s;
      if (!sim.distributed()) check_overlaps();
      if (!c.overlap.empty() && io && !overlaps.warned()) std::fprintf(stderr, "%s\n", c.overlap.c_str());
      if (!c.overlap.empty()) overlaps.set_warned();
    }
    if (vtk.due(sim.time(), dt)) writer.frame();
    if (csv.due(sim.time(), dt) && writer.energy_row()) check_overlaps();  // distributed: check_state's
    if (ckpt.due(sim.time(), dt) && s != last_step) writer.checkpoint(sim);
    const std::optional<bool> seen = sim.stop_seen();  // in the step's collective: every rank stops at the same step
    const bool interrupted = seen ? *seen : sim.any_rank(g_interrupted);  // else a collective of its own
    const bool kept = recorded || seen.value_or(false);  // a stop seen inside the step kept the records
    if (interrupted) sim.close_step();  // its checkpoint reads the bodies at the full step
    if (interrupted && !kept) {  // the checkpoint needs the contacts' records: one more step
      g_interrupted = stopping = true;
      continue;
    }
    if (interrupted) {
      g_interrupted = true;
      const std::string path = writer.checkpoint(sim);
      if (io) std::fprintf(stderr, "\ninterrupted at t = %.6g s; continue with: polydem run %s --out %s --resume %s\n",
                   sim.time(), sim.scene().path.c_str(), o.out_dir.c_str(), path.c_str());
      break;
    }
    const auto now = Clock::now();
    if (o.progress && io && std::chrono::duration<double>(now - last_print).count() > 2.0) {
      last_print = now;
      const double wall = std::chrono::duration<double>(now - start).count();
      const double rate = double(s - first_step) / wall;
      // Distributed runs count the contacts at CSV rows only (a reduction): none shown here.
      const std::string contacts = sim.distributed() ? "" : std::to_string(sim.contacts()) + " contacts  ";
      std::fprintf(stderr, "t = %.4g / %.4g s  step %lld  %.0f steps/s  %sleft %s%s",
                   sim.time(), end_time, static_cast<long long>(s), rate, contacts.c_str(),
                   format_duration(double(last_step - s) / rate).c_str(), isatty(2) ? "      \r" : "\n");
    }
  }
  std::signal(SIGINT, previous);
  std::signal(SIGTERM, previous_term);
  omp_set_num_threads(max_threads);
  summary.interrupted = g_interrupted;
  summary.steps_at_threads = governor.steps_at();
  memory_mark("steps", sim.rank());
  if (!g_interrupted) writer.checkpoint(sim);
  memory_mark("final checkpoint", sim.rank());
  summary.steps = sim.step_index() - first_step;
  summary.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  summary.rebuilds = sim.rebuilds();
  if (o.progress && isatty(2)) std::fprintf(stderr, "\n");
  return summary;
}

}  // namespace polydem
