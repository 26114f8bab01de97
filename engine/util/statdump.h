// Statistics said one way everywhere: named values in a fixed order, printed as a
// `key=value` line (whole numbers exactly, others to 6 significant digits) or as a
// JSON object with the same names. Deterministic fields and timings are kept in
// separate lists by the callers, so a statdump line is reproducible byte for byte.
#pragma once

#include <string>
#include <vector>

namespace p3d {

struct Stat {
  std::string name;
  double value;  // whole numbers up to 2^53 print exactly
};
using Stats = std::vector<Stat>;

// "a=1 b=2.5"
std::string statdump(const Stats& stats);
// {"a": 1, "b": 2.5}
std::string stats_json(const Stats& stats);
// A number as both formats write it: "12", "0.0625", "1.5e+09".
std::string stat_number(double value);
// A JSON string literal.
std::string json_string(const std::string& text);

}  // namespace p3d
