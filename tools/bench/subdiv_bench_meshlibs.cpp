// subdiv-bench-meshlibs: SubdivKit against OpenMesh's and CGAL's subdividers (√3,
// Doo-Sabin, modified butterfly, Loop, Catmull-Clark) on large generated closed meshes,
// single-threaded, each measurement in its own process (meshlibs_worker.h), the outputs
// checked against each other by position (meshlibs_check.h). docs/benchmarks.md, "Other
// schemes: OpenMesh and CGAL", says how to read the output.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "meshlibs_check.h"
#include "meshlibs_mesh.h"
#include "meshlibs_sides.h"
#include "meshlibs_worker.h"

namespace subdiv_bench {
namespace {

constexpr double kTargetRatio = 1.0 / 3.0;  // the target: at least 3x faster

// What each library's subdivider computes on closed meshes, from its source, against the
// shipped scheme file (printed once per pair, so the output says what was compared).
const std::map<std::string, std::string>& scheme_notes() {
  static const std::map<std::string, std::string> notes = {
      {"sqrt3/openmesh", "Sqrt3T.hh: Kobbelt's alpha_n = (4 - 2 cos(2 pi/n))/9 and face centroids, as sqrt3.json"},
      {"sqrt3/cgal", "Sqrt3_mask_3: Kobbelt's alpha_n = (4 - 2 cos(2 pi/n))/9 and face centroids, as sqrt3.json"},
      {"doo-sabin/cgal", "DooSabin_mask_3: Doo-Sabin's (n+5)/(4n), (3 + 2 cos(2 pi k/n))/(4n) (9,3,1,3 /16 on "
                         "quads), as doo-sabin.json"},
      {"modified-butterfly/openmesh",
       "ModifiedButterFlyT.hh: Zorin-Schroeder-Sweldens, the 10-point stencil between valence-6 ends, s_j (valence "
       "3, 4, >= 5) at one extraordinary end, the average at two, as modified-butterfly.json"},
      {"loop/openmesh", "LoopT.hh: Loop's beta_n = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n (not Warren's), loop.json's "
                        "default beta=loop"},
      {"loop/cgal", "Loop_mask_3: Loop's beta_n (written with Cn = n beta_n; 1/16 at valence 6), loop.json's "
                    "default beta=loop"},
      {"catmull-clark/openmesh", "CatmullClarkT: Catmull-Clark's face, edge and vertex points, as catmull-clark.json"},
      {"catmull-clark/cgal", "CatmullClark_mask_3: Catmull-Clark's face, edge and vertex points, as catmull-clark.json"},
  };
  return notes;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

std::vector<int> parse_levels(const std::string& text) {
  std::vector<int> levels;
  for (const std::string& item : split_list(text)) {
    const int level = std::atoi(item.c_str());
    if (level < 1 || level > 4) throw std::invalid_argument("--levels: each level must be 1 to 4, got '" + item + "'");
    levels.push_back(level);
  }
  if (levels.empty()) throw std::invalid_argument("--levels: give a comma list such as 1,2");
  return levels;
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string number(double x, const char* format = "%.1f") {
  char text[32];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

struct Options {
  std::vector<std::string> schemes, libraries;
  std::vector<int> levels;
  std::vector<bool> extraordinary;  // per mesh variant
  MeshlibsJob base;
  bool check = true;
  double tolerance = 1e-9;
};

// One output line for a scheme, level and library: times (the warm wall-clock total is the
// headline; user time and the cold run follow), memory and the check.
std::string result_line(const MeshlibsJob& job, const WorkerOutcome& ours, const WorkerOutcome& theirs,
                        const Options& options, bool& failed) {
  std::string line = job.scheme + " library=" + job.library + " mesh=" + job.mesh + " level=" + std::to_string(job.level);
  auto field = [&](const std::string& name, const std::string& value) { line += " " + name + "=" + value; };
  const WorkerReport& a = ours.report;
  const WorkerReport& b = theirs.report;
  const bool both = ours.ok && theirs.ok;
  field("base_faces", std::to_string(ours.ok ? a.base_faces : b.base_faces));
  field("refined_faces", ours.ok ? std::to_string(a.faces) : "n/a");
  auto times = [&](const char* name, bool ok, const Clocks& c, bool user) {
    field(name, ok ? number(user ? c.user_ms : c.wall_ms) : "n/a");
  };
  auto ratio = [&](const char* name, double x, double y) { field(name, both && y > 0 ? number(x / y, "%.2f") : "n/a"); };
  times("subdivkit_ms", ours.ok, a.warm.total(), false);
  times("other_ms", theirs.ok, b.warm.total(), false);
  ratio("ratio", a.warm.total().wall_ms, b.warm.total().wall_ms);
  times("subdivkit_setup_ms", ours.ok, a.warm.setup, false);
  times("other_setup_ms", theirs.ok, b.warm.setup, false);
  ratio("refine_ratio", (a.warm.total().wall_ms - a.warm.setup.wall_ms), (b.warm.total().wall_ms - b.warm.setup.wall_ms));
  // SubdivKit's refinement in its two parts (the others refine topology and points in one pass).
  times("subdivkit_topo_ms", ours.ok, a.warm.topo, false);
  times("subdivkit_geom_ms", ours.ok, a.warm.geom(), false);
  if (ours.ok)
    field("subdivkit_points", "kernel:" + std::to_string(a.kernel_points) + ",plan:" + std::to_string(a.plan_points) +
                                  ",generic:" + std::to_string(a.generic_points) +
                                  ",flat:" + std::to_string(a.flat_points));
  times("subdivkit_user_ms", ours.ok, a.warm.total(), true);
  times("other_user_ms", theirs.ok, b.warm.total(), true);
  ratio("user_ratio", a.warm.total().user_ms, b.warm.total().user_ms);
  times("subdivkit_cold_ms", ours.ok, a.cold.total(), false);
  times("other_cold_ms", theirs.ok, b.cold.total(), false);
  ratio("cold_ratio", a.cold.total().wall_ms, b.cold.total().wall_ms);
  field("subdivkit_peak_mb", ours.ok ? number(a.peak_mb) : "n/a");
  field("other_peak_mb", theirs.ok ? number(b.peak_mb) : "n/a");
  // On a busy machine wall-clock time includes waiting for a core; user time does not.
  if (both) field("target_3x", a.warm.total().wall_ms <= kTargetRatio * b.warm.total().wall_ms ? "met" : "not_met");
  if (both) field("target_3x_user", a.warm.total().user_ms <= kTargetRatio * b.warm.total().user_ms ? "met" : "not_met");
  if (!ours.ok) field("subdivkit_error", "\"" + ours.error + "\""), failed = true;
  if (!theirs.ok) field("other_error", "\"" + theirs.error + "\""), failed = true;
  for (const WorkerOutcome* o : {&ours, &theirs})
    if (o->ok && !o->report.warm_digest_same) field("warm_bits", "DIFFERENT"), failed = true;
  if (!both || !options.check) {
    field("check", "off");
    return line;
  }
  std::string problem;
  if (a.vertices != b.vertices) problem = "vertex counts differ (" + std::to_string(a.vertices) + " vs " + std::to_string(b.vertices) + ")";
  else if (a.faces != b.faces) problem = "face counts differ (" + std::to_string(a.faces) + " vs " + std::to_string(b.faces) + ")";
  PointSetMatch match;
  if (problem.empty()) {
    match = match_point_sets(a.records, b.records, options.tolerance);
    if (!match.ok) problem = match.problem.empty() ? "points further apart than " + number(options.tolerance, "%.3g") : match.problem;
  }
  field("check", problem.empty() ? "ok" : "FAIL");
  if (match.compared > 0) field("maxdiff", number(match.maxdiff, "%.3g"));
  if (problem.empty()) field("checked", std::to_string(match.compared) + "/" + std::to_string(2 * a.vertices));
  else field("reason", "\"" + problem + "\""), failed = true;
  return line;
}

bool library_has(const std::string& library, const std::string& scheme) {
  const SideRequest request{scheme, 1, true};
  return library == "openmesh" ? bool(openmesh_side(request)) : bool(cgal_side(request));
}

int run(const Options& options) {
  double load[3] = {-1, -1, -1};
  ::getloadavg(load, 3);
  std::printf("# subdiv-bench-meshlibs: cpu=\"%s\" threads=1 warm_repeat=%d openmesh=%s cgal=%s last_level=%s "
              "loadavg=%.2f %.2f %.2f\n",
              cpu_name().c_str(), options.base.repeat, openmesh_version().c_str(), cgal_version().c_str(),
              options.base.last_level_full ? "full" : "faces", load[0], load[1], load[2]);
  std::printf("# times: warm wall-clock totals (setup + refinement), ratio = subdivkit_ms / other_ms, "
              "target_3x: ratio <= 0.33 (target_3x_user: the same in user time)\n");
  std::fflush(stdout);
  bool failed = false;
  for (const std::string& scheme : options.schemes) {
    std::vector<std::string> libraries;
    for (const std::string& library : options.libraries) {
      if (!library_has(library, scheme)) {
        const bool built = (library == "openmesh" ? openmesh_version() : cgal_version()) != "none";
        std::printf("# %s/%s: %s\n", scheme.c_str(), library.c_str(),
                    built ? "the library has no such subdivider" : "not built in (install its -dev package, rebuild)");
        continue;
      }
      libraries.push_back(library);
      std::printf("# %s/%s: %s\n", scheme.c_str(), library.c_str(), scheme_notes().at(scheme + "/" + library).c_str());
    }
    for (bool extraordinary : options.extraordinary)
      for (int level : options.levels) {
        MeshlibsJob job = options.base;
        job.scheme = scheme;
        job.level = level;
        job.mesh = mesh_kind_for(scheme, extraordinary);
        job.library = "subdivkit";
        if (!options.check) job.check_max = -1;
        const WorkerOutcome ours = run_meshlibs_worker(job);
        if (libraries.empty()) {
          bool ignored = false;
          std::printf("%s\n", result_line(job, ours, WorkerOutcome{false, "no other library", {}}, options, ignored).c_str());
          failed |= !ours.ok;
        }
        for (const std::string& library : libraries) {
          job.library = library;
          const WorkerOutcome theirs = run_meshlibs_worker(job);
          std::printf("%s\n", result_line(job, ours, theirs, options, failed).c_str());
          std::fflush(stdout);
        }
      }
  }
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace subdiv_bench

int main(int argc, char** argv) {
  using namespace subdiv_bench;
  CLI::App app{
      "subdiv-bench-meshlibs: times SubdivKit against OpenMesh's and CGAL's uniform subdividers on large\n"
      "generated closed meshes (a torus of triangles or quads), single-threaded, each library in its own\n"
      "process, once cold and --repeat times warm. One line per scheme, level and library: subdivkit_ms,\n"
      "other_ms and ratio = subdivkit_ms / other_ms (warm wall-clock, each library's mesh setup included\n"
      "and shown apart), user and cold times, peak memory, and whether the two libraries computed the same\n"
      "points (check=ok). Exits 1 when a check or a run fails. See docs/benchmarks.md."};
  Options options;
  options.base.faces = 1'000'000;
  options.base.check_max = 200'000;
  std::string schemes = "sqrt3,doo-sabin,modified-butterfly,loop", libraries = "openmesh,cgal", levels = "1";
  std::string mesh = "regular", check = "sample", last_level = "full";
  app.add_option("--faces", options.base.faces, "approximate face count of the generated base mesh")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t(8), std::int64_t(20'000'000)));
  app.add_option("--schemes", schemes, "comma list: sqrt3, doo-sabin, modified-butterfly, loop, catmull-clark")
      ->capture_default_str();
  app.add_option("--library", libraries, "comma list: openmesh, cgal")->capture_default_str();
  app.add_option("--levels", levels, "comma list of levels, e.g. 1,2 (level 2 of 1M triangles: 9M faces "
                                     "for sqrt3, 16M for Loop and butterfly)")
      ->capture_default_str();
  app.add_option("--repeat", options.base.repeat, "warm repetitions after the cold one and one unmeasured; the best "
                                                  "is reported")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--mesh", mesh, "regular (tri-torus: valence 6; torus: valence 4), extraordinary (tri-torus-ev: "
                                 "valences 3 to 8; torus-ev: 3, 4 and 6), or both")
      ->capture_default_str()
      ->check(CLI::IsMember({"regular", "extraordinary", "both"}));
  app.add_option("--check", check, "compare the libraries' points: sample (about --check-max points), full, or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"sample", "full", "off"}));
  app.add_option("--check-max", options.base.check_max, "points sampled per side with --check sample")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t(-1), std::int64_t(1) << 40));
  app.add_option("--tolerance", options.tolerance, "largest coordinate difference between partners")
      ->capture_default_str();
  app.add_option("--last-level", last_level,
                 "SubdivKit's last level: full (edges and vertex rings, a mesh as navigable as OpenMesh's and CGAL's "
                 "results) or faces (faces only, RefineOptions::faces_only_last_level)")
      ->capture_default_str()
      ->check(CLI::IsMember({"full", "faces"}));
  std::string worker_library, worker_mesh;
  int worker_fd = -1;
  app.add_option("--worker", worker_library)->group("");  // internal: run one measurement
  app.add_option("--worker-fd", worker_fd)->group("");
  app.add_option("--worker-mesh", worker_mesh)->group("");
  CLI11_PARSE(app, argc, argv);
  options.base.last_level_full = last_level == "full";
  try {
    if (!worker_library.empty()) {
      MeshlibsJob job = options.base;
      job.library = worker_library;
      job.scheme = schemes;
      job.mesh = worker_mesh;
      job.level = std::stoi(levels);
      return meshlibs_worker_main(job, worker_fd);
    }
    options.schemes = split_list(schemes);
    for (const std::string& s : options.schemes)
      if (!scheme_notes().count(s + "/openmesh") && !scheme_notes().count(s + "/cgal"))
        throw std::invalid_argument("--schemes: unknown scheme '" + s + "'");
    options.libraries = split_list(libraries);
    for (const std::string& l : options.libraries)
      if (l != "openmesh" && l != "cgal") throw std::invalid_argument("--library: unknown library '" + l + "'");
    options.levels = parse_levels(levels);
    options.extraordinary = mesh == "both" ? std::vector<bool>{false, true} : std::vector<bool>{mesh == "extraordinary"};
    options.check = check != "off";
    if (check == "full") options.base.check_max = 0;
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subdiv-bench-meshlibs: %s\n", e.what());
    return 2;
  }
}
