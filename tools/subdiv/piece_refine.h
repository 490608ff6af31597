#pragma once
// `subdiv refine MESH --pieces N -o OUT.pvtp` (docs/scale.md): the base mesh cut into N
// pieces, each refined on its own with its ghost rings (engine/mesh_pieces.h), one after
// another so that only one piece is in memory at a time, or spread over the ranks of
// mpirun; one .vtp per piece and a .pvtp that ParaView opens as one dataset.
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_data.h"
#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme_sequence.h"
#include "output_options.h"

namespace subdiv::cli {

struct PieceJob {
  std::filesystem::path output;  // the .pvtp
  int pieces = 0;                // 0: as many as --max-memory needs
  double max_memory = 0;         // bytes per piece, 0: what the machine has
  OutputChoice format;           // the pieces' arrays and compression (refine --arrays, --compression)
  std::function<void(int piece, int pieces)> piece_starts;  // for progress; may be empty
};

// A piece's mesh data refined through its hierarchy, level by level (refine_command.cpp).
using RefinePieceData =
    std::function<std::vector<LevelData>(const Hierarchy& h, const MeshData& mesh, const RefineOptions& options)>;

struct PieceSummary {
  int pieces = 0, rings = 0, ranks = 1;
  std::string method;               // how the faces were cut
  long long faces = 0;  // written by this rank
};

// Throws subdiv::Error, leaving no piece and no .pvtp behind, when any piece on any rank fails.
PieceSummary refine_in_pieces(const PieceJob& job, const SchemeSequence& seq, const MeshData& mesh, const Level& base,
                              const RefineOptions& options, const RefinePieceData& refine_data);

// The piece count --max-memory asks for: enough that the largest piece with its ghost rings
// fits (memory_guard.h's estimate), at most one face per piece.
int pieces_for_memory(const SchemeSequence& seq, const Level& base, std::span<const double> positions, int rings,
                      double max_memory);

}  // namespace subdiv::cli
