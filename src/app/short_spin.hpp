// How OpenMP's waiting threads wait: a short spin unless the environment says otherwise.
#pragma once

#include <string>

namespace polydem {

// Starts the program again with GOMP_SPINCOUNT=1000 when the environment sets neither it nor
// OMP_WAIT_POLICY (libgomp reads them once, at load) and binds no threads (OMP_PROC_BIND,
// OMP_PLACES, GOMP_CPU_AFFINITY); returns when it does not.
void run_again_with_short_spin(char** argv);

// ", GOMP_SPINCOUNT=1000"-like text for the run's first line (the wait and the binding), or "".
std::string wait_note();

}  // namespace polydem
