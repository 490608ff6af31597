#include "framework/rules/stencil_builder.h"

#include <algorithm>
#include <tbb/parallel_for.h>

#include "framework/rules/row_plans.h"
#include "framework/util/bulk_memory.h"

namespace subdiv {
namespace {

// When every group's children are one run of consecutive child indices (the primal
// splits number vertex, edge and face children in blocks), the groups in the order of
// their runs; else empty.
std::vector<int> contiguous_group_order(const std::vector<ChildGroup>& groups, Index child_count) {
  std::vector<int> order;
  for (int g = 0; g < int(groups.size()); ++g) {
    const ChildGroup& group = groups[g];
    if (group.empty()) continue;
    if (group.child(group.size() - 1) - group.child(0) + 1 != group.size()) return {};
    order.push_back(g);
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return groups[a].child(0) < groups[b].child(0); });
  Index next = 0;
  for (int g : order) {
    if (groups[g].child(0) != next) return {};
    next += groups[g].size();
  }
  return next == child_count ? order : std::vector<int>{};
}

// The table as the chunks one after the other, each chunk's memory released as soon as it
// is copied: the final table's pages replace the chunks' instead of adding to them, so the
// peak stays near the size of one copy of the rows.
StencilTable concatenate_rows(Index source_count, const std::vector<int>& order, std::vector<ChunkedRows>& blocks) {
  size_t rows = 0, entries = 0;
  for (int g : order)
    for (const RowBlock& b : blocks[g].chunks) rows += b.offsets.size() - 1, entries += b.indices.size();
  StencilTable table;
  table.source_count = source_count;
  reserve_bulk(table.offsets, rows + 1);
  reserve_bulk(table.indices, entries);
  reserve_bulk(table.weights, entries);
  for (int g : order)
    for (RowBlock& b : blocks[g].chunks) {
      const Index base = table.offsets.back();
      for (size_t r = 1; r < b.offsets.size(); ++r) table.offsets.push_back(base + b.offsets[r]);
      table.indices.insert(table.indices.end(), b.indices.begin(), b.indices.end());
      table.weights.insert(table.weights.end(), b.weights.begin(), b.weights.end());
      b = RowBlock{};
    }
  return table;
}

// Any other numbering: child c is row `position` of its group's block.
StencilTable gather_rows(const StepContext& s, const std::vector<ChildGroup>& groups,
                         const std::vector<ChunkedRows>& blocks) {
  const Index child_count = Index(s.origins.kind.size());
  std::vector<Index> position(child_count);
  for (const auto& g : groups)
    for (Index r = 0; r < g.size(); ++r) position[g.child(r)] = r;
  StencilTable table;
  table.source_count = s.parent.vertex_count;
  resize_bulk(table.offsets, size_t(child_count) + 1);
  table.offsets[0] = 0;
  for (Index c = 0; c < child_count; ++c)
    table.offsets[c + 1] = table.offsets[c] + blocks[int(s.origins.kind[c])].row_size(position[c]);
  resize_bulk(table.indices, size_t(table.offsets.back()));
  resize_bulk(table.weights, size_t(table.offsets.back()));
  tbb::parallel_for(Index(0), child_count, [&](Index c) {
    const ChunkedRows& rows = blocks[int(s.origins.kind[c])];
    const RowBlock& b = rows.chunk_of(position[c]);
    const Index from = b.offsets[rows.local(position[c])], to = b.offsets[rows.local(position[c]) + 1];
    std::copy(b.indices.begin() + from, b.indices.begin() + to, table.indices.begin() + table.offsets[c]);
    std::copy(b.weights.begin() + from, b.weights.begin() + to, table.weights.begin() + table.offsets[c]);
  });
  return table;
}

}  // namespace

ChildOrigins identity_origins(const Level& level) {
  ChildOrigins o;
  o.kind.assign(level.vertex_count, OriginKind::Vertex);
  o.parent.resize(level.vertex_count);
  for (Index v = 0; v < level.vertex_count; ++v) o.parent[v] = v;
  o.local.assign(level.vertex_count, 0);
  return o;
}

StencilTable build_step_stencils(const StepContext& s) {
  const std::vector<ChildGroup> groups = group_children(s);
  RuleInputs in{s.parent, s.features};
  in.groups = &groups;
  std::vector<ChunkedRows> blocks(kElementCount);
  RowPlanStore plans(s.parent, s.origins, s.tables, s.features, s.code != nullptr);
  for (Element e : build_order(s, groups)) {
    blocks[int(e)] = build_rows(s, in, groups[int(e)], plans);
    in.blocks[int(e)] = &blocks[int(e)];
  }
  const std::vector<int> order = contiguous_group_order(groups, Index(s.origins.kind.size()));
  if (!order.empty()) return concatenate_rows(s.parent.vertex_count, order, blocks);
  return gather_rows(s, groups, blocks);
}

}  // namespace subdiv
