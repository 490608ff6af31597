// key_cut (limit/cut_key.h): a face's key read from the mesh must label as the canonical
// labelling does, and faces with one key must have cuts with one signature (what lets the
// limit surface share a node between them without cutting).
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>

#include "framework/analysis/surface/local_patch.h"
#include "framework/features/sharpness.h"
#include "framework/limit/cut_key.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

constexpr int kRadius = 4;  // the cut the limit surface takes (limit_surface.cpp)

// The cut's signature as the nodes key it (labelled beyond the cut, so that every vertex of
// the cut has a label), with its holes' label lists.
std::pair<std::vector<double>, std::vector<std::vector<Index>>> cut_signature(const Level& L, Index face) {
  const Extracted e = extract_neighbourhood(L, CentreKind::Face, face, kRadius);
  Level cut = e.level;
  Index local = kNone;
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == face) local = Index(f);
  const Labelling lab = label_neighbourhood(cut, CentreKind::Face, local, 0, kRadius + 3);
  std::vector<std::vector<Index>> holes;
  for (size_t f = 0; f < e.face_original.size(); ++f) {
    if (!L.is_hole(e.face_original[f])) continue;
    std::vector<Index> labels;
    for (Index v : cut.face(Index(f))) labels.push_back(lab.label_of[size_t(v)]);
    std::rotate(labels.begin(), std::min_element(labels.begin(), labels.end()), labels.end());
    holes.push_back(labels);
  }
  std::sort(holes.begin(), holes.end());
  return {lab.signature, holes};
}

// A 12 x 12 quad grid with an infinitely sharp crease across it, a semi-sharp edge, a
// tagged corner and a hole.
Level tagged_grid() {
  Level L = test::grid(12, 12).level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  for (Index i = 0; i < 12; ++i) L.edge_sharpness[size_t(find_edge(L, 65 + i, 66 + i))] = kInfinitelySharp;
  L.edge_sharpness[size_t(find_edge(L, 28, 29))] = 1.5f;
  L.vertex_sharpness[100] = kInfinitelySharp;
  L.face_hole.assign(size_t(L.face_count()), 0);
  L.face_hole[110] = 1;
  return L;
}

// A 16 x 16 torus with an infinitely sharp loop along row 0 and a semi-sharp (1.5) loop
// along row 8: neighbourhoods repeat along the rows, the tags tell the rows apart.
Level creased_torus() {
  Level L = test::torus(16, 16).level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (Index i = 0; i < 16; ++i) {
    L.edge_sharpness[size_t(find_edge(L, i, (i + 1) % 16))] = kInfinitelySharp;
    L.edge_sharpness[size_t(find_edge(L, 128 + i, 128 + (i + 1) % 16))] = 1.5f;
  }
  return L;
}

}  // namespace

TEST_CASE("key_cut labels as label_neighbourhood does, and one key means one cut signature") {
  LocalConfig three, five;
  three.valence = 3;
  five.valence = 5;
  const std::vector<std::pair<const char*, Level>> meshes = {
      {"tagged grid with a hole", tagged_grid()},
      {"valence-3 patch", make_vertex_patch(PatchCells::Quads, three, 9).level},
      {"valence-5 patch", make_vertex_patch(PatchCells::Quads, five, 9).level},
      {"triangulated torus", test::torus(14, 12, true).level()},
      {"cube", test::cube().level()},
      {"narrow torus", test::torus(6, 30).level()},
      {"creased torus", creased_torus()}};
  for (const auto& mesh : meshes) {
    // Named copies, not structured bindings: doctest's INFO captures them in a lambda.
    const std::string name = mesh.first;
    const Level& L = mesh.second;
    CutKey k;
    Labelling lab;
    std::map<std::vector<std::uint32_t>, std::pair<std::vector<double>, std::vector<std::vector<Index>>>> seen;
    int shared = 0;
    for (Index f = 0; f < L.face_count(); ++f) {
      INFO(name << ", face " << f);
      key_cut(k, L, f, kRadius);
      label_neighbourhood(lab, L, CentreKind::Face, f, 0, kRadius);
      REQUIRE(k.vertices == lab.vertices);
      CHECK(k.distance == lab.distance);
      CHECK(k.count_within(1) == lab.count_within(1));
      const auto signature = cut_signature(L, f);
      const auto made = seen.emplace(k.key, signature);
      if (!made.second) {
        ++shared;
        CHECK(made.first->second == signature);
      }
    }
    // On a torus every face's neighbourhood is every other's up to a translation (two
    // kinds of triangle when triangulated; one per row with the creases): the key is
    // shared, not one per face.
    if (name.find("torus") != std::string::npos) CHECK(shared >= L.face_count() - 16);
  }
}
