#pragma once
// Limit evaluation as every front-end asks for it (`subdiv evaluate`, Python's
// subdivkit.evaluate and subdivkit.LimitSurface): a mesh, a scheme and the shape options,
// loaded exactly as a refinement loads them (prepare_refinement: the mesh's option tags,
// feature files and angles, unused vertices dropped), then points (face, u, v) of the limit
// surface with their derivatives, or limit stencils over the request's vertices.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/limit/limit_surface.h"
#include "framework/limit/tessellation.h"
#include "framework/pipeline/refine_request.h"
#include "framework/primvar/face_varying.h"
#include "framework/util/option_spelling.h"

namespace subdiv {

struct EvaluateRequest {
  // The mesh: read from `mesh_file` when given, else `mesh` (with its tags).
  std::string mesh_file;
  MeshData mesh;
  std::string mesh_name;  // names the mesh in messages
  SchemeSource scheme;
  ShapeChoices shape;
  std::string feature_file;   // a feature sidecar (io/feature_file.h)
  double feature_angle = -1;  // degrees: sharper edges become infinitely sharp creases; < 0: off
  // As RefineRequest's: told each phase as it starts, and the share of the long work done
  // (0 to 1) from the thread that made the request, for a front-end's bar.
  std::function<void(const std::string& phase)> progress;
  std::function<void(double done)> progress_fraction;
};

// A face-varying channel's limit (OpenSubdiv's face-varying surfaces, Bfr's
// InitFaceVaryingSurface): the channel's value mesh (primvar/face_varying.h: seams are its
// boundaries, the mode's corners tagged) evaluated with the same scheme and the boundary
// rule EdgesOnly, or, in the mode All (OpenSubdiv's default), bilinear in each face (each
// sub-face of an n-gon of a quad scheme: its corner, the two edge middles and the face's
// centroid, as Bfr's linear patches).
struct FaceVaryingSurface {
  std::string name;
  int components = 2;
  ArrayRole role = ArrayRole::Data;  // e.g. texture coordinates
  FaceVaryingLinear mode = FaceVaryingLinear::All;
  std::vector<double> values;                    // components per value of the value mesh
  Level level;                                   // the value mesh (faces as the mesh's)
  std::shared_ptr<const LimitSurface> surface;   // null in the mode All
};

// The surface prepared once: evaluate any number of point sets with it (thread-safe).
struct PreparedEvaluation {
  std::string mesh_name;  // names the mesh in messages, as EvaluateRequest's
  std::string scheme_label;
  std::shared_ptr<const Scheme> scheme;
  MeshData mesh;                      // the request's mesh without unused vertices
  std::vector<Index> request_vertex;  // per vertex of `mesh`: its number in the request's mesh
  Index request_vertex_count = 0;
  std::shared_ptr<const LimitSurface> surface;
  bool sequence_head = false;  // a sequence "A:k,B": B's limit over the mesh A's k levels make
  // Rational weights (rational_weights.h), per vertex of `mesh`; empty when the mesh has
  // none or all are 1. Positions are then evaluated as (w·p, w) and projected.
  std::vector<double> weights;
  std::vector<FaceVaryingSurface> face_varying;  // the mesh's face-varying channels (normals left out)
  std::vector<std::string> warnings;  // the mesh reader's, clean-up's
  std::vector<std::string> notes;     // feature files and angles applied
};

// Throws subdiv::Error naming the mesh or the scheme (and why a scheme cannot be evaluated:
// limit_surface_unsupported, a sequence head that does not nest), or subdiv::OptionError
// naming an option. A sequence "A:k,B" is evaluated as B's limit over the mesh A's k levels make.
PreparedEvaluation prepare_evaluation(EvaluateRequest request);

// `work()`, with an Error it throws (not an OptionError) given the mesh's name in front, as
// the preparation's errors have it: a point refused while a surface is sampled names the file.
template <class Work>
auto naming_the_mesh(const PreparedEvaluation& prepared, Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw Error(prepared.mesh_name + ": " + e.what());
  }
}

// Points of the limit surface: `channels` values per point for the position and each
// derivative up to the order asked for (0, 1 or 2), NaN where a derivative does not exist
// (limit_surface.h says where). Empty vectors for orders not asked for.
struct EvaluatedPoints {
  Index count = 0;
  int channels = 3;
  std::vector<double> position, du, dv, duu, duv, dvv;
};

// Evaluates the mesh's positions, or `values` (`channels` per vertex of the request's mesh)
// when given, at (faces[i], uv[2 i], uv[2 i + 1]). With rational weights the positions are
// those of the rational surface (the homogeneous limit projected, derivatives by the
// quotient rule); `values` are evaluated as given (a non-finite one is refused with its
// vertex and column). Every point is checked first: a bad one
// is refused as "point i (face f, u, v): why" (i from 0), before anything is evaluated.
// Runs in parallel over the points (TBB, within the caller's thread limit).
EvaluatedPoints evaluate_limit_points(const PreparedEvaluation& prepared, std::span<const Index> faces,
                                      std::span<const double> uv, int derivatives,
                                      std::span<const double> values = {}, int channels = 3);

// One point at a time, as tessellation asks (limit/tessellation.h): the position and first
// derivatives of the polynomial surface of the mesh's positions, or of the rational surface
// of its weights. Valid while `prepared` lives.
SurfaceSample limit_sampler(const PreparedEvaluation& prepared);

// The limit of face-varying channel `channel` at the points (components per point), as
// evaluate_limit_points.
EvaluatedPoints evaluate_face_varying(const PreparedEvaluation& prepared, size_t channel, std::span<const Index> faces,
                                      std::span<const double> uv, int derivatives);

// Limit stencils of the points as sparse matrices over the request's vertices (CSR, one row
// per point): the position and each derivative up to `derivatives`. A row is empty where
// the derivative does not exist (has[i] false for that order).
struct LimitStencilMatrices {
  struct Matrix {
    std::vector<Index> offsets{0}, columns;
    std::vector<double> weights;
  };
  Index rows = 0, columns = 0;
  Matrix position, du, dv, duu, duv, dvv;
  std::vector<std::uint8_t> has_first, has_second;  // per point
};
LimitStencilMatrices limit_stencil_matrices(const PreparedEvaluation& prepared, std::span<const Index> faces,
                                            std::span<const double> uv, int derivatives);

}  // namespace subdiv
