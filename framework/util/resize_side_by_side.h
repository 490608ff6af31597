#pragma once
// Sizing several large vectors at once.
//
// std::vector::resize zero-fills in the calling thread: sizing a level's arrays one after
// another is serial memory traffic (some 90 MB for a million faces). Here each vector's
// zero-fill runs in a task of its own. The memory is reserved first, in the calling thread:
// glibc gives each thread its own heap (arena), and the warm-memory mode of benchmarks and
// animation (reuse_bulk_memory) counts on the next refinement's arrays coming from the heap
// the last ones went back to; a worker thread's arena would hand out fresh pages instead.
#include <cstddef>
#include <tbb/parallel_invoke.h>
#include <vector>

#include "framework/util/bulk_memory.h"

namespace subdiv {

template <class T>
struct Sized {
  std::vector<T>& vector;
  std::size_t size;
};
template <class T>
Sized(std::vector<T>&, std::size_t) -> Sized<T>;

// Resizes every vector to its size (new elements value-initialised, as resize does), with
// huge pages advised as resize_bulk does. Needs two vectors or more.
template <class... T>
void resize_side_by_side(Sized<T>... sized) {
  (reserve_bulk(sized.vector, sized.size), ...);
  tbb::parallel_invoke([&vector = sized.vector, size = sized.size] { vector.resize(size); }...);
}

}  // namespace subdiv
