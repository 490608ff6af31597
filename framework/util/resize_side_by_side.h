#pragma once
// Sizing several large vectors at once.
//
// std::vector::resize zero-fills in the calling thread: sizing a level's arrays one after
// another is serial memory traffic (some 90 MB for a million faces). Here each vector's
// zero-fill runs in a task of its own; a level's own arrays are ScratchVectors
// (util/scratch_vector.h), which are not filled at all. The memory is reserved first, in the calling thread:
// glibc gives each thread its own heap (arena), and the warm-memory mode of benchmarks and
// animation (reuse_bulk_memory) counts on the next refinement's arrays coming from the heap
// the last ones went back to; a worker thread's arena would hand out fresh pages instead.
#include <cstddef>
#include <tbb/parallel_invoke.h>
#include <vector>

#include "framework/util/bulk_memory.h"

namespace subdiv {

template <class V>
struct Sized {
  V& vector;
  std::size_t size;
};
template <class T, class A>
Sized(std::vector<T, A>&, std::size_t) -> Sized<std::vector<T, A>>;

// Resizes every vector to its size (new elements value-initialised as resize does, or for a
// ScratchVector left as they come: util/scratch_vector.h), with huge pages advised as
// resize_bulk does. Needs two vectors or more.
template <class... V>
void resize_side_by_side(Sized<V>... sized) {
  (reserve_bulk(sized.vector, sized.size), ...);
  tbb::parallel_invoke([&vector = sized.vector, size = sized.size] { grow(vector, size); }...);
}

}  // namespace subdiv
