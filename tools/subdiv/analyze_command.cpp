// `subdiv analyze SCHEME`: convergence and smoothness of a scheme. Surface schemes: the
// eigen-analysis at extraordinary vertices (faces, for dual schemes) for a range of
// valences; curve schemes: the symbol analysis. Reports as a table, JSON and SVG.
#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "shared_options.h"
#include "curve_report.h"
#include "surface_report.h"
#include "framework/analysis/curve/curve_scheme_analysis.h"
#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/pipeline/analysis_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/atomic_file.h"
#include "framework/util/checked_file_stream.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

struct AnalyzeArgs {
  std::string scheme;
  std::string valence = "3..12";
  std::string vtk_dir, json_file, svg_file;
  std::vector<std::string> params;
  std::string boundary_mode = "edges-and-corners";
  bool boundary = false;
  bool crease = false;
  bool corner = false;
  bool details = false;
  int level = 0;
  int max_ring = 5;
};


int parse_int(const std::string& text, const std::string& what) {
  try {
    size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size()) return v;
  } catch (...) {
  }
  throw Error(fmt::format("--valence: {} in {} is not a whole number", subdiv::quoted(text), subdiv::quoted(what)));
}

// "3..12", "5", "3,5,8"; the pipeline checks their range.
std::vector<int> parse_valences(const std::string& text) {
  std::vector<int> out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    const std::string part = text.substr(start, end - start);
    const size_t dots = part.find("..");
    if (dots != std::string::npos) {
      const int a = parse_int(part.substr(0, dots), text), b = parse_int(part.substr(dots + 2), text);
      if (a > b) throw Error(fmt::format("--valence {}: the range is empty", text));
      for (int n = a; n <= b; ++n) out.push_back(n);
    } else if (!part.empty()) {
      out.push_back(parse_int(part, text));
    }
    start = end + 1;
  }
  if (out.empty()) throw Error("--valence: give a valence, a range a..b or a list a,b,c");
  return out;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  write_file_atomically(file, [&](const std::filesystem::path& tmp) {
    CheckedFileStream out(tmp, file);  // a full disk is an error with the fix, never a short file
    out << text;
    out.close();
  });
}

void write_characteristic_maps(const std::filesystem::path& dir, const std::string& scheme,
                               const std::vector<SurfaceAnalysis>& analyses, const char* prefix) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir, ec))
    throw Error(fmt::format("--vtk {}: cannot create the directory", dir.string()));
  for (const auto& a : analyses) {
    const auto& cm = a.characteristic_map;
    if (!cm.computed || cm.mesh.face_count() == 0) continue;
    OutputLevel out;
    out.mesh = &cm.mesh;
    out.level = cm.refinement_steps;
    out.point_data.push_back(DataArray{"ring", 1, cm.ring, true});
    std::vector<double> radius(size_t(cm.mesh.vertex_count()));
    for (Index v = 0; v < cm.mesh.vertex_count(); ++v)
      radius[size_t(v)] = std::hypot(cm.mesh.positions[size_t(3 * v)], cm.mesh.positions[size_t(3 * v + 1)]);
    out.point_data.push_back(DataArray{"radius", 1, radius, false});
    write_vtp(dir / fmt::format("{}_{}characteristic_n{}.vtp", scheme, prefix, a.config.valence), out);
  }
}

void run_curve(const AnalyzeArgs& a) {
  const auto curve = load_curve_scheme_named(a.scheme, parse_params(a.params));
  const CurveSchemeAnalysis r = analyse_curve_scheme(*curve, a.level);
  print_safe("{}", curve_scheme_summary(r));
  if (!a.json_file.empty()) write_text(a.json_file, curve_scheme_json(r).dump(2) + "\n");
  if (!a.svg_file.empty())
    write_text(a.svg_file, eigenvalue_svg(r.analysis.eigen.eigenvalues,
                                          fmt::format("{}: local subdivision matrix eigenvalues", curve->name)));
  if (!a.vtk_dir.empty()) print_safe("(--vtk: curve schemes have no characteristic map to write)\n");
}

// A scheme whose rules refine no neighbourhood (weights that are not affine or not finite, a
// rule missing) has no analysis at any valence: that is an error in the scheme, not a verdict
// on it, and exits as one, before any report file is written.
void refuse_unanalysable(const Scheme& scheme, const std::vector<SurfaceAnalysis>& interior) {
  if (interior.empty() || std::any_of(interior.begin(), interior.end(),
                                      [](const SurfaceAnalysis& r) { return r.error.empty(); }))
    return;
  throw Error(fmt::format("scheme {} could not be analysed at any valence: {}; check its rules with `subdiv "
                          "validate{} {}`",
                          subdiv::quoted(scheme.name), interior.front().error, scheme_plugin_options(scheme),
                          scheme_argument(scheme)));
}

void run_surface(const AnalyzeArgs& a) {
  const auto scheme = load_scheme(a.scheme, parse_params(a.params));
  SurfaceAnalysisOptions options;
  options.features.boundary = boundary_from_name(a.boundary_mode);
  options.max_ring = a.max_ring;
  options.characteristic_map = true;
  const CentreKind centre = analysis_centre(*scheme);
  std::vector<SurfaceAnalysis> interior, boundary, crease, corner;
  const std::vector<int> valences = parse_valences(a.valence);
  ValenceAnalysisRequest request{scheme, {}, false, a.level, options};
  request.valences = valences;
  interior = analyse_valences(request);
  print_safe("scheme {} ({})\n", scheme->name, scheme->path);
  const bool level_dependent = scheme_is_level_dependent(*scheme);
  if (level_dependent)
    print_safe("non-stationary: weights depend on the level l; analysed with the weights of level {} (--level), "
               "as if every step used them\n",
               a.level);
  print_safe("analysed at {} (the centre of the invariant neighbourhood); S on the k-ring that maps to itself\n",
             centre == CentreKind::Face ? "an n-gon face: a dual scheme turns a valence-n vertex into one"
                                        : "a vertex of valence n");
  print_safe("\n{}", surface_table(interior));
  if (a.boundary) {
    request.valences = valences, request.boundary = true;
    boundary = analyse_valences(request);
    print_safe("\nboundary vertices (n ring edges, n - 1 faces{}):\n{}",
               centre == CentreKind::Face ? "; analysed at the face they become" : "", surface_table(boundary));
  }
  if (a.crease) {
    request.valences = valences, request.boundary = false, request.crease = true;
    crease = analyse_valences(request);
    print_safe("\ncrease vertices (n ring edges, sharp ring edges 0 and n/2{}):\n{}",
               centre == CentreKind::Face ? "; analysed at the face of the first side's sector" : "",
               surface_table(crease));
  }
  if (a.corner) {
    request.valences = valences, request.boundary = false, request.crease = false, request.corner = true;
    corner = analyse_valences(request);
    print_safe("\ncorner vertices (n ring edges, sharp ring edges 0, n/3 and 2n/3: three sectors):\n{}",
               surface_table(corner));
  }
  if (a.details) {
    for (const auto* list : {&interior, &boundary, &crease, &corner})
      for (const auto& r : *list) {
        print_safe("\n");
        for (const auto& line : surface_summary_lines(r)) print_safe("  {}\n", line);
      }
  } else {
    print_safe("\ncurvature (Peters & Reif 2004, lambda_1^2 against |lambda_3|):\n");
    for (const auto& r : interior)
      if (!r.curvature.empty()) print_safe("  n = {:>2}: {}\n", r.config.valence, r.curvature);
  }
  int c1 = 0;
  for (const auto& r : interior) c1 += r.c1;
  print_safe("\n{} of {} valences C1 (eigenvalue conditions and a regular, injective characteristic map)\n", c1,
             interior.size());
  refuse_unanalysable(*scheme, interior);
  if (!a.json_file.empty()) {
    nlohmann::json j = surface_report_json(interior);
    if (!boundary.empty()) {
      j["boundary_analyses"] = nlohmann::json::array();
      for (const auto& r : boundary) j["boundary_analyses"].push_back(surface_json(r));
    }
    if (!crease.empty()) {
      j["crease_analyses"] = nlohmann::json::array();
      for (const auto& r : crease) j["crease_analyses"].push_back(surface_json(r));
    }
    if (!corner.empty()) {
      j["corner_analyses"] = nlohmann::json::array();
      for (const auto& r : corner) j["corner_analyses"].push_back(surface_json(r));
    }
    j["stationary"] = !level_dependent;
    j["level"] = a.level;
    j["parameters"] = nlohmann::json::object();
    for (const auto& [k, v] : parse_params(a.params)) j["parameters"][k] = v;
    write_text(a.json_file, j.dump(2) + "\n");
  }
  if (!a.svg_file.empty())
    write_text(a.svg_file, spectrum_svg(interior, fmt::format("{}: eigenvalue moduli by valence", scheme->name)));
  if (!a.vtk_dir.empty()) {
    write_characteristic_maps(a.vtk_dir, scheme->name, interior, "");
    write_characteristic_maps(a.vtk_dir, scheme->name, boundary, "boundary_");
    write_characteristic_maps(a.vtk_dir, scheme->name, crease, "crease_");
    write_characteristic_maps(a.vtk_dir, scheme->name, corner, "corner_");
  }
}

}  // namespace

void add_analyze_command(CLI::App& app) {
  auto args = std::make_shared<AnalyzeArgs>();
  auto* cmd = app.add_subcommand("analyze", "Convergence and smoothness of a scheme: eigen-analysis at extraordinary "
                                            "vertices, or the symbol analysis of a curve scheme");
  cmd->add_option("scheme", args->scheme, "Scheme name (see `subdiv schemes`) or path to a .json file")->required();
  cmd->add_option("--valence", args->valence, "Valences to analyse (2..512; boundary, crease and corner vertices 2..64): a..b, n, or a list a,b,c")->capture_default_str();
  cmd->add_option("--vtk", args->vtk_dir, "Write each valence's characteristic map as a .vtp file into this directory");
  cmd->add_option("--json", args->json_file, "Write the report as JSON");
  cmd->add_option("--svg", args->svg_file, "Write the spectrum (eigenvalue moduli against valence) as an SVG plot");
  add_param_option(cmd, args->params);
  cmd->add_flag("--boundary", args->boundary, "Also analyse boundary vertices of each valence");
  cmd->add_flag("--crease", args->crease,
                "Also analyse crease vertices of each valence (infinitely sharp ring edges 0 and n/2)");
  cmd->add_flag("--corner", args->corner,
                "Also analyse corner vertices of each valence from 3 (infinitely sharp ring edges 0, n/3 and 2n/3; "
                "each of the three sectors judged as at a boundary)");
  add_boundary_option(cmd, "--boundary-interpolation", args->boundary_mode);
  cmd->add_flag("--details", args->details, "Print every valence's full analysis (eigenvalues, checks, masks)");
  cmd->add_option("--level", args->level, "Level whose weights are analysed (level-dependent schemes)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--max-ring", args->max_ring, "Largest k-ring tried as the invariant neighbourhood")
      ->check(CLI::Range(1, 8))
      ->capture_default_str();
  cmd->footer("Examples:\n  subdiv analyze catmull-clark --valence 3..12 --svg cc.svg --json cc.json\n"
              "  subdiv analyze loop --param beta=warren --vtk maps/\n  subdiv analyze four-point --param w=0.0625");
  cmd->callback([args] {
    if (scheme_kind_of(args->scheme) == "curve") run_curve(*args);
    else run_surface(*args);
  });
}

}  // namespace subdiv::cli
