// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/grate (see fix_tdem_grate.h, docs/liggghts/fix_tdem_grate.md).
#include "fix_tdem_grate.h"

#include <mpi.h>

#include <cerrno>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "lammps.h"
#include "modify.h"
#include "tri_mesh.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tg = tdem::grate;

namespace {

std::string fmt(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

bool is_number(const char* s) {
  if (!s || !*s) return false;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  return end && *end == '\0' && std::isfinite(v);  // NaN and inf are no values of a grate
}

using Triangle = std::array<tg::Vec3, 3>;

// The triangles of a set of boxes that go into a LIGGGHTS mesh. Left out: triangles in a periodic
// boundary plane of axis `drop_axis` (coordinate lo or hi; LIGGGHTS wraps mesh nodes periodically, so
// the two lateral end faces would be duplicate elements, and particles cross that plane anyway) and
// the shared faces of touching boxes (tg::shared_faces: inside the bars, and duplicates too).
std::vector<Triangle> mesh_triangles(const std::vector<tg::Box>& boxes, int drop_axis, double lo, double hi) {
  const tg::Mesh m = tg::box_mesh(boxes);
  const std::vector<bool> shared = tg::shared_faces(m);
  const double tol = 1e-9 * std::max(1.0, hi - lo);
  auto on_plane = [&](const tg::Vec3& a, const tg::Vec3& b, const tg::Vec3& c, double x) {
    return std::fabs(a[drop_axis] - x) <= tol && std::fabs(b[drop_axis] - x) <= tol && std::fabs(c[drop_axis] - x) <= tol;
  };
  std::vector<Triangle> out;
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& tr = m.triangles[i];
    const tg::Vec3 a = m.points[tr[0]], b = m.points[tr[1]], c = m.points[tr[2]];
    if (shared[i] || (drop_axis >= 0 && (on_plane(a, b, c, lo) || on_plane(a, b, c, hi)))) continue;
    out.push_back({a, b, c});
  }
  return out;
}

// ASCII STL of triangles (17 significant digits).
void write_stl(const std::string& path, const std::string& name, const std::vector<Triangle>& tris) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot open '" + path + "' for writing");
  f.precision(17);
  f << "solid " << name << "\n";
  for (const Triangle& t : tris) {
    tg::Vec3 n = tg::cross(t[1] - t[0], t[2] - t[0]);
    const double l = tg::norm(n);
    if (l > 0.0) n = (1.0 / l) * n;
    f << " facet normal " << n.x << " " << n.y << " " << n.z << "\n  outer loop\n";
    for (const tg::Vec3& p : t) f << "   vertex " << p.x << " " << p.y << " " << p.z << "\n";
    f << "  endloop\n endfacet\n";
  }
  f << "endsolid " << name << "\n";
  if (!f) throw std::runtime_error("writing '" + path + "' failed");
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMGrate::FixTDEMGrate(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  const std::string where = std::string("fix ") + id + " tdem/grate";
  auto fail = [&](const std::string& msg) { error->all(FLERR, (where + ": " + msg).c_str()); };
  auto need = [&](int iarg, int n, const std::string& key, const std::string& what) {
    if (iarg + n >= narg) fail("keyword '" + key + "' needs " + what);
  };
  auto num = [&](int i, const std::string& key, const std::string& allowed) -> double {
    if (!is_number(arg[i]))
      fail("keyword '" + key + "' = '" + std::string(arg[i]) + "' is not a number; allowed: " + allowed);
    return std::strtod(arg[i], nullptr);
  };
  auto integer = [&](int i, const std::string& key, const std::string& allowed) -> int {
    const double v = num(i, key, allowed);
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      fail("keyword '" + key + "' = '" + std::string(arg[i]) + "' is not an integer; allowed: " + allowed);
    return static_cast<int>(v);
  };
  auto yesno = [&](int i, const std::string& key) -> bool {
    const std::string v = arg[i];
    if (v == "yes" || v == "on") return true;
    if (v == "no" || v == "off") return false;
    fail("keyword '" + key + "' = '" + v + "' is not known; allowed: yes, no");
    return false;
  };

  tg::GrateParams p;
  std::vector<int> row_group;
  bool have_row_group = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "rows") {
      need(iarg, 1, key, "a value (integer in [1, " + std::to_string(tg::kMaxRows) + "])");
      p.rows = integer(iarg + 1, key, "integers >= 1");
      if (p.rows < 1 || p.rows > tg::kMaxRows)
        fail("keyword 'rows' = '" + std::string(arg[iarg + 1]) + "' is outside the allowed range [1, " +
             std::to_string(tg::kMaxRows) + "]");
      iarg += 2;
    } else if (key == "bar_length" || key == "bar_height" || key == "bar_thickness" || key == "bar_gap" ||
               key == "step_height" || key == "overlap" || key == "declination" || key == "declination_deg" ||
               key == "width" || key == "wall_height" || key == "wall_thickness" || key == "stroke" ||
               key == "period" || key == "frequency" || key == "t_start" || key == "dwell_out" ||
               key == "dwell_home" || key == "forward_share" || key == "ramp") {
      need(iarg, 1, key, "a value");
      const double v = num(iarg + 1, key, "a real number");
      if (key == "bar_length") p.bar_length = v;
      else if (key == "bar_height") p.bar_height = v;
      else if (key == "bar_thickness") p.bar_thickness = v;
      else if (key == "bar_gap") p.bar_gap = v;
      else if (key == "step_height") p.step_height = v;
      else if (key == "overlap") p.overlap = v;
      else if (key == "declination" || key == "declination_deg") p.declination_deg = v;
      else if (key == "width") p.width = v;
      else if (key == "wall_height") p.wall_height = v;
      else if (key == "wall_thickness") p.wall_thickness = v;
      else if (key == "stroke") p.motion.stroke = v;
      else if (key == "period") p.motion.period = v;
      else if (key == "frequency") {
        if (!(v > 0.0) || !std::isfinite(v))
          fail("keyword 'frequency' = " + fmt(v) + " is outside the allowed range (0, inf)");
        p.motion.period = 1.0 / v;
      } else if (key == "t_start") p.motion.t_start = v;
      else if (key == "dwell_out") p.motion.dwell_out = v;
      else if (key == "dwell_home") p.motion.dwell_home = v;
      else if (key == "forward_share") p.motion.forward_share = v;
      else if (key == "ramp") p.motion.ramp = v;
      iarg += 2;
    } else if (key == "side_walls") {
      need(iarg, 1, key, "a value (yes or no)");
      p.side_walls = yesno(iarg + 1, key);
      iarg += 2;
    } else if (key == "type") {
      need(iarg, 1, key, "a value (forward or reverse)");
      try {
        p.type = tg::parse_grate_type(arg[iarg + 1]);
      } catch (const std::exception& e) {
        fail(e.what());
      }
      iarg += 2;
    } else if (key == "frame") {
      need(iarg, 1, key, "a value (xyz or xy)");
      const std::string v = arg[iarg + 1];
      if (v == "xyz") p.frame = tg::Frame::xyz;
      else if (v == "xy") p.frame = tg::Frame::xy;
      else fail("keyword 'frame' = '" + v + "' is not known; allowed: xyz (3D), xy (2D)");
      iarg += 2;
    } else if (key == "profile") {
      need(iarg, 1, key, "a value (sinusoidal, trapezoidal or trapezoidal_accel)");
      try {
        p.motion.profile = tg::parse_profile(arg[iarg + 1]);
      } catch (const std::exception& e) {
        fail(e.what());
      }
      iarg += 2;
    } else if (key == "origin") {
      need(iarg, 3, key, "three values (x y z)");
      p.origin.x = num(iarg + 1, key, "three real numbers");
      p.origin.y = num(iarg + 2, key, "three real numbers");
      p.origin.z = num(iarg + 3, key, "three real numbers");
      iarg += 4;
    } else if (key == "row_group" || key == "moving") {
      // one integer per row (-1 fixed, g >= 0 phase group g); the number of rows must be known
      have_row_group = true;
      row_group.clear();
      ++iarg;
      while (iarg < narg && is_number(arg[iarg])) {
        row_group.push_back(integer(iarg, key, "one integer per row: -1 (fixed) or a phase group 0, 1, ..."));
        ++iarg;
      }
      if (row_group.empty()) fail("keyword '" + key + "' needs one value per row: -1 (fixed) or a phase group 0, 1, ...");
    } else if (key == "group_phase" || key == "phase") {
      p.group_phase.clear();
      ++iarg;
      while (iarg < narg && is_number(arg[iarg])) {
        p.group_phase.push_back(num(iarg, key, "fractions of the period in [0, 1)"));
        ++iarg;
      }
      if (p.group_phase.empty()) fail("keyword '" + key + "' needs one value per phase group, each in [0, 1)");
    } else if (key == "wall_type") {
      need(iarg, 1, key, "a value (atom type of the meshes)");
      wall_type_ = integer(iarg + 1, key, "an atom type 1 .. " + std::to_string(atom->ntypes));
      if (wall_type_ < 1 || wall_type_ > atom->ntypes)
        fail("keyword 'wall_type' = " + std::to_string(wall_type_) + " is outside the allowed range [1, " +
             std::to_string(atom->ntypes) + "] (atom types)");
      iarg += 2;
    } else if (key == "vtk") {
      need(iarg, 2, key, "two values (N prefix)");
      vtk_every_ = integer(iarg + 1, key, "an integer >= 1");
      if (vtk_every_ < 1) fail("keyword 'vtk' N = " + std::to_string(vtk_every_) + " is outside the allowed range [1, inf)");
      vtk_prefix_ = arg[iarg + 2];
      iarg += 3;
    } else {
      fail("unknown keyword '" + key +
           "'; allowed: rows bar_length bar_height bar_thickness bar_gap step_height overlap declination width "
           "side_walls wall_height wall_thickness type frame origin row_group group_phase profile stroke period "
           "frequency t_start dwell_out dwell_home forward_share ramp wall_type vtk");
    }
  }
  if (have_row_group) p.row_group = row_group;
  if (p.frame == tg::Frame::xy && domain->dimension != 2)
    fail("keyword 'frame' = 'xy' (2D) needs 'dimension 2'; allowed in 3D: frame xyz");
  if (p.frame == tg::Frame::xyz && domain->dimension != 3)
    fail("keyword 'frame' = 'xyz' (3D) is not allowed with 'dimension 2'; allowed in 2D: frame xy");
  try {
    grate_.reset(new tg::Grate(p));
  } catch (const std::exception& e) {
    fail(e.what());
  }
  const tg::GrateParams& gp = grate_->params();
  ngroups_ = static_cast<int>(gp.group_phase.size());
  u_.assign(ngroups_, 0.0);
  v_.assign(ngroups_, 0.0);

  // meshes: fixed bars + walls, then one per phase group that has rows
  bool any_fixed = p.side_walls;
  std::vector<bool> used(ngroups_, false);
  for (int g : gp.row_group) {
    if (g < 0) any_fixed = true;
    else used[g] = true;
  }
  if (any_fixed) {
    MeshInfo mi;
    mi.id = std::string(id) + "_fixed";
    meshes_.push_back(mi);
  }
  for (int g = 0; g < ngroups_; ++g)
    if (used[g]) {
      MeshInfo mi;
      mi.id = std::string(id) + "_moving" + std::to_string(g);
      mi.group = g;
      meshes_.push_back(mi);
    }

  tb_ = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  sb_ = update->ntimestep;
  dtb_ = update->dt;
  t_now_ = step_time();
  t_created_ = t_now_;
  update_state(t_now_);

  restart_global = 1;
  vector_flag = 1;
  size_vector = 1 + 2 * ngroups_;
  global_freq = 1;
  extvector = 0;
  time_depend = 1;
  nevery = 1;
}

FixTDEMGrate::~FixTDEMGrate() = default;

int FixTDEMGrate::setmask() {
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  if (vtk_every_ > 0) mask |= END_OF_STEP;
  return mask;
}

double FixTDEMGrate::step_time() {
  if (update->dt != dtb_) {  // `timestep` changed dt (only possible between runs): re-base the clock
    tb_ += (update->ntimestep - sb_) * dtb_;
    sb_ = update->ntimestep;
    dtb_ = update->dt;
  }
  return tb_ + (update->ntimestep - sb_) * dtb_;
}

void FixTDEMGrate::write_restart(FILE* fp) {
  double list[4] = {1.0, tb_, static_cast<double>(sb_), dtb_};
  if (comm->me == 0) {
    int size = 4 * sizeof(double);
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(list, sizeof(double), 4, fp);
  }
}

void FixTDEMGrate::restart(char* buf) {
  const double* list = reinterpret_cast<const double*>(buf);
  if (list[0] != 1.0)
    error->all(FLERR, (std::string("fix ") + id + " tdem/grate: the restart record has an unknown layout").c_str());
  tb_ = list[1];
  sb_ = static_cast<bigint>(list[2]);
  dtb_ = list[3];
  // called while the fix is created, before post_create() builds the meshes: they are built at this time
  t_now_ = step_time();
  t_created_ = t_now_;
  update_state(t_now_);
}

void FixTDEMGrate::update_state(double t) {
  const tg::GrateParams& gp = grate_->params();
  for (int g = 0; g < ngroups_; ++g) {
    const tg::MotionState m = tg::evaluate(gp.motion, t, gp.group_phase[g]);
    u_[g] = m.u;
    v_[g] = m.v;
  }
}

/* ----------------------------------------------------------------------
   create the mesh/surface fixes (after this fix is complete in modify's list)
------------------------------------------------------------------------- */

void FixTDEMGrate::post_create() {
  const std::string where = std::string("fix ") + id + " tdem/grate";
  const std::vector<tg::Box> all = grate_->boxes(t_created_);
  const int wax = grate_->width_axis();
  const int drop_axis = domain->periodicity[wax] ? wax : -1;
  if (drop_axis >= 0 && comm->me == 0) {
    const double lo = grate_->params().origin[wax] - 0.5 * grate_->params().width;
    const double hi = grate_->params().origin[wax] + 0.5 * grate_->params().width;
    const double tol = 1e-9 * std::max(1.0, hi - lo);
    if (std::fabs(lo - domain->boxlo[wax]) > tol || std::fabs(hi - domain->boxhi[wax]) > tol)
      error->warning(FLERR, (where + ": the width axis is periodic but the grate width [" + fmt(lo) + ", " + fmt(hi) +
                             "] differs from the box [" + fmt(domain->boxlo[wax]) + ", " + fmt(domain->boxhi[wax]) +
                             "]; the bars should span the periodic box exactly").c_str());
  }
  for (MeshInfo& mi : meshes_) {
    std::vector<tg::Box> sel;
    for (const tg::Box& b : all)
      if ((mi.group < 0 && b.group < 0) || (mi.group >= 0 && b.group == mi.group)) sel.push_back(b);
    const std::string path = "tdem_grate_" + mi.id + ".stl";
    const std::vector<Triangle> tris =
        mesh_triangles(sel, drop_axis, domain->boxlo[std::max(wax, 0)], domain->boxhi[std::max(wax, 0)]);
    if (tris.empty())
      error->all(FLERR, (where + ": mesh " + mi.id + " has no faces left: its bars are degenerate in double "
                         "precision; allowed: sizes of one scale (keywords 'bar_length' " + fmt(grate_->params().bar_length) +
                         ", 'bar_height' " + fmt(grate_->params().bar_height) + ", 'bar_thickness', 'width' " +
                         fmt(grate_->params().width) + ")").c_str());
    // LIGGGHTS drops mesh elements whose centre is outside the box, and its message about that
    // overflows a buffer for far-away meshes: every rank checks first (the same grate everywhere).
    // Shrink-wrapped sides (boundary s, m) are not checked.
    for (const Triangle& t : tris) {
      const tg::Vec3 c = (1.0 / 3.0) * (t[0] + t[1] + t[2]);
      for (int k = 0; k < domain->dimension; ++k)
        if (!(c[k] >= domain->boxlo[k] || domain->boundary[k][0] >= 2) ||
            !(c[k] <= domain->boxhi[k] || domain->boundary[k][1] >= 2))
          error->all(FLERR, (where + ": the bars of mesh " + mi.id + " reach outside the simulation box: a face "
                             "centred at (" + fmt(c.x) + ", " + fmt(c.y) + ", " + fmt(c.z) + ") is outside " +
                             "xyz"[k] + " [" + fmt(domain->boxlo[k]) + ", " + fmt(domain->boxhi[k]) + "]; allowed: "
                             "bars inside the box (keywords 'origin', 'rows', 'bar_length', 'bar_height', "
                             "'declination', 'step_height', side walls: 'wall_height', 'wall_thickness')").c_str());
    }
    int ok = 1;
    std::string msg;
    if (comm->me == 0) {
      try {
        write_stl(path, mi.id, tris);
      } catch (const std::exception& e) {
        ok = 0;
        msg = e.what();
      }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok) error->one(FLERR, (where + ": " + msg).c_str());
    MPI_Barrier(world);
    if (modify->find_fix(mi.id.c_str()) >= 0)
      error->all(FLERR, (where + ": a fix with the mesh ID '" + mi.id + "' exists already").c_str());
    const std::string type = std::to_string(wall_type_);
    std::vector<std::string> words = {mi.id, "all", "mesh/surface", "file", path, "type", type};
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(&w[0]);
    modify->add_fix(static_cast<int>(argv.size()), argv.data());
    mi.fix = dynamic_cast<FixMeshSurface*>(modify->find_fix_id(mi.id.c_str()));
    if (!mi.fix) error->all(FLERR, (where + ": creating the mesh '" + mi.id + "' failed").c_str());
    mi.u_applied = mi.group >= 0 ? u_[mi.group] : 0.0;
    if (mi.group >= 0) {
      AbstractMesh* mesh = mi.fix->mesh();
      mesh->registerMove(false, true, false);
      if (!mesh->prop().getElementProperty<MultiVectorContainer<double, 3, 3> >("v"))
        mesh->prop().addElementProperty<MultiVectorContainer<double, 3, 3> >("v", "comm_exchange_borders",
                                                                              "frame_invariant", "restart_no");
    }
  }
  if (comm->me == 0) {
    std::string list;
    for (const MeshInfo& mi : meshes_) list += " " + mi.id;
    const std::string line = where + ": " + std::to_string(meshes_.size()) + " meshes:" + list +
                             " (use: fix ID all wall/gran ... mesh n_meshes " + std::to_string(meshes_.size()) +
                             " meshes" + list + ")\n";
    if (screen) std::fputs(line.c_str(), screen);
    if (logfile) std::fputs(line.c_str(), logfile);
  }
}

// `unfix`: the meshes stay (a wall/gran may still use them) but stop moving, with zero velocity.
void FixTDEMGrate::pre_delete(bool unfixflag) {
  if (!unfixflag) return;
  for (MeshInfo& mi : meshes_) {
    if (mi.group < 0 || modify->find_fix(mi.id.c_str()) < 0) continue;
    AbstractMesh* mesh = mi.fix->mesh();
    MultiVectorContainer<double, 3, 3>* vp = mesh->prop().getElementProperty<MultiVectorContainer<double, 3, 3> >("v");
    if (vp) vp->setAll(0.0);
    mesh->unregisterMove(false, true, false);
  }
}

void FixTDEMGrate::init() {
  if (update->whichflag == 1 && std::strcmp(update->integrate_style, "verlet") != 0)
    error->all(FLERR, (std::string("fix ") + id + " tdem/grate: run_style '" + update->integrate_style +
                       "' is not supported; allowed: verlet").c_str());
}

/* ---------------------------------------------------------------------- */

void FixTDEMGrate::move_meshes() {
  const tg::Vec3 dir = grate_->stroke_direction();
  for (MeshInfo& mi : meshes_) {
    if (mi.group < 0) continue;
    AbstractMesh* mesh = mi.fix->mesh();
    const double u = u_[mi.group], vel = v_[mi.group];
    const double du = u - mi.u_applied;
    if (du != 0.0) {
      const double d[3] = {du * dir.x, du * dir.y, du * dir.z};
      mesh->move(d);
      mi.u_applied = u;
    }
    MultiVectorContainer<double, 3, 3>* vp = mesh->prop().getElementProperty<MultiVectorContainer<double, 3, 3> >("v");
    if (!vp) continue;
    double*** v = vp->begin();
    const int n = mesh->sizeLocal() + mesh->sizeGhost();
    const double w[3] = {vel * dir.x, vel * dir.y, vel * dir.z};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) v[i][j][k] = w[k];
  }
}

void FixTDEMGrate::setup(int) {
  t_now_ = step_time();
  update_state(t_now_);
  move_meshes();
  if (vtk_every_ > 0) write_vtk();
}

void FixTDEMGrate::initial_integrate(int) {
  t_now_ = step_time();  // ntimestep is already the new step: positions are advanced to t_{n+1}
  update_state(t_now_);
  move_meshes();
}

void FixTDEMGrate::end_of_step() {
  if (vtk_every_ > 0 && update->ntimestep % vtk_every_ == 0) write_vtk();
}

void FixTDEMGrate::write_vtk() {
  if (update->ntimestep == last_vtk_step_) return;
  last_vtk_step_ = update->ntimestep;
  int ok = 1;
  std::string msg;
  if (comm->me == 0) {
    try {
      if (!vtk_files_)
        vtk_files_ = std::make_unique<tdem::vtkio::StepFiles>(vtk_prefix_, tdem::vtkio::StepFiles::Kind::polydata);
      vtk_files_->write(update->ntimestep, tg::bars_dataset(grate_->boxes(t_now_), t_now_));
    } catch (const std::exception& e) {
      ok = 0;
      msg = e.what();
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, world);
  if (!ok) error->one(FLERR, (std::string("fix ") + id + " tdem/grate: " + msg).c_str());
}

double FixTDEMGrate::compute_vector(int i) {
  if (i == 0) return t_now_;
  const int g = (i - 1) / 2;
  if (g < 0 || g >= ngroups_) return 0.0;
  return (i - 1) % 2 == 0 ? u_[g] : v_[g];
}

void* FixTDEMGrate::extract(const char* name, int& dim) {
  dim = 0;
  if (std::strcmp(name, "tdem_grate") == 0) return const_cast<tg::Grate*>(grate_.get());
  if (std::strcmp(name, "tdem_grate_time") == 0) return &t_now_;
  return nullptr;
}
