#include "piece_refine.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <new>
#include <string>
#include <system_error>

#include "framework/engine/face_partition.h"
#include "framework/engine/ghost_rings.h"
#include "framework/engine/mesh_pieces.h"
#include "framework/io/vtk/vtk_pieces.h"
#include "framework/util/atomic_file.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "level_output.h"
#include "framework/pipeline/memory_guard.h"
#include "mesh_subset.h"
#include "process_group.h"

namespace subdiv::cli {
namespace {

// The memory guard's estimate leaves out the .vtp writer's copies of the finest level:
// measured at 464 bytes per face against its 300 (docs/scale.md), so --max-memory plans
// with half as much again.
constexpr double kWriterOverhead = 1.55;

// The mesh's arrays on the piece's vertices, faces and corners.
MeshData piece_data(const MeshData& mesh, const MeshPiece& cut) {
  std::vector<Index> new_vertex(mesh.vertex_count(), kNone);
  for (size_t i = 0; i < cut.base_vertex.size(); ++i) new_vertex[cut.base_vertex[i]] = Index(i);
  return mesh_subset(mesh, cut.base_vertex, cut.base_face, new_vertex);
}

RefineOptions piece_options(const RefineOptions& options, const MeshPiece& cut) {
  RefineOptions o = options;
  for (auto& [name, values] : o.vertex_parameters) values = gather_tuples(values, 1, cut.base_vertex);
  return o;
}

struct PieceCounts {
  long long faces = 0;
};

// What to ask for when a piece does not fit. More pieces help only while the piece can be cut
// smaller (it owns more than one face) and one face's share fits: past that only fewer levels do.
std::string piece_memory_advice(const PieceJob& job, const SchemeSequence& seq, const MeshPiece& cut,
                                const std::vector<int>& owner, int piece, int rings) {
  const double budget = memory_budget(job.max_memory).bytes;
  const double per_face = refinement_bytes(*seq.schemes.front(), cut.level, seq.total_levels) /
                          std::max(1.0, double(cut.level.face_count()));
  const auto own_faces = std::count(owner.begin(), owner.end(), piece);
  const std::string larger_budget = job.max_memory > 0 ? " or a larger --max-memory" : "";
  if (per_face > budget)
    return fmt::format("piece {} with its {} ghost ring(s) has {} faces, and even one face refined {} levels would "
                       "not fit: no number of pieces helps; ask for fewer levels{}",
                       piece, rings, cut.level.face_count(), seq.total_levels, larger_budget);
  if (own_faces <= 1)
    return fmt::format("piece {} is one face of the mesh with its {} ghost ring(s), {} faces in all: no number of "
                       "pieces makes it smaller; ask for fewer levels{}",
                       piece, rings, cut.level.face_count(), larger_budget);
  return fmt::format("piece {} with its {} ghost ring(s) has {} faces; ask for more --pieces (or a larger "
                     "--max-memory) or fewer levels",
                     piece, rings, cut.level.face_count());
}

PieceCounts refine_piece(const PieceJob& job, const SchemeSequence& seq, const MeshData& mesh, const Level& base,
                         const RefineOptions& options, const RefinePieceData& refine_data,
                         const std::vector<int>& owner, int piece, int rings, StagedFiles& staged) {
  const MeshPiece cut = cut_piece(base, owner, piece, rings);
  check_fits_in_memory(*seq.schemes.front(), cut.level, seq.total_levels, job.max_memory,
                       piece_memory_advice(job, seq, cut, owner, piece, rings));
  const RefineOptions o = piece_options(options, cut);
  const Hierarchy h = refine_topology(seq.runs, cut.level, o);
  std::vector<LevelData> levels = refine_data(h, piece_data(mesh, cut), o);
  const std::vector<int> finest_owner = finest_face_owners(h, cut.face_owner);
  write_piece(staged, piece_file(job.output, piece), h, std::move(levels), o.features, cut.base_face, finest_owner,
              piece, job.format);
  PieceCounts counts;
  const Level& fine = h.levels.back();
  for (Index f = 0; f < fine.face_count(); ++f) counts.faces += finest_owner[f] == piece && !fine.is_hole(f);
  return counts;
}

// Piece files of an earlier run with more pieces would sit beside the .pvtp unlisted.
void remove_stale_pieces(const std::filesystem::path& pvtp, int pieces) {
  std::error_code ec;
  for (int i = pieces; std::filesystem::remove(piece_file(pvtp, i), ec); ++i) {
  }
}

}  // namespace

int pieces_for_memory(const SchemeSequence& seq, const Level& base, std::span<const double> positions, int rings,
                      double max_memory) {
  const Scheme& scheme = *seq.schemes.front();
  // What is held already (the base mesh, its level) stays while every piece is refined.
  const double held = resident_bytes();
  const double budget = max_memory - held;
  if (budget <= 0) {
    const auto [held_text, max_text] = byte_sizes_compared(held, max_memory);
    throw Error(fmt::format("--max-memory {} is less than the base mesh alone takes ({}); allow more", max_text,
                            held_text));
  }
  const double whole = refinement_bytes(scheme, base, seq.total_levels) * kWriterOverhead;
  // Ghost faces make pieces larger than their share: from the share's count, double until
  // the largest piece with its ghost rings fits (or every face is a piece).
  int pieces = int(std::clamp(std::ceil(whole / budget), 1.0, double(base.face_count())));
  for (;; pieces = std::min(2 * pieces, int(base.face_count()))) {
    const std::vector<int> owner = partition_faces(base, positions, pieces).face_piece;
    Index largest = 0;
    for (int p = 0; p < pieces; ++p) largest = std::max(largest, piece_face_count(base, owner, p, rings));
    if (whole * largest / base.face_count() <= budget || pieces == base.face_count()) return pieces;
  }
}

PieceSummary refine_in_pieces(const PieceJob& job, const SchemeSequence& seq, const MeshData& mesh, const Level& base,
                              const RefineOptions& options, const RefinePieceData& refine_data) {
  PieceSummary summary;
  try {
    summary.rings = ghost_rings(seq.runs);
  } catch (const Error& e) {
    throw Error(fmt::format("--pieces: {}", e.what()));
  }
  summary.pieces = job.pieces > 0 ? job.pieces : pieces_for_memory(seq, base, mesh.positions, summary.rings, job.max_memory);
  const FacePartition cut = partition_faces(base, mesh.positions, summary.pieces);
  summary.method = cut.method;
  const ProcessGroup& group = ProcessGroup::join();
  summary.ranks = group.size();
  make_piece_folder(job.output);
  StagedFiles staged;  // this rank's pieces, renamed into place only when every rank succeeded
  std::string failure;
  try {
    for (int piece = group.rank(); piece < summary.pieces; piece += group.size()) {
      if (job.piece_starts) job.piece_starts(piece, summary.pieces);
      const PieceCounts counts =
          refine_piece(job, seq, mesh, base, options, refine_data, cut.face_piece, piece, summary.rings, staged);
      summary.faces += counts.faces;
    }
  } catch (const Error& e) {
    failure = e.what();
  } catch (const std::bad_alloc&) {
    failure = "out of memory while refining a piece; ask for more --pieces or a smaller --max-memory";
  }
  if (!group.all(failure.empty())) {
    staged.discard();
    std::error_code ec;
    std::filesystem::remove(piece_file(job.output, 0).parent_path(), ec);  // only if no earlier run's pieces are in it
    throw Error(failure.empty() ? "another rank failed (its message is above); no piece was written" : failure);
  }
  staged.commit();
  group.barrier();
  if (group.rank() == 0) {
    remove_stale_pieces(job.output, summary.pieces);
    write_pvtp(job.output, summary.pieces);
  }
  group.barrier();
  return summary;
}

}  // namespace subdiv::cli
