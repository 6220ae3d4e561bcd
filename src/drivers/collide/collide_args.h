// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the options (Args), their readers with range checks, and the JSON writer. A part of main.cpp (collide_common.h).
#pragma once

#include "collide_common.h"
#include "contact/input_checks.h"
#include "collide_help.h"

namespace {

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string num_str(double v) { return checks::number(v); }

class Args {
 public:
  Args(int argc, char** argv) {
    static const std::set<std::string> flags = {"--wall", "--help", "--analytic"};
    static const std::set<std::string> known = {
        "--law", "--m1", "--m2", "--R1", "--R2", "--rho", "--rho2", "--wall", "--v0", "--k",
        "--gamma", "--e", "--tc", "--end", "--Estar", "--E", "--nu", "--E2", "--nu2",
        "--damping", "--A", "--alpha", "--theta", "--kl", "--kul", "--s", "--py", "--vy",
        "--eps", "--x-min", "--n", "--d", "--x-cut", "--steps", "--dt", "--curve", "--help",
        "--e-fit", "--e-coef", "--tc-fit", "--tc-coef", "--v-min", "--v-max", "--e-min", "--al", "--p",
        "--aul", "--q", "--angle", "--spin", "--spin2", "--tangential", "--mu", "--kt", "--kappa", "--gammat",
        "--friction-limit", "--slip-reset", "--gstar", "--eta-ratio", "--beta0", "--psi-kappa", "--lever-arm",
        "--analytic", "--scheme", "--gap", "--phases", "--grid-correction", "--energy", "--params"};
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "-h") a = "--help";
      if (!known.count(a)) throw BadInput("unknown option '" + a + "' (see --help)");
      if (given_.count(a)) throw BadInput("option " + a + " is given twice");
      if (flags.count(a)) {
        given_[a] = "";
        continue;
      }
      if (i + 1 >= argc) throw BadInput("option " + a + " needs a value");
      given_[a] = argv[++i];
    }
  }
  bool has(const std::string& o) const { return given_.count(o) != 0; }
  bool flag(const std::string& o) {
    used_.insert(o);
    return has(o);
  }
  std::string str(const std::string& o) {
    used_.insert(o);
    return given_.at(o);
  }
  // A number in the range; 'what' is the range as text; allow_inf for "inf".
  double number(const std::string& o, double lo, double hi, bool lo_open, bool hi_open, const char* what,
                bool allow_inf = false) {
    used_.insert(o);
    const std::string& s = given_.at(o);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end == s.c_str() || *end != '\0' || std::isnan(v))
      throw BadInput("option " + o + ": '" + s + "' is not a number (allowed: " + what + ")");
    const bool inf_ok = allow_inf && v == INFINITY;
    if (!inf_ok && (!std::isfinite(v) || (lo_open ? v <= lo : v < lo) || (hi_open ? v >= hi : v > hi)))
      throw BadInput("option " + o + " = " + s + " is outside the allowed range " + what);
    return v;
  }
  double positive(const std::string& o, bool allow_inf = false) {
    return number(o, 0.0, INFINITY, true, true, allow_inf ? "(0, inf]" : "(0, inf)", allow_inf);
  }
  double non_negative(const std::string& o) { return number(o, 0.0, INFINITY, false, true, "[0, inf)"); }
  double restitution(const std::string& o) { return number(o, 0.0, 1.0, true, false, "(0, 1]"); }
  double poisson(const std::string& o) { return number(o, -1.0, 0.5, true, false, "(-1, 0.5]"); }
  std::string choice(const std::string& o, const std::vector<std::string>& allowed) {
    const std::string v = str(o);
    std::string list;
    for (const auto& a : allowed) {
      if (a == v) return v;
      list += (list.empty() ? "" : ", ") + a;
    }
    throw BadInput("option " + o + " = '" + v + "' is not one of: " + list);
  }
  void require(const std::string& o, const std::string& why) const {
    if (!has(o)) throw BadInput("option " + o + " is required " + why);
  }
  void forbid(const std::string& o, const std::string& why) const {
    if (has(o)) throw BadInput("option " + o + " cannot be used " + why);
  }
  // A list of numbers "v1 v2 ..." (blanks or commas between them).
  std::vector<double> numbers(const std::string& o) {
    used_.insert(o);
    std::string s = given_.at(o);
    for (char& ch : s)
      if (ch == ',') ch = ' ';
    std::vector<double> out;
    size_t i = 0;
    while (true) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= s.size()) break;
      size_t j = i;
      while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      const std::string w = s.substr(i, j - i);
      char* end = nullptr;
      const double v = std::strtod(w.c_str(), &end);
      if (end == w.c_str() || *end != '\0' || !std::isfinite(v))
        throw BadInput("option " + o + ": '" + w + "' is not a number");
      out.push_back(v);
      i = j;
    }
    return out;
  }
  // Every option given must have been read.
  void check_all_used(const std::string& law) const {
    for (const auto& kv : given_)
      if (!used_.count(kv.first))
        throw BadInput("option " + kv.first + " does not apply to --law " + law +
                       " with the other options given (see --help)");
  }

 private:
  std::map<std::string, std::string> given_;
  std::set<std::string> used_;
};

// JSON object writer (flat values and one level of nesting).
class Json {
 public:
  void key(const std::string& k) {
    out_ += first_ ? "\n" : ",\n";
    out_ += std::string(2 * depth_, ' ') + "\"" + k + "\": ";
    first_ = false;
  }
  void num(const std::string& k, double v) {
    key(k);
    if (!std::isfinite(v)) {
      out_ += "null";
      return;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    out_ += buf;
  }
  void integer(const std::string& k, long v) {
    key(k);
    out_ += std::to_string(v);
  }
  void boolean(const std::string& k, bool v) {
    key(k);
    out_ += v ? "true" : "false";
  }
  void null(const std::string& k) {
    key(k);
    out_ += "null";
  }
  void str(const std::string& k, const std::string& v) {
    key(k);
    out_ += "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += c;
      }
    }
    out_ += "\"";
  }
  void raw(const std::string& k, const std::string& json) {
    key(k);
    out_ += json;
  }
  void open(const std::string& k) {
    key(k);
    out_ += "{";
    ++depth_;
    first_ = true;
  }
  void close() {
    --depth_;
    out_ += "\n" + std::string(2 * depth_, ' ') + "}";
    first_ = false;
  }
  std::string done() { return "{" + out_ + "\n}\n"; }

 private:
  std::string out_;
  bool first_ = true;
  int depth_ = 1;
};

ContactEnd read_end(Args& a, ContactEnd dflt) {
  if (!a.has("--end")) return dflt;
  return a.choice("--end", {"zero_overlap", "zero_force"}) == "zero_force" ? ContactEnd::zero_force
                                                                           : ContactEnd::zero_overlap;
}

// A law that ends at zero force only: --end, if given, must say so.
void only_zero_force_end(Args& a, const std::string& law) {
  if (a.has("--end") && read_end(a, ContactEnd::zero_force) != ContactEnd::zero_force)
    throw BadInput("option --end = zero_overlap is not allowed for --law " + law + " (allowed: zero_force)");
}

// E* from --Estar or --E/--nu [--E2/--nu2]; for hertz also --k or --tc (returns k~ directly).
double read_modulus(Args& a) {
  if (a.has("--Estar")) {
    a.forbid("--E", "together with --Estar");
    return a.positive("--Estar");
  }
  a.require("--E", "(or --Estar) for the elastic modulus");
  a.require("--nu", "with --E");
  const double E1 = a.positive("--E"), nu1 = a.poisson("--nu");
  const double E2 = a.has("--E2") ? a.positive("--E2", true) : E1;
  const double nu2 = a.has("--nu2") ? a.poisson("--nu2") : nu1;
  return hertz::effective_modulus(E1, nu1, E2, nu2);
}

double need_reff(const Bodies& b, const char* why) {
  if (!(b.R1 > 0.0)) throw BadInput(std::string("option --R1 is required ") + why);
  if (!std::isinf(b.R2) && !(b.R2 > 0.0)) throw BadInput(std::string("option --R2 is required ") + why);
  return b.reff();
}

// "C0,C1,..." -> the coefficients of a fit form.
fits::Fit read_fit(Args& a, const std::string& form_opt, const std::string& coef_opt, char what) {
  a.require(form_opt, "for this law");
  a.require(coef_opt, "with " + form_opt);
  fits::Fit f;
  const std::vector<std::string> forms = what == 'e' ? std::vector<std::string>{"constant", "rational", "power"}
                                                     : std::vector<std::string>{"constant", "power"};
  fits::parse(a.choice(form_opt, forms), f.form);
  const std::string list = a.str(coef_opt);
  std::vector<double> c;
  size_t pos = 0;
  while (pos <= list.size()) {
    const size_t comma = std::min(list.find(',', pos), list.size());
    const std::string item = list.substr(pos, comma - pos);
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v))
      throw BadInput("option " + coef_opt + ": '" + item + "' is not a finite number");
    c.push_back(v);
    pos = comma + 1;
  }
  const int n = fits::coefficient_count(f.form, what);
  if (static_cast<int>(c.size()) != n)
    throw BadInput("option " + coef_opt + " needs " + std::to_string(n) + " comma-separated coefficients for form '" +
                   fits::to_string(f.form) + "', got " + std::to_string(c.size()));
  for (int i = 0; i < n; ++i) f.c[i] = c[i];
  try {  // the kernel's range checks, with the option named
    if (what == 'e') fits::validate_restitution(f);
    else fits::validate_contact_time(f);
  } catch (const std::exception& e) {
    throw BadInput("option " + coef_opt + " (form " + fits::to_string(f.form) + "): " + e.what());
  }
  return f;
}

fits::Range read_range(Args& a) {
  fits::Range r;
  if (a.has("--v-min")) r.v_min = a.positive("--v-min");
  if (a.has("--v-max")) r.v_max = a.positive("--v-max");
  if (a.has("--e-min")) r.e_min = a.number("--e-min", 0.0, 1.0, true, true, "(0, 1)");
  try {
    fits::validate_range(r);
  } catch (const std::exception& e) {
    throw BadInput(std::string("options --v-min, --v-max, --e-min: ") + e.what());
  }
  return r;
}

void fit_params(std::vector<std::pair<std::string, double>>& P, const char* name, const fits::Fit& f) {
  const int n = fits::coefficient_count(f.form, name[0] == 'e' ? 'e' : 't');
  for (int i = 0; i < n; ++i) P.push_back({std::string(name) + "_c" + std::to_string(i), f.c[i]});
}

}  // namespace
