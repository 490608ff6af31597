// `subdiv parameterize MESH -o OUT [--boundary-shape circle|square] [--corners A,B,C,D]
// [--weights uniform|mean-value]`: texture coordinates for a disc-like mesh by Tutte's
// embedding (framework/parameterize, docs/parameterize.md), written as OBJ vt or a .vtp's
// active texture coordinates, which `subdiv refine` carries as face-varying data.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.h"
#include "framework/io/formats.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/parameterize/parameterize_mesh.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "level_output.h"
#include "safe_print.h"

namespace subdiv::cli {
namespace {

struct ParameterizeArgs {
  std::string mesh, output, boundary = "circle", weights = "uniform";
  std::vector<Index> corners;
  bool quiet = false;
  bool force = false;  // --force: -o may be the input mesh
};

void check_output(const std::string& out) {
  const std::string ext = lowercase_extension(out);
  if (ext == ".obj" || ext == ".vtp" || ext == ".ply" || ext == ".off") return;
  throw Error(fmt::format("cannot write texture coordinates to {}: use .obj (vt), .vtp (active texture coordinates), "
                          ".ply or .off",
                          subdiv::quoted(out)));
}

void run(const ParameterizeArgs& a) {
  check_output(a.output);
  check_output_not_input(a.mesh, a.output, a.force);
  TutteOptions o;
  o.boundary = boundary_shape_from_name(a.boundary, "--boundary-shape");
  o.weights = tutte_weights_from_name(a.weights, "--weights");
  if (!a.corners.empty() && o.boundary != BoundaryShape::Square)
    throw Error("--corners places the corners of a square boundary; add --boundary-shape square");
  o.corners = a.corners;
  const ParameterizedMesh done = parameterize_mesh(read_mesh(a.mesh), o, a.mesh);
  write_mesh(a.output, done.mesh);
  if (a.quiet) return;
  for (const auto& note : done.notes) print_safe("{}: {}\n", a.mesh, note);
  print_safe("{}: {} vertices ({} on the boundary{}) mapped to the {} with {} weights -> {}\n", a.mesh,
             done.mesh.vertex_count(), done.embedding.boundary.size(),
             done.embedding.corners.empty()
                 ? std::string()
                 : fmt::format(", corners {}", fmt::join(done.embedding.corners, " ")),
             a.boundary == "square" ? "unit square" : "unit circle", a.weights, a.output);
}

}  // namespace

void add_parameterize_command(CLI::App& app) {
  auto args = std::make_shared<ParameterizeArgs>();
  auto* cmd = app.add_subcommand(
      "parameterize", "Give a disc-like mesh texture coordinates by Tutte's embedding (one sparse solve)");
  cmd->add_option("mesh", args->mesh,
                  "Input mesh: a topological disc (connected, one boundary loop, Euler characteristic 1)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output: .obj (UVs as vt, read back by `subdiv refine` as face-varying data), .vtp (active "
                  "texture coordinates), .ply or .off")
      ->required();
  cmd->add_option("--boundary-shape", args->boundary,
                  "Where the boundary goes, by arc length: circle (the unit circle) or square (the unit square, "
                  "corners from --corners or the boundary's four sharpest turns)")
      ->check(CLI::IsMember({"circle", "square"}))
      ->capture_default_str();
  cmd->add_option("--corners", args->corners, "With --boundary-shape square: the 4 boundary vertices (from 0) at the "
                                              "square's corners")
      ->delimiter(',')
      ->expected(4);
  cmd->add_option("--weights", args->weights,
                  "Interior vertices as convex combinations of their neighbours: uniform (Tutte 1963) or mean-value "
                  "(Floater 2003: keeps shapes closer); both one-to-one for a convex boundary")
      ->check(CLI::IsMember({"uniform", "mean-value"}))
      ->capture_default_str();
  cmd->add_flag("--force", args->force, "Write -o even where it is the input mesh, which is then lost");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->footer("Example: subdiv parameterize face.obj --weights mean-value -o face-uv.obj");
  cmd->callback([args] { run(*args); });
}

}  // namespace subdiv::cli
