#include "app/cmd_run.hpp"
#include "app/short_spin.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <optional>

#include "geometry/features.hpp"
#include "io/generate.hpp"
#include "io/scene.hpp"
#include "polydem/error.hpp"
#include "polydem/release.hpp"
#include "sim/checkpoint.hpp"
#include "sim/run_limits.hpp"
#include "sim/runner.hpp"
#include "sim/step_accuracy.hpp"

namespace polydem {

namespace {

const char* kRunHelp =
    "usage: polydem run SCENE.yaml [--out DIR] [--threads N [--fixed-threads]] [--until T]\n"
    "                   [--resume CHECKPOINT [--force]] [--body-order space|input]\n"
    "  --out DIR        output folder (default: output.dir of the scene, else out/ beside it)\n"
    "  --threads N      OpenMP threads (default: simulation.threads, else all cores);\n"
    "                   results are bitwise identical for any N; the run uses fewer while\n"
    "                   fewer step faster (a busy machine), measured as it goes\n"
    "  --fixed-threads  exactly N threads all along (thread-efficiency benchmarks)\n"
    "  --until T        stop at simulated time T (s, or with a unit: \"0.1 s\")\n"
    "  --resume FILE    continue bit for bit from a checkpoint_NNNNNN.bin of this scene; the CSV\n"
    "                   files of the output folder are cut back to the checkpoint's time\n"
    "  --force          resume a checkpoint written for another scene (with a warning)\n"
    "  --body-order space|input  how a fresh run stores its bodies (simulation.body_order);\n"
    "                   a resumed run keeps its checkpoint's order\n"
    "Writes scene.pvd (ParaView), bodies/drivers/contacts VTK files, energy.csv and checkpoints.\n"
    "Ctrl-C or SIGTERM stops at the end of the current step and writes a checkpoint to resume\n"
    "from. Exit codes: 0 done, 1 bad input, 2 the run failed, 3 interrupted (checkpoint written).\n";

const char* kCheckHelp =
    "usage: polydem check SCENE.yaml\n"
    "Validates the scene and prints the bodies per shape, the total mass, the critical time step\n"
    "and the chosen one, without running it.\n";

struct RunArgs {
  std::string scene;
  std::optional<std::string> out;
  std::optional<int> threads;
  std::optional<double> until;
  std::string resume;
  bool force = false;
  bool fixed_threads = false;
  std::optional<SimulationSettings::BodyOrder> body_order;
};

double parse_seconds(const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try { v = std::stod(text, &used); } catch (...) { used = 0; }
  std::string unit = text.substr(used);
  while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
  const std::map<std::string, double> units{{"", 1.0}, {"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"min", 60.0}};
  if (used == 0 || !units.count(unit) || !(v >= 0) || !std::isfinite(v))
    throw InputError("--until: expected a time such as 0.5 or \"500 ms\", got '" + text + "'");
  return v * units.at(unit);
}

RunArgs parse_run_args(const std::vector<std::string>& args, const char* help, bool run) {
  RunArgs r;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    auto value = [&]() -> const std::string& {
      if (k + 1 >= args.size()) throw InputError(a + " needs a value (see --help)");
      return args[++k];
    };
    if (a == "--help" || a == "-h") { std::fputs(help, stdout); std::exit(0); }
    else if (run && a == "--out") r.out = value();
    else if (run && a == "--threads") {
      const std::string& v = value();
      std::size_t used = 0;
      try { r.threads = std::stoi(v, &used); } catch (...) { r.threads = 0; }
      if (*r.threads < 1 || used != v.size())
        throw InputError("--threads: expected a whole number >= 1, got '" + v + "'");
    }
    else if (run && a == "--until") r.until = parse_seconds(value());
    else if (run && a == "--resume") r.resume = value();
    else if (run && a == "--force") r.force = true;
    else if (run && a == "--fixed-threads") r.fixed_threads = true;
    else if (run && a == "--body-order") {
      const std::string& v = value();
      if (v != "space" && v != "input") throw InputError("--body-order: expected space or input, got '" + v + "'");
      r.body_order = v == "space" ? SimulationSettings::BodyOrder::space : SimulationSettings::BodyOrder::input;
    }
    else if (!a.empty() && a[0] == '-') throw InputError("unknown option '" + a + "' (see --help)");
    else if (r.scene.empty()) r.scene = a;
    else throw InputError("unexpected argument '" + a + "' (one scene file per run)");
  }
  if (r.scene.empty()) throw InputError(std::string("missing the scene file\n") + help);
  if (r.force && r.resume.empty()) throw InputError("--force goes with --resume (see --help)");
  return r;
}

void print_counts(const Simulation& sim) {
  std::map<std::string, std::pair<std::size_t, double>> per_shape;
  double total = 0.0;
  for (std::size_t b = 0; b < sim.bodies.size(); ++b) {
    auto& e = per_shape[sim.shapes()[sim.bodies.shape[b]].name];
    ++e.first;
    e.second += sim.bodies.mass[b];
    total += sim.bodies.mass[b];
  }
  std::printf("bodies: %zu\n", sim.bodies.size());
  for (const auto& [name, e] : per_shape) std::printf("  %-20s %8zu bodies  %12.6g kg\n", name.c_str(), e.first, e.second);
  std::printf("total mass: %.6g kg\n", total);
  std::printf("drivers: %zu\n", sim.drivers.size());
  const TimeStepEstimate& t = sim.time_step();
  std::printf("critical time step: %.4g s (smallest contact-point mass %.4g kg)\n", t.critical, t.m_eff);
  std::printf("  set by the %s mode (normal mode alone: %.4g s; tangential contact-point mass %.4g kg)\n",
              step_mode_name(t.mode), t.critical_normal, t.m_tangential);
  const ContactOperator& law = sim.scene().forces.contact;
  if (law.config.hertz || law.config_driver.hertz)  // its stiffness grows with the overlap
    std::printf("  hertz: for an impact at %.3g m/s (fastest body plus a fall over the scene's height), "
                "kn %.4g N/m between bodies, %.4g N/m on drivers\n",
                t.impact_speed, t.kn_particle, t.kn_driver);
  std::printf("chosen time step:   %.4g s (%.3g x critical)%s\n", t.chosen, t.chosen / t.critical,
              sim.scene().simulation.dt ? "" : (sim.scene().simulation.accuracy ? " [auto, accuracy]" : " [auto]"));
  if (sim.scene().forces.contact.present)
    std::printf("  %s\n", impact_error_note(t.chosen, t.critical, t.model).c_str());
  const double steps = sim.scene().simulation.duration / t.chosen;
  std::printf("steps for %.4g s: %.0f\n", sim.scene().simulation.duration, steps);
}

// " (expected restitution error ...)" after the dt of the start-up line, "" without a contact law.
std::string dt_note(const Simulation& sim) {
  if (!sim.scene().forces.contact.present) return "";
  return " (" + impact_error_note(sim.dt(), sim.time_step().critical, sim.time_step().model) + ")";
}

void warn_unsafe_step(const Simulation& sim) {
  const std::string w = unsafe_step_warning(sim.time_step());
  if (!w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
}

void warn_fast_impacts(const Simulation& sim) {
  const std::string& w = sim.fast_impact_warning();
  if (!w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
}

// Shapes, bodies and the simulation of a parsed scene (threads are set before: the first
// contact search already runs in parallel).
// `resume`: the checkpoint whose body order the bodies take. The simulation keeps the scene
// without its body list (~290 bytes a listed body, the specs' copy): nothing reads it after this.
std::unique_ptr<Simulation> build(Scene scene, const RankLink* link = nullptr, const std::string& resume = "") {
  const ShapeLibrary library = load_shape_library(scene.shape_files);
  std::vector<BodySpec> specs = expand_bodies(scene, library);
  release(scene.bodies);
  std::optional<std::vector<std::uint32_t>> order;
  if (!resume.empty()) order = checkpoint_body_order(resume, specs.size());
  return std::make_unique<Simulation>(scene, library, std::move(specs), link, std::move(order));
}

// More threads than cores share them and wait on each other at every loop of the step.
void warn_threads(int threads, const Scene& scene, bool from_command_line) {
  const int cores = omp_get_num_procs();
  if (threads <= cores) return;
  const std::string where = from_command_line ? std::string("--threads: ") :
      input_message(scene.key_locs.at("simulation.threads").file, scene.key_locs.at("simulation.threads").line,
                    "threads", "");
  std::fprintf(stderr, "warning: %s%d threads on %d cores: they take turns on the cores and the run is much "
               "slower; give at most %d\n", where.c_str(), threads, cores, cores);
}

// The share of steps at each thread count, when the governor used more than one.
void print_thread_use(const std::vector<std::int64_t>& steps_at) {
  std::int64_t total = 0;
  int used = 0;
  for (std::int64_t n : steps_at) { total += n; used += n > 0; }
  if (used < 2) return;
  std::string shares;
  for (std::size_t t = steps_at.size(); t-- > 1;)
    if (steps_at[t] > 0) {
      const long percent = std::lround(100.0 * double(steps_at[t]) / double(total));
      shares += (shares.empty() ? "" : ", ") + std::to_string(t) + " for " +
                (percent ? std::to_string(percent) : std::string("<1")) + "%";
    }
  std::fprintf(stderr, "polydem: threads by share of steps: %s (fewer threads stepped faster on this machine "
               "then; --fixed-threads to keep them all)\n", shares.c_str());
}

// Each rank's share and traffic (POLYDEM_MPI_COUNTS set: README, MPI section): counted, not timed.
void print_link_counts(const Simulation& sim, const RankLink& link, std::int64_t steps) {
  const LinkCounts c = link.counts();
  const double n = double(std::max<std::int64_t>(1, steps));
  std::fprintf(stderr, "polydem: rank %d of %d: holds %zu of %zu bodies (%zu owned, %zu ghosts); per step: %.3g "
               "point-to-point messages, %.4g bytes; %.3g collectives, %.4g bytes of its own in them, %.4g bytes "
               "received\n",
               link.rank(), link.ranks(), sim.owned_bodies() + sim.ghost_bodies(), sim.bodies.size(),
               sim.owned_bodies(), sim.ghost_bodies(), double(c.parcels) / n, double(c.parcel_bytes) / n,
               double(c.collectives) / n, double(c.collective_bytes) / n, double(c.collective_bytes_in) / n);
  if (const RankContacts* r = sim.rank_contacts()) {
    std::fprintf(stderr, "polydem: rank %d of %d: last lists: %zu pairs, %zu candidate feature pairs; %.1f%% of the "
                 "weight; %zu cuts in %zu rebuilds; the scene's arrays hold %.0f bytes a body; its weights x %.3f (the cut "
                 "in time)\n", link.rank(), link.ranks(), r->pairs(), r->candidates(), 100.0 * r->load_share(),
                 r->cuts(), r->rebuilds(), double(sim.bodies.held_bytes()) / double(std::max<std::size_t>(1, sim.bodies.size())),
                 r->time_scale());
    const LinkCounts& b = r->rebuild_traffic();  // the share of the totals above spent at rebuilds
    const double k = double(std::max<std::size_t>(1, r->rebuilds()));
    std::fprintf(stderr, "polydem: rank %d of %d: per rebuild: %.3g point-to-point messages, %.4g bytes; %.3g "
                 "collectives, %.4g bytes of its own in them, %.4g bytes received\n", link.rank(), link.ranks(),
                 double(b.parcels) / k, double(b.parcel_bytes) / k, double(b.collectives) / k,
                 double(b.collective_bytes) / k, double(b.collective_bytes_in) / k);
  }
}

// Each rank's clock (POLYDEM_MPI_TIMES set): the run loop's wall and CPU seconds and the part of
// them inside MPI calls, by kind; the rest is the rank's work. Timed: read on a quiet machine.
void print_link_times(const RankLink& link, double loop_wall, double loop_cpu) {
  const LinkTimes t = link.times();
  std::fprintf(stderr, "polydem: rank %d of %d: loop %.3f s wall, %.3f s CPU; in MPI (wall / CPU s): ghost waits "
               "%.3f / %.3f, reductions %.3f / %.3f, gathers %.3f / %.3f\n", link.rank(), link.ranks(), loop_wall,
               loop_cpu, t.wall[LinkTimes::kExchange], t.cpu[LinkTimes::kExchange], t.wall[LinkTimes::kReduction],
               t.cpu[LinkTimes::kReduction], t.wall[LinkTimes::kGather], t.cpu[LinkTimes::kGather]);
}

}  // namespace

int cmd_run(const std::vector<std::string>& args, const RankLink* link) {
  const RunArgs a = parse_run_args(args, kRunHelp, true);
  Scene scene = load_scene(a.scene);
  if (a.body_order) scene.simulation.body_order = *a.body_order;
  const bool io = !link || link->rank() == 0;  // one message per run, whatever the rank count
  const int threads = a.threads ? *a.threads : scene.simulation.threads;
  if (threads > 0 && io) warn_threads(threads, scene, bool(a.threads));
  if (threads > 0) omp_set_num_threads(threads);
  const auto built = build(std::move(scene), link, a.resume);
  Simulation& sim = *built;
  if (io) warn_unsafe_step(sim);
  if (io) warn_fast_impacts(sim);
  RunOptions o;
  o.out_dir = a.out ? *a.out : sim.scene().output.dir;
  o.until = a.until;
  o.resume = a.resume;
  o.force = a.force;
  o.adapt_threads = !a.fixed_threads;
  const int team = omp_get_max_threads();
  if (io)
    std::fprintf(stderr, "polydem: %zu bodies, %zu drivers, dt = %.4g s%s, %s kernels, %d thread%s%s%s, output in %s\n",
                 sim.bodies.size(), sim.drivers.size(), sim.dt(), dt_note(sim).c_str(), kHasAvx ? "AVX" : "SSE2", team,
                 team > 1 ? "s" : "",
                 link ? (" x " + std::to_string(link->ranks()) + " ranks").c_str() : "",
                 team > 1 ? wait_note().c_str() : "", o.out_dir.c_str());
  if (RankContacts* r = sim.rank_contacts(); r && std::getenv("POLYDEM_CUT_TIMED")) r->time_by_clock();  // README: the cut in time
  const std::clock_t cpu_start = std::clock();
  const RunSummary s = run_simulation(sim, o);
  const double loop_cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;  // s, every thread of the process
  if (link && std::getenv("POLYDEM_MPI_COUNTS")) print_link_counts(sim, *link, s.steps);
  if (link && std::getenv("POLYDEM_MPI_TIMES")) print_link_times(*link, s.wall_seconds, loop_cpu);
  if (!io) return s.interrupted ? kExitInterrupted : 0;
  const ContactStats& c = sim.engine().stats();
  std::fprintf(stderr, "polydem: %lld steps in %.2f s (%.3g us per body-step), %zu rebuilds; ParaView: %s/scene.pvd\n",
               static_cast<long long>(s.steps), s.wall_seconds,
               1e6 * s.wall_seconds / std::max<double>(1.0, double(s.steps) * double(sim.bodies.size())),
               s.rebuilds, o.out_dir.c_str());
  print_thread_use(s.steps_at_threads);
  if (link) return s.interrupted ? kExitInterrupted : 0;  // the lists below are each rank's own
  std::fprintf(stderr, "polydem: last list: %zu body pairs, %zu driver pairs, %zu candidate feature pairs; %zu contacts\n",
               c.body_pairs, c.driver_pairs, c.slots, c.contacts);
  std::fprintf(stderr, "polydem: broad phase: %zu sphere tests in %zu rebuilds (%.3g per body per rebuild), %zu size classes, %.3g MB\n",
               c.broad_tests, c.rebuilds,
               double(c.broad_tests) / std::max<double>(1.0, double(c.rebuilds) * double(sim.bodies.size())),
               c.broad_levels, 1e-6 * double(c.broad_bytes));
  return s.interrupted ? kExitInterrupted : 0;
}

int cmd_check(const std::vector<std::string>& args) {
  const RunArgs a = parse_run_args(args, kCheckHelp, false);
  const auto sim = build(load_scene(a.scene));
  std::printf("scene: %s: valid\n", a.scene.c_str());
  print_counts(*sim);
  for (const std::string& w : check_run_limits(*sim, std::nullopt)) std::fprintf(stderr, "%s\n", w.c_str());
  warn_unsafe_step(*sim);
  warn_fast_impacts(*sim);
  return 0;
}

}  // namespace polydem
