#pragma once
// A scheme applied for a number of levels: what `--scheme a:1,b:3` says, and what the
// engine refines with. Runs apply in order (Lin et al. 2015's two-step scheme is a shape step
// for one level, then Catmull-Clark).
namespace subdiv {

struct Scheme;

struct SchemeRun {
  const Scheme* scheme = nullptr;
  int levels = 0;
};

}  // namespace subdiv
