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

enum class Clock { Wall, Cpu, User };
const char* clock_name(Clock clock);

struct Job {
  std::string side;    // "subdivkit" or "osd"
  std::string scheme;  // "catmull-clark" or "loop"
  std::string mesh;    // a mesh kind, see bench_mesh.h
  std::int64_t faces = 0;
  int level = 1;
  int threads = 1;
  int repeat = 1;
  std::int64_t check_max = 0;  // at most about this many vertices sent back for the check
  Clock clock = Clock::Wall;
  bool row_plans = true;       // SubdivKit: replay learnt stencil rows (rules/row_plans.h)
  bool tables = false;         // SubdivKit: build stencil tables and apply them, instead of step_values
};

// Milliseconds on the wall clock (steady), on the process CPU clock (user + system time of
// all threads: on a shared machine it does not count time spent waiting for a core, but it
// adds up the threads, so it only compares like with like at --threads 1), or of user time
// alone (leaves out the kernel's work, mostly zeroing fresh pages, whose cost on a virtual
// machine depends on the host).
double now_ms(Clock clock);

// Milliseconds of the best repetition (the one with the smallest total), and memory.
struct Timings {
  double setup_ms = 0;    // base-level topology from the face arrays
  double topo_ms = 0;     // uniform refinement of the topology to the level
  double stencil_ms = 0;  // SubdivKit with --geometry tables: building the stencil tables (else and OSD: 0)
  double apply_ms = 0;    // interpolating xyz level by level
  double total_ms() const { return setup_ms + topo_ms + stencil_ms + apply_ms; }
  double geom_ms() const { return stencil_ms + apply_ms; }
};

struct CheckRecord {
  std::uint64_t key;
  double xyz[3];
};

struct WorkerReport {
  Timings best;
  std::int64_t peak_rss_bytes = 0;  // the side: peak RSS right after its last repetition
  double peak_mb = 0;          // the worker: that peak minus the RSS after making the mesh
  std::int64_t base_faces = 0;  // of the generated mesh
  std::int64_t vertices = 0;   // at the refined level
  std::int64_t faces = 0;      // at the refined level
  std::uint64_t digest = 0;    // hash of the refined positions' bits in the side's own order
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

// The sides. Each runs job.repeat times inside the calling (worker) process and reports
// the best repetition. run_osd exists only when built with OpenSubdiv.
WorkerReport run_subdivkit(const Job& job, const Mesh& mesh);
WorkerReport run_osd(const Job& job, const Mesh& mesh);

}  // namespace subdiv_bench
