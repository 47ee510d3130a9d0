#include "app/short_spin.hpp"

#include <cstdlib>
#include <cstring>

#include <strings.h>

#include <unistd.h>

namespace polydem {
namespace {

// libgomp's default spin holds a core for ~ms at each wait: on a shared machine the thread
// waited for then queues for the other core, and 2 threads ran 15-20x slower than 1 (README,
// "A slow core"); 1000 spins (~us) then sleep kept them faster than 1, and quiet times the same.
constexpr const char* kShortSpin = "1000";

// The user bound the threads: libgomp has bound this first image's thread to one place already,
// and a second image would inherit that one core for every thread (2 threads on 1 core).
bool threads_bound() {
  const char* bind = std::getenv("OMP_PROC_BIND");
  return (bind && strcasecmp(bind, "false") != 0) || std::getenv("OMP_PLACES") || std::getenv("GOMP_CPU_AFFINITY");
}

bool under_valgrind() {  // its tool would follow only the first image
  const char* preload = std::getenv("LD_PRELOAD");
  return preload && std::strstr(preload, "vgpreload");
}

}  // namespace

void run_again_with_short_spin(char** argv) {
  if (std::getenv("GOMP_SPINCOUNT") || std::getenv("OMP_WAIT_POLICY") || threads_bound() || under_valgrind()) return;
  if (setenv("GOMP_SPINCOUNT", kShortSpin, 1) != 0) return;
  execv("/proc/self/exe", argv);  // same process id, arguments and open files
  unsetenv("GOMP_SPINCOUNT");     // not run again: go on with libgomp's default, as the note says
}

std::string wait_note() {
  std::string note;
  for (const char* key : {"OMP_WAIT_POLICY", "GOMP_SPINCOUNT", "OMP_PROC_BIND", "OMP_PLACES"})
    if (const char* value = std::getenv(key)) note += std::string(", ") + key + "=" + value;
  return note;
}

}  // namespace polydem
