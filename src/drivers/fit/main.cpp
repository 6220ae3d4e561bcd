// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-fit: fits the coefficients of the tdem normal laws to measured e(v0) (and t_c(v0), peak
// force where given) by weighted least squares over the single-collision solution, and prints
// the coefficients, chi^2 and ready-to-paste input lines for LIGGGHTS and LAMMPS. See docs/tools/tdem-fit.md.
// Exit status: 0 success, 1 a fit failed / the JSON file could not be written, 2 bad input (the
// message names the option or the file line, the value and the allowed range).
#include "fit_one.h"

namespace {

// ------------------------------------------------------------------ output
std::string g(double v, int prec = 6) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", prec, v);
  return buf;
}

std::string json_str(const std::string& s) {
  std::string o = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') {
      o += '\\';
      o += ch;
    } else if (ch == '\n') {
      o += "\\n";
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", ch);
      o += buf;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}

std::string json_num(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string json_array(const std::vector<double>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + json_num(v[i]);
  return s + "]";
}

std::string json_lines(const std::vector<std::string>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ",\n        " : "\n        ") + json_str(v[i]);
  return s + "]";
}

struct Best {
  std::string by_chi2, by_aic;
  std::string criterion;
  std::vector<std::string> near_chi2, near_aic;  // within 1 % of the lowest chi^2 / within 2 of the lowest AIC(c)
};

Best choose(const std::vector<FitResult>& rs) {
  Best b;
  double bc = INFINITY, ba = INFINITY;
  bool all_aicc = true;
  for (const auto& r : rs)
    if (r.ok && !std::isfinite(r.aicc)) all_aicc = false;
  b.criterion = all_aicc ? "AICc" : "AIC";
  for (const auto& r : rs) {
    if (!r.ok) continue;
    if (r.res.chi2 < bc) {
      bc = r.res.chi2;
      b.by_chi2 = r.law;
    }
    const double a = all_aicc ? r.aicc : r.aic;
    if (a < ba) {
      ba = a;
      b.by_aic = r.law;
    }
  }
  for (const auto& r : rs) {
    if (!r.ok) continue;
    if (r.law != b.by_chi2 && r.res.chi2 <= 1.01 * bc) b.near_chi2.push_back(r.law);
    if (r.law != b.by_aic && (all_aicc ? r.aicc : r.aic) < ba + 2.0) b.near_aic.push_back(r.law);
  }
  return b;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

void print_report(const Context& c, const Weights& W, const std::vector<FitResult>& rs, const Best& best,
                  bool quiet) {
  const auto& d = c.data;
  std::printf("tdem-fit: %s\n", d.file == "-" ? "standard input" : d.file.c_str());
  std::printf("material: %s\n", d.material.c_str());
  std::printf("configuration: %s; R1 = %s m, rho = %s kg/m^3, E = %s Pa, nu = %s; partner E2 = %s Pa, nu2 = %s",
              d.wall ? "sphere on a wall" : "two spheres", g(d.R1).c_str(), g(d.rho).c_str(), g(d.E).c_str(),
              g(d.nu).c_str(), std::isinf(d.E2) ? "inf" : g(d.E2).c_str(), g(d.nu2).c_str());
  if (!d.wall) std::printf(", R2 = %s m, rho2 = %s kg/m^3", g(d.R2).c_str(), g(d.rho2).c_str());
  std::printf("\nm* = %s kg, R* = %s m, E* = %s Pa, k~ = %s N/m^1.5\n", g(c.meff).c_str(), g(c.reff).c_str(),
              g(c.estar).c_str(), g(c.khertz).c_str());
  std::printf("data: %d e, %d t_c, %d F_max values at v0 = %s ... %s m/s (median %s); weights: %s\n",
              d.count('e'), d.count('t'), d.count('f'), g(c.v_lo).c_str(), g(c.v_hi).c_str(), g(c.v_ref).c_str(),
              W.note.c_str());
  std::printf("end of contact (lsd, hertz_*, extended_*): %s\n\n", to_string(c.end));
  if (!quiet) {
    for (const auto& r : rs) {
      std::printf("== %s: %s\n", r.law.c_str(), r.description.c_str());
      for (const auto& k : r.coefs)
        std::printf("   %-6s %-8s = %-16s %-14s %s\n", k.fitted ? "fitted" : "fixed", k.name.c_str(),
                    g(k.value, 9).c_str(), ("[" + k.unit + "]").c_str(), k.note.c_str());
      std::printf("   chi2 = %s, reduced chi2 = %s (N = %d, k = %d), max |rel. residual| = %s (%s, line %d), %s = %s\n",
                  g(r.res.chi2).c_str(), g(r.reduced).c_str(), r.n, r.k, g(r.res.max_rel, 3).c_str(),
                  r.res.max_q.c_str(), r.res.max_line, best.criterion.c_str(),
                  g(best.criterion == "AICc" ? r.aicc : r.aic, 5).c_str());
      std::printf("   minimised on the %s (%d evaluations)", r.closed_used ? "closed form" : "integration", r.evals);
      if (r.closed_used) std::printf("; closed form vs integration at the optimum: %s", g(r.closed_check, 2).c_str());
      std::printf("\n");
      std::printf("   %ld single collisions integrated", r.integrations);
      if (r.tabulated)
        std::printf(" (tabulated solutions; table vs integration at %zu rows at the optimum: %s)",
                    std::min(d.points.size(), kTableCheckRows), g(r.table_check, 2).c_str());
      std::printf("\n");
      if (!r.warning.empty()) std::printf("   warning: %s\n", r.warning.c_str());
      std::printf("   v0 [m/s]   e data   e model");
      if (c.has_tc) std::printf("   t_c data    t_c model");
      if (c.has_f) std::printf("  F data      F model");
      std::printf("\n");
      for (size_t i = 0; i < d.points.size(); ++i) {
        const auto& p = d.points[i];
        const auto& m = r.pred[i];
        std::printf("   %-9s  %-7s  %-8s", g(p.v0, 4).c_str(), std::isfinite(p.e) ? g(p.e, 4).c_str() : "-",
                    m.ok ? g(m.e, 4).c_str() : "-");
        if (c.has_tc)
          std::printf("  %-10s  %-10s", std::isfinite(p.tc) ? g(p.tc, 4).c_str() : "-", m.ok ? g(m.tc, 4).c_str() : "-");
        if (c.has_f)
          std::printf("  %-10s  %-10s", std::isfinite(p.fmax) ? g(p.fmax, 4).c_str() : "-",
                      m.ok ? g(m.fmax, 4).c_str() : "-");
        std::printf("\n");
      }
      std::printf("   LIGGGHTS:\n");
      for (const auto& l : r.hosts.liggghts) std::printf("     %s\n", l.c_str());
      std::printf("   LAMMPS:\n");
      for (const auto& l : r.hosts.lammps) std::printf("     %s\n", l.c_str());
      std::printf("\n");
    }
  }
  std::printf("summary (%s):\n", d.material.c_str());
  std::printf("  %-30s %12s %12s %4s %12s %12s\n", "law", "chi2", "red. chi2", "k", "max |res|",
              best.criterion.c_str());
  for (const auto& r : rs)
    std::printf("  %-30s %12s %12s %4d %12s %12s%s\n", r.law.c_str(), g(r.res.chi2, 4).c_str(),
                g(r.reduced, 4).c_str(), r.k, g(r.res.max_rel, 3).c_str(),
                g(best.criterion == "AICc" ? r.aicc : r.aic, 5).c_str(), r.ok ? "" : "  (failed)");
  std::printf("best law (lowest chi2): %s\n", best.by_chi2.c_str());
  if (!best.near_chi2.empty())
    std::printf("  (within 1 %% of its chi2: %s)\n", join(best.near_chi2).c_str());
  std::printf("best law (lowest %s, penalises the number of parameters): %s\n", best.criterion.c_str(),
              best.by_aic.c_str());
  if (!best.near_aic.empty())
    std::printf("  (within 2 of its %s, about as well supported: %s)\n", best.criterion.c_str(),
                join(best.near_aic).c_str());
}

bool write_json(const std::string& path, const Context& c, const Weights& W, const std::vector<FitResult>& rs,
                const Best& best, const Options& o) {
  const auto& d = c.data;
  std::string s = "{\n";
  s += "  \"file\": " + json_str(d.file) + ",\n";
  s += "  \"material\": " + json_str(d.material) + ",\n";
  s += "  \"source\": " + json_str(d.source) + ",\n";
  s += "  \"notes\": " + json_str(d.notes) + ",\n";
  s += "  \"configuration\": " + json_str(d.wall ? "wall" : "pair") + ",\n";
  s += "  \"R1\": " + json_num(d.R1) + ", \"rho\": " + json_num(d.rho) + ", \"E\": " + json_num(d.E) +
       ", \"nu\": " + json_num(d.nu) + ",\n";
  s += "  \"E2\": " + (std::isinf(d.E2) ? std::string("\"inf\"") : json_num(d.E2)) + ", \"nu2\": " + json_num(d.nu2) +
       ", \"R2\": " + (std::isinf(d.R2) ? std::string("\"inf\"") : json_num(d.R2)) +
       ", \"rho2\": " + (std::isinf(d.rho2) ? std::string("\"inf\"") : json_num(d.rho2)) + ",\n";
  s += "  \"m_eff\": " + json_num(c.meff) + ", \"r_eff\": " + json_num(c.reff) + ", \"E_star\": " +
       json_num(c.estar) + ", \"k_hertz\": " + json_num(c.khertz) + ",\n";
  s += "  \"v_ref\": " + json_num(c.v_ref) + ",\n";
  s += "  \"end\": " + json_str(to_string(c.end)) + ",\n";
  s += "  \"weights\": " + json_str(W.note) + ",\n";
  s += "  \"weights_from_errors\": " + std::string(W.from_errors ? "true" : "false") + ",\n";
  s += "  \"steps\": " + std::to_string(o.steps) + ",\n";
  auto col = [&](auto f) {
    std::vector<double> v;
    for (const auto& p : d.points) v.push_back(f(p));
    return json_array(v);
  };
  s += "  \"data\": {\"v0\": " + col([](const auto& p) { return p.v0; }) +
       ", \"e\": " + col([](const auto& p) { return p.e; }) +
       ", \"e_err\": " + col([](const auto& p) { return p.e_err; }) +
       ", \"tc\": " + col([](const auto& p) { return p.tc; }) +
       ", \"tc_err\": " + col([](const auto& p) { return p.tc_err; }) +
       ", \"fmax\": " + col([](const auto& p) { return p.fmax; }) +
       ", \"fmax_err\": " + col([](const auto& p) { return p.fmax_err; }) + "},\n";
  s += "  \"criterion\": " + json_str(best.criterion) + ",\n";
  s += "  \"best_chi2\": " + json_str(best.by_chi2) + ",\n";
  s += "  \"best_aic\": " + json_str(best.by_aic) + ",\n";
  auto str_list = [](const std::vector<std::string>& v) {
    std::string l = "[";
    for (size_t i = 0; i < v.size(); ++i) l += (i ? ", " : "") + json_str(v[i]);
    return l + "]";
  };
  s += "  \"near_best_chi2\": " + str_list(best.near_chi2) + ",\n";
  s += "  \"near_best_aic\": " + str_list(best.near_aic) + ",\n";
  s += "  \"laws\": [";
  for (size_t li = 0; li < rs.size(); ++li) {
    const auto& r = rs[li];
    s += li ? ",\n    {\n" : "\n    {\n";
    s += "      \"law\": " + json_str(r.law) + ",\n";
    s += "      \"description\": " + json_str(r.description) + ",\n";
    s += "      \"ok\": " + std::string(r.ok ? "true" : "false") + ",\n";
    s += "      \"coefficients\": [";
    for (size_t i = 0; i < r.coefs.size(); ++i) {
      const auto& k = r.coefs[i];
      s += (i ? ",\n        " : "\n        ") + std::string("{\"name\": ") + json_str(k.name) +
           ", \"unit\": " + json_str(k.unit) + ", \"value\": " + json_num(k.value) +
           ", \"fitted\": " + (k.fitted ? "true" : "false") + ", \"note\": " + json_str(k.note) + "}";
    }
    s += "],\n";
    s += "      \"chi2\": " + json_num(r.res.chi2) + ", \"reduced_chi2\": " + json_num(r.reduced) +
         ", \"n\": " + std::to_string(r.n) + ", \"k\": " + std::to_string(r.k) + ",\n";
    s += "      \"max_rel_residual\": " + json_num(r.res.max_rel) + ", \"max_rel_residual_quantity\": " +
         json_str(r.res.max_q) + ", \"max_rel_residual_line\": " + std::to_string(r.res.max_line) + ",\n";
    s += "      \"aic\": " + json_num(r.aic) + ", \"aicc\": " + json_num(r.aicc) + ",\n";
    s += "      \"closed_form_used\": " + std::string(r.closed_used ? "true" : "false") +
         ", \"closed_form_check\": " + json_num(r.closed_check) + ", \"evaluations\": " + std::to_string(r.evals) +
         ", \"tabulated\": " + (r.tabulated ? "true" : "false") + ", \"table_check\": " + json_num(r.table_check) +
         ", \"integrations\": " + std::to_string(r.integrations) +
         ",\n";
    s += "      \"warning\": " + json_str(r.warning) + ",\n";
    std::vector<double> pe, pt, pf;
    for (const auto& p : r.pred) {
      pe.push_back(p.ok ? p.e : NAN);
      pt.push_back(p.ok ? p.tc : NAN);
      pf.push_back(p.ok ? p.fmax : NAN);
    }
    s += "      \"model\": {\"e\": " + json_array(pe) + ", \"tc\": " + json_array(pt) + ", \"fmax\": " +
         json_array(pf) + "},\n";
    s += "      \"curve\": {\"v0\": " + json_array(r.cv) + ", \"e\": " + json_array(r.ce) + ", \"tc\": " +
         json_array(r.ctc) + ", \"fmax\": " + json_array(r.cf) + "},\n";
    s += "      \"liggghts\": " + json_lines(r.hosts.liggghts) + ",\n";
    s += "      \"lammps\": " + json_lines(r.hosts.lammps) + "\n";
    s += "    }";
  }
  s += "\n  ]\n}\n";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "tdem-fit: error: cannot write the JSON file '%s': %s\n", path.c_str(), std::strerror(errno));
    return false;
  }
  std::fputs(s.c_str(), f);
  return std::fclose(f) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  Context c;
  try {
    o = parse_args(argc, argv);
    if (o.help) {
      std::fputs(kHelp, stdout);
      std::fputs(unit_help().c_str(), stdout);
      std::fputs(kHelpOptions, stdout);
      return 0;
    }
    const auto data = fitdata::read(o.file);
    for (const std::string& w : data.warnings) std::fprintf(stderr, "tdem-fit: warning: %s\n", w.c_str());
    c = make_context(data, o);
  } catch (const BadInput& e) {
    std::fprintf(stderr, "tdem-fit: error: %s\n", e.what());
    return 2;
  } catch (const fitdata::BadData& e) {
    std::fprintf(stderr, "tdem-fit: error: %s\n", e.what());
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "tdem-fit: error: %s: %s\n", o.file.c_str(), e.what());
    return 2;
  }
  const Weights W = make_weights(c, o);
  std::vector<FitResult> rs;
  int status = 0;
  for (const auto& name : o.laws) {
    const auto law = make_law(name, c);
    try {
      rs.push_back(fit_one(*law, c, W, o.table));
      add_curve(rs.back(), *law, c, o.curve);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tdem-fit: error: law %s: %s\n", name.c_str(), e.what());
      status = 1;
      continue;
    }
    if (!rs.back().ok) status = 1;
  }
  const Best best = choose(rs);
  print_report(c, W, rs, best, o.quiet);
  if (!o.json.empty() && !write_json(o.json, c, W, rs, best, o)) status = 1;
  return status;
}
