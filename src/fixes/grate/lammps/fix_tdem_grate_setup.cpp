// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/grate, its constructor: the arguments, their checks and the
// geometry they give (see fix_tdem_grate.h and docs/lammps/fix_tdem_grate.md). The time stepping, the
// per-atom state and restart are in fix_tdem_grate.cpp.

#include "fix_tdem_grate.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "respa.h"
#include "update.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include "contact/energy.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tg = tdem::grate;

namespace {

const char *GRATE_KEYWORDS =
    "rows, bar_length, bar_height, bar_thickness, bar_gap, step_height, overlap, declination, "
    "width, side_walls, wall_height, wall_thickness, type, frame, origin, row_group, group_phase, "
    "profile, stroke, period, frequency, t_start, dwell_out, dwell_home, forward_share, ramp, vtk, "
    "max_contacts, energy";

bool parse_double(const char *s, double &v)
{
  char *end = nullptr;
  errno = 0;
  v = strtod(s, &end);
  return end != s && *end == '\0' && errno != ERANGE && std::isfinite(v);
}

bool parse_int(const char *s, long &v)
{
  char *end = nullptr;
  errno = 0;
  v = strtol(s, &end, 10);
  return end != s && *end == '\0' && errno != ERANGE;
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMGrate::FixTDEMGrate(LAMMPS *lmp, int narg, char **arg) :
    PerAtomRows(lmp, narg, arg)
{
  where = std::string("fix ") + id + " tdem/grate";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR, where + " requires atom_style sphere (per-atom radius, rmass, omega)");

  create_attribute = 1;
  restart_peratom = 1;
  restart_global = 1;
  nlevels_respa = 0;
  ndeep = 0;
  per_axis = -1;
  per_len = 0.0;
  force_flag = 0;
  fbar[0] = fbar[1] = fbar[2] = 0.0;
  fbar_all[0] = fbar_all[1] = fbar_all[2] = 0.0;

  int iarg = tdem_lammps::parse_law(lmp, where, narg, arg, 3, true, law);
  if (law.roll)
    error->all(FLERR, where + ": keyword 'rolling' is not available for the bars of fix tdem/grate; "
                              "allowed: the law without rolling resistance (pair tdem/gran and "
                              "fix tdem/wall/gran have it)");
  size_history = tdem_lammps::history_size(law.mode, law.tlaw);

  // ---- grate and motion keywords
  tg::GrateParams gp;
  max_contacts = 4;
  energy_on = 0;
  vtk_every = 0;
  bool frame_given = false;
  auto value = [&](const std::string &key, int k) -> const char * {
    if (iarg + k >= narg)
      error->all(FLERR, where + ": keyword '" + key + "' needs a value, got end of line");
    return arg[iarg + k];
  };
  auto number = [&](const std::string &key, int k) -> double {
    const char *s = value(key, k);
    double v;
    if (!parse_double(s, v))
      error->all(FLERR, where + ": keyword '" + key + "' = '" + s + "' is not a finite number");
    return v;
  };
  auto integer = [&](const std::string &key, int k) -> long {
    const char *s = value(key, k);
    long v;
    if (!parse_int(s, v))
      error->all(FLERR, where + ": keyword '" + key + "' = '" + s + "' is not an integer");
    return v;
  };
  auto choice = [&](const std::string &key, const std::vector<std::string> &allowed) -> int {
    const std::string s = value(key, 1);
    for (size_t k = 0; k < allowed.size(); ++k)
      if (s == allowed[k]) return static_cast<int>(k);
    std::string all;
    for (const auto &a : allowed) all += (all.empty() ? "" : ", ") + a;
    error->all(FLERR, where + ": keyword '" + key + "' = '" + s + "' is not known; allowed: " + all);
    return -1;
  };

  while (iarg < narg) {
    std::string key = arg[iarg];
    // aliases (the core's field names, the LIGGGHTS fix's spellings)
    if (key == "declination_deg") key = "declination";
    else if (key == "moving") key = "row_group";
    else if (key == "phase") key = "group_phase";
    if (key == "rows") {
      const long v = integer(key, 1);
      if (v < 1 || v > tg::kMaxRows)
        error->all(FLERR, where + ": keyword 'rows' = " + arg[iarg + 1] + " is outside the allowed range [1, " +
                              std::to_string(tg::kMaxRows) + "]");
      gp.rows = static_cast<int>(v);
      iarg += 2;
    } else if (key == "bar_length") {
      gp.bar_length = number(key, 1), iarg += 2;
    } else if (key == "bar_height") {
      gp.bar_height = number(key, 1), iarg += 2;
    } else if (key == "bar_thickness") {
      gp.bar_thickness = number(key, 1), iarg += 2;
    } else if (key == "bar_gap") {
      gp.bar_gap = number(key, 1), iarg += 2;
    } else if (key == "step_height") {
      gp.step_height = number(key, 1), iarg += 2;
    } else if (key == "overlap") {
      gp.overlap = number(key, 1), iarg += 2;
    } else if (key == "declination") {
      gp.declination_deg = number(key, 1), iarg += 2;
    } else if (key == "width") {
      gp.width = number(key, 1), iarg += 2;
    } else if (key == "side_walls") {
      gp.side_walls = choice(key, {"no", "yes"}) == 1, iarg += 2;
    } else if (key == "wall_height") {
      gp.wall_height = number(key, 1), iarg += 2;
    } else if (key == "wall_thickness") {
      gp.wall_thickness = number(key, 1), iarg += 2;
    } else if (key == "type") {
      gp.type = choice(key, {"forward", "reverse"}) == 0 ? tg::GrateType::forward_acting
                                                         : tg::GrateType::reverse_acting;
      iarg += 2;
    } else if (key == "frame") {
      gp.frame = choice(key, {"xyz", "xy"}) == 0 ? tg::Frame::xyz : tg::Frame::xy;
      frame_given = true;
      iarg += 2;
    } else if (key == "origin") {
      gp.origin = {number(key, 1), number(key, 2), number(key, 3)};
      iarg += 4;
    } else if (key == "row_group") {
      gp.row_group.clear();
      long v;
      ++iarg;
      while (iarg < narg && parse_int(arg[iarg], v)) {
        if (v < -1)
          error->all(FLERR, where + ": keyword 'row_group' value " + arg[iarg] +
                                " is outside the allowed values {-1 (fixed), 0, 1, ...}");
        gp.row_group.push_back(static_cast<int>(v));
        ++iarg;
      }
      if (gp.row_group.empty())
        error->all(FLERR, where + ": keyword 'row_group' needs one integer per row (-1 fixed, "
                                  "g >= 0 moving in phase group g), got '" +
                              (iarg < narg ? arg[iarg] : "end of line") + "'");
    } else if (key == "group_phase") {
      gp.group_phase.clear();
      double v;
      ++iarg;
      while (iarg < narg && parse_double(arg[iarg], v)) {
        gp.group_phase.push_back(v);
        ++iarg;
      }
      if (gp.group_phase.empty())
        error->all(FLERR, where + ": keyword 'group_phase' needs one value in [0, 1) per phase "
                                  "group, got '" +
                              (iarg < narg ? arg[iarg] : "end of line") + "'");
    } else if (key == "profile") {
      const int p = choice(key, {"sinusoidal", "trapezoidal", "trapezoidal_accel"});
      gp.motion.profile = p == 0 ? tg::Profile::sinusoidal
                          : p == 1 ? tg::Profile::trapezoidal
                                   : tg::Profile::trapezoidal_accel;
      iarg += 2;
    } else if (key == "stroke") {
      gp.motion.stroke = number(key, 1), iarg += 2;
    } else if (key == "period") {
      gp.motion.period = number(key, 1), iarg += 2;
    } else if (key == "frequency") {
      const double f = number(key, 1);
      if (!(f > 0.0))
        error->all(FLERR, where + ": keyword 'frequency' = " + arg[iarg + 1] +
                              " is outside the allowed range (0, inf)");
      gp.motion.period = 1.0 / f;
      iarg += 2;
    } else if (key == "t_start") {
      gp.motion.t_start = number(key, 1), iarg += 2;
    } else if (key == "dwell_out") {
      gp.motion.dwell_out = number(key, 1), iarg += 2;
    } else if (key == "dwell_home") {
      gp.motion.dwell_home = number(key, 1), iarg += 2;
    } else if (key == "forward_share") {
      gp.motion.forward_share = number(key, 1), iarg += 2;
    } else if (key == "ramp") {
      gp.motion.ramp = number(key, 1), iarg += 2;
    } else if (key == "vtk") {
      const long n = integer(key, 1);
      if (n < 1)
        error->all(FLERR, where + ": keyword 'vtk' N = " + arg[iarg + 1] +
                              " is outside the allowed range [1, inf) (steps between VTK files)");
      vtk_every = static_cast<int>(n);
      vtk_prefix = value(key, 2);
      iarg += 3;
    } else if (key == "energy") {
      const std::string val = value(key, 1);
      if (val != "yes" && val != "no")
        error->all(FLERR, where + ": keyword 'energy' = '" + val + "' is not allowed; allowed: no, yes");
      energy_on = val == "yes";
      iarg += 2;
    } else if (key == "max_contacts") {
      const long k = integer(key, 1);
      if (k < 1 || k > 64)
        error->all(FLERR, where + ": keyword 'max_contacts' = " + arg[iarg + 1] +
                              " is outside the allowed range [1, 64]");
      max_contacts = static_cast<int>(k);
      iarg += 2;
    } else {
      error->all(FLERR, where + ": unknown keyword '" + key + "'; allowed after the law: " +
                            GRATE_KEYWORDS);
    }
  }

  // 2D: frame xy (up +y, width along z) with dimension 2
  if (domain->dimension == 2) {
    if (frame_given && gp.frame != tg::Frame::xy)
      error->all(FLERR, where + ": keyword 'frame' = 'xyz' is not allowed with dimension 2; "
                                "allowed: xy");
    gp.frame = tg::Frame::xy;
  } else if (frame_given && gp.frame == tg::Frame::xy) {
    // the 2D frame has up +y and no depth: in a 3-d box the bed would fall along -z past the bars
    error->all(FLERR, where + ": keyword 'frame' = 'xy' (2D) needs 'dimension 2'; allowed in 3D: frame xyz");
  } else {
    gp.frame = tg::Frame::xyz;
  }

  // the phase groups checked here with this fix's keyword names (the core says 'moving', 'phase')
  if (!gp.row_group.empty() && static_cast<int>(gp.row_group.size()) != gp.rows)
    error->all(FLERR, where + ": keyword 'row_group' has " + std::to_string(gp.row_group.size()) +
                          " values; allowed: one entry per row (rows = " + std::to_string(gp.rows) + ")");
  {
    int ng = gp.row_group.empty() ? (gp.rows > 1 ? 1 : 0) : 0;
    for (int g : gp.row_group) ng = std::max(ng, g + 1);
    for (double ph : gp.group_phase)
      if (!(ph >= 0.0 && ph < 1.0))
        error->all(FLERR, where + ": keyword 'group_phase' = " + std::to_string(ph) +
                              " is outside the allowed range [0, 1) (fraction of the period)");
    if (!gp.group_phase.empty() && static_cast<int>(gp.group_phase.size()) != ng)
      error->all(FLERR, where + ": keyword 'group_phase' has " + std::to_string(gp.group_phase.size()) +
                            " values; allowed: one value per phase group (row_group uses " +
                            std::to_string(ng) + " groups)");
  }

  try {
    grate_ = std::make_unique<tg::Grate>(gp);
  } catch (const std::invalid_argument &ex) {
    error->all(FLERR, where + ": " + ex.what());
  }

  // a periodic width should equal the grate width (otherwise particles fall off the bar ends)
  const tg::GrateParams &p = grate_->params();
  if (p.frame == tg::Frame::xyz && !p.side_walls && comm->me == 0) {
    if (!domain->yperiodic)
      error->warning(FLERR, where + ": no side walls and y is not periodic: particles can leave "
                                    "the grate sideways");
    else if (std::fabs(domain->prd[1] - p.width) > 1e-9 * p.width)
      error->warning(FLERR, where + ": the periodic box length along y (" +
                                std::to_string(domain->prd[1]) + ") differs from the grate width (" +
                                std::to_string(p.width) + ")");
  }

  ngroups = static_cast<int>(p.group_phase.size());
  vector_flag = 1;
  size_vector = 3 + 2 * ngroups;
  global_freq = 1;
  extvector = -1;
  extlist_store.assign(size_vector, 0);
  extlist_store[0] = extlist_store[1] = extlist_store[2] = 1;
  extlist = extlist_store.data();

  law_history = size_history;
  if (energy_on) size_history += tdem::energy::kSlots;
  slot_size = 1 + size_history;
  rows_init(max_contacts * slot_size + (energy_on ? tdem::energy::kParts + 1 : 0), "tdem/grate:slots");
  boxes_ = grate_->boxes(0.0);
  // half extents of the axis-aligned bounding box of each box (the boxes only translate)
  for (const auto &b : boxes_)
    for (int k = 0; k < 3; ++k)
      box_extent.push_back(std::fabs(b.axis[0][k]) * b.half[0] + std::fabs(b.axis[1][k]) * b.half[1] +
                           std::fabs(b.axis[2][k]) * b.half[2]);

  // time origin: the step of definition (restart() replaces it by the stored one)
  t_base = 0.0;
  step_base = update->ntimestep;
  dt_cur = update->dt;
  t_last = 0.0;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}
