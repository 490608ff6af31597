#pragma once
// What a measurement worker reports to the parent, and the origin keys used to match the
// two libraries' refined vertices.
#include <cstdint>
#include <cstring>
#include <utility>
#include <span>
#include <string>
#include <vector>

#include "bench_mesh.h"

namespace subdiv_bench {

struct Job {
  std::string side;    // "subdivkit" or "osd"
  std::string scheme;  // "catmull-clark" or "loop"
  std::string mesh;    // a mesh kind, see bench_mesh.h
  std::int64_t faces = 0;
  int level = 1;
  int threads = 1;
  int repeat = 2;  // warm repetitions, after the cold one (bench_memory.h)
  std::int64_t check_max = 0;  // at most about this many vertices sent back for the check
  bool osd_full_topology = false;  // OpenSubdiv: full topology in the last level (not its default)
  bool row_plans = true;       // SubdivKit: replay learnt stencil rows (rules/row_plans.h)
  bool kernels = true;         // SubdivKit: compiled smooth kernels (rules/smooth_kernels.h)
  bool tables = false;         // SubdivKit: build stencil tables and apply them, instead of step_values
  // Repeated evaluation (--mode update): topology (and tables) once, outside the
  // repetitions, then only the positions re-evaluated: OpenSubdiv's StencilTableFactory +
  // UpdateValues against step_values (or, with tables, one composed table).
  bool update = false;
};

// A stage's time on two clocks: elapsed (wall) and the process's user time, which leaves
// out the kernel's work (mostly zeroing fresh pages, whose cost on a virtual machine
// depends on the host) and, single-threaded, waiting for a core on a busy machine.
struct Clocks {
  double wall_ms = 0, user_ms = 0;
  Clocks operator+(const Clocks& o) const { return {wall_ms + o.wall_ms, user_ms + o.user_ms}; }
};

// Times stages one after the other: each lap() returns the time since the previous one.
class Stopwatch {
public:
  Stopwatch();
  Clocks lap();

private:
  Clocks last_;
};

// One repetition's stages.
struct Timings {
  Clocks setup;    // base-level topology from the face arrays
  Clocks topo;     // uniform refinement of the topology to the level
  Clocks stencil;  // SubdivKit with --geometry tables: building the stencil tables (else and OSD: 0)
  Clocks apply;    // interpolating xyz level by level (--mode update: one re-evaluation)
  Clocks total() const { return setup + topo + stencil + apply; }
  Clocks geom() const { return stencil + apply; }
};

struct CheckRecord {
  std::uint64_t key;
  double xyz[3];
};

struct WorkerReport {
  Timings cold;  // the first repetition, in fresh process memory
  Timings warm;  // the best (by wall-clock total) of the warm repetitions
  bool warm_digest_same = true;  // every warm repetition gave the cold one's bits
  std::int64_t peak_rss_bytes = 0;  // the side: peak RSS right after its cold repetition
  double peak_mb = 0;          // the worker: that peak minus the RSS after making the mesh
  std::int64_t base_faces = 0;  // of the generated mesh
  std::int64_t vertices = 0;   // at the refined level
  std::int64_t faces = 0;      // at the refined level
  std::uint64_t digest = 0;    // hash of the refined positions' bits in the side's own order
  // SubdivKit, cold repetition: new points computed by each path of step_values.
  std::int64_t kernel_points = 0, plan_points = 0, generic_points = 0, flat_points = 0;  // flat: of the kernel points
  std::uint64_t check_modulus = 1;  // records kept: key % modulus == 0 (none if 0)
  std::vector<CheckRecord> records;
};

// Origin keys: a 64-bit name for every refined vertex that depends only on how it was
// made (level-0 vertex index; child of a vertex, of an edge's two end points, of a face's
// corners), not on either library's numbering. Both sides compute them from their own
// topology, so sorting by key matches the vertices of the two libraries.
inline std::uint64_t key_mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
inline std::uint64_t key_base(std::int64_t vertex) { return key_mix(std::uint64_t(vertex) ^ 0x5EEDull); }
inline std::uint64_t key_of_vertex_child(std::uint64_t parent) { return key_mix(parent ^ 0x1111111111111111ull); }
inline std::uint64_t key_of_edge_child(std::uint64_t a, std::uint64_t b) {
  if (a > b) std::swap(a, b);
  return key_mix(key_mix(a ^ 0x2222222222222222ull) ^ b);
}
// Order-free over the corners: sum of mixed keys, then mixed with the corner count.
inline std::uint64_t key_of_face_child(std::uint64_t corner_key_sum, int corners) {
  return key_mix(corner_key_sum ^ (0x3333333333333333ull + std::uint64_t(corners)));
}
inline std::uint64_t key_face_term(std::uint64_t corner) { return key_mix(corner ^ 0x4444444444444444ull); }

// A hash of the positions' bits: the same digest means the same output bits.
inline std::uint64_t digest_of(std::span<const double> values) {
  std::uint64_t h = 0x243F6A8885A308D3ull;
  for (double v : values) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = key_mix(h ^ bits);
  }
  return h;
}

// Memory figures from /proc/self/status, in bytes (0 when unavailable).
std::int64_t current_rss_bytes();
std::int64_t peak_rss_bytes();
// Resets the kernel's peak-RSS mark to the current RSS; false when not supported.
bool reset_peak_rss();

// Keeps the records whose key is a multiple of the modulus chosen so that about
// `check_max` of `count` vertices remain: all of them when check_max == 0 or >= count,
// none (modulus 0) when check_max < 0.
std::uint64_t check_modulus_for(std::int64_t count, std::int64_t check_max);

// The sides. Each runs once cold, then job.repeat times warm inside the calling (worker)
// process (repeat_cold_and_warm, bench_memory.h). run_osd exists only when built with
// OpenSubdiv.
WorkerReport run_subdivkit(const Job& job, const Mesh& mesh);
WorkerReport run_osd(const Job& job, const Mesh& mesh);

}  // namespace subdiv_bench
