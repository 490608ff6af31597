#pragma once
// ParaView output of a refinement in pieces: one .vtp per piece, in a folder next to a .pvtp
// that lists them, which ParaView opens as one dataset (and pvserver / pvbatch under MPI
// reads piece by piece).
#include <filesystem>
#include <span>
#include <string>

#include "framework/io/vtk/vtk_output.h"
#include "framework/util/atomic_file.h"

namespace subdiv {

// <dir>/<stem>_pieces/piece_<i>.vtp for OUT = <dir>/<stem>.pvtp, and the name the .pvtp
// gives it (relative, '/' separators).
std::filesystem::path piece_file(const std::filesystem::path& pvtp, int piece);
std::string piece_source(const std::filesystem::path& pvtp, int piece);

// Creates the pieces' folder if it is missing (several processes may race: each succeeds).
void make_piece_folder(const std::filesystem::path& pvtp);

// Writes one piece like write_vtp, under a temporary name staged in `staged`: it appears
// under its own name only when the caller commits, so that a failed run leaves no piece.
void write_piece_vtp(StagedFiles& staged, const std::filesystem::path& target, const OutputLevel& level,
                     const VtkWriteOptions& options = {});

// Writes the .pvtp (atomically) listing `pieces` pieces, its array declarations read from
// piece 0's file, which must exist: every piece of a refinement carries the same arrays.
void write_pvtp(const std::filesystem::path& pvtp, int pieces);

}  // namespace subdiv
