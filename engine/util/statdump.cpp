#include "engine/util/statdump.h"

#include <cmath>
#include <cstdio>

namespace p3d {

std::string stat_number(double v) {
  char buf[40];
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9007199254740992.0)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (std::isfinite(v))
    std::snprintf(buf, sizeof buf, "%.6g", v);
  else
    return "null";
  return buf;
}

std::string statdump(const Stats& stats) {
  std::string out;
  for (const Stat& s : stats) out += (out.empty() ? "" : " ") + s.name + "=" + stat_number(s.value);
  return out;
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string stats_json(const Stats& stats) {
  std::string out = "{";
  for (size_t i = 0; i < stats.size(); ++i)
    out += (i ? ", " : "") + json_string(stats[i].name) + ": " + stat_number(stats[i].value);
  return out + "}";
}

}  // namespace p3d
