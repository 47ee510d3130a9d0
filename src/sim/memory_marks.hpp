#pragma once
// The peak memory of a run's phases, to size a run (issue 20): with POLYDEM_MEMORY set, each
// mark prints this process's peak resident size since the last mark (Linux's VmHWM, kB) and
// resets it (/proc/self/clear_refs), so the set-up, a resume's read and the steps each show
// their own peak. Nothing without the variable, or where /proc does not tell.
namespace polydem {

void memory_mark(const char* phase, int rank);

}  // namespace polydem
