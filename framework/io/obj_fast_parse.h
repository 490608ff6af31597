#pragma once
// The OBJ reader's fast path for large files: the text split at line ends into chunks that
// are parsed on every core, then joined in order (on one core, reading a 1M-face OBJ
// takes about as long as refining it twice).
//
// It takes only the statements large meshes consist of (v, vt, vn, f, comments, and the
// statements every reader ignores: g, o, s, usemtl, ...) and gives exactly the MeshData the
// line-by-line reader (obj_read.cpp) gives. It declines (returns nothing) on anything else:
// tags, polylines, line continuations, lone '\r' line ends, any error, and anything the
// line-by-line reader would warn about. The caller then reads the file with that reader,
// which names the file and line of every problem; so no error message is written twice and
// none depends on where the chunks were cut.
// Internal to io/.
#include <cstddef>
#include <optional>
#include <string_view>

#include "framework/io/mesh_data.h"

namespace subdiv::io_detail {

// Statements of the OBJ specification (Wavefront, "Object Files (.obj)", Appendix B1 of the
// Advanced Visualizer manual) that SubdivKit does not use: groups, materials, free-form
// geometry, display and render attributes. Both readers skip them quietly, as OpenSubdiv's
// shape_utils reader does; any other statement is skipped with a warning naming its lines.
bool obj_spec_statement(std::string_view keyword);

// `chunks` pieces of about equal size (at least 1), each parsed as one task.
std::optional<MeshData> parse_obj_fast(std::string_view text, std::size_t chunks);

// The number of chunks read_obj uses for a text of `bytes` on this machine's threads: 1 (the
// line-by-line reader, no fast path) below a megabyte.
std::size_t obj_chunks_for(std::size_t bytes);

}  // namespace subdiv::io_detail
