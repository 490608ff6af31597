#pragma once
// The machine's memory bandwidth, measured in the benchmark's own run: each figure is also
// printed as "x the bandwidth bound" (the bytes a level must write over this bandwidth).

namespace subdiv::bench {

struct Bandwidth {
  double write_gbs = 0;  // memset of a buffer far larger than the caches, best of the tries
  double copy_gbs = 0;   // memcpy between two such buffers: bytes read plus bytes written
};

// One core, `megabytes` per buffer (already touched, so first-touch costs are left out),
// best of `tries`.
Bandwidth measure_bandwidth(int megabytes = 512, int tries = 5);

}  // namespace subdiv::bench
