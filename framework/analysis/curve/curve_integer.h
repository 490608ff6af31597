#pragma once
// Integer division rounding towards -infinity / +infinity and a non-negative modulo: mask
// and symbol indices are often negative, where C++'s truncating '/' and '%' are wrong.

namespace subdiv {

inline int floor_div(int a, int b) {  // b > 0
  const int q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

inline int ceil_div(int a, int b) {  // b > 0
  const int q = a / b;
  return (a % b != 0 && a > 0) ? q + 1 : q;
}

inline long long positive_mod(long long a, long long b) {  // b > 0, result in [0, b)
  const long long r = a % b;
  return r < 0 ? r + b : r;
}

}  // namespace subdiv
