#include "app/cmd_shape.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "polydem/error.hpp"
#include "polydem/shape_library.hpp"
#include "shape/hull.hpp"
#include "shape/length_text.hpp"
#include "shape/point_sources.hpp"
#include "shape/shp_io.hpp"

namespace polydem {
namespace {

const char* kShapeHelp =
    "usage: polydem shape COMMAND ...\n"
    "  info FILE [--json]      per shape: counts, radius, volume, centre of mass, I/m\n"
    "  hull INPUT --radius R --name NAME -o OUT.shp [--append]\n"
    "                          convex hull of a point list, .obj or .stl, as a .shp shape\n"
    "Run 'polydem shape COMMAND --help' for details.\n";

const char* kInfoHelp =
    "usage: polydem shape info FILE [--json]\n"
    "Reads a shape library (.shp Rockable format or .yaml) and prints, per shape: vertex,\n"
    "edge and face counts, Minkowski radius (m), volume of the rounded body (m^3), centre of\n"
    "mass in the frame the shape was given in (m), principal inertia per unit mass (m^2,\n"
    "ascending), bounding radius about the centre (m), whether the core is convex, and the\n"
    "relative error bound of the mass properties (exact: closed forms; non-convex shapes that\n"
    "are not apart balls: a quadrature). --json prints a JSON list instead.\n";

const char* kHullHelp =
    "usage: polydem shape hull INPUT --radius R --name NAME -o OUT.shp [--append]\n"
    "INPUT: a point list (one 'x y z' a line, '#' comments), a Wavefront .obj (v lines) or\n"
    "an .stl (ASCII or binary), in metres. R: the Minkowski radius, in metres or with a unit\n"
    "(\"0.5 mm\", \"0.05 cm\"). Coplanar triangles are merged into polygon faces; with R > 0\n"
    "one point gives a sphere, collinear points a segment, coplanar points a plate.\n"
    "-o writes OUT.shp (replaced; --append adds the shape to the shapes already in it).\n";

bool wants_help(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

[[noreturn]] void usage_error(const std::string& what, const char* help) {
  const std::string topic = help == kShapeHelp ? "shape" : help == kInfoHelp ? "shape info" : "shape hull";
  throw InputError(what + " (see 'polydem " + topic + " --help')");
}

std::string json_vec(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", v.x(), v.y(), v.z());
  return buf;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

void print_json(const std::vector<Shape>& shapes) {
  std::cout << "[";
  for (size_t i = 0; i < shapes.size(); ++i) {
    const Shape& s = shapes[i];
    char numbers[200];
    std::snprintf(numbers, sizeof numbers,
                  "\"radius\": %.17g, \"volume\": %.17g, \"bounding_radius\": %.17g, \"mass_error\": %.3g",
                  s.radius, s.volume, s.bounding_radius, s.mass_error);
    std::cout << (i ? ",\n " : "\n ") << "{\"name\": " << json_string(s.name)
              << ", \"nv\": " << s.vertices.size() << ", \"ne\": " << s.edges.size()
              << ", \"nf\": " << s.faces.size() << ", \"convex\": " << (s.convex ? "true" : "false")
              << ", \"surface\": " << (s.surface ? "true" : "false") << ", " << numbers
              << ", \"center\": " << json_vec(s.input_center)
              << ", \"inertia_per_mass\": " << json_vec(s.inertia_per_mass) << "}";
  }
  std::cout << "\n]\n";
}

// "exact" for closed forms, else the quadrature's relative error bound.
std::string mass_accuracy(const Shape& s) {
  if (s.mass_error == 0.0) return "exact";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", s.mass_error);
  return buf;
}

void print_table(const std::vector<Shape>& shapes) {
  std::printf("%-16s %4s %4s %4s %6s %11s %11s %35s %35s %11s %8s\n", "name", "nv", "ne", "nf", "convex",
              "radius m", "volume m^3", "centre of mass (input frame) m", "I/m principal m^2", "bounding m",
              "mass err");
  for (const Shape& s : shapes) {
    const Vec3& c = s.input_center;
    const Vec3& i = s.inertia_per_mass;
    std::printf("%-16s %4zu %4zu %4zu %6s %11.4e %11.4e %11.4e %11.4e %11.4e %11.4e %11.4e %11.4e %11.4e %8s\n",
                s.name.c_str(), s.vertices.size(), s.edges.size(), s.faces.size(), s.convex ? "yes" : "no",
                s.radius, s.volume, c.x(), c.y(), c.z(), i.x(), i.y(), i.z(), s.bounding_radius,
                mass_accuracy(s).c_str());
  }
  for (const Shape& s : shapes)
    std::printf("%s: convex: %s%s, mass properties: %s\n", s.name.c_str(), s.convex ? "yes" : "no",
                s.surface ? " (open surface)" : "",
                s.mass_error == 0.0 ? "exact (closed form or given)"
                                    : ("quadrature, relative error below " + mass_accuracy(s)).c_str());
}

int info(const std::vector<std::string>& args) {
  if (wants_help(args)) return std::cout << kInfoHelp, 0;
  std::string file;
  bool json = false;
  for (const auto& a : args) {
    if (a == "--json")
      json = true;
    else if (!a.empty() && a[0] == '-')
      usage_error("shape info: unknown option '" + a + "'", kInfoHelp);
    else if (file.empty())
      file = a;
    else
      usage_error("shape info: one FILE only, got '" + file + "' and '" + a + "'", kInfoHelp);
  }
  if (file.empty()) usage_error("shape info: missing FILE", kInfoHelp);
  const std::vector<Shape> shapes = read_shape_file(file);
  json ? print_json(shapes) : print_table(shapes);
  return 0;
}

// "--radius R --name NAME -o OUT" into a map, the one positional word into "input".
std::map<std::string, std::string> hull_options(const std::vector<std::string>& args) {
  std::map<std::string, std::string> opt;
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a == "--append") {
      opt[a] = "yes";
    } else if (a == "--radius" || a == "--name" || a == "-o") {
      if (k + 1 >= args.size()) usage_error("shape hull: " + a + " needs a value", kHullHelp);
      opt[a] = args[++k];
    } else if (!a.empty() && a[0] == '-') {
      usage_error("shape hull: unknown option '" + a + "'", kHullHelp);
    } else if (opt.count("input")) {
      usage_error("shape hull: one INPUT only, got '" + opt["input"] + "' and '" + a + "'", kHullHelp);
    } else {
      opt["input"] = a;
    }
  }
  for (const char* need : {"input", "--radius", "--name", "-o"})
    if (!opt.count(need))
      usage_error(std::string("shape hull: missing ") + (opt.count("input") ? need : "INPUT"), kHullHelp);
  return opt;
}

int hull(const std::vector<std::string>& args) {
  if (wants_help(args)) return std::cout << kHullHelp, 0;
  auto opt = hull_options(args);
  const auto radius = parse_length(opt["--radius"]);
  if (!radius)
    throw InputError(input_message("command line", 0, "--radius",
                                   "'" + opt["--radius"] + "' is not a length (write 0.0005 or \"0.5 mm\")"));
  Shape shape;
  try {
    shape = build_hull_shape(read_points(opt["input"]), *radius, opt["--name"]);
  } catch (const InputError& e) {  // the hull names the shape; say which input it came from
    const std::string what = e.what();
    if (what.rfind(opt["input"], 0) == 0) throw;
    throw InputError(opt["input"] + ": " + what);
  }
  std::vector<Shape> shapes;
  if (opt.count("--append") && std::ifstream(opt["-o"])) shapes = read_shp_file(opt["-o"]);
  for (const Shape& s : shapes)
    if (s.name == shape.name)
      throw InputError(
          input_message(opt["-o"], 0, "name", "shape '" + shape.name + "' is already in this file"));
  shapes.push_back(shape);
  write_shp_file(opt["-o"], shapes);
  std::cout << "shape '" << shape.name << "': " << shape.vertices.size() << " vertices, "
            << shape.edges.size() << " edges, " << shape.faces.size() << " faces -> " << opt["-o"] << "\n";
  return 0;
}

}  // namespace

int cmd_shape(const std::vector<std::string>& args) {
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h") {
      (args.empty() ? std::cerr : std::cout) << kShapeHelp;
      return args.empty() ? 1 : 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "info") return info(rest);
    if (args[0] == "hull") return hull(rest);
    usage_error("shape: unknown command '" + args[0] + "' (info or hull)", kShapeHelp);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace polydem
