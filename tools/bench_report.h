// bench's shared pieces: the report (markdown tables, kept for --json) and the small
// statistics every section uses. Sections live in bench.cpp, bench_wad.cpp,
// bench_doom.cpp and bench_play.cpp; what they share besides, in bench_common.h.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "engine/util/statdump.h"

namespace p3d::bench {

// The tables bench prints, kept as they are printed so --json says the same thing
// with the same names: a section per "### title", a row per table line, each cell
// under its column's name in snake case, numbers as numbers.
class Report {
 public:
  void print(const char* fmt, ...) __attribute__((format(printf, 2, 3))) {
    char buf[4096];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    std::fputs(buf, stdout);
    std::fflush(stdout);
    pending_ += buf;
    for (size_t nl; (nl = pending_.find('\n')) != std::string::npos; pending_.erase(0, nl + 1)) line(pending_.substr(0, nl));
  }

  struct Section {
    std::string title;
    std::vector<std::string> columns;           // as printed
    std::vector<std::string> rows;              // as JSON objects
    std::vector<std::vector<std::string>> cells;  // as printed, per row
  };

  // The first section whose title starts with prefix, or null.
  const Section* find(const std::string& prefix) const {
    for (const Section& s : sections_)
      if (s.title.rfind(prefix, 0) == 0) return &s;
    return nullptr;
  }

  std::string json() const {
    std::string out = "{\"sections\": [";
    for (size_t i = 0; i < sections_.size(); ++i) {
      out += std::string(i ? ",\n " : "\n ") + "{\"title\": " + json_string(sections_[i].title) + ", \"rows\": [";
      for (size_t r = 0; r < sections_[i].rows.size(); ++r) out += std::string(r ? ",\n  " : "\n  ") + sections_[i].rows[r];
      out += "]}";
    }
    return out + "\n]}\n";
  }

 private:
  static std::vector<std::string> cells(const std::string& line) {
    std::vector<std::string> out;
    size_t start = 1;
    for (size_t bar; (bar = line.find('|', start)) != std::string::npos; start = bar + 1) {
      std::string cell = line.substr(start, bar - start);
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      out.push_back(cell);
    }
    return out;
  }

  static std::string snake(const std::string& name) {
    std::string out;
    for (const char c : name)
      if (std::isalnum(static_cast<unsigned char>(c)))
        out += char(std::tolower(static_cast<unsigned char>(c)));
      else if (!out.empty() && out.back() != '_')
        out += '_';
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
  }

  static std::string value(const std::string& cell) {
    if (cell.empty()) return "null";
    char* end = nullptr;
    const double v = std::strtod(cell.c_str(), &end);
    if (!cell.empty() && end && *end == 0 && std::isfinite(v)) return stat_number(v);
    return json_string(cell);
  }

  void line(const std::string& text) {
    if (text.rfind("### ", 0) == 0) {
      sections_.push_back({text.substr(4), {}, {}, {}});
      return;
    }
    if (sections_.empty() || text.rfind("|", 0) != 0) return;
    Section& s = sections_.back();
    const std::vector<std::string> row = cells(text);
    if (s.columns.empty()) {
      s.columns = row;
      return;
    }
    if (!row.empty() && row[0].rfind("---", 0) == 0) return;  // the header's rule
    std::string object = "{";
    for (size_t i = 0; i < row.size() && i < s.columns.size(); ++i)
      object += (i ? ", " : "") + json_string(snake(s.columns[i])) + ": " + value(row[i]);
    s.rows.push_back(object + "}");
    s.cells.push_back(row);
  }

  std::string pending_;
  std::vector<Section> sections_;
};

// The report every section prints into.
inline Report report;

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

inline std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

inline double geomean(const std::vector<double>& v) {
  double log_sum = 0;
  for (double x : v) log_sum += std::log(x);
  return v.empty() ? 0 : std::exp(log_sum / double(v.size()));
}

}  // namespace p3d::bench
