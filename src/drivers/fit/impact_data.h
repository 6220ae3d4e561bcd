// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: reading measured impact data (docs/tools/tdem-fit.md, "CSV format").
//
//   # material: steel (AISI 52100)
//   # source: Author et al., Journal 1 (2000) 1-10, Fig. 3          (may be repeated)
//   # notes: ...                                                   (may be repeated)
//   # configuration: wall            (wall | pair)
//   # R1: 0.0025                     sphere radius [m]
//   # rho: 7800                      sphere density [kg/m^3]
//   # E: 2.1e11                      Young's modulus [Pa]
//   # nu: 0.3                        Poisson ratio
//   # E2: inf                        wall / partner modulus (default E; inf: rigid)
//   # nu2: 0.3                       (default nu)
//   # R2: 0.0025                     partner radius (pair only; default R1)
//   # rho2: 7800                     partner density (pair only; default rho)
//   v0,e,e_err,tc,tc_err             header: v0 and e required, the others optional
//   0.5,0.95,0.01,,                  rows (SI units, empty cells allowed)
//
// Optional extra columns fmax, fmax_err (peak force [N]). A number may be followed by a unit in
// the comment lines ("# R1: 0.0025 m"). Every error names the line number.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace tdem {
namespace fitdata {

struct BadData : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Point {
  int line = 0;
  double v0 = NAN;
  double e = NAN, e_err = NAN;
  double tc = NAN, tc_err = NAN;
  double fmax = NAN, fmax_err = NAN;
};

struct Data {
  std::string file;
  std::string material, source, notes;
  bool wall = true;
  double R1 = NAN, rho = NAN, E = NAN, nu = NAN;
  double E2 = NAN, nu2 = NAN, R2 = NAN, rho2 = NAN;  // filled with the defaults after reading
  std::vector<Point> points;
  std::vector<std::string> warnings;  // "path:line: ..." (unknown keys that look like known ones)

  int count(char q) const {
    int n = 0;
    for (const auto& p : points) n += std::isfinite(q == 'e' ? p.e : q == 't' ? p.tc : p.fmax);
    return n;
  }
};

inline std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

// Levenshtein distance of two short words (for "did you mean" of a misspelt key)
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

[[noreturn]] inline void fail(const std::string& file, int line, const std::string& msg) {
  throw BadData(file + ":" + std::to_string(line) + ": " + msg);
}

// A number; allow_unit: trailing text after whitespace is a unit / comment.
inline double parse_number(const std::string& file, int line, const std::string& what, const std::string& text,
                           bool allow_unit, bool allow_inf = false) {
  const std::string s = trim(text);
  const char* b = s.c_str();
  char* end = nullptr;
  const double v = std::strtod(b, &end);
  bool ok = !s.empty() && end != b && !std::isnan(v);
  if (ok && *end != '\0') ok = allow_unit && std::isspace(static_cast<unsigned char>(*end));
  if (!ok) fail(file, line, what + ": '" + s + "' is not a number");
  if (std::isinf(v) && !(allow_inf && v > 0))
    fail(file, line, what + " = " + s + " is outside the allowed range " + (allow_inf ? "(0, inf]" : "(0, inf)"));
  return v;
}

inline void check_range(const std::string& file, int line, const std::string& what, double v, double lo, double hi,
                        bool lo_open, bool hi_open, const char* range) {
  const bool bad = !(lo_open ? v > lo : v >= lo) || !(hi_open ? v < hi : v <= hi);
  if (bad) {
    std::ostringstream o;
    o.precision(17);
    o << what << " = " << v << " is outside the allowed range " << range;
    fail(file, line, o.str());
  }
}

inline std::vector<std::string> split_csv(const std::string& s) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (true) {
    const size_t c = s.find(',', pos);
    out.push_back(trim(s.substr(pos, c == std::string::npos ? std::string::npos : c - pos)));
    if (c == std::string::npos) break;
    pos = c + 1;
  }
  return out;
}

// Reads the data file line by line (streamed: the rows are not held as text); path "-" reads
// standard input. A UTF-8 byte-order mark and CRLF line ends are accepted; UTF-16, CR-only line
// ends and binary files are refused with a message that says so.
inline Data read(const std::string& path) {
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) throw BadData(path + ": cannot open the data file");
  }
  std::istream& in = path == "-" ? std::cin : file;
  Data d;
  d.file = path;
  std::map<std::string, int> seen;  // numeric key -> line
  std::vector<std::string> header;
  std::string raw;
  int line = 0;
  static const std::vector<std::string> columns = {"v0", "e", "e_err", "tc", "tc_err", "fmax", "fmax_err"};
  while (std::getline(in, raw)) {
    ++line;
    if (line == 1) {
      if (raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);  // UTF-8 byte-order mark
      else if (raw.compare(0, 2, "\xFF\xFE") == 0 || raw.compare(0, 2, "\xFE\xFF") == 0)
        fail(path, line, "the file is UTF-16 encoded (byte-order mark " +
                             std::string(raw[0] == '\xFF' ? "FF FE" : "FE FF") + "); save it as UTF-8 or ASCII text");
    }
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();  // CRLF line ends
    if (raw.find('\r') != std::string::npos)
      fail(path, line, "the line contains a carriage return (CR): the file has CR-only (old Mac) line ends; "
                       "convert them to LF or CRLF");
    if (raw.find('\0') != std::string::npos)
      fail(path, line, "the line contains a NUL byte: not a text file (UTF-16 without a byte-order mark?)");
    const std::string s = trim(raw);
    if (s.empty()) continue;
    if (s[0] == '#') {
      const std::string body = trim(s.substr(1));
      const size_t colon = body.find(':');
      if (colon == std::string::npos) continue;  // a free comment
      const std::string key = trim(body.substr(0, colon));
      const std::string value = trim(body.substr(colon + 1));
      if (key.empty() || key.find(' ') != std::string::npos) continue;  // free comment with a colon
      const std::string k = lower(key);
      auto append = [&](std::string& to) { to += (to.empty() ? "" : "\n") + value; };
      if (k == "material") append(d.material);
      else if (k == "source" || k == "sources") append(d.source);
      else if (k == "notes" || k == "note") append(d.notes);
      else if (k == "configuration") {
        const std::string v = lower(value);
        if (v == "wall") d.wall = true;
        else if (v == "pair") d.wall = false;
        else fail(path, line, "configuration: '" + value + "' is not one of: wall, pair");
        seen["configuration"] = line;
      } else {
        static const std::vector<std::string> numeric = {"r1", "rho", "e", "nu", "e2", "nu2", "r2", "rho2"};
        if (std::find(numeric.begin(), numeric.end(), k) == numeric.end()) {  // unknown key: a comment
          // ... unless it looks like a known one (E_2, Rho2, rh0): say so, the value is not used
          std::string norm;
          for (char ch : k)
            if (std::isalnum(static_cast<unsigned char>(ch))) norm += ch;
          static const std::vector<std::string> shown = {"R1", "rho", "E", "nu", "E2", "nu2", "R2", "rho2"};
          for (std::size_t q = 0; q < numeric.size(); ++q)
            if (norm == numeric[q] || (k.size() >= 3 && edit_distance(k, numeric[q]) == 1)) {
              d.warnings.push_back(path + ":" + std::to_string(line) + ": key '" + key + "' is not known and is "
                                   "taken as a comment; did you mean '" + shown[q] + "'?");
              break;
            }
          continue;
        }
        if (seen.count(k)) fail(path, line, "key '" + key + "' given twice (first on line " + std::to_string(seen[k]) + ")");
        seen[k] = line;
        if (k == "e2") {
          const std::string v = lower(value);
          d.E2 = (v == "inf" || v.rfind("inf ", 0) == 0) ? INFINITY : parse_number(path, line, key, value, true, true);
          check_range(path, line, key, d.E2, 0, INFINITY, true, false, "(0, inf]");
          continue;
        }
        const double v = parse_number(path, line, key, value, true);
        if (k == "nu" || k == "nu2") {
          check_range(path, line, key, v, -1.0, 0.5, true, false, "(-1, 0.5]");
        } else {
          check_range(path, line, key, v, 0.0, INFINITY, true, true, "(0, inf)");
        }
        if (k == "r1") d.R1 = v;
        else if (k == "rho") d.rho = v;
        else if (k == "e") d.E = v;
        else if (k == "nu") d.nu = v;
        else if (k == "nu2") d.nu2 = v;
        else if (k == "r2") d.R2 = v;
        else d.rho2 = v;
      }
      continue;
    }
    if (header.empty()) {
      header = split_csv(s);
      for (size_t i = 0; i < header.size(); ++i) {
        header[i] = lower(header[i]);
        if (std::find(columns.begin(), columns.end(), header[i]) == columns.end())
          fail(path, line, "header: unknown column '" + header[i] + "' (allowed: v0, e, e_err, tc, tc_err, fmax, fmax_err)");
        for (size_t j = 0; j < i; ++j)
          if (header[j] == header[i]) fail(path, line, "header: column '" + header[i] + "' given twice");
      }
      if (std::find(header.begin(), header.end(), "v0") == header.end() ||
          std::find(header.begin(), header.end(), "e") == header.end())
        fail(path, line, "header: the columns v0 and e are required (found '" + s + "')");
      continue;
    }
    const auto cells = split_csv(s);
    if (cells.size() != header.size())
      fail(path, line, "row has " + std::to_string(cells.size()) + " cells, the header has " +
                           std::to_string(header.size()));
    Point p;
    p.line = line;
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string& h = header[i];
      if (cells[i].empty()) {
        if (h == "v0") fail(path, line, "v0 is empty (every row needs an impact velocity)");
        continue;
      }
      const double v = parse_number(path, line, h, cells[i], false);
      if (h == "v0") {
        check_range(path, line, h, v, 0.0, INFINITY, true, true, "(0, inf)");
        p.v0 = v;
      } else if (h == "e") {
        check_range(path, line, h, v, 0.0, 1.0, true, false, "(0, 1]");
        p.e = v;
      } else {
        check_range(path, line, h, v, 0.0, INFINITY, true, true, "(0, inf)");
        if (h == "e_err") p.e_err = v;
        else if (h == "tc") p.tc = v;
        else if (h == "tc_err") p.tc_err = v;
        else if (h == "fmax") p.fmax = v;
        else p.fmax_err = v;
      }
    }
    if (!std::isfinite(p.e) && !std::isfinite(p.tc) && !std::isfinite(p.fmax))
      fail(path, line, "row has no measured value (e, tc or fmax)");
    if (std::isfinite(p.e_err) && !std::isfinite(p.e)) fail(path, line, "e_err is given without e");
    if (std::isfinite(p.tc_err) && !std::isfinite(p.tc)) fail(path, line, "tc_err is given without tc");
    if (std::isfinite(p.fmax_err) && !std::isfinite(p.fmax)) fail(path, line, "fmax_err is given without fmax");
    d.points.push_back(p);
  }
  if (header.empty()) fail(path, line, "no header line (expected e.g. 'v0,e,e_err,tc,tc_err')");
  if (d.points.empty()) fail(path, line, "no data rows after the header");
  if (d.count('e') == 0) fail(path, line, "no restitution values (column e is empty in every row)");
  for (const char* k : {"r1", "rho", "e", "nu"})
    if (!seen.count(k)) {
      const std::string key = std::string(k) == "r1" ? "R1" : std::string(k) == "e" ? "E" : k;
      fail(path, line, "missing '# " + key + ": value' line (needed: R1 [m], rho [kg/m^3], E [Pa], nu)");
    }
  if (!seen.count("configuration")) fail(path, line, "missing '# configuration: wall|pair' line");
  if (!std::isfinite(d.nu2)) d.nu2 = d.nu;
  if (std::isnan(d.E2)) d.E2 = d.E;
  if (d.wall) {
    for (const char* k : {"r2", "rho2"})
      if (seen.count(k))
        fail(path, seen[k], std::string(k == std::string("r2") ? "R2" : "rho2") +
                                " is given for configuration wall (allowed for pair only)");
    d.R2 = INFINITY;
    d.rho2 = INFINITY;
  } else {
    if (!std::isfinite(d.R2)) d.R2 = d.R1;
    if (!std::isfinite(d.rho2)) d.rho2 = d.rho;
  }
  if (d.material.empty() && path == "-") d.material = "standard input";
  if (d.material.empty()) {
    const size_t slash = path.find_last_of('/');
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const size_t dot = base.rfind('.');
    d.material = dot == std::string::npos ? base : base.substr(0, dot);
  }
  return d;
}

}  // namespace fitdata
}  // namespace tdem
