#include "scurve/types.h"

#include <algorithm>

namespace scurve {

std::string to_string_i128(i128 v) {
  if (v == 0) return "0";
  const bool neg = v < 0;
  u128 u = neg ? u128(-(v + 1)) + 1 : u128(v);
  std::string s;
  while (u) {
    s.push_back(char('0' + int(u % 10)));
    u /= 10;
  }
  if (neg) s.push_back('-');
  std::reverse(s.begin(), s.end());
  return s;
}

std::string to_hex_u128(u128 v, int bits) {
  v = mask_bits(v, bits);
  const int digits = (bits + 3) / 4;
  std::string s(size_t(digits), '0');
  for (int i = digits - 1; i >= 0; --i) {
    s[size_t(i)] = "0123456789abcdef"[int(v & 0xf)];
    v >>= 4;
  }
  return "0x" + s;
}

}  // namespace scurve
