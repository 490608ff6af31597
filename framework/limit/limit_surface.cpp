#include "framework/limit/limit_surface.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <list>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <fmt/format.h>
#include <tbb/task_arena.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/analysis/surface/rim_rules.h"
#include "framework/engine/ghost_rings.h"
#include "framework/features/base_tags.h"
#include "framework/engine/refiner.h"
#include "framework/limit/bspline_patch.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/cut_key.h"
#include "framework/limit/dual_limit.h"
#include "framework/limit/sequence_head.h"
#include "framework/limit/sqrt3_limit.h"
#include "framework/limit/limit_nodes.h"
#include "framework/limit/manifold_sheets.h"
#include "framework/limit/mid_edge_limit.h"
#include "framework/limit/plugin_split_limit.h"
#include "framework/limit/tensor_patch.h"
#include "framework/limit/triangle_patch.h"
#include "framework/limit/face_domain.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/step_tables.h"
#include "framework/scheme/scheme.h"
#include "framework/topology/non_manifold_place.h"
#include "framework/util/bulk_memory.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// The values at `reads` (`channels` each), in that order: what a descent's first rows act on.
std::vector<double> gathered(std::span<const Index> reads, std::span<const double> values, int channels) {
  std::vector<double> out(reads.size() * size_t(channels));
  for (size_t k = 0; k < reads.size(); ++k)
    for (int c = 0; c < channels; ++c)
      out[k * size_t(channels) + size_t(c)] = values[size_t(reads[k]) * size_t(channels) + size_t(c)];
  return out;
}

// A face's neighbourhood cut out of a level, with its values and the point inside it.
struct Neighbourhood {
  Level level;
  std::vector<double> values;
  std::vector<Index> original;  // vertex -> vertex of the level it was cut from
  FacePoint point;
};

Neighbourhood cut(const Level& L, std::span<const double> values, int channels, const FacePoint& p, int radius) {
  Extracted e = extract_neighbourhood(L, CentreKind::Face, p.face, radius);
  Neighbourhood n;
  n.level = std::move(e.level);
  n.original = std::move(e.original);
  n.values.resize(n.original.size() * size_t(channels));
  for (size_t v = 0; v < n.original.size(); ++v)
    for (int c = 0; c < channels; ++c)
      n.values[v * size_t(channels) + size_t(c)] = values[size_t(n.original[v]) * size_t(channels) + size_t(c)];
  n.point = p;
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == p.face) n.point.face = Index(f);
  if (!L.face_hole.empty()) {
    n.level.face_hole.assign(size_t(n.level.face_count()), 0);
    for (size_t f = 0; f < e.face_original.size(); ++f) n.level.face_hole[f] = L.face_hole[size_t(e.face_original[f])];
  }
  return n;
}

// The point with its Jacobian d(s, t)/d(u, v) halved: carried as 2^-level times the
// Jacobian, whose entries grow like 2^level and would overflow past level 1023, so that
// derivative rows start at 2^-level times their size (step_matrix.h).
FacePoint halved(FacePoint p) {
  for (auto& row : p.jacobian)
    for (double& x : row) x *= 0.5;
  return p;
}

StepMatrix renumbering(const std::vector<Index>& order, Index source_count) {
  StepMatrix m;
  m.source_count = source_count;
  m.scale = 1;
  for (Index v : order) {
    m.columns.push_back(v);
    m.weights.push_back(1.0);
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

// Runs `f` for the point (face, u, v) a caller asked for; an error from the neighbourhood
// names that point. Only the outermost call names it: a non-manifold mesh's sheets and a
// sequence's tail are surfaces of their own, whose faces are numbered their way. Errors that
// name a face already (the point's own checks), option errors (they name the option) and
// NotClosed (caught inside, to widen the cuts) pass unchanged.
thread_local int point_call_depth = 0;

template <class F>
auto naming_the_point(Index face, double u, double v, F&& f) -> decltype(f()) {
  struct Depth {
    Depth() { ++point_call_depth; }
    ~Depth() { --point_call_depth; }
  } depth;
  if (point_call_depth > 1) return f();
  try {
    return f();
  } catch (const NotClosed&) {
    throw;
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    if (std::string_view(e.what()).starts_with(fmt::format("face {} ", face))) throw;
    throw Error(fmt::format("face {} at (u, v) = ({}, {}): {}", face, u, v, e.what()));
  }
}

// A face number past the end or negative (a points file's row, a Python index).
std::string no_such_face(Index face, Index count) {
  if (count == 0) return fmt::format("face {} does not exist: the mesh has no faces", face);
  return fmt::format("face {} does not exist: the mesh has {} faces, numbered from 0 to {}", face, count, count - 1);
}

}  // namespace

std::string limit_surface_unsupported(const Scheme& scheme) {
  if (!scheme.linear())
    return fmt::format("scheme {} has non-linear rules: its limit is no fixed combination of the control points, "
                       "so it has no limit masks or stencils to evaluate; refine it uniformly instead (`subdiv "
                       "refine{} MESH -s {} -l L`; Python: `subdivkit.refine`), whose finest level approaches the limit",
                       subdiv::quoted(scheme.name), scheme_plugin_options(scheme), scheme_argument(scheme));
  if (scheme_is_level_dependent(scheme))
    return fmt::format("scheme {} is non-stationary (its weights depend on the level l): the local subdivision "
                       "matrix changes from level to level and has no fixed eigen-structure to evaluate the limit "
                       "with; refine it uniformly instead (`subdiv refine{} MESH -s {} -l L`; Python: "
                       "`subdivkit.refine`), or run its level-dependent levels first in a sequence whose last "
                       "scheme is stationary (`-s {}:K,STATIONARY`: that scheme's limit over the mesh they make)",
                       subdiv::quoted(scheme.name), scheme_plugin_options(scheme), scheme_argument(scheme),
                       scheme_argument(scheme));
  // Every split is taken here; the mid-edge and plugins' splits are checked with the mesh
  // (mid_edge_limit_unsupported, plugin_split_limit_unsupported).
  return {};
}

struct LimitSurface::Impl {
  std::shared_ptr<const Scheme> scheme;
  Level base;
  LimitSurfaceOptions options;
  bool triangles = false;
  int radius = 4;
  std::unique_ptr<SchemeLimits> limits;
  std::unique_ptr<DualLimit> dual;  // set for a dual split (dual_limit.h)
  std::unique_ptr<Sqrt3Limit> sqrt3;  // set for the sqrt3 split (sqrt3_limit.h)
  std::unique_ptr<MidEdgeLimit> mid_edge;  // set for the mid-edge split (mid_edge_limit.h)
  std::unique_ptr<PluginSplitLimit> plugin;  // set for a plugin's split (plugin_split_limit.h)
  // Set for a sequence: its head, and the limit of its tail over the mesh the head makes.
  std::unique_ptr<SequenceHead> head;
  std::unique_ptr<LimitSurface> tail;
  // Set for a non-manifold base: the limit over its manifold sheets, and per sheet vertex
  // the base vertex it copies (manifold_sheets.h).
  std::unique_ptr<LimitSurface> sheets;
  std::vector<Index> sheet_origin;

  // The binary quad and triangle splits make every non-manifold element a feature, so the
  // mesh's limit is its sheets' limit; other splits refuse it.
  void cut_into_sheets(std::shared_ptr<const Scheme> s, const Level& mesh, const LimitSurfaceOptions& o) {
    if (s->split() != SplitKind::Quad && s->split() != SplitKind::Triangle)
      throw Error("the mesh is non-manifold (an edge with more than two faces, or a vertex where separate fans of "
                  "faces meet): limit evaluation at (face, u, v) takes such a mesh under the binary quad and "
                  "triangle splits only; split it into manifold parts");
    ManifoldSheets cut = manifold_sheets(mesh, o.features);
    LimitSurfaceOptions sheet_options = o;
    sheet_options.features.boundary = BoundaryInterpolation::EdgesOnly;  // the mesh's corners are tagged
    sheet_origin = std::move(cut.origin);
    sheets = std::make_unique<LimitSurface>(std::move(s), std::move(cut.level), sheet_options);
    triangles = sheets->triangles();
  }

  // Per base face (made on first use): the node of its cut and the base vertices in the
  // node's label order. What a point in a face with a closed form reads first lies in the
  // first cache line (grid, lattice, box_vertices).
  struct alignas(64) Entry {
    // The node's control point grid when its limit is the bicubic B-spline patch
    // (LimitNodes::bspline), else null: a point in the face is then evaluated at once.
    const std::array<Index, 16>* grid = nullptr;
    // Otherwise the node's polynomial patch (LimitNodes::quartic: a quartic over a triangle,
    // degree 4 per direction over a quad) when it has one, else null.
    const PolynomialPatch* lattice = nullptr;
    // With the box spline's closed form (lattice->box): its functions' vertices in their
    // labels' order (BoxSplineLabels::by_label), read without going through `vertices`.
    std::array<Index, kBoxSplineFunctions> box_vertices{};
    int node = -1;
    std::vector<Index> vertices;
    // With a grid: per label, its cell in the grid (row by row from (-1, -1)).
    std::array<std::uint8_t, 16> grid_cell{};

    void set_grid(const std::array<Index, 16>* g) {
      grid = g;
      if (!g) return;
      for (size_t k = 0; k < 16; ++k) grid_cell[size_t(g->at(k))] = std::uint8_t(k);
    }
  };
  // A face whose entry would be the regular one's (Cache::regular, a bicubic node) but for
  // its vertices: those 16 in label order, one cache line per face, each stored plus one so
  // that zero is "not yet" (the last one written last: when it is set, all are; a point
  // reads one cache line). Plain integers read and written through std::atomic_ref, so that
  // the array can come zeroed from the system (Cache::slot_array).
  struct alignas(64) GridSlot {
    std::array<Index, 16> vertex;
    Index get(size_t l, std::memory_order order) const {
      return std::atomic_ref<Index>(const_cast<Index&>(vertex[l])).load(order);
    }
    void set(size_t l, Index x, std::memory_order order) { std::atomic_ref<Index>(vertex[l]).store(x, order); }
  };
  // A face's cut known by its key (key_cut, cut_key.h): the node, the labels it keeps and
  // what make_entry asks of it.
  struct KnownCut {
    int node = -1;
    Index kept = 0;
    const std::array<Index, 16>* grid = nullptr;
    const PolynomialPatch* lattice = nullptr;
  };
  // The entries of the faces around a face, as labels of the face's key at a wider radius
  // (radius + kPieceMargin): a face whose wide key is equal has, at the same places of its
  // key, faces whose cuts are the same (their cuts lie inside the wider one, which the key
  // records up to the labelling), so their entries are these with the labels read through
  // its own labelling, without keying, cutting or signing each face.
  static constexpr int kPieceMargin = 4;
  struct PieceFace {
    Index at = 0;       // the face's place in the wide key's faces (CutKey::faces)
    Index corner0 = 0;  // the label of its corner 0 (where its own labelling starts)
    int node = -1;
    const std::array<Index, 16>* grid = nullptr;
    const PolynomialPatch* lattice = nullptr;
    std::vector<Index> labels;  // the entry's vertices as labels of the wide key
  };
  struct Piece {
    std::vector<PieceFace> faces;  // the first one is the face itself
  };
  // A point in a sub-face of an n-gon (a quad split's face of another size) starts with one
  // step of the engine over the face's cut, after which its face is a child quad with a
  // node. That step is the same for every point of the face; around a vertex of high
  // valence the cut holds the whole fan, so it is made once per face, not per point.
  struct ChildStart {
    Index level_face = kNone;  // the child face in the refined cut
    Index face = kNone;        // the child face in its own cut
    int node = -1;
    // Rows: the vertices of the child's cut that the node keeps, in the cut's order; columns:
    // the face's cut. Then the node's labels from those rows.
    StepMatrix step, renumber;
    std::string error;  // why the child's cut has no node: thrown for a point that needs it
  };
  struct SubFaceStart {
    std::vector<Index> original;  // the face's cut: vertex -> base vertex (what a point reads)
    Index face = kNone;           // the face in its cut
    std::vector<std::vector<ChildFace>> children;  // per sub-face: the face's children in its frame
    std::vector<ChildStart> starts;                // by level_face, increasing
    const ChildStart& child(Index level_face) const {
      const auto at = std::lower_bound(starts.begin(), starts.end(), level_face,
                                       [](const ChildStart& s, Index f) { return s.level_face < f; });
      if (at == starts.end() || at->level_face != level_face) throw Error("internal: a sub-face's child has no start");
      return *at;
    }
    size_t bytes() const {
      size_t b = sizeof(*this) + original.size() * sizeof(Index);
      for (const auto& c : children)
        for (const ChildFace& f : c) b += sizeof(f) + f.corners.size() * sizeof(Uv);
      for (const ChildStart& s : starts)
        for (const StepMatrix* m : {&s.step, &s.renumber})
          b += m->offsets.size() * sizeof(Index) + m->columns.size() * (sizeof(Index) + sizeof(double));
      return b + starts.size() * sizeof(ChildStart);
    }
  };
  // The hash reads the size and at most the first kHashed values (where neighbourhoods
  // differ first: the labelling starts at the face); equal hashes are told apart by comparing the keys.
  using Key = std::vector<std::uint32_t>;
  struct KeyHash {
    static constexpr size_t kHashed = 1024;
    size_t operator()(const Key& key) const noexcept {
      constexpr std::uint64_t kOdd = 0x9E3779B97F4A7C15ull;
      // Four independent lanes (multiply-xor): no long chain of dependent multiplications.
      std::uint64_t h[4] = {key.size(), 1, 2, 3};
      const size_t n = std::min(key.size(), kHashed);
      size_t i = 0;
      for (; i + 4 <= n; i += 4)
        for (size_t l = 0; l < 4; ++l) h[l] = (h[l] ^ key[i + l]) * kOdd;
      for (; i < n; ++i) h[0] = (h[0] ^ key[i]) * kOdd;
      std::uint64_t r = h[0];
      for (size_t l = 1; l < 4; ++l) r = (r ^ (h[l] >> 31) ^ h[l]) * kOdd;
      return size_t(r ^ (r >> 32));
    }
  };
  // The nodes for one depth and the entries into them. The depth starts at one ring and
  // grows when a scheme reads further (NotClosed); evaluations under way keep theirs.
  struct Cache {
    std::unique_ptr<LimitNodes> nodes;
    // Each entry is published once (compare-exchange) and never changes: read without a lock.
    std::unique_ptr<std::atomic<Entry*>[]> entries;
    Index entry_count = 0;
    // An entry of a face in an untagged regular quad grid (quad_grid_labelled), once one has
    // been made the general way: every such face's cut has its signature, hence its node.
    std::atomic<const Entry*> regular{nullptr};
    // Per face (made with the first face that fills one), for regular faces when the
    // regular node is a bicubic patch.
    std::atomic<GridSlot*> slots{nullptr};
    // Cuts by their key_cut (cut_key.h) at the cut's radius (make_entry).
    std::mutex known_mutex;
    std::unordered_map<Key, KnownCut, KeyHash> known;
    // The keys' total length: a mesh whose neighbourhoods hardly repeat (a scan, say) would
    // otherwise keep a key of thousands of values per face; past the budget new keys are not
    // kept and their faces take the general way, as every face would without keys.
    size_t known_words = 0;
    static constexpr size_t kKnownBudget = size_t(1) << 24;  // 64 MB of keys
    // Pieces by their key at the wider radius (make_entry): null once met, then what a
    // face met the second time found for the faces around it.
    std::mutex pieces_mutex;
    std::unordered_map<Key, std::shared_ptr<const Piece>, KeyHash> pieces;
    size_t pieces_met = 0, pieces_used = 0;
    size_t piece_words = 0;  // the wide keys' total length, within their own budget
    static constexpr size_t kPieceBudget = size_t(1) << 22;  // 16 MB of wide keys
    // Set when the wide keys hardly repeat (a mesh without a pattern): faces then read
    // their own key only.
    std::atomic<bool> pieces_off{false};
    // The first steps of points in faces with sub-faces (SubFaceStart), per base face, while
    // their size is within the budget (past it a face's start is made for each point).
    std::mutex starts_mutex;
    std::unordered_map<Index, std::shared_ptr<const SubFaceStart>> starts;
    size_t starts_bytes = 0;
    static constexpr size_t kStartsBudget = size_t(1) << 27;  // 128 MB
    ~Cache() {
      for (Index f = 0; f < entry_count; ++f) delete entries[size_t(f)].load();
      if (GridSlot* a = slots.load()) release_lazy_bulk(a, slot_bytes());
    }
    size_t slot_bytes() const { return std::max<size_t>(size_t(entry_count), 1) * sizeof(GridSlot); }
    // One slot per face, zero: a million faces' slots are 64 MB, placed as faces are met
    // (allocate_lazy_bulk: on 2 MB pages, where a fresh 4 KB page's first touch costs about
    // as much as a face's whole first point).
    GridSlot* slot_array() {
      if (GridSlot* a = slots.load(std::memory_order_acquire)) return a;
      GridSlot* made = static_cast<GridSlot*>(allocate_lazy_bulk(slot_bytes()));
      GridSlot* none = nullptr;
      if (slots.compare_exchange_strong(none, made, std::memory_order_acq_rel)) return made;
      release_lazy_bulk(made, slot_bytes());
      return none;
    }
  };
  mutable std::mutex cache_mutex;
  mutable std::shared_ptr<Cache> cache;
  // The current cache for lock-free reads; replaced caches stay alive (a read may hold one).
  mutable std::atomic<Cache*> cache_now{nullptr};
  mutable std::vector<std::shared_ptr<Cache>> retired;
  // Faces known to be in untagged regular quad grid (in_quad_grid): 1, else 0 (not known).
  mutable std::unique_ptr<std::atomic<char>[]> grid_face;
  // Set when a wide grid piece failed (in_quad_grid): the narrow pieces from then on.
  mutable std::atomic<bool> narrow_pieces{false};

  std::shared_ptr<Cache> make_cache(int depth) const {
    auto c = std::make_shared<Cache>();
    c->nodes = std::make_unique<LimitNodes>(*scheme, options.features, radius, depth, triangles, *limits);
    c->entry_count = base.face_count();
    c->entries = std::make_unique<std::atomic<Entry*>[]>(size_t(c->entry_count));  // value-initialised: null
    return c;
  }
  void set_cache(std::shared_ptr<Cache> c) const {
    if (cache) retired.push_back(cache);
    cache = std::move(c);
    cache_now.store(cache.get(), std::memory_order_release);
  }
  std::shared_ptr<Cache> current() const {
    std::lock_guard lock(cache_mutex);
    return cache;
  }
  void grow(const std::shared_ptr<Cache>& failed, const NotClosed& why) const {
    std::lock_guard lock(cache_mutex);
    if (cache != failed) return;
    const int depth = failed->nodes->depth() + 1;
    if (depth > radius - 2) throw Error(fmt::format("internal: {} even with a cut of {} rings", why.what(), radius));
    set_cache(make_cache(depth));
  }

  const Entry& entry(Cache& c, Index face) const {
    std::atomic<Entry*>& slot = c.entries[size_t(face)];
    if (const Entry* e = slot.load(std::memory_order_acquire)) return *e;
    bool regular = false;
    std::unique_ptr<Entry> made;
    if (options.shortcuts && !c.pieces_off.load(std::memory_order_relaxed)) made = piece_entry(c, face, regular);
    if (!made) made = make_entry(c, face, regular);
    return publish(c, face, std::move(made), regular);
  }
  // Publishes a face's entry made here unless another thread's came first; the one kept.
  const Entry& publish(Cache& c, Index face, std::unique_ptr<Entry> made, bool regular) const {
    std::atomic<Entry*>& slot = c.entries[size_t(face)];
    if (made->lattice && made->lattice->box) {
      const BoxSplineLabels& box = *made->lattice->box;
      for (size_t k = 0; k < size_t(kBoxSplineFunctions); ++k)
        made->box_vertices[k] = made->vertices[box.label[box.by_label[k]]];
    }
    Entry* found = nullptr;
    if (!slot.compare_exchange_strong(found, made.get(), std::memory_order_acq_rel)) return *found;
    const Entry* e = made.release();
    const Entry* none = nullptr;
    if (regular) c.regular.compare_exchange_strong(none, e, std::memory_order_acq_rel);
    return *e;
  }

  // A face's entry from its piece (Piece), or null when the face's wide key was not met
  // before. The second face with a wide key makes the piece: the entries of the faces whose
  // cuts lie in its wide cut, the general way; faces with that key after it take them all.
  std::unique_ptr<Entry> piece_entry(Cache& c, Index face, bool& regular) const {
    thread_local CutKey wide;
    const int reach = radius + kPieceMargin;
    key_cut(wide, base, face, reach);
    std::shared_ptr<const Piece> piece;
    {
      std::lock_guard lock(c.pieces_mutex);
      const auto found = c.pieces.find(wide.key);
      if (found == c.pieces.end()) {
        // A key met once is kept (a pattern shows only when it repeats) while they repeat
        // often enough to pay for reading them: a wide key costs a few cuts' keys, a piece
        // spares tens of them. Faces near tags miss until the pattern is met away from them.
        ++c.pieces_met;
        if (c.pieces_met > std::max<size_t>(1024, size_t(c.entry_count) / 16) && c.pieces_met > 8 * c.pieces_used)
          c.pieces_off.store(true);
        if (c.piece_words + wide.key.size() <= Cache::kPieceBudget) {
          c.piece_words += wide.key.size();
          c.pieces.emplace(wide.key, nullptr);
        }
        return nullptr;
      }
      ++c.pieces_used;
      piece = found->second;
    }
    if (!piece) return make_piece(c, wide, reach, regular);
    std::unique_ptr<Entry> own;
    for (const PieceFace& pf : piece->faces) {
      const Index g = wide.faces[size_t(pf.at)];
      if (wide.label_of[size_t(base.face(g)[0])] != pf.corner0) continue;
      if (g != face && c.entries[size_t(g)].load(std::memory_order_acquire)) continue;
      auto e = std::make_unique<Entry>();
      e->node = pf.node;
      e->vertices.reserve(pf.labels.size());
      for (Index l : pf.labels) e->vertices.push_back(wide.vertices[size_t(l)]);
      e->set_grid(pf.grid);
      e->lattice = pf.lattice;
      if (g == face)
        own = std::move(e);
      else
        publish(c, g, std::move(e), false);
    }
    return own;
  }
  // The piece of `wide` (the key of its first face): the entries of its faces whose corners
  // lie within kPieceMargin of the first face's (so that their cuts, of the cut's radius,
  // lie in the wide one), made and published here; the first face's own entry returned
  // (`own_regular` as make_entry sets it).
  std::unique_ptr<Entry> make_piece(Cache& c, const CutKey& wide, int reach, bool& own_regular) const {
    auto piece = std::make_shared<Piece>();
    std::unique_ptr<Entry> own;
    // Only faces a point takes an entry of (the split's own shape, not holes: other faces'
    // points start in sub-faces or are refused).
    const int shape = triangles ? 3 : 4;
    for (size_t i = 0; i < wide.faces.size(); ++i) {
      const Index g = wide.faces[i];
      const auto corners = base.face(g);
      if (i > 0 && (int(corners.size()) != shape || base.is_hole(g))) continue;
      if (std::any_of(corners.begin(), corners.end(), [&](Index v) {
            const Index l = wide.label_of[size_t(v)];
            return l == kNone || wide.distance[size_t(l)] > reach - radius;
          }))
        continue;
      // make_entry, not entry(): the faces around are not made from pieces (which would
      // overwrite `wide`, the thread's).
      const Entry* e = nullptr;
      std::unique_ptr<Entry> made;
      bool regular = false;
      if (i == 0) {
        made = make_entry(c, g, own_regular);
        e = made.get();
      } else if (!(e = c.entries[size_t(g)].load(std::memory_order_acquire))) {
        // A face around it whose cut the engine refuses is left to its own points (the error
        // belongs to them): the piece is made without it.
        try {
          e = &publish(c, g, make_entry(c, g, regular), regular);
        } catch (const std::exception&) {
          continue;
        }
      }
      PieceFace pf;
      pf.at = Index(i);
      pf.corner0 = wide.label_of[size_t(corners[0])];
      pf.node = e->node, pf.grid = e->grid, pf.lattice = e->lattice;
      bool inside = true;
      for (Index v : e->vertices) {
        const Index l = wide.label_of[size_t(v)];
        inside = inside && l != kNone;
        pf.labels.push_back(l);
      }
      if (inside) piece->faces.push_back(std::move(pf));
      if (i == 0) own = std::move(made);
    }
    std::lock_guard lock(c.pieces_mutex);
    if (const auto found = c.pieces.find(wide.key); found != c.pieces.end() && !found->second) found->second = piece;
    return own;
  }

  // A face's entry: in an untagged regular quad grid (`regular` set) the node other such
  // faces found and the face's first labels, which are the cut's (the labelling depends on
  // the combinatorics only); otherwise, or for the first such face, from the face's cut and
  // its signature.
  std::unique_ptr<Entry> make_entry(Cache& c, Index face, bool& regular) const {
    auto e = std::make_unique<Entry>();
    thread_local Labelling lab;
    regular = options.shortcuts && !triangles && in_quad_grid(lab, face, c.nodes->depth());
    if (regular)
      if (const Entry* r = c.regular.load(std::memory_order_acquire)) {
        e->node = r->node;
        e->vertices.assign(lab.vertices.begin(), lab.vertices.begin() + std::ptrdiff_t(r->vertices.size()));
        e->set_grid(r->grid);
        e->lattice = r->lattice;
        return e;
      }
    // A face whose cut's key (read from the base, cut_key.h) was met already takes that
    // cut's node without cutting or signing.
    thread_local CutKey ck;
    Key key;
    std::vector<Index> key_vertices;
    const bool keyed = options.shortcuts;
    if (keyed) {
      key_cut(ck, base, face, radius);
      std::unique_lock lock(c.known_mutex);
      if (const auto found = c.known.find(ck.key); found != c.known.end()) {
        const KnownCut k = found->second;
        lock.unlock();
        e->node = k.node;
        e->vertices.assign(ck.vertices.begin(), ck.vertices.begin() + std::ptrdiff_t(k.kept));
        e->set_grid(k.grid);
        e->lattice = k.lattice;
        return e;
      }
      lock.unlock();
      key = ck.key;
      key_vertices = ck.vertices;
    }
    FacePoint p;
    p.face = face;
    const Neighbourhood n = cut(base, {}, 0, p, radius);
    std::vector<Index> order;
    e->node = c.nodes->intern(n.level, n.point.face, order);
    for (Index v : order) e->vertices.push_back(n.original[size_t(v)]);
    // What walk() asks first of a face's node, asked here once for the face.
    if (!triangles) e->set_grid(c.nodes->bspline(e->node));
    // And what it asks next (only with the shortcuts: without them every query is walk()'s).
    if (!e->grid && options.shortcuts) {
      std::vector<int> stack;
      e->lattice = quartic(c, e->node, stack);
    }
    // The key's labels are the cut's (checked: a key is kept only where they agree).
    if (keyed && key_vertices.size() >= e->vertices.size() &&
        std::equal(e->vertices.begin(), e->vertices.end(), key_vertices.begin())) {
      const KnownCut k{e->node, Index(e->vertices.size()), e->grid, e->lattice};
      std::lock_guard lock(c.known_mutex);
      if (c.known_words + key.size() <= Cache::kKnownBudget) {
        c.known_words += key.size();
        c.known.emplace(std::move(key), k);
      }
    }
    return e;
  }


  // Whether the face's cut is a piece of untagged regular quad grid (quad_grid_labelled),
  // leaving in `lab` at least its labels within `depth`. A larger piece is checked first:
  // when it is grid, so is the cut of every face near its centre, which is marked, and
  // those faces then only label their own few rings.
  bool in_quad_grid(Labelling& lab, Index face, int depth) const {
    if (grid_face[size_t(face)].load(std::memory_order_relaxed)) return quad_grid_labelled(lab, base, face, depth);
    // A wider piece marks more faces for the vertices it labels, but fails where a narrower
    // one passes: on a torus or tube only a little wider than the narrow piece (its paths
    // meet again), and near any face that is not grid. After its first failure every piece
    // is the narrow one, so such meshes pay one wide piece more than with the narrow alone.
    constexpr int kWideMargin = 16, kMargin = 8;
    bool piece = false;
    if (!narrow_pieces.load(std::memory_order_relaxed)) {
      piece = grid_piece(lab, face, kWideMargin);
      if (!piece) narrow_pieces.store(true, std::memory_order_relaxed);
    }
    if (!piece) piece = grid_piece(lab, face, kMargin);
    if (piece && grid_face[size_t(face)].load(std::memory_order_relaxed)) return quad_grid_labelled(lab, base, face, depth);
    return quad_grid_labelled(lab, base, face, radius);
  }
  // Checks a piece `margin` rings wider than the cut, centred near `face`; when it is grid,
  // marks the faces whose cuts lie inside it and returns true (`lab` then holds the piece's
  // distances, not a face's labels).
  bool grid_piece(Labelling& lab, Index face, int margin) const {
    // The piece is centred up to margin - 1 faces on, across corners towards higher face
    // numbers (where a caller going through the faces in order goes next), so that it marks
    // this face and more of the faces not met yet than a piece centred here would: on a grid
    // numbered row by row the walk goes diagonally, and the face is near the piece's corner.
    Index centre = face;
    for (int step = 0; step + 1 < margin; ++step) {
      Index next = centre;
      for (Index v : base.face(centre))
        for (Index g : base.ring_faces(v)) next = std::max(next, g);
      if (next == centre) break;
      centre = next;
    }
    if (!quad_grid_distances(lab, base, centre, radius + margin)) return false;
    // A face with a corner closer than margin - 1 has its corners within margin of the
    // centre's and its cut within this piece; this face is one of them (each step across
    // a corner moves a face's corners one ring at most), checked all the same.
    for (size_t q = 0; q < lab.vertices.size() && lab.distance[q] < margin; ++q)
      for (Index f : base.ring_faces(lab.vertices[q])) grid_face[size_t(f)].store(1, std::memory_order_relaxed);
    return true;
  }

  // prepare() of a face made already (e set when not a grid slot), without a lock; false
  // with e null when not made.
  static bool prepared(const Cache& c, Index face, const Entry*& e) {
    if (const GridSlot* a = c.slots.load(std::memory_order_acquire))
      if (a[size_t(face)].get(15, std::memory_order_acquire) != 0) return true;
    e = c.entries[size_t(face)].load(std::memory_order_acquire);
    return false;
  }

  // A face's grid slot, filled (true) when the face is in untagged regular quad grid and the
  // regular node is the bicubic patch, or its entry otherwise.
  bool prepare(Cache& c, Index face, const Entry*& e) const {
    if (prepared(c, face, e) || fill_slot(c, face)) return true;
    if (!e) e = &entry(c, face);
    return false;
  }
  // The grid slot of a face in untagged regular quad grid once the regular node is known to
  // be a bicubic patch; false otherwise. Runs no engine (no isolation needed).
  bool fill_slot(Cache& c, Index face) const {
    const Entry* r = c.regular.load(std::memory_order_acquire);
    thread_local Labelling lab;
    if (!options.shortcuts || !r || !r->grid) return false;
    std::array<Index, 16> ring{};
    if (grid_face[size_t(face)].load(std::memory_order_relaxed)) {
      first_grid_labels(face, ring);
    } else {
      if (!in_quad_grid(lab, face, c.nodes->depth())) return false;
      std::copy(lab.vertices.begin(), lab.vertices.begin() + 16, ring.begin());
    }
    GridSlot& slot = c.slot_array()[size_t(face)];
    for (size_t l = 0; l < 16; ++l)
      slot.set(l, ring[l] + 1, l == 15 ? std::memory_order_release : std::memory_order_relaxed);
    return true;
  }

  // The first 16 labels of a face known to be in untagged regular quad grid (grid_face):
  // label_neighbourhood's breadth-first order (its corners from corner 0, then each corner's
  // faces counter-clockwise from this one, each face's corners after the vertex), without
  // the checks that made it known or the labelling's arrays over the level. In such grid the
  // corners met first are the same for every face: around corner q, its t-th face from this
  // one (fi below) runs out of the corner along the edge the face before runs into it, so
  // the face's corners c + 1 (met already) and c + 2, c + 3 (new on the second and third
  // faces, c + 2 only on the fourth) — less those met around the corners before.
  void first_grid_labels(Index face, std::array<Index, 16>& out) const {
    struct Met {
      std::uint8_t t, i;
    };
    static constexpr Met kFirst[] = {{1, 2}, {1, 3}, {2, 2}, {2, 3}, {3, 2}};  // corner 0
    static constexpr Met kMiddle[] = {{2, 2}, {2, 3}, {3, 2}};                // corners 1 and 2
    static constexpr Met kLast[] = {{2, 2}};                                  // corner 3
    const auto corners = base.face(face);
    size_t count = 0;
    for (size_t i = 0; i < 4; ++i) out[count++] = corners[i];
    for (size_t q = 0; q < 4; ++q) {
      const Index v = corners[q];
      const auto faces = base.ring_faces(v);
      const Index first = base.vertex_face_offsets[v];
      size_t entry = 0;
      while (faces[entry] != face) ++entry;
      const std::span<const Met> met = q == 0 ? std::span<const Met>(kFirst)
                                       : q == 3 ? std::span<const Met>(kLast)
                                                : std::span<const Met>(kMiddle);
      for (const Met m : met) {
        const size_t fi = (entry + m.t) & 3;
        const auto fc = base.face(faces[fi]);
        const size_t c = size_t(base.vertex_face_corner[size_t(first) + fi]);
        out[count++] = fc[(c + m.i) & 3];
      }
    }
  }

  // Position and first derivatives of three channels in one pass over `count` labels (label
  // l: weights(l) for position, d/du and d/dv, at vertex(l)): nine sums kept in registers,
  // each taking its products in the labels' order and passing over its zero weights as a sum
  // that skips them does (a select rather than a branch: the same bits), each vertex read once.
  template <class Weights, class Vertex>
  static void first_order_sums(size_t count, Weights weights, Vertex vertex, std::span<const double> values,
                               LimitSample& out) {
    std::array<double, 9> sum{};
    for (size_t l = 0; l < count; ++l) {
      const std::array<double, 3> w = weights(l);
      const double* at = &values[size_t(vertex(l)) * 3];
      for (size_t k = 0; k < 3; ++k)
        for (size_t c = 0; c < 3; ++c) {
          double& x = sum[3 * k + c];
          x = w[k] != 0 ? x + w[k] * at[c] : x;
        }
    }
    put_three(out.position, sum[0], sum[1], sum[2]);
    put_three(out.du, sum[3], sum[4], sum[5]);
    put_three(out.dv, sum[6], sum[7], sum[8]);
    out.has_derivatives = true;
  }
  // Three values into `to`, keeping its memory: element by element, as assigning a list
  // costs a call to memmove per vector, about a tenth of a regular face's point (by value:
  // the sums stay in registers).
  static void put_three(std::vector<double>& to, double x, double y, double z) {
    to.clear();
    to.reserve(3);
    to.push_back(x), to.push_back(y), to.push_back(z);
  }

  // walk()'s first step where the face's node is the bicubic patch: finish() of
  // bspline_rows() with nothing to pull back, the same products summed in the same order
  // (the same bits), without the rows, the copied values or the nodes' lock.
  template <class Vertex>
  static void bspline_sample(const std::array<std::uint8_t, 16>& cell, Vertex vertex, const FacePoint& p,
                             std::span<const double> values, int channels, int derivatives, LimitSample& out) {
    const BsplineWeights w = bspline_weights(p.st, derivatives);
    const size_t C = size_t(channels);
    const auto& J = p.jacobian;
    if (C == 3 && derivatives >= 1) {
      // Three channels (positions): the sums in registers (first_order_sums), the same bits.
      first_order_sums(
          16,
          [&](size_t l) {
            const size_t k = cell[l];
            return std::array<double, 3>{w.position[k], J[0][0] * w.ds[k] + J[1][0] * w.dt[k],
                                         J[0][1] * w.ds[k] + J[1][1] * w.dt[k]};
          },
          vertex, values, out);
    } else if (derivatives >= 1) {
      out.position.assign(C, 0.0);
      // Each sum over the labels in their order, as applied() takes them; zero weights skipped
      // as it skips them.
      out.du.assign(C, 0.0);
      out.dv.assign(C, 0.0);
      out.has_derivatives = true;
      double* pos = out.position.data();
      double* du = out.du.data();
      double* dv = out.dv.data();
      for (size_t l = 0; l < 16; ++l) {
        const size_t k = cell[l];
        const double* at = &values[size_t(vertex(l)) * C];
        const double x = w.position[k];
        const double a = J[0][0] * w.ds[k] + J[1][0] * w.dt[k];
        const double b = J[0][1] * w.ds[k] + J[1][1] * w.dt[k];
        for (size_t ch = 0; ch < C; ++ch) {
          if (x != 0) pos[ch] += x * at[ch];
          if (a != 0) du[ch] += a * at[ch];
          if (b != 0) dv[ch] += b * at[ch];
        }
      }
    } else {
      out.position.assign(C, 0.0);
      for (size_t l = 0; l < 16; ++l) {
        const double x = w.position[cell[l]];
        if (x == 0) continue;
        const double* at = &values[size_t(vertex(l)) * C];
        for (size_t ch = 0; ch < C; ++ch) out.position[ch] += x * at[ch];
      }
    }
    if (derivatives < 2) return;
    auto second = [&](size_t a, size_t b, std::vector<double>& r) {
      r.assign(C, 0.0);
      for (size_t l = 0; l < 16; ++l) {
        const size_t k = cell[l];
        const double x = J[0][a] * J[0][b] * w.dss[k] + (J[0][a] * J[1][b] + J[1][a] * J[0][b]) * w.dst[k] +
                         J[1][a] * J[1][b] * w.dtt[k];
        if (x == 0) continue;
        const double* at = &values[size_t(vertex(l)) * C];
        for (size_t ch = 0; ch < C; ++ch) r[ch] += x * at[ch];
      }
    };
    second(0, 0, out.duu);
    second(0, 1, out.duv);
    second(1, 1, out.dvv);
    out.has_second_derivatives = true;
  }

  // finish() of a polynomial patch's rows with nothing to pull back, applied to the face's
  // vertices' values where they lie: the same products summed in the same order (the same
  // bits), without the rows' or the gathered values' allocations.
  static void fixed_sample(const FixedRows& r, const std::vector<Index>& vertices, const FacePoint& p,
                           std::span<const double> values, int channels, int derivatives, LimitSample& out) {
    const size_t C = size_t(channels), L = r.labels;
    // Sums kept in registers for three channels (positions), in the same order.
    auto apply = [&](const double* row, std::vector<double>& out) {
      if (C == 3) {
        double x = 0, y = 0, z = 0;
        for (size_t l = 0; l < L; ++l) {
          if (row[l] == 0) continue;
          const double* at = &values[size_t(vertices[l]) * 3];
          x += row[l] * at[0], y += row[l] * at[1], z += row[l] * at[2];
        }
        out = {x, y, z};
        return;
      }
      out.assign(C, 0.0);
      for (size_t l = 0; l < L; ++l) {
        if (row[l] == 0) continue;
        const double* at = &values[size_t(vertices[l]) * C];
        for (size_t c = 0; c < C; ++c) out[c] += row[l] * at[c];
      }
    };
    const auto& J = p.jacobian;
    const auto& ds = r.row[1];
    const auto& dt = r.row[2];
    if (C == 3 && derivatives >= 1 && r.count >= 3) {
      const double* position = r.row[0].data();
      first_order_sums(
          L,
          [&](size_t l) {
            return std::array<double, 3>{position[l], J[0][0] * ds[l] + J[1][0] * dt[l], J[0][1] * ds[l] + J[1][1] * dt[l]};
          },
          [&](size_t l) { return vertices[l]; }, values, out);
    } else {
      apply(r.row[0].data(), out.position);
    }
    if (!out.has_derivatives && derivatives >= 1 && r.count >= 3) {
      std::array<double, kFixedLabels> du, dv;
      for (size_t i = 0; i < L; ++i) du[i] = J[0][0] * ds[i] + J[1][0] * dt[i];
      for (size_t i = 0; i < L; ++i) dv[i] = J[0][1] * ds[i] + J[1][1] * dt[i];
      apply(du.data(), out.du);
      apply(dv.data(), out.dv);
      out.has_derivatives = true;
    }
    if (derivatives >= 2 && out.has_derivatives && r.count >= 6) {
      const auto& dss = r.row[3];
      const auto& dst = r.row[4];
      const auto& dtt = r.row[5];
      auto second = [&](size_t a, size_t b, std::vector<double>& o) {
        std::array<double, kFixedLabels> x{};
        for (size_t i = 0; i < L; ++i)
          x[i] = J[0][a] * J[0][b] * dss[i] + (J[0][a] * J[1][b] + J[1][a] * J[0][b]) * dst[i] +
                 J[1][a] * J[1][b] * dtt[i];
        apply(x.data(), o);
      };
      second(0, 0, out.duu);
      second(0, 1, out.duv);
      second(1, 1, out.dvv);
      out.has_second_derivatives = true;
    }
  }

  // fixed_sample() of the quartic box spline's rows (box_spline_patch.h: Loop's regular
  // triangles) for three channels: the twelve functions' weights taken in their labels'
  // order, each function's vertex (Entry::box_vertices) read once, the products and sums
  // fixed_sample takes (its other labels' rows are zero, and skipped there as here) — the
  // same bits, without placing the weights in rows over the labels first.
  static void box_spline_sample(const BoxSplineLabels& box, const std::array<Index, kBoxSplineFunctions>& vertices,
                                const FacePoint& p, std::span<const double> values, int derivatives,
                                LimitSample& out) {
    BoxSplineWeights w;
    box_spline_weights(p.st, derivatives >= 2 ? 6 : derivatives >= 1 ? 3 : 1, w);
    const auto& J = p.jacobian;
    std::array<double, 9> sum{};
    if (derivatives >= 1) {
      for (size_t k = 0; k < size_t(kBoxSplineFunctions); ++k) {
        const size_t f = box.by_label[k];
        const double ds = w[1][f], dt = w[2][f];
        const double x[3] = {w[0][f], J[0][0] * ds + J[1][0] * dt, J[0][1] * ds + J[1][1] * dt};
        const double* at = &values[size_t(vertices[k]) * 3];
        for (size_t n = 0; n < 3; ++n)
          for (size_t c = 0; c < 3; ++c) {
            double& s = sum[3 * n + c];
            s = x[n] != 0 ? s + x[n] * at[c] : s;
          }
      }
      put3(out.du, &sum[3]);
      put3(out.dv, &sum[6]);
      out.has_derivatives = true;
    } else {
      for (size_t k = 0; k < size_t(kBoxSplineFunctions); ++k) {
        const size_t f = box.by_label[k];
        const double x = w[0][f];
        if (x == 0) continue;
        const double* at = &values[size_t(vertices[k]) * 3];
        sum[0] += x * at[0], sum[1] += x * at[1], sum[2] += x * at[2];
      }
    }
    put3(out.position, &sum[0]);
    if (derivatives < 2) return;
    // As fixed_sample's second(): each second derivative's weights, then their sums with the
    // zero weights passed over.
    const auto second = [&](size_t a, size_t b, std::vector<double>& to) {
      double x[3] = {0, 0, 0};
      for (size_t k = 0; k < size_t(kBoxSplineFunctions); ++k) {
        const size_t f = box.by_label[k];
        const double weight = J[0][a] * J[0][b] * w[3][f] + (J[0][a] * J[1][b] + J[1][a] * J[0][b]) * w[4][f] +
                              J[1][a] * J[1][b] * w[5][f];
        if (weight == 0) continue;
        const double* at = &values[size_t(vertices[k]) * 3];
        x[0] += weight * at[0], x[1] += weight * at[1], x[2] += weight * at[2];
      }
      put3(to, x);
    };
    second(0, 0, out.duu);
    second(0, 1, out.duv);
    second(1, 1, out.dvv);
    out.has_second_derivatives = true;
  }
  // Three values into `v`, its memory kept (pushed one by one: within the capacity inline,
  // no call to resize or copy 24 bytes).
  static void put3(std::vector<double>& v, const double* x) {
    v.clear();
    v.push_back(x[0]), v.push_back(x[1]), v.push_back(x[2]);
  }

  // The base vertices an evaluation in the point's face reads, in the order descend() takes
  // their values.
  std::vector<Index> reads(Cache& c, const FacePoint& p) const {
    if (p.sub_face < 0) return entry(c, p.face).vertices;
    if (!options.shortcuts) return cut(base, {}, 0, p, radius).original;
    return sub_face_start(c, p.face)->original;
  }

  // Runs `f(cache)` until the cache's depth suffices.
  template <class F>
  auto with_cache(F&& f) const {
    // Isolated: the engine's parallel loops inside must not hand this thread another
    // evaluation of a caller's parallel loop while it holds a node's lock or is half-way.
    return tbb::this_task_arena::isolate([&] { return with_cache_isolated(f); });
  }
  template <class F>
  auto with_cache_isolated(F& f) const {
    for (;;) {
      const std::shared_ptr<Cache> c = current();
      try {
        return f(*c);
      } catch (const NotClosed& e) {
        grow(c, e);
      }
    }
  }

  FacePoint start(Index face, double u, double v) const {
    const char* why = "";
    if (face < 0 || face >= base.face_count())
      throw Error(no_such_face(face, base.face_count()));
    if (base.is_hole(face)) throw Error(fmt::format("face {} is a hole: it has no limit surface", face));
    const auto p = base_face_point(base, face, u, v, triangles, &why);
    if (!p) throw Error(fmt::format("face {} at (u, v) = ({}, {}): {}", face, u, v, why));
    return *p;
  }

  // The derivatives as rows over the first cut's vertices.
  struct DerivativeRows {
    std::vector<double> du, dv, duu, duv, dvv;
  };

  // Follows the point down the refinement of its neighbourhood until it is a vertex or in a
  // face with a closed form. The position from the values carried down; the derivatives
  // (`derivatives`: their highest order) as rows over the first cut's vertices, pulled back
  // and applied to its values (and kept in `rows_out` when given).
  LimitSample descend(Cache& c, const FacePoint& p0, const std::vector<double>& first_values, int channels,
                      int derivatives, DerivativeRows* rows_out = nullptr) const {
    std::vector<const StepMatrix*> path;
    int id = -1;
    std::vector<double> values;
    FacePoint p = p0;
    std::list<StepMatrix> owned;  // the steps a sub-face's point makes alone (a list: no allocation when empty)
    std::shared_ptr<const SubFaceStart> start;  // holds the first steps of `path`
    if (p0.sub_face < 0) {
      id = entry(c, p0.face).node;
      values = first_values;
    } else if (!options.shortcuts) {
      start_in_sub_face_alone(*c.nodes, p0, first_values, channels, owned, path, id, values, p);
    } else {
      start = sub_face_start(c, p0.face);
      start_in_sub_face(*start, p0, first_values, channels, path, id, values, p);
    }
    return walk(c, id, p, std::move(values), channels, derivatives, path, first_values, rows_out, true);
  }

  // The descent from node `id` with the point p and the node's values; `closed_forms`:
  // regular nodes' patches may end it (off while those patches are being sampled).
  LimitSample walk(Cache& c, int id, FacePoint p, std::vector<double> values, int channels, int derivatives,
                   std::vector<const StepMatrix*>& path, const std::vector<double>& first_values,
                   DerivativeRows* rows_out, bool closed_forms) const {
    std::vector<double> next;
    NoLimitMask mask_error;
    // `iteration`: the steps taken, a run of self-similar levels counting as one.
    for (int iteration = 0;; ++iteration) {
      const int shape = c.nodes->node(id).level.face_size(c.nodes->node(id).face);
      if (iteration >= options.max_steps) {
        // The face is 2^-max_steps of the base face: its nearest corner is the point to round-off.
        p.st = {std::round(p.st[0]), std::round(p.st[1])};
        if (triangles && p.st[0] + p.st[1] > 1) p.st[1] = 0;
        if (iteration >= options.max_steps + 16) throw Error(no_limit_mask(*scheme, iteration, mask_error));
      }
      if (closed_forms && !triangles)
        if (const std::array<Index, 16>* grid = c.nodes->bspline(id))
          return bspline_end(bicubic_labels(*grid), p, values, channels, derivatives, path, first_values, iteration,
                             rows_out);
      if (closed_forms) {
        std::vector<int> stack;
        if (const auto* lattice = quartic(c, id, stack)) {
          if (lattice->bicubic)
            return bspline_end(*lattice->bicubic, p, values, channels, derivatives, path, first_values, iteration,
                               rows_out);
          // Only the derivative rows asked for: finish() reads no others.
          const CornerRows rows =
              triangles ? quartic_rows(*lattice, p.st, derivatives) : tensor_rows(lattice->lattice, p.st, derivatives);
          return finish(rows, p, values, channels, derivatives, path, first_values, iteration, rows_out);
        }
      }
      const int corner = corner_at(p, shape, triangles);
      if (corner >= 0) {
        mask_error = {};
        if (const CornerRows* rows = c.nodes->corner(id, corner, mask_error))
          return finish(*rows, p, values, channels, derivatives, path, first_values, iteration, rows_out);
        // The point is the vertex, whose configuration (valence, boundary, tags) its child
        // keeps under a binary primal split: an analysis that failed fails at every level, so
        // the refusal comes now, not after the steps to round-off (a valence-1000 fan's cut
        // made 80 of them, seconds).
        if (!mask_error.verdict.empty()) throw Error(no_limit_mask(*scheme, iteration, mask_error));
      }
      const LimitNode& N = c.nodes->expanded(id);
      int which = -1;
      const auto q = locate(N.children, p, triangles, &which);
      if (!q) throw Error("internal: no child face holds the point (the split is not a binary primal one)");
      if (N.child_node[size_t(which)] == id) {
        // A self-similar step: count how many times in a row the point takes it, and take
        // them at once.
        FacePoint r = halved(*q);
        int more = 0, again = -1;
        while (more + 1 < (1 << LimitNodes::kPowers) - 1 && corner_at(r, shape, triangles) < 0) {
          const auto t = locate(N.children, r, triangles, &again);
          if (!t || again != which) break;
          r = halved(*t), ++more;
        }
        // Worth it from about eight levels: a power is dense, a step sparse.
        if (more + 1 >= 8) {
          const int levels = more + 1;
          const LimitNode::Powers& powers =
              c.nodes->powers(id, which, int(std::bit_width(unsigned(levels))), derivatives >= 2);
          for (int j = 0; j < LimitNodes::kPowers; ++j) {
            if (!((levels >> j) & 1)) continue;
            const StepMatrix& m = powers.forward[size_t(j)];
            next.resize(size_t(m.rows()) * size_t(channels));
            m.apply(values, next, channels);
            values.swap(next);
            path.push_back(&m);
          }
          p = r;
          continue;
        }
      }
      const StepMatrix& m = N.child_matrix[size_t(which)];
      next.resize(size_t(m.rows()) * size_t(channels));
      m.apply(values, next, channels);
      values.swap(next);
      path.push_back(&m);
      id = N.child_node[size_t(which)];
      p = halved(*q);
    }
  }

  // The polynomial patch of a node (a quartic over a triangle, triangle_patch.h; degree 4 in
  // each of s and t over a quad, tensor_patch.h), decided on first use: every child of the
  // node must be the node itself, a B-spline node or such a patch in turn, and the rows
  // sampled at the lattice points (exact: each is a vertex after two steps) must satisfy the
  // node's refinement equations — the child's rows at its lattice points, through the
  // child's matrix, are the node's patch at those points. Both sides are polynomials of the
  // patch's degree, so agreeing at the lattice they agree everywhere; and the limit is the
  // unique bounded solution of those equations (a zero-sum row through ever more steps of a
  // convergent scheme tends to zero), so the patch is the limit.
  const PolynomialPatch* quartic(Cache& c, int id, std::vector<int>& stack) const {
    bool untried = false;
    if (const auto* rows = c.nodes->quartic(id, untried)) return rows;
    if (!untried) return nullptr;
    if (std::find(stack.begin(), stack.end(), id) != stack.end()) return nullptr;  // a cycle: leave it to the descent
    stack.push_back(id);
    std::vector<std::vector<double>> rows = fit_quartic(c, id, stack);
    stack.pop_back();
    c.nodes->set_quartic(id, triangles ? triangle_patch(std::move(rows)) : tensor_patch(std::move(rows)));
    return c.nodes->quartic(id, untried);
  }

  // The rows of node `id`'s limit at lattice point q of its face, from the node's closed form
  // (itself: the candidate `own`).
  std::vector<double> lattice_rows(Cache& c, int id, int child, int q,
                                   const std::vector<std::vector<double>>& own) const {
    if (child == id) return own[size_t(q)];
    bool untried = false;
    if (const auto* patch = c.nodes->quartic(child, untried)) return patch->lattice[size_t(q)];
    const LimitNode& C = c.nodes->node(child);
    return bspline_rows(*c.nodes->bspline(child), tensor_lattice_point(q), C.kept).position;
  }

  std::vector<std::vector<double>> fit_quartic(Cache& c, int id, std::vector<int>& stack) const {
    const LimitNode& N = c.nodes->expanded(id);
    for (int child : N.child_node) {
      if (child == id || (!triangles && c.nodes->bspline(child))) continue;
      if (!quartic(c, child, stack)) return {};
    }
    const int lattice = triangles ? kQuarticLattice : kTensorLattice;
    const auto point = [&](int q) { return triangles ? quartic_lattice_point(q) : tensor_lattice_point(q); };
    const size_t K = size_t(N.kept);
    std::vector<double> unit(K * K, 0.0);
    for (size_t k = 0; k < K; ++k) unit[k * K + k] = 1.0;
    std::vector<std::vector<double>> rows;
    try {
      for (int q = 0; q < lattice; ++q) {
        FacePoint p;
        p.st = point(q);
        std::vector<const StepMatrix*> path;
        rows.push_back(walk(c, id, p, unit, int(K), 0, path, unit, nullptr, false).position);
      }
    } catch (const NotClosed&) {
      throw;
    } catch (const Error&) {
      return {};
    }
    for (size_t i = 0; i < N.children.size(); ++i) {
      const auto& C = N.children[i].corners;
      const StepMatrix& m = N.child_matrix[i];
      // The child's (s, t) axes in the node's frame: towards its corner 1 and its last corner.
      const Uv a{C[1][0] - C[0][0], C[1][1] - C[0][1]}, b{C.back()[0] - C[0][0], C.back()[1] - C[0][1]};
      for (int q = 0; q < lattice; ++q) {
        const Uv y = point(q);
        const Uv x{C[0][0] + y[0] * a[0] + y[1] * b[0], C[0][1] + y[0] * a[1] + y[1] * b[1]};
        const std::vector<double> child = lattice_rows(c, id, N.child_node[i], q, rows);
        std::vector<double> rhs(K, 0.0);
        for (Index r = 0; r < m.rows(); ++r)
          for (Index e = m.offsets[size_t(r)]; e < m.offsets[size_t(r) + 1]; ++e)
            rhs[size_t(m.columns[size_t(e)])] += child[size_t(r)] * m.weights[size_t(e)];
        const std::vector<double> lhs =
            triangles ? quartic_rows(rows, x, 0).position : tensor_rows(rows, x, 0).position;
        for (size_t l = 0; l < K; ++l)
          if (std::fabs(lhs[l] - rhs[l]) > 1e-12) return {};
      }
    }
    return rows;
  }

  // A descent's end in a bicubic B-spline patch: the patch's weights applied to the values
  // carried down (bspline_sample) where finish() would apply its rows to them (forward_factor:
  // a short path, shorter for second derivatives): the same products in the same
  // order, the same bits, without the rows over every label. Otherwise finish() of the rows.
  static LimitSample bspline_end(const BicubicLabels& b, const FacePoint& p, const std::vector<double>& values,
                                 int channels, int derivatives, const std::vector<const StepMatrix*>& path,
                                 const std::vector<double>& first_values, int iteration, DerivativeRows* rows_out) {
    const double factor = forward_factor(path);
    if (!rows_out && factor > 0 && (derivatives <= 1 || factor <= kSecondForwardFactor)) {
      LimitSample out;
      out.steps = iteration;
      bspline_sample(b.cell, [&](size_t l) { return b.label[l]; }, p, values, channels, derivatives, out);
      if (factor != 1) {
        for (auto* r : {&out.du, &out.dv})
          for (double& x : *r) x *= factor;
        for (auto* r : {&out.duu, &out.duv, &out.dvv})
          for (double& x : *r) x *= factor * factor;
      }
      return out;
    }
    const CornerRows rows = bspline_rows(b.grid, p.st, Index(values.size() / size_t(channels)));
    return finish(rows, p, values, channels, derivatives, path, first_values, iteration, rows_out);
  }

  // Where the descent is short, the first derivatives are its rows applied to the values
  // carried down, times the steps' factors (each step doubles the parameter): rounding in
  // the carried values grows by that factor, at most kForwardFactor (a few bits), against
  // pulling the rows back through every step. Returns the factor, or 0 where the rows are
  // pulled back instead: a longer path, or a power of a step (whose derivative form differs).
  // At the bicubic patch (bspline_end), whose weights are small, the second derivatives the
  // same way, their rounding growing by the factor squared: at most kSecondForwardFactor (two
  // binary steps). Elsewhere they are pulled back: a polynomial patch's lattice form has
  // second-derivative weights of its Lagrange bases' size (Loop's boundary triangles lost
  // 1e-12 against Bfr's exact patches applied forward).
  static constexpr double kForwardFactor = 16;
  static constexpr double kSecondForwardFactor = 4;
  static double forward_factor(const std::vector<const StepMatrix*>& path) {
    double factor = 1;
    for (const StepMatrix* m : path) {
      if (m->backward) return 0;
      factor *= m->scale;
    }
    return factor <= kForwardFactor ? factor : 0;
  }

  // d/du and d/dv: the chain rule's rows (as first_derivative_rows makes them) applied to
  // `values`, each sum over the labels in their order, zero weights skipped (as applied()
  // does: with nothing to pull back, the same bits), then scaled by `factor` (a power of the
  // steps' scales: exact).
  static void forward_first_derivatives(const CornerRows& rows, const std::array<std::array<double, 2>, 2>& J,
                                        const std::vector<double>& values, int channels, double factor,
                                        LimitSample& out) {
    const size_t C = size_t(channels);
    out.du.assign(C, 0.0);
    out.dv.assign(C, 0.0);
    double* du = out.du.data();
    double* dv = out.dv.data();
    for (size_t l = 0; l < rows.ds.size(); ++l) {
      const double a = J[0][0] * rows.ds[l] + J[1][0] * rows.dt[l];
      const double b = J[0][1] * rows.ds[l] + J[1][1] * rows.dt[l];
      const double* at = &values[l * C];
      if (a != 0)
        for (size_t c = 0; c < C; ++c) du[c] += a * at[c];
      if (b != 0)
        for (size_t c = 0; c < C; ++c) dv[c] += b * at[c];
    }
    if (factor != 1)
      for (size_t c = 0; c < C; ++c) du[c] *= factor, dv[c] *= factor;
    out.has_derivatives = true;
  }

  // The sample from rows over the current node's labels: the position from the values
  // carried down, the derivatives pulled back to the first values. The point's Jacobian
  // d(s, t)/d(u, v) is constant within a face (every step is affine), so the chain rule
  // has no second-order term: d2/du_a du_b = sum J[i][a] J[j][b] d2/ds_i ds_j.
  static LimitSample finish(const CornerRows& rows, const FacePoint& p, const std::vector<double>& values, int channels,
                            int derivatives, const std::vector<const StepMatrix*>& path,
                            const std::vector<double>& first_values, int iteration, DerivativeRows* rows_out) {
    if (derivatives >= 1 && !rows.no_derivatives.empty()) throw Error(rows.no_derivatives);
    LimitSample out;
    out.steps = iteration;
    out.position = applied(rows.position, values, channels);
    const auto& J = p.jacobian;
    if (derivatives >= 1 && !rows.ds.empty() && forward_factor(path) > 0) {
      forward_first_derivatives(rows, J, values, channels, forward_factor(path), out);
      if (rows_out) rows_out->du = out.du, rows_out->dv = out.dv;
    } else if (derivatives >= 1 && !rows.ds.empty()) {
      FirstDerivativeRows d = first_derivative_rows(rows.ds, rows.dt, J, path);
      out.du = applied(d.du, first_values, channels);
      out.dv = applied(d.dv, first_values, channels);
      out.has_derivatives = true;
      if (rows_out) rows_out->du = std::move(d.du), rows_out->dv = std::move(d.dv);
    }
    if (derivatives >= 2 && out.has_derivatives && !rows.dss.empty()) {
      SecondDerivativeRows d = second_derivative_rows(rows.dss, rows.dst, rows.dtt, J, path);
      out.duu = applied(d.duu, first_values, channels);
      out.duv = applied(d.duv, first_values, channels);
      out.dvv = applied(d.dvv, first_values, channels);
      out.has_second_derivatives = true;
      if (rows_out) rows_out->duu = std::move(d.duu), rows_out->duv = std::move(d.duv), rows_out->dvv = std::move(d.dvv);
    }
    return out;
  }

  // An n-gon's sub-face is not a face yet: one step with the engine over the face's cut makes
  // it one. The general way, for each point (without the shortcuts).
  void start_in_sub_face_alone(LimitNodes& nodes, const FacePoint& p0, const std::vector<double>& first_values,
                               int channels, std::list<StepMatrix>& owned, std::vector<const StepMatrix*>& path,
                               int& id, std::vector<double>& values, FacePoint& p) const {
    Neighbourhood n = cut(base, {}, 0, p0, radius);
    n.values = first_values;
    const Hierarchy h = refine_step(n.level, nodes);
    const std::vector<double> child = h.stencils[0].apply(n.values, channels);
    const auto q = child_face_point(n.level, h.levels[1], h.origins[0], n.point, triangles);
    if (!q) throw Error("internal: no child face holds the point (the split is not a binary primal one)");
    const Index parent_count = n.level.vertex_count;
    n = cut(h.levels[1], child, channels, *q, radius);
    owned.push_back(step_matrix(h.stencils[0], n.original, parent_count));
    path.push_back(&owned.back());
    std::vector<Index> order;
    id = nodes.intern(n.level, n.point.face, order);
    owned.push_back(renumbering(order, n.level.vertex_count));
    values.resize(order.size() * size_t(channels));
    path.push_back(&owned.back());
    owned.back().apply(n.values, values, channels);
    p = halved(n.point);
  }

  // With the shortcuts, that step is the face's (SubFaceStart), worked out once; here the
  // point finds its child and takes the child's rows, summed as the step over the whole cut
  // sums them (the same bits).
  void start_in_sub_face(const SubFaceStart& s, const FacePoint& p0, const std::vector<double>& first_values,
                         int channels, std::vector<const StepMatrix*>& path, int& id, std::vector<double>& values,
                         FacePoint& p) const {
    FacePoint at = p0;
    at.face = s.face;
    const std::vector<ChildFace>& children = s.children[size_t(p0.sub_face)];
    int which = -1;
    const auto q = locate(children, at, triangles, &which);
    if (!q) throw Error("internal: no child face holds the point (the split is not a binary primal one)");
    const ChildStart& child = s.child(children[size_t(which)].face);
    if (!child.error.empty()) throw Error(child.error);
    std::vector<double> kept(size_t(child.step.rows()) * size_t(channels));
    child.step.apply(first_values, kept, channels);
    path.push_back(&child.step);
    id = child.node;
    values.resize(size_t(child.renumber.rows()) * size_t(channels));
    child.renumber.apply(kept, values, channels);
    path.push_back(&child.renumber);
    FacePoint r = *q;
    r.face = child.face;
    p = halved(r);
  }

  // The first step of every point in the sub-faces of `face`: its cut refined once with the
  // engine, and per child face the child's cut, node and the step's rows for the vertices
  // the node keeps. Rows the node does not keep only ever carry zeros (forward unread,
  // backward skipped), so leaving them out changes no sum.
  std::shared_ptr<const SubFaceStart> make_sub_face_start(Cache& c, Index face) const {
    FacePoint p;
    p.face = face;
    const Neighbourhood n = cut(base, {}, 0, p, radius);
    auto s = std::make_shared<SubFaceStart>();
    s->original = n.original;
    s->face = n.point.face;
    const Hierarchy h = refine_step(n.level, *c.nodes);
    const int k = base.face_size(face);
    std::vector<Index> child_faces_met;
    for (int sub = 0; sub < k; ++sub) {
      FacePoint q = n.point;
      q.sub_face = sub;
      s->children.push_back(child_faces(n.level, h.levels[1], h.origins[0], q, triangles));
      for (const ChildFace& f : s->children.back()) child_faces_met.push_back(f.face);
    }
    std::sort(child_faces_met.begin(), child_faces_met.end());
    child_faces_met.erase(std::unique(child_faces_met.begin(), child_faces_met.end()), child_faces_met.end());
    for (Index g : child_faces_met) {
      ChildStart& child = s->starts.emplace_back();
      child.level_face = g;
      try {
        FacePoint q;
        q.face = g;
        const Neighbourhood m = cut(h.levels[1], {}, 0, q, radius);
        child.face = m.point.face;
        std::vector<Index> order;
        child.node = c.nodes->intern(m.level, m.point.face, order);
        // The kept vertices in the cut's order (the order the whole step's rows have).
        std::vector<Index> rows = order;
        std::sort(rows.begin(), rows.end());
        std::vector<Index> level_rows;
        for (Index v : rows) level_rows.push_back(m.original[size_t(v)]);
        child.step = step_matrix(h.stencils[0], level_rows, n.level.vertex_count);
        child.renumber.source_count = Index(rows.size());
        child.renumber.scale = 1;
        for (Index v : order) {
          child.renumber.columns.push_back(Index(std::lower_bound(rows.begin(), rows.end(), v) - rows.begin()));
          child.renumber.weights.push_back(1.0);
          child.renumber.offsets.push_back(Index(child.renumber.columns.size()));
        }
      } catch (const NotClosed&) {
        throw;
      } catch (const Error& e) {
        child.error = e.what();
      }
    }
    return s;
  }

  // The face's SubFaceStart, kept in the cache while the starts' budget lasts.
  std::shared_ptr<const SubFaceStart> sub_face_start(Cache& c, Index face) const {
    {
      std::lock_guard lock(c.starts_mutex);
      if (const auto found = c.starts.find(face); found != c.starts.end()) return found->second;
    }
    std::shared_ptr<const SubFaceStart> made = make_sub_face_start(c, face);
    std::lock_guard lock(c.starts_mutex);
    const auto [at, inserted] = c.starts.emplace(face, made);
    if (!inserted) return at->second;
    const size_t bytes = made->bytes();
    if (c.starts_bytes + bytes > Cache::kStartsBudget) {
      c.starts.erase(at);
      return made;
    }
    c.starts_bytes += bytes;
    return made;
  }

  // The limit of `tail` over the mesh `head` makes, in the base faces' (u, v)
  // (sequence_head.h).
  void become_sequence(std::vector<LimitHeadRun> head_runs, std::shared_ptr<const Scheme> tail_scheme, Level mesh,
                       const LimitSurfaceOptions& o) {
    scheme = tail_scheme;
    options = o;
    // The sqrt3 split trisects boundaries and creases in every second step counted from the
    // base mesh, across a sequence too (docs/scheme-format.md), and its evaluator starts on a
    // step that keeps them: after an odd head the tail's first step joins the head.
    int head_levels = 0;
    for (const LimitHeadRun& run : head_runs) head_levels += std::max(run.levels, 0);
    if (tail_scheme->split() == SplitKind::Sqrt3 && head_levels % 2 == 1) head_runs.push_back({tail_scheme, 1});
    head = std::make_unique<SequenceHead>(std::move(head_runs), mesh, o.features);
    // As refinement says it (catmull-clark:1,loop: Loop on the head's quads), not at the first
    // point as a face "not a triangle" of a mesh the user never saw.
    check_face_sizes(*tail_scheme, head->refined(), {}, head->levels());
    tail = std::make_unique<LimitSurface>(std::move(tail_scheme), head->refined(), o);
    base = std::move(mesh);
    tag_boundary_holes(base, o.features.boundary);
    triangles = head->triangles();
  }

  Hierarchy refine_step(const Level& level, const LimitNodes& nodes) const {
    RefineOptions ro;
    ro.levels = 1;
    ro.features = options.features;
    ro.evaluation.weight_tables = nodes.weight_tables();
    return refine(*scheme, level, ro);
  }
};

LimitSurface::LimitSurface(std::shared_ptr<const Scheme> scheme, Level base, const LimitSurfaceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (!scheme) throw Error("no scheme given for the limit surface");
  if (const std::string why = limit_surface_unsupported(*scheme); !why.empty()) throw Error(why);
  if (!has_feature_rules(*scheme) && needs_no_feature_rules(base)) scheme = with_stand_in_rim_rules(*scheme);
  if (!base.manifold()) {
    impl_->cut_into_sheets(std::move(scheme), base, options);
    impl_->base = std::move(base);
    impl_->options = options;
    tag_boundary_holes(impl_->base, options.features.boundary);
    return;
  }
  // Where a sharpness ends between the two steps of a √3 pair, the pairs do not nest until it
  // has decayed: those first steps are the head of a sequence, followed one at a time.
  if (scheme->split() == SplitKind::Sqrt3)
    if (const int levels = sqrt3_single_step_levels(base); levels > 0) {
      impl_->become_sequence({{scheme, levels}}, scheme, std::move(base), options);
      return;
    }
  impl_->scheme = std::move(scheme);
  impl_->base = std::move(base);
  impl_->options = options;
  // With boundary interpolation "none" the faces along a boundary are holes (as the
  // engine and OpenSubdiv make them): they have no limit surface.
  tag_boundary_holes(impl_->base, options.features.boundary);
  if (impl_->scheme->split() == SplitKind::Dual) {
    if (const std::string why = dual_limit_unsupported(impl_->base); !why.empty())
      throw Error(fmt::format("scheme {} is a dual scheme and {}", subdiv::quoted(impl_->scheme->name), why));
  }
  if (impl_->scheme->split() >= SplitKind(kFirstRegisteredSplit)) {
    if (const std::string why = plugin_split_limit_unsupported(*impl_->scheme, impl_->base); !why.empty())
      throw Error(why);
  }
  if (impl_->scheme->split() == SplitKind::MidEdge) {
    if (const std::string why = mid_edge_limit_unsupported(impl_->base); !why.empty())
      throw Error(fmt::format("scheme {} uses the mid-edge split and {}", subdiv::quoted(impl_->scheme->name), why));
  }
  impl_->triangles = impl_->scheme->split() == SplitKind::Triangle || impl_->scheme->split() == SplitKind::Sqrt3;
  // Children near the cut's rim follow the rim's artificial boundary; with a reach of r
  // parent rings, 2 r + 2 rings keep the face's own neighbourhood right from level to level.
  const SchemeRun run{impl_->scheme.get(), 1};
  double loss = 1;
  if (impl_->scheme->split() < SplitKind(kFirstRegisteredSplit))  // a plugin's split may not state its reach
    for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss = std::max(loss, x);
  impl_->radius = std::max(4, 2 * int(std::ceil(loss)) + 2);
  // The evaluation carries the vertices within a few rings of the face (at most radius - 2:
  // the rim's two rings absorb the cut's artificial boundary); the nodes check that each
  // step reads only them, and the depth grows from one ring until it does.
  LimitOptions lo;
  lo.features = options.features;
  impl_->limits = std::make_unique<SchemeLimits>(*impl_->scheme, lo);
  impl_->set_cache(impl_->make_cache(1));
  impl_->grid_face = std::make_unique<std::atomic<char>[]>(size_t(impl_->base.face_count()));  // zero
  if (impl_->scheme->split() == SplitKind::Dual)
    impl_->dual = std::make_unique<DualLimit>(*impl_->scheme, impl_->base, options, impl_->radius, *impl_->limits);
  if (impl_->scheme->split() == SplitKind::Sqrt3)
    impl_->sqrt3 = std::make_unique<Sqrt3Limit>(*impl_->scheme, impl_->base, options, *impl_->limits);
  if (impl_->scheme->split() == SplitKind::MidEdge)
    impl_->mid_edge = std::make_unique<MidEdgeLimit>(*impl_->scheme, impl_->base, options, *impl_->limits);
  if (impl_->scheme->split() >= SplitKind(kFirstRegisteredSplit)) {
    impl_->plugin = std::make_unique<PluginSplitLimit>(*impl_->scheme, impl_->base, options, *impl_->limits);
    impl_->triangles = impl_->plugin->triangles();
  }
}

LimitSurface::LimitSurface(std::vector<LimitHeadRun> head, std::shared_ptr<const Scheme> tail, Level base,
                           const LimitSurfaceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (!tail) throw Error("no scheme given for the limit surface");
  if (const std::string why = limit_surface_unsupported(*tail); !why.empty()) throw Error(why);
  if (!base.manifold())
    throw Error(fmt::format("limit evaluation at (face, u, v) of a scheme sequence needs a manifold mesh, but {}",
                            non_manifold_place(base)));
  impl_->become_sequence(std::move(head), std::move(tail), std::move(base), options);
}

LimitStencil LimitSurface::sequence_stencil(Index face, double u, double v, int derivatives) const {
  if (face < 0 || face >= impl_->base.face_count())
    throw Error(no_such_face(face, impl_->base.face_count()));
  if (impl_->base.is_hole(face)) throw Error(fmt::format("face {} is a hole: it has no limit surface", face));
  const FacePoint q = impl_->head->map(impl_->base, face, u, v);
  const LimitStencil w = impl_->tail->stencil(q.face, q.st[0], q.st[1], derivatives);
  // Weights over the head's mesh pulled back to the base; derivatives by the chain rule
  // with the head's constant d(st)/d(u, v) (every split is affine on the point's face).
  const auto& J = q.jacobian;
  auto lift = [&](auto weight) {
    SparseRow r;
    for (size_t k = 0; k < w.vertices.size(); ++k) r.emplace_back(w.vertices[k], weight(k));
    return impl_->head->pull_back(std::move(r));
  };
  LimitStencil out;
  out.has_derivatives = w.has_derivatives;
  out.has_second_derivatives = w.has_second_derivatives;
  std::vector<SparseRow> rows{lift([&](size_t k) { return w.position[k]; })};
  if (w.has_derivatives)
    for (size_t a = 0; a < 2; ++a)
      rows.push_back(lift([&](size_t k) { return J[0][a] * w.du[k] + J[1][a] * w.dv[k]; }));
  if (w.has_second_derivatives) {
    constexpr size_t kPairs[3][2] = {{0, 0}, {0, 1}, {1, 1}};
    for (const auto& pair : kPairs) {
      const size_t a = pair[0], b = pair[1];
      rows.push_back(lift([&](size_t k) {
        return J[0][a] * J[0][b] * w.duu[k] + (J[0][a] * J[1][b] + J[1][a] * J[0][b]) * w.duv[k] +
               J[1][a] * J[1][b] * w.dvv[k];
      }));
    }
  }
  // One vertex list for every row.
  std::vector<Index> all;
  for (const SparseRow& r : rows)
    for (const auto& e : r) all.push_back(e.first);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  out.vertices = all;
  std::vector<std::vector<double>*> targets{&out.position, &out.du, &out.dv, &out.duu, &out.duv, &out.dvv};
  for (size_t i = 0; i < rows.size(); ++i) {
    std::vector<double>& t = *targets[i];
    t.assign(all.size(), 0.0);
    for (const auto& [vertex, weight] : rows[i])
      t[size_t(std::lower_bound(all.begin(), all.end(), vertex) - all.begin())] = weight;
  }
  return out;
}

namespace {

// A stencil over the sheets' vertices as one over the base vertices they copy: the copies'
// weights summed, the vertices in increasing order.
LimitStencil on_base_vertices(const LimitStencil& w, const std::vector<Index>& origin) {
  LimitStencil out;
  out.has_derivatives = w.has_derivatives;
  out.has_second_derivatives = w.has_second_derivatives;
  for (Index v : w.vertices) out.vertices.push_back(origin[size_t(v)]);
  std::sort(out.vertices.begin(), out.vertices.end());
  out.vertices.erase(std::unique(out.vertices.begin(), out.vertices.end()), out.vertices.end());
  const auto place = [&](size_t k) {
    return size_t(std::lower_bound(out.vertices.begin(), out.vertices.end(), origin[size_t(w.vertices[k])]) -
                  out.vertices.begin());
  };
  const std::pair<const std::vector<double>*, std::vector<double>*> rows[] = {
      {&w.position, &out.position}, {&w.du, &out.du}, {&w.dv, &out.dv},
      {&w.duu, &out.duu},           {&w.duv, &out.duv}, {&w.dvv, &out.dvv}};
  for (const auto& [from, to] : rows) {
    if (from->empty()) continue;
    to->assign(out.vertices.size(), 0.0);
    for (size_t k = 0; k < w.vertices.size(); ++k) (*to)[place(k)] += (*from)[k];
  }
  return out;
}

}  // namespace

LimitSurface::~LimitSurface() = default;
LimitSurface::LimitSurface(LimitSurface&&) noexcept = default;
LimitSurface& LimitSurface::operator=(LimitSurface&&) noexcept = default;

const Level& LimitSurface::base() const { return impl_->base; }
const LimitSurfaceOptions& LimitSurface::options() const { return impl_->options; }
bool LimitSurface::triangles() const { return impl_->triangles; }

std::string LimitSurface::check(Index face, double u, double v) const {
  if (impl_->sheets) return impl_->sheets->check(face, u, v);
  try {
    if (impl_->tail) {
      if (face < 0 || face >= impl_->base.face_count())
        throw Error(no_such_face(face, impl_->base.face_count()));
      if (impl_->base.is_hole(face)) throw Error(fmt::format("face {} is a hole: it has no limit surface", face));
      impl_->head->map(impl_->base, face, u, v);
      return {};
    }
    impl_->start(face, u, v);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

namespace {

// A sample as a fresh one is, its vectors' memory kept.
void clear_sample(LimitSample& s) {
  for (std::vector<double>* v : {&s.position, &s.du, &s.dv, &s.duu, &s.duv, &s.dvv}) v->clear();
  s.has_derivatives = s.has_second_derivatives = false;
  s.steps = 0;
}

}  // namespace

LimitSample LimitSurface::evaluate(Index face, double u, double v, std::span<const double> values, int channels,
                                   int derivatives) const {
  LimitSample out;
  evaluate_into(face, u, v, values, channels, derivatives, out);
  return out;
}

void LimitSurface::evaluate_into(Index face, double u, double v, std::span<const double> values, int channels,
                                 int derivatives, LimitSample& out) const {
  if (derivatives < 0 || derivatives > 2)
    throw Error(fmt::format("derivatives {}: the order must be 0, 1 or 2", derivatives));
  if (channels < 1 || values.size() < size_t(impl_->base.vertex_count) * size_t(channels))
    throw Error(fmt::format("limit evaluation needs {} values per vertex for {} vertices, got {}", channels,
                            impl_->base.vertex_count, values.size()));
  naming_the_point(face, u, v, [&] { evaluate_unnamed(face, u, v, values, channels, derivatives, out); });
}

void LimitSurface::evaluate_unnamed(Index face, double u, double v, std::span<const double> values, int channels,
                                    int derivatives, LimitSample& out) const {
  clear_sample(out);
  if (impl_->sheets || impl_->tail) {
    // Through the stencil: a non-manifold mesh's sheets would need a copy of every vertex's
    // values per point; a sequence's head has no values of its own.
    const LimitStencil w = impl_->sheets ? stencil(face, u, v, derivatives) : sequence_stencil(face, u, v, derivatives);
    auto apply = [&](const std::vector<double>& weights, std::vector<double>& r) {
      r.assign(size_t(channels), 0.0);
      for (size_t k = 0; k < w.vertices.size(); ++k)
        for (int c = 0; c < channels; ++c)
          r[size_t(c)] += weights[k] * values[size_t(w.vertices[k]) * size_t(channels) + size_t(c)];
    };
    apply(w.position, out.position);
    out.has_derivatives = w.has_derivatives && derivatives >= 1;
    out.has_second_derivatives = w.has_second_derivatives && derivatives >= 2;
    if (out.has_derivatives) apply(w.du, out.du), apply(w.dv, out.dv);
    if (out.has_second_derivatives) apply(w.duu, out.duu), apply(w.duv, out.duv), apply(w.dvv, out.dvv);
    return;
  }
  evaluate_at(impl_->start(face, u, v), values, channels, derivatives, out);
}

void LimitSurface::evaluate_at(const FacePoint& p, std::span<const double> values, int channels, int derivatives,
                               LimitSample& out) const {
  // The splits with evaluators of their own (dual, plugin, mid-edge, sqrt3): the values they
  // read, then their own descent.
  const auto by = [&](const auto& evaluator) {
    const std::vector<double> first = gathered(evaluator.reads(p), values, channels);
    // A sample made anyway: moved into `out` (its buffers taken, not copied).
    out = tbb::this_task_arena::isolate([&] { return evaluator.evaluate(p, first, channels, derivatives); });
  };
  if (impl_->dual) return by(*impl_->dual);
  if (impl_->plugin) return by(*impl_->plugin);
  if (impl_->mid_edge) return by(*impl_->mid_edge);
  if (impl_->sqrt3) return by(*impl_->sqrt3);
  if (impl_->options.shortcuts && p.sub_face < 0 && impl_->options.max_steps > 0) {
    Impl::Cache* c = impl_->cache_now.load(std::memory_order_acquire);
    const Impl::Entry* e = nullptr;
    bool grid = Impl::prepared(*c, p.face, e) || (!e && impl_->fill_slot(*c, p.face));
    if (!grid && !e)
      grid = impl_->with_cache([&](Impl::Cache& cache) { return impl_->prepare(*(c = &cache), p.face, e); });
    if (grid) {
      const Impl::GridSlot& slot = c->slots.load(std::memory_order_acquire)[size_t(p.face)];
      return Impl::bspline_sample(
          c->regular.load(std::memory_order_acquire)->grid_cell,
          [&](size_t l) { return slot.get(l, std::memory_order_relaxed) - 1; }, p, values, channels,
          derivatives, out);
    }
    if (e->grid)
      return Impl::bspline_sample(
          e->grid_cell, [&](size_t l) { return e->vertices[l]; }, p, values, channels, derivatives, out);
    if (e->lattice && impl_->triangles) {
      if (e->lattice->box && channels == 3)
        return Impl::box_spline_sample(*e->lattice->box, e->box_vertices, p, values, derivatives, out);
      FixedRows rows;
      if (quartic_rows_fixed(*e->lattice, p.st, derivatives, rows))
        return Impl::fixed_sample(rows, e->vertices, p, values, channels, derivatives, out);
    }
    if (e->lattice && e->lattice->bicubic) {
      // walk()'s first step where the face's node is the bicubic patch (bspline_end).
      const BicubicLabels& b = *e->lattice->bicubic;
      out.steps = 0;
      return Impl::bspline_sample(
          b.cell, [&](size_t l) { return e->vertices[size_t(b.label[l])]; }, p, values, channels, derivatives, out);
    }
    if (e->lattice) {
      // walk()'s first step where the face's node is a polynomial patch, without the nodes' lock.
      const std::vector<double> first = gathered(e->vertices, values, channels);
      const CornerRows rows = impl_->triangles ? quartic_rows(*e->lattice, p.st, derivatives)
                                               : tensor_rows(e->lattice->lattice, p.st, derivatives);
      const std::vector<const StepMatrix*> path;
      out = Impl::finish(rows, p, first, channels, derivatives, path, first, 0, nullptr);
      return;
    }
  }
  out = impl_->with_cache([&](Impl::Cache& cache) {
    const std::vector<double> first = gathered(impl_->reads(cache, p), values, channels);
    return impl_->descend(cache, p, first, channels, derivatives);
  });
}

LimitStencil LimitSurface::stencil(Index face, double u, double v, int derivatives) const {
  if (derivatives < 0 || derivatives > 2)
    throw Error(fmt::format("derivatives {}: the order must be 0, 1 or 2", derivatives));
  return naming_the_point(face, u, v, [&] { return stencil_unnamed(face, u, v, derivatives); });
}

LimitStencil LimitSurface::stencil_unnamed(Index face, double u, double v, int derivatives) const {
  if (impl_->sheets) return on_base_vertices(impl_->sheets->stencil(face, u, v, derivatives), impl_->sheet_origin);
  if (impl_->tail) return sequence_stencil(face, u, v, derivatives);
  const FacePoint p = impl_->start(face, u, v);
  // The evaluation is linear in the values: evaluate the unit vectors of the face's
  // neighbourhood (the only vertices it reads) as channels.
  std::vector<Index> original;
  Impl::DerivativeRows rows;
  const LimitSample s = impl_->plugin ? tbb::this_task_arena::isolate([&] {
    original = impl_->plugin->reads(p);
    const size_t n = original.size();
    std::vector<double> unit(n * n, 0.0);
    for (size_t k = 0; k < n; ++k) unit[k * n + k] = 1.0;
    PluginSplitLimit::Rows r;
    LimitSample out = impl_->plugin->evaluate(p, unit, int(n), derivatives, &r);
    rows.du = std::move(r.du), rows.dv = std::move(r.dv);
    return out;
  }) : impl_->mid_edge ? tbb::this_task_arena::isolate([&] {
    original = impl_->mid_edge->reads(p);
    const size_t n = original.size();
    std::vector<double> unit(n * n, 0.0);
    for (size_t k = 0; k < n; ++k) unit[k * n + k] = 1.0;
    MidEdgeLimit::Rows r;
    LimitSample out = impl_->mid_edge->evaluate(p, unit, int(n), derivatives, &r);
    rows.du = std::move(r.du), rows.dv = std::move(r.dv);
    rows.duu = std::move(r.duu), rows.duv = std::move(r.duv), rows.dvv = std::move(r.dvv);
    return out;
  }) : impl_->sqrt3 ? tbb::this_task_arena::isolate([&] {
    original = impl_->sqrt3->reads(p);
    const size_t n = original.size();
    std::vector<double> unit(n * n, 0.0);
    for (size_t k = 0; k < n; ++k) unit[k * n + k] = 1.0;
    Sqrt3Limit::Rows r;
    LimitSample out = impl_->sqrt3->evaluate(p, unit, int(n), derivatives, &r);
    rows.du = std::move(r.du), rows.dv = std::move(r.dv);
    rows.duu = std::move(r.duu), rows.duv = std::move(r.duv), rows.dvv = std::move(r.dvv);
    return out;
  }) : impl_->dual ? tbb::this_task_arena::isolate([&] {
    original = impl_->dual->reads(p);
    const size_t n = original.size();
    std::vector<double> unit(n * n, 0.0);
    for (size_t k = 0; k < n; ++k) unit[k * n + k] = 1.0;
    DualLimit::Rows r;
    LimitSample out = impl_->dual->evaluate(p, unit, int(n), derivatives, &r);
    rows.du = std::move(r.du), rows.dv = std::move(r.dv);
    rows.duu = std::move(r.duu), rows.duv = std::move(r.duv), rows.dvv = std::move(r.dvv);
    return out;
  }) : impl_->with_cache([&](Impl::Cache& cache) {
    original = impl_->reads(cache, p);
    const size_t n = original.size();
    std::vector<double> unit(n * n, 0.0);
    for (size_t k = 0; k < n; ++k) unit[k * n + k] = 1.0;
    return impl_->descend(cache, p, unit, int(n), derivatives, &rows);
  });
  const size_t m = original.size();
  LimitStencil out;
  out.has_derivatives = s.has_derivatives;
  out.has_second_derivatives = s.has_second_derivatives;
  auto used = [&](size_t k) {
    bool any = s.position[k] != 0;
    if (s.has_derivatives) any = any || rows.du[k] != 0 || rows.dv[k] != 0;
    if (s.has_second_derivatives) any = any || rows.duu[k] != 0 || rows.duv[k] != 0 || rows.dvv[k] != 0;
    return any;
  };
  for (size_t k = 0; k < m; ++k) {
    if (!used(k)) continue;
    out.vertices.push_back(original[k]);
    out.position.push_back(s.position[k]);
    if (s.has_derivatives) out.du.push_back(rows.du[k]), out.dv.push_back(rows.dv[k]);
    if (s.has_second_derivatives)
      out.duu.push_back(rows.duu[k]), out.duv.push_back(rows.duv[k]), out.dvv.push_back(rows.dvv[k]);
  }
  return out;
}

}  // namespace subdiv
