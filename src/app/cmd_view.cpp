#include "app/cmd_view.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "polydem/error.hpp"

namespace polydem {

namespace fs = std::filesystem;

namespace {

const char* kPlotHelp =
    "usage: polydem plot OUT_DIR [-o DIR]\n"
    "One PNG per CSV of a run's output folder (energy budget and balance residual, driver\n"
    "forces, flow probes with their steady rate, repose angle, fluid probes), into DIR\n"
    "(default OUT_DIR/plots), with DIR/plots.txt listing each file and its title.\n"
    "Needs /usr/bin/python3 with matplotlib (Debian: python3-matplotlib).\n";

const char* kRenderHelp =
    "usage: polydem render OUT_DIR [--time T | --every K] [--color velocity|group|id|radius]\n"
    "                      [--size WxH] -o FILE.png|FILE.mp4|FILE.gif\n"
    "Draws bodies.pvd and drivers.pvd headless with VTK: side view with gravity down, camera\n"
    "on the bodies, drivers translucent, a colour bar and the time. A .png is the frame at time\n"
    "T (default: the last); .mp4 or .gif is every K-th frame (default 1) through ffmpeg.\n"
    "Needs /usr/bin/python3 with VTK (python3-vtk9), xvfb-run when there is no display\n"
    "(xvfb), and ffmpeg for videos.\n";

bool wants_help(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

// The folder of the running binary (/proc/self/exe), or "" when unknown.
fs::path binary_folder() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// The script NAME: $POLYDEM_SCRIPTS, then share/polydem beside an installed binary, then the
// source tree the binary was built from.
std::string find_script(const std::string& name) {
  std::vector<fs::path> places;
  if (const char* dir = std::getenv("POLYDEM_SCRIPTS")) places.emplace_back(dir);
  if (const fs::path bin = binary_folder(); !bin.empty()) places.push_back(bin / ".." / "share" / "polydem");
  places.emplace_back(fs::path(POLYDEM_SOURCE_DIR) / "tools" / "view");
  std::string tried;
  for (const fs::path& p : places) {
    if (fs::exists(p / name)) return (p / name).lexically_normal().string();
    tried += " " + (p / name).string();
  }
  throw InputError("cannot find the script " + name + " (looked at" + tried + "; set POLYDEM_SCRIPTS to its folder)");
}

std::string python() {
  const char* p = std::getenv("POLYDEM_PYTHON");  // Debian's, where python3-vtk9 and matplotlib live
  return p ? p : "/usr/bin/python3";
}

// Runs argv, waits, and returns its exit code (2 when it could not start or was killed).
int run(const std::vector<std::string>& argv) {
  std::vector<char*> c_argv;
  for (const std::string& a : argv) c_argv.push_back(const_cast<char*>(a.c_str()));
  c_argv.push_back(nullptr);
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execvp(c_argv[0], c_argv.data());
    std::fprintf(stderr, "error: cannot run %s (is it installed? tools/setup.sh installs it)\n", c_argv[0]);
    ::_exit(127);
  }
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) < 0) return 2;
  if (!WIFEXITED(status)) return 2;
  const int code = WEXITSTATUS(status);
  return code == 127 ? 2 : code;
}

// True when display :N looks taken: its lock file in /tmp or its socket (abstract or path,
// listed in /proc/net/unix) seen, which a server of another container may own.
bool display_taken(int n) {
  const std::string name = "/tmp/.X11-unix/X" + std::to_string(n);
  if (fs::exists("/tmp/.X" + std::to_string(n) + "-lock") || fs::exists(name)) return true;
  std::ifstream sockets("/proc/net/unix");
  for (std::string line; std::getline(sockets, line);) {
    const std::size_t at = line.find(name);
    if (at != std::string::npos && at + name.size() == line.size()) return true;
  }
  return false;
}

// A free display number drawn at random, so renders started at once (here or in a container
// sharing the network) do not meet on one number.
int free_display() {
  std::random_device seed;
  std::uniform_int_distribution<int> pick(100, 29999);
  int n = pick(seed);
  while (display_taken(n)) n = n < 29999 ? n + 1 : 100;
  return n;
}

// Runs argv with an X server of its own (VTK's GL needs one). When the program aborts on the
// X connection (exit 134: VTK's "bad X server connection"), tries twice more on new numbers.
int run_under_xvfb(const std::vector<std::string>& argv) {
  for (int attempt = 1;; ++attempt) {
    const int n = free_display();
    std::vector<std::string> wrapped{"xvfb-run", "-a", "-n", std::to_string(n)};
    wrapped.insert(wrapped.end(), argv.begin(), argv.end());
    const int code = run(wrapped);
    if (code != 134) return code;
    std::fprintf(stderr, "render: the drawing under the X server :%d aborted (try %d of 3)\n", n, attempt);
    if (attempt == 3) return 2;
  }
}

std::string output_folder(const std::string& dir) {
  if (!fs::is_directory(dir)) throw InputError(dir + ": no such output folder");
  return dir;
}

}  // namespace

int cmd_plot(const std::vector<std::string>& args) {
  if (wants_help(args)) return std::fputs(kPlotHelp, stdout), 0;
  std::string dir, png_dir;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "-o" && k + 1 < args.size()) png_dir = args[++k];
    else if (dir.empty() && args[k][0] != '-') dir = args[k];
    else throw InputError("plot: unexpected argument '" + args[k] + "' (see 'polydem plot --help')");
  }
  if (dir.empty()) throw InputError("plot: which output folder? (see 'polydem plot --help')");
  output_folder(dir);
  if (png_dir.empty()) png_dir = (fs::path(dir) / "plots").string();
  return run({python(), find_script("plot.py"), dir, png_dir});
}

int cmd_render(const std::vector<std::string>& args) {
  if (wants_help(args)) return std::fputs(kRenderHelp, stdout), 0;
  std::string dir, out;
  std::vector<std::string> options;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    const bool valued = a == "--time" || a == "--every" || a == "--color" || a == "--size" || a == "-o";
    if (valued && k + 1 < args.size()) {
      if (a == "-o") out = args[++k];
      else options.insert(options.end(), {a, args[++k]});
    } else if (dir.empty() && a[0] != '-') {
      dir = a;
    } else {
      throw InputError("render: unexpected argument '" + a + "' (see 'polydem render --help')");
    }
  }
  if (dir.empty() || out.empty()) throw InputError("render: needs OUT_DIR and -o FILE (see 'polydem render --help')");
  output_folder(dir);
  std::vector<std::string> argv{python(), find_script("render.py"), dir, out};
  argv.insert(argv.end(), options.begin(), options.end());
  const char* display = std::getenv("DISPLAY");
  if (display && *display) return run(argv);
  return run_under_xvfb(argv);
}

}  // namespace polydem
