#include "level_output.h"

#include <algorithm>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_seams.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_pieces.h"
#include "mesh_subset.h"
#include "framework/util/atomic_file.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::cli {
namespace {
// The faces of `mesh` at `kept` with the vertices they use, in their old order.
MeshData keep_faces(const MeshData& mesh, const std::vector<Index>& kept, std::vector<Index>& new_vertex) {
  new_vertex.assign(mesh.vertex_count(), kNone);
  for (Index f : kept)
    for (Index i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i) new_vertex[mesh.face_vertices[i]] = 0;
  std::vector<Index> used;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (new_vertex[v] == 0) new_vertex[v] = Index(used.size()), used.push_back(v);
  return mesh_subset(mesh, used, kept, new_vertex);
}

}  // namespace

void write_piece(StagedFiles& staged, const std::filesystem::path& target, const Hierarchy& h,
                 std::vector<LevelData> data, const FeatureOptions& features, const std::vector<Index>& base_faces,
                 const std::vector<int>& finest_owner, int piece, const OutputChoice& choice) {
  const int finest = int(h.levels.size()) - 1;
  const Level& L = h.levels[finest];
  MeshData whole = level_mesh(L, std::move(data[finest]));
  // The arrays SubdivKit adds, base_face numbered in the whole mesh.
  std::vector<double> base_face;
  if (choice.arrays.has("base_face")) {
    base_face = base_faces_down_to(h, finest);
    for (double& b : base_face) b = b < 0 ? b : double(base_faces[size_t(b)]);
  }
  add_level_arrays(h, finest, whole, features, std::move(base_face), choice.arrays);
  // The piece's own faces, numbered as `whole` numbers them (holes left out).
  std::vector<Index> kept;
  for (Index f = 0, written = 0; f < L.face_count(); ++f) {
    if (L.is_hole(f)) continue;
    if (finest_owner[f] == piece) kept.push_back(written);
    ++written;
  }
  std::vector<Index> new_vertex;
  MeshData mine = keep_faces(whole, kept, new_vertex);
  for (const CreaseTag& c : whole.creases) {
    const Index e = find_edge(L, c.v0, c.v1);
    if (e != kNone && finest_owner[L.edge_faces[2 * e]] == piece && new_vertex[c.v0] != kNone && new_vertex[c.v1] != kNone)
      mine.creases.push_back({new_vertex[c.v0], new_vertex[c.v1], c.sharpness});
  }
  const OutputLevel level = output_level(mine, finest);
  write_piece_vtp(staged, target, level, choice.vtk);
}

void check_output_path(const std::filesystem::path& out) {
  const std::string ext = lowercase_extension(out);
  if (ext != ".vtp" && ext != ".pvd" && ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw Error(fmt::format("cannot write {}: unknown output format {}; use .vtp or .pvd (ParaView), "
                            "or .obj, .off, .ply, .stl", subdiv::quoted(out.string()), subdiv::quoted(ext)));
  check_writable(out);  // a folder that does not exist or is read-only: said before any work
}

void check_output_not_input(const std::filesystem::path& input, const std::filesystem::path& out, bool force,
                            std::string_view option) {
  if (force) return;
  namespace fs = std::filesystem;
  auto same = [](const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::equivalent(a, b, ec) && !ec;
  };
  const auto refuse = [&](const std::string& how) {
    throw Error(fmt::format("{} {} {} the input mesh {}: writing would lose the control mesh; name another "
                            "output, or add --force to overwrite it", option, subdiv::quoted(out.string()), how, subdiv::quoted(input.string())));
  };
  if (same(input, out)) refuse("is");
  const std::string ext = lowercase_extension(out);
  const fs::path folder = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  const fs::path input_folder = input.parent_path().empty() ? fs::path(".") : input.parent_path();
  if (ext == ".pvd" && same(input_folder, folder / (out.stem().string() + "_levels")))
    refuse("rewrites the folder of");
  if (ext == ".pvtp" && same(input_folder, folder / (out.stem().string() + "_pieces")))
    refuse("rewrites the folder of");
}

void write_levels(const std::filesystem::path& out, Hierarchy&& h, std::vector<LevelData> data,
                  const FeatureOptions& features, const std::vector<DataArray>& finest_point_data,
                  const MeshOptions& obj_tags, const OutputChoice& choice) {
  const std::string ext = lowercase_extension(out);
  const int finest = int(h.levels.size()) - 1;
  if (ext != ".vtp" && ext != ".pvd") {
    MeshData mesh = level_mesh(h.levels[finest], std::move(data[finest]), &h.levels[finest]);
    mesh.point_data.insert(mesh.point_data.end(), finest_point_data.begin(), finest_point_data.end());
    mesh.options = obj_tags;
    // OBJ holds face-varying data as vt; the other formats get a point per side of a seam.
    write_mesh(out, ext == ".obj" || mesh.face_varying.empty() ? mesh : split_at_seams(mesh), choice.vtk.progress);
    return;
  }
  std::vector<MeshData> meshes;
  const std::vector<OutputLevel> levels = describe_levels(h, std::move(data), features, finest_point_data, meshes,
                                                          choice.arrays, ext == ".vtp" ? finest : 0, &h);
  if (ext == ".vtp") write_vtp(out, levels.back(), choice.vtk);
  else write_pvd(out, levels, choice.vtk);
}

}  // namespace subdiv::cli
