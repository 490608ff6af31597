#pragma once
// Refinement in pieces (docs/scale.md): a base mesh cut into pieces of whole faces, each
// refined on its own with a ring of ghost faces around it wide enough that its own faces
// come out exactly as in a refinement of the whole mesh; the ghosts' descendants are then
// dropped. This file cuts a piece out and says which refined faces a piece keeps.
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/topology/level.h"

namespace subdiv {

// A piece's own faces with its ghost rings, as a level of its own.
struct MeshPiece {
  Level level;                     // the base mesh's faces and tags (sharpness, holes) there
  std::vector<Index> base_vertex;  // per vertex of `level`: the base mesh's vertex
  std::vector<Index> base_face;    // per face of `level`: the base mesh's face
  std::vector<int> face_owner;     // per face of `level`: the piece that owns it
};

// The faces of `piece` (face_owner[f] == piece) and every face within `ghost_rings` rings
// of them (ring k: the faces sharing a vertex with ring k - 1), plus the faces around any
// vertex where those would form two fans (a pinch). Faces and vertices keep the
// base mesh's relative order, so every ring starts where it starts in the whole mesh and
// each row is summed in the same order. Throws subdiv::Error when the piece has no face.
// With `faces_only`, the piece's level has its faces only (vertex_count, face_offsets,
// face_vertices; no edges, rings or tags), for a level nothing refines or searches further.
MeshPiece cut_piece(const Level& base, std::span<const int> face_owner, int piece, int ghost_rings,
                    bool faces_only = false);

// How many faces cut_piece's level would have, without building it.
Index piece_face_count(const Level& base, std::span<const int> face_owner, int piece, int ghost_rings);

// Per face of every level of `h` (refined from a piece's level), the piece that owns it: a
// child face lying in a parent face is owned by that face's owner; a face lying in none (the
// faces a dual split makes around edges and vertices) by the smallest owner among the parent
// elements its vertices come from, so that exactly one piece keeps it. Returns the finest
// level's owners.
std::vector<int> finest_face_owners(const Hierarchy& h, std::span<const int> base_owner);

// Every value `values` (components per element) at the indices `kept`, in that order.
std::vector<double> gather_tuples(std::span<const double> values, int components, std::span<const Index> kept);

}  // namespace subdiv
