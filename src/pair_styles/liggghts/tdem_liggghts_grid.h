// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS: the contact model of every combination with a tdem normal law (and the
// default surface model), with the time-grid correction (src/contact/grid_correction.h) of the
// step in which a contact starts and the step after it ends:
//
//   pair_style gran model tdem/<law> tangential ... grid_correction on|off      (default off)
//   fix ID all wall/gran model tdem/<law> tangential ... grid_correction on ...
//
// TdemContactModel<Style> has the interface of LIGGGHTS's ContactModel<Style> (which keeps its
// five models private) and calls the five models in the same order. With the correction off
// that is all it does: results are bitwise those of ContactModel<Style>. With it on it keeps two
// history values after the models' own: the contact's state, (step + 1) * 8 + a code (tdem_grid::
// below; the step stamp makes a pair that was not evaluated at the last step count as new:
// LIGGGHTS keeps a separated pair's history until the next neighbour rebuild), and m* (the end step
// has no effective mass in LIGGGHTS's data for a separated pair). In the loop a contact step costs
// one comparison of the state and its new stamp.
//  - start: the first contact step of a pair (code 0 or a stale stamp). If the touch tau = xi / xi'
//    lies within the last step and the contact is resolved (grid::resolved), the normal kick is the
//    power model's (grid::start_force; its exponents from the law at xi/2, except for the linear
//    law and a law that declares them) and the tangential spring starts at the touch (the tangential and rolling models run with
//    dt = tau); the tangential kick follows the normal one while sliding, else it is linear from
//    the law at the touch. Otherwise the contact is evaluated as without the correction.
//  - end: the first step without contact (surfacesClose; the contact distance is raised to
//    kContactDistance so that LIGGGHTS calls it for a pair that has just separated), or for a
//    law that ends at zero force the step where its force is clipped to zero. The last contact
//    step is reconstructed from the history at xi - h xi' (grid::previous_overlap) and the end's
//    extra impulse applied, normal and tangential (with torques). A contact whose approach speed
//    times the step exceeds the contact distance (a fast one) is watched at every step: an end whose
//    gap after one step lies beyond the contact distance is foreseen and warned about once.
// The same rules as LAMMPS's pair tdem/gran (src/pair_styles/lammps/grid_host.h) and the
// single-collision harness (tdem-collide --grid-correction on).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "contact_models.h"
#include "atom.h"
#include "neighbor.h"
#include "update.h"
#include "error.h"
#include "global_properties.h"

#include "contact/grid_correction.h"
#include "tdem_liggghts_apply.h"
#include "tdem_liggghts_settings.h"

namespace LIGGGHTS {
namespace ContactModels {

namespace tdem_grid {
// Contact distance / (r_i + r_j) registered with the correction on (as LIGGGHTS's own models do
// for their energy accounting): an end is corrected when the gap at the first step apart is at
// most 1 % of the radius sum (of the sphere's radius for walls), or what neigh_modify
// contact_distance_factor gives. A larger factor lengthens the neighbour lists of every step.
inline constexpr double kContactDistance = 1.01;
inline constexpr int kMaxHistory = 64;
// The contact's state: 8 * (the step of its last evaluation + 1) + a code. The codes of the flags
// of grid_correction.h (on 1, ended 2, seen 4) run the plain models; the codes below 1 are events:
// 0 (new), negative (a stale stamp: not evaluated at the last step), and two more states of a
// corrected contact whose end is watched at every step, so that one comparison decides in the loop.
// A corrected contact that has not ended has a code in (0, 1].
inline constexpr double kFast = 0.25;    // its approach speed times the step exceeds the contact distance
inline constexpr double kWatched = 0.5;  // of a zero-force law: its clip is watched

// A normal model that declares its exponents (bool power_exponents(data, p, q): false where it
// cannot) spares the correction the probe of the law at xi/2 at every start and end.
template <class M, class = void>
struct DeclaresExponents : std::false_type {};
template <class M>
struct DeclaresExponents<M, std::void_t<decltype(&M::power_exponents)>> : std::true_type {};

// The tangential (and rolling) models read update->dt: a start runs them with the time since the
// touch.
class StepGuard {
 public:
  StepGuard(LAMMPS_NS::Update* u, double dt) : u_(u), saved_(u->dt) { u->dt = dt; }
  ~StepGuard() { u_->dt = saved_; }
  StepGuard(const StepGuard&) = delete;
  StepGuard& operator=(const StepGuard&) = delete;

 private:
  LAMMPS_NS::Update* u_;
  double saved_;
};

// A kick on the two partners (forces and torques), combined component by component.
struct Kick {
  ForceData i, j;
  template <class F>
  static Kick combine(const Kick& a, const Kick& b, F f) {
    Kick r;
    for (int c = 0; c < 3; ++c) {
      r.i.delta_F[c] = f(a.i.delta_F[c], b.i.delta_F[c]);
      r.j.delta_F[c] = f(a.j.delta_F[c], b.j.delta_F[c]);
      r.i.delta_torque[c] = f(a.i.delta_torque[c], b.i.delta_torque[c]);
      r.j.delta_torque[c] = f(a.j.delta_torque[c], b.j.delta_torque[c]);
    }
    return r;
  }
  void add_to(ForceData& fi, ForceData& fj) const {
    for (int c = 0; c < 3; ++c) {
      fi.delta_F[c] += i.delta_F[c], fj.delta_F[c] += j.delta_F[c];
      fi.delta_torque[c] += i.delta_torque[c], fj.delta_torque[c] += j.delta_torque[c];
    }
  }
  double force_squared() const {
    return i.delta_F[0] * i.delta_F[0] + i.delta_F[1] * i.delta_F[1] + i.delta_F[2] * i.delta_F[2];
  }
};
}  // namespace tdem_grid

// GC: the correction is compiled in (the variant `grid_correction on` selects, its hash with
// kGridCorrectionBit); without it the model is LIGGGHTS's sequence only and accepts
// `grid_correction off`.
template <typename Style, bool GC>
class TdemContactModel : public ContactModelBase {
  static_assert(Style::COHESION == COHESION_OFF, "tdem's contact model has no cohesion");
  using Kick = tdem_grid::Kick;
  static constexpr double kFast = tdem_grid::kFast, kWatched = tdem_grid::kWatched;

  SurfaceModel<Style::SURFACE> surfaceModel;
  NormalModel<Style::MODEL> normalModel;
  CohesionModel<Style::COHESION> cohesionModel;
  TangentialModel<Style::TANGENTIAL> tangentialModel;
  RollingModel<Style::ROLLING> rollingModel;

 public:
  static const int64_t STYLE_HASHCODE = Style::HASHCODE | (GC ? tdem::liggghts::kGridCorrectionBit : 0);

  TdemContactModel(LAMMPS* lmp, IContactHistorySetup* hsetup, bool is_wall, const int64_t)
      : ContactModelBase(lmp, is_wall),
        surfaceModel(lmp, hsetup, this),
        normalModel(lmp, hsetup, this),
        cohesionModel(lmp, hsetup, this),
        tangentialModel(lmp, hsetup, this),
        rollingModel(lmp, hsetup, this),
        host_(lmp),
        is_wall_(is_wall),
        mode_(is_wall ? kWall : kIdle) {}

  int64_t hashcode() { return STYLE_HASHCODE; }

  void registerSettings(Settings& settings) {
    surfaceModel.registerSettings(settings);
    normalModel.registerSettings(settings);
    cohesionModel.registerSettings(settings);
    tangentialModel.registerSettings(settings);
    rollingModel.registerSettings(settings);
    // (the value chose the variant: tdem::liggghts::select_variant)
    tdem::liggghts::register_on_off(host_, settings, "gran contact model", "grid_correction", setting_, false);
  }

  void postSettings(IContactHistorySetup* hsetup) {
    surfaceModel.postSettings(hsetup, this);
    normalModel.postSettings(hsetup, this);
    cohesionModel.postSettings(hsetup, this);
    tangentialModel.postSettings(hsetup, this);
    rollingModel.postSettings(hsetup, this);
    if (setting_ != GC) host_->error->all(FLERR, "grid_correction: internal error (variant and setting differ)");
    if constexpr (GC) {  // the last values of the contact's history
      state_ = hsetup->add_history_value("tdem_gc_state", "0");
      meff_ = hsetup->add_history_value("tdem_gc_meff", "0");
      hsize_ = meff_ + 1;
      if (hsize_ > tdem_grid::kMaxHistory)
        host_->error->all(FLERR, "grid_correction: the contact history is too long (raise kMaxHistory)");
      host_->neighbor->register_contact_dist_factor(tdem_grid::kContactDistance);
    }
  }

  void connectToProperties(PropertyRegistry& registry) {
    surfaceModel.connectToProperties(registry);
    normalModel.connectToProperties(registry);
    cohesionModel.connectToProperties(registry);
    tangentialModel.connectToProperties(registry);
    rollingModel.connectToProperties(registry);
    if constexpr (GC) {
      watch_clip_ = normalModel.contact_end() == tdem::ContactEnd::zero_force;
      on_ = watch_clip_ ? kWatched : tdem::grid::kFlagOn;
      gap_ = host_->neighbor->contactDistanceFactor - 1.0;
    }
    if constexpr (GC && Style::TANGENTIAL != TANGENTIAL_OFF) {  // mu, to tell sliding from sticking
      registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
      registry.connect("coeffFrict", mu_, "grid_correction");
    }
  }

  // (LIGGGHTS's pair loop calls it before its loop, the wall fixes do not)
  void beginPass(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    if constexpr (GC) {  // the pass's constants
      if (!is_wall_) mode_ = sidata.computeflag && sidata.shearupdate ? kLivePass : kIdle;
      stamp_ = 8.0 * static_cast<double>(host_->update->ntimestep);
      lo_ = stamp_ + tdem::grid::kFlagOn;
    }
    surfaceModel.beginPass(sidata, i_forces, j_forces);
    normalModel.beginPass(sidata, i_forces, j_forces);
    cohesionModel.beginPass(sidata, i_forces, j_forces);
    tangentialModel.beginPass(sidata, i_forces, j_forces);
    rollingModel.beginPass(sidata, i_forces, j_forces);
  }
  void endPass(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    rollingModel.endPass(sidata, i_forces, j_forces);
    tangentialModel.endPass(sidata, i_forces, j_forces);
    cohesionModel.endPass(sidata, i_forces, j_forces);
    normalModel.endPass(sidata, i_forces, j_forces);
    surfaceModel.endPass(sidata, i_forces, j_forces);
  }

  double stressStrainExponent() { return normalModel.stressStrainExponent(); }
  void tally_pp(double val, int i, int j, int index) { surfaceModel.tally_pp(val, i, j, index); }
  void tally_pw(double val, int i, int j, int index) { surfaceModel.tally_pw(val, i, j, index); }
  bool checkSurfaceIntersect(SurfacesIntersectData& sidata) { return surfaceModel.checkSurfaceIntersect(sidata); }

  // With the correction on (and the history updated) a touching contact whose code is below 1 is an
  // event (event(): its first step, code 0 or a stale stamp; a corrected contact whose end is
  // watched: a fast one, or one of a zero-force law); any other runs the plain models and its state
  // takes the new stamp. That test is all that stays in the loop (the pass's constants: beginPass).
  // (always inlined into the pair loop, as LIGGGHTS's ContactModel is, with one call site of the
  // models: an out-of-line copy cost 60 instructions per contact-step)
  [[gnu::always_inline]] inline void surfacesIntersect(SurfacesIntersectData& sidata, ForceData& i_forces,
                                                       ForceData& j_forces) {
    if constexpr (GC) {
      if (__builtin_expect(mode_ == kLivePass, 1)) {
        double& state = sidata.contact_history[state_];
        if (__builtin_expect(state < lo_, 0)) return event(sidata, i_forces, j_forces, stamp_);
        state += 8.0;
      } else if (mode_ == kWall) {
        return wall_intersect(sidata, i_forces, j_forces);
      }
    }
    plain(sidata, i_forces, j_forces);
  }

  void endSurfacesIntersect(SurfacesIntersectData& sidata, TriMesh* mesh, ForceData& i_forces, ForceData& j_forces) {
    surfaceModel.endSurfacesIntersect(sidata, mesh, i_forces.delta_F);
    cohesionModel.endSurfacesIntersect(sidata, i_forces, j_forces);
  }

  // A pair within the contact distance, not touching. With the correction on (and the history
  // updated), only its first step apart does anything: the end of a corrected contact, and the
  // models' surfacesClose, which only reset the contact's history and flags. At its later steps
  // apart (code <= 0: a stale stamp; or 0, a pair that never touched) the models' reset has been
  // done already (or there is nothing to reset), so it is skipped: the pairs within 1 % of contact
  // cost one comparison a step. (A pair that left the contact distance within one step and came
  // back keeps its tangential history, as every pair does without the contact distance in stock
  // LIGGGHTS.) The state is not reset: from the next step on its stamp says "not evaluated at the
  // last step".
  [[gnu::always_inline]] inline void surfacesClose(SurfacesCloseData& scdata, ForceData& i_forces,
                                                   ForceData& j_forces) {
    if constexpr (GC) {
      if (__builtin_expect(mode_ == kLivePass, 1)) {
        const double state = scdata.contact_history[state_];
        if (state <= stamp_) return;  // code <= 0
        if (state <= lo_) separation(static_cast<SurfacesIntersectData&>(scdata), i_forces, j_forces);  // (0, 1]
      } else if (mode_ == kWall && !wall_close(scdata, i_forces, j_forces)) {
        return;
      }
    }
    surfaceModel.surfacesClose(scdata, i_forces, j_forces);
    normalModel.surfacesClose(scdata, i_forces, j_forces);
    cohesionModel.surfacesClose(scdata, i_forces, j_forces);
    tangentialModel.surfacesClose(scdata, i_forces, j_forces);
    rollingModel.surfacesClose(scdata, i_forces, j_forces);
  }

  bool contact_match(const std::string mtype, const std::string model) {
    Factory& f = Factory::instance();
    if (mtype == "surface") return Style::SURFACE == f.getSurfaceModelId(model);
    if (mtype == "normal") return Style::MODEL == f.getNormalModelId(model);
    if (mtype == "cohesion") return Style::COHESION == f.getCohesionModelId(model);
    if (mtype == "tangential") return Style::TANGENTIAL == f.getTangentialModelId(model);
    if (mtype == "rolling_friction") return Style::ROLLING == f.getRollingModelId(model);
    return false;
  }

 private:
  // LIGGGHTS's own sequence (ContactModel<Style>::surfacesIntersect).
  inline void plain(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    surfaceModel.surfacesIntersect(sidata, i_forces, j_forces);
    after_surface(sidata, i_forces, j_forces);
  }
  inline void after_surface(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    normalModel.surfacesIntersect(sidata, i_forces, j_forces);
    cohesionModel.surfacesIntersect(sidata, i_forces, j_forces);
    tangentialModel.surfacesIntersect(sidata, i_forces, j_forces);
    rollingModel.surfacesIntersect(sidata, i_forces, j_forces);
  }

  [[gnu::cold, gnu::noinline]] void end_unseen() {
    if (warned_) return;
    warned_ = true;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "grid_correction: a contact is about to end with a gap beyond the contact distance (factor %g), "
                  "where LIGGGHTS does not show it: its end is not corrected; raise it with neigh_modify "
                  "contact_distance_factor (printed once per rank)",
                  1.0 + gap_);
    host_->error->warning(FLERR, buf);
  }

  // A wall fix's contact (no beginPass): whether the history is updated, and the stamp.
  bool update_now(const SurfacesCloseData& d, double& stamp) const {
    stamp = 8.0 * static_cast<double>(host_->update->ntimestep);
    return d.contact_history && d.computeflag && d.shearupdate;
  }
  // surfacesIntersect and surfacesClose of a wall fix's contact (out of the pair loop's way): the
  // pair loop's tests with the constants per contact. (Written out twice on purpose: the same
  // tests through shared inline helpers cost the pair loop 0.07-0.18 % instructions.)
  [[gnu::noinline]] void wall_intersect(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces) {
    double stamp;
    if (update_now(sidata, stamp)) {
      double& state = sidata.contact_history[state_];
      if (state < stamp + tdem::grid::kFlagOn) return event(sidata, i_forces, j_forces, stamp);
      state += 8.0;
    }
    plain(sidata, i_forces, j_forces);
  }
  // false: skip the models' surfacesClose (a later step apart)
  [[gnu::noinline]] bool wall_close(SurfacesCloseData& scdata, ForceData& i_forces, ForceData& j_forces) {
    double stamp;
    if (!update_now(scdata, stamp)) return true;
    const double code = scdata.contact_history[state_] - stamp;
    if (code <= 0.0) return false;
    if (code <= tdem::grid::kFlagOn) separation(static_cast<SurfacesIntersectData&>(scdata), i_forces, j_forces);
    return true;
  }
  // A fast contact (kFast) whose gap after the next step would be beyond the contact distance:
  // its end will not be shown to the model.
  void foresee_end(const SurfacesIntersectData& d) {
    if (d.deltan - host_->update->dt * d.vn < -gap_ * d.radsum) end_unseen();
  }

  double friction(const SurfacesCloseData& d) const { return mu_ ? mu_[d.itype][d.jtype] : 0.0; }
  void set_state(double* hist, double code) const {
    hist[state_] = 8.0 * (static_cast<double>(host_->update->ntimestep) + 1.0) + code;
  }

  // The normal law on a probe (a copy of the contact data) at overlap xi on history `hist`, no
  // update; the probe keeps the law's published result for the tangential law.
  tdem::NormalResult<double> normal_at(SurfacesIntersectData& probe, double xi, double* hist) {
    probe.deltan = xi;
    probe.contact_history = hist;
    probe.shearupdate = 0;
    probe.contact_flags = nullptr;
    return normalModel.law(probe);
  }
  // The tangential model's kick on the probe's data (its normal force probe.Fn), no update.
  Kick tangential_at(SurfacesIntersectData& probe) {
    Kick k;
    tangentialModel.surfacesIntersect(probe, k.i, k.j);
    return k;
  }
  // The exponents of the law's two parts at overlap xi (result r there): 1 and 0 for the linear
  // law, else from a probe at xi/2 on `hist`.
  void exponents(const SurfacesIntersectData& data, double xi, double* hist, const tdem::NormalResult<double>& r,
                 double& p, double& q) {
    if constexpr (NormalModel<Style::MODEL>::linear) {
      p = 1.0, q = 0.0;
      return;
    }
    if constexpr (tdem_grid::DeclaresExponents<NormalModel<Style::MODEL>>::value) {
      if (normalModel.power_exponents(data, p, q)) return;
    }
    double copy[tdem_grid::kMaxHistory];
    std::memcpy(copy, hist, sizeof(double) * hsize_);
    SurfacesIntersectData probe = data;
    const tdem::NormalResult<double> hf = normal_at(probe, 0.5 * xi, copy);
    p = tdem::grid::power_exponent(r.elastic, hf.elastic, 1.0);
    q = tdem::grid::power_exponent(r.force - r.elastic, hf.force - hf.elastic, 0.0);
  }
  // A step of a contact that needs more than the plain models: its first step (code 0 or a stale
  // stamp), or a corrected contact whose end is watched (kFast, kWatched). `stamp`: 8 * the step.
  [[gnu::cold, gnu::noinline]] void event(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces,
                                          double stamp) {
    double* const hist = sidata.contact_history;
    const double code = hist[state_] - stamp;
    if (code == kFast || code == kWatched) return watched_step(sidata, i_forces, j_forces, code);
    surfaceModel.surfacesIntersect(sidata, i_forces, j_forces);
    const double h = host_->update->dt, xi = sidata.deltan, rate = -sidata.vn;
    const double tau = tdem::grid::touch_age(xi, rate, h);
    if (tau < 0.0) {  // an old overlap, or not approaching: not corrected
      after_surface(sidata, i_forces, j_forces);
      return set_state(hist, tdem::grid::kFlagSeen);
    }
    double fresh[tdem_grid::kMaxHistory];
    std::memcpy(fresh, hist, sizeof(double) * hsize_);
    SurfacesIntersectData at_touch = sidata;
    const tdem::NormalResult<double> nr = normalModel.law(sidata);  // commits the normal history
    Kick a;
    {
      tdem_grid::StepGuard g(host_->update, tau);
      tangentialModel.surfacesIntersect(sidata, a.i, a.j);  // the spring from the touch
    }
    double pe, pq;
    exponents(at_touch, xi, fresh, nr, pe, pq);
    if (!tdem::grid::resolved(nr.elastic, pe, nr.damping, xi, rate, sidata.meff, h)) {
      std::memcpy(hist, fresh, sizeof(double) * hsize_);
      after_surface(sidata, i_forces, j_forces);
      return set_state(hist, tdem::grid::kFlagSeen);
    }
    const double fn = nr.force;
    const double fn_apply = tdem::grid::start_force(nr.elastic, pe, fn - nr.elastic, pq, tau, h);
    tdem::liggghts::add_normal_force(sidata, fn_apply, i_forces, j_forces);
    Kick t;
    if (tdem::grid::sliding(a.force_squared(), friction(sidata), fn)) {
      t = Kick::combine(a, a, [&](double x, double) { return x / fn * fn_apply; });
    } else {  // linear from the law at the touch (spring 0)
      normal_at(at_touch, 0.0, fresh);  // (at_touch is not needed any more)
      const Kick b = tangential_at(at_touch);
      t = Kick::combine(a, b, [&](double x, double x0) { return tdem::grid::start_force(x - x0, 1.0, x0, 0.0, tau, h); });
    }
    t.add_to(i_forces, j_forces);
    {
      tdem_grid::StepGuard g(host_->update, tau);
      rollingModel.surfacesIntersect(sidata, i_forces, j_forces);
    }
    set_state(hist, rate * h > gap_ * sidata.radsum ? kFast : on_);
    hist[meff_] = sidata.meff;
  }

  // A corrected contact whose end is watched (its code `on`: kFast or kWatched). A fast one
  // foresees an end beyond the contact distance. One of a zero-force law: the plain step, and the
  // end if its force was clipped to zero (the history of the last step, saved before this one,
  // reconstructs it).
  void watched_step(SurfacesIntersectData& sidata, ForceData& i_forces, ForceData& j_forces, double on) {
    double* const hist = sidata.contact_history;
    if (!watch_clip_) {
      plain(sidata, i_forces, j_forces);
      set_state(hist, on);
      return foresee_end(sidata);
    }
    double prev[tdem_grid::kMaxHistory];
    std::memcpy(prev, hist, sizeof(double) * hsize_);
    surfaceModel.surfacesIntersect(sidata, i_forces, j_forces);
    const SurfacesIntersectData now = sidata;
    const tdem::NormalResult<double> nr = normalModel.law(sidata);
    tdem::liggghts::apply_normal_force(sidata, i_forces, j_forces);
    cohesionModel.surfacesIntersect(sidata, i_forces, j_forces);
    tangentialModel.surfacesIntersect(sidata, i_forces, j_forces);
    rollingModel.surfacesIntersect(sidata, i_forces, j_forces);
    if (on == kFast) foresee_end(now);
    if (nr.force > 0.0) return set_state(hist, on);
    set_state(hist, tdem::grid::kFlagEnded);
    const double h = host_->update->dt, xi = now.deltan, rate = -now.vn;
    SurfacesIntersectData probe = now;
    const double xi_prev = tdem::grid::previous_overlap(xi, rate, h);
    const tdem::NormalResult<double> np = normal_at(probe, xi_prev, prev);
    const double fp = np.force;
    if (!tdem::grid::end_usable(xi_prev, fp, xi, true)) return;
    const Kick p = tangential_at(probe);
    // where the unclipped force crossed zero: the law's parts now, or (a law that reports none
    // when clipped) the tangent of the last step
    const double s = nr.elastic != 0.0 || nr.damping != 0.0 ? tdem::grid::end_time(fp, nr.elastic + nr.damping * rate, h)
                                                            : tdem::grid::end_time(fp, fp + np.stiffness * rate * h, h);
    const double fn_x = tdem::grid::end_extra(fp, fp, 1.0, 0.0, 0.0, s, h);
    tdem::liggghts::add_normal_force(now, fn_x, i_forces, j_forces);
    end_tangential(p, 0.0, fp, fn_x, s, h, tdem::grid::sliding(p.force_squared(), friction(now), fp))
        .add_to(i_forces, j_forces);
  }

  // The tangential part of an end: following the normal force if the last step was sliding,
  // else linear from the last step's kick p to cap * p (p capped by the limit at the end; 0 for a
  // zero-force end).
  static Kick end_tangential(const Kick& p, double cap, double fp, double fn_x, double s, double h, bool sliding) {
    if (sliding) return Kick::combine(p, p, [&](double x, double) { return x / fp * (fn_x + fp) - x; });
    return Kick::combine(p, p, [&](double x, double) {
      const double fte = cap * x;
      return tdem::grid::end_extra(x, x - fte, 1.0, fte, 0.0, s, h);
    });
  }

  // The first step without contact of a corrected contact (surfacesClose): the end's extra kick.
  [[gnu::cold, gnu::noinline]] void separation(SurfacesIntersectData& sidata, ForceData& i_forces,
                                               ForceData& j_forces) {
    SurfacesIntersectData k = sidata;
    if (!k.is_wall) {  // LIGGGHTS fills the contact geometry of a pair only for touching spheres
      k.r = std::sqrt(k.rsq);
      k.rinv = 1.0 / k.r;
      for (int c = 0; c < 3; ++c) k.en[c] = k.delta[c] * k.rinv;
      k.omega_i = host_->atom->omega[k.i];
      k.omega_j = host_->atom->omega[k.j];
    }
    k.meff = sidata.contact_history[meff_];
    ForceData scratch_i, scratch_j;
    surfaceModel.surfacesIntersect(k, scratch_i, scratch_j);  // vn, deltan (< 0), vtr, lever arms
    double prev[tdem_grid::kMaxHistory];
    std::memcpy(prev, sidata.contact_history, sizeof(double) * hsize_);
    const double h = host_->update->dt, xi = k.deltan, rate = -k.vn;
    const double xi_prev = tdem::grid::previous_overlap(xi, rate, h);
    // (the probes below run on k: the law and the tangential model only read its geometry)
    const tdem::NormalResult<double> np = normal_at(k, xi_prev, prev);
    const double fp = np.force;
    if (!tdem::grid::end_usable(xi_prev, fp, xi, false)) return;
    const Kick p = tangential_at(k);
    const double s = tdem::grid::end_time(xi_prev, xi, h);
    double pe, q;
    exponents(k, xi_prev, prev, np, pe, q);
    const double fn_x = tdem::grid::end_extra(fp, np.elastic, pe, fp - np.elastic, q, s, h);
    const bool slide = tdem::grid::sliding(p.force_squared(), friction(k), fp);
    double cap = 1.0;
    if (!slide) {  // the factor that caps the last kick by the limit at the end: from the law there
      const double fe = normal_at(k, 0.0, prev).force;
      k.Fn = fe;
      const double p2 = p.force_squared(), e2 = tangential_at(k).force_squared();
      if (e2 < p2) cap = std::sqrt(e2 / p2);
    }
    tdem::liggghts::add_normal_force(k, fn_x, i_forces, j_forces);
    end_tangential(p, cap, fp, fn_x, s, h, slide).add_to(i_forces, j_forces);
    sidata.has_force_update = true;
  }

  LAMMPS_NS::LAMMPS* host_;
  bool setting_ = false;     // the keyword's value (checked against GC)
  bool watch_clip_ = false;  // the law ends at zero force: its corrected contacts are watched
  bool warned_ = false;
  // kLivePass: the pair's pass updates the history (computeflag and shearupdate; beginPass);
  // kWall: a wall fix's model (no beginPass), whose contacts take the pass's constants each
  enum Mode { kIdle, kLivePass, kWall };
  const bool is_wall_;
  Mode mode_;
  double stamp_ = 0.0;       // 8 * the pass's step
  double lo_ = 0.0;          // stamp_ + 1: a state below it is an event
  double on_ = 0.0;          // the code of a corrected contact that is not fast
  double gap_ = 0.0;         // the contact distance factor - 1
  int state_ = 0, meff_ = 0, hsize_ = 0;
  double** mu_ = nullptr;
};

}  // namespace ContactModels
}  // namespace LIGGGHTS
