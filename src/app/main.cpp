// polydem: the command-line program. Exit codes: 0 ok, 1 bad input, 2 runtime failure,
// 3 interrupted by SIGINT or SIGTERM (a checkpoint written).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <malloc.h>

#include "app/cmd_run.hpp"
#include "app/cmd_shape.hpp"
#include "app/cmd_view.hpp"
#include "app/mpi_session.hpp"
#include "app/short_spin.hpp"
#include "polydem/error.hpp"

namespace {

const char* kUsage =
    "polydem: Discrete Element Method for rigid spheropolyhedra\n"
    "\n"
    "usage:\n"
    "  polydem run SCENE.yaml [--out DIR] [--threads N] [--until T] [--resume CHECKPOINT]\n"
    "  polydem check SCENE.yaml           validate; print counts, masses, critical and chosen dt\n"
    "  polydem shape info FILE [--json]   per shape: counts, radius, volume, centre, inertia\n"
    "  polydem shape hull INPUT --radius R --name NAME -o OUT.shp\n"
    "  polydem plot OUT_DIR [-o DIR]      one PNG per CSV of a run (energy budget, forces, probes)\n"
    "  polydem render OUT_DIR [--time T|--every K] [--color velocity|group|...] -o PNG|MP4|GIF\n"
    "\n"
    "`polydem COMMAND --help` describes each command.\n";

// Blocks of 1 MiB or more (a large scene's per-body and per-pair arrays) are mapped apart
// and returned to the system when freed. glibc's default threshold grows to the largest block
// freed (up to 32 MiB), after which a rebuild's arrays come from the heap, whose freed space
// stays resident: 91k spheres peaked ~13 MB higher that way (README, Benchmarks, memory).
// Not lower: at 128 KiB a 2,000-body pour page-faulted 6.5 times as often (its rebuilds' arrays).
void map_large_blocks_apart() {
#ifdef __GLIBC__
  if (!std::getenv("MALLOC_MMAP_THRESHOLD_")) mallopt(M_MMAP_THRESHOLD, 1024 * 1024);  // bytes; the user's setting wins
#endif
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && !std::strcmp(argv[1], "run")) polydem::run_again_with_short_spin(argv);  // before MPI starts
  map_large_blocks_apart();
  const polydem::MpiSession mpi(argc, argv);
  // Many ranks share `run` alone; the rest, or a build without MPI, stop at once, every rank
  // with exit 1, rank 0 saying why.
  const bool many = mpi.ranks() > 1, io = mpi.rank() == 0;
  if (many && (!mpi.link() || argc < 2 || std::strcmp(argv[1], "run") != 0)) {
    if (io)
      std::fprintf(stderr, "error: %d MPI ranks: %s; use mpirun -np 1 and --threads N\n", mpi.ranks(),
                   mpi.link() ? "only 'polydem run' runs over many ranks" : "this build has no MPI");
    return 1;
  }
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "run") return polydem::cmd_run(args, many ? mpi.link() : nullptr);
    if (command == "check") return polydem::cmd_check(args);
    if (command == "shape") return polydem::cmd_shape(args);
    if (command == "plot") return polydem::cmd_plot(args);
    if (command == "render") return polydem::cmd_render(args);
    std::fprintf(stderr, "polydem: unknown command '%s' (commands: run, check, shape, plot, render)\n",
                 command.c_str());
    return 1;
  } catch (const polydem::InputError& e) {  // every rank meets a bad scene: rank 0 says it
    if (io) std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {  // the state is the same on every rank: so is the failure
    if (io) std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
