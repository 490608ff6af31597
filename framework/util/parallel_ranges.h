#pragma once
// A loop over [0, count) cut into blocks of at least `grain` elements, each block handed to
// `body(begin, end)` on some thread: the shape of every parallel pass over a level's
// elements (topology builders, splits). TBB chooses the blocks; a body that writes only
// its own elements' results gives the same output for any thread count.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace subdiv {

template <class Index, class Body>
void parallel_ranges(Index count, Index grain, Body body) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, count, grain),
                    [&](const tbb::blocked_range<Index>& r) { body(r.begin(), r.end()); });
}

}  // namespace subdiv
