// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: the tangential laws of src/contact/tangential/ (issue 4) as LIGGGHTS TangentialModels,
// usable in pair gran and wall gran with any compiled normal model:
//
//   tangential tdem/haff_werner          viscous friction, no memory         (haff_werner.h)
//   tangential tdem/linear_spring        spring(-dashpot) + Coulomb limit    (linear_spring.h)
//   tangential tdem/walton_braun         Walton-Braun stiffness k_t0 (1-x)^(1/3) (walton_braun_tangential.h)
//   tangential tdem/mindlin_deresiewicz  loading/unloading/reloading, Masing memory (mindlin_deresiewicz.h)
//   tangential tdem/mindlin_no_slip      Tsuji no-slip spring 8 G* a + dashpot (mindlin_no_slip.h)
//   tangential tdem/di_renzo             2/3 of the no-slip stiffness, no dashpot (di_renzo.h)
//
// Settings keywords (after the tangential model name, like other LIGGGHTS model settings):
//   frictionLimit absolute|positive_normal    (all laws; default absolute: F_lim = mu |F_n| as the
//                                               stock styles; positive_normal: mu max(F_n, 0))
//   slipReset spring_only|spring_and_dashpot  (linear_spring, mindlin_no_slip; default spring_only)
// Parameters (fix property/global):
//   coefficientFriction      peratomtypepair  mu >= 0                     (all laws)
//   tangentialDampingRatio   peratomtypepair  >= 0: gamma_t = ratio * gamma_n, gamma_n the normal
//                                              damping coefficient the normal model used this step
//                                              (haff_werner, linear_spring, mindlin_no_slip)
//   youngsModulus, poissonsRatio peratomtype  -> G* (LIGGGHTS Geff = 1/((2-nu1)/G1 + (2-nu2)/G2))
//                                              (mindlin_deresiewicz, mindlin_no_slip, di_renzo)
//   linear_spring and walton_braun take their (initial) stiffness k_t (k_t0) from the normal
//   model (sidata.kt: tangentialStiffnessRatio * k_n for the tdem laws, 8 G* a for stock hertz,
//   kt for stock hooke), as the stock `tangential history` does.
// Kinematics handed to the kernels: n = en (from j to i), v_t = LIGGGHTS's contact-point slip
// velocity (lever arm R - xi/2), spin_n = (omega_i + omega_j)/2 . n (wall: omega_i . n / 2), the
// turning rate of the normal omega_t = n x (v_i - v_j)/|x_i - x_j| for pairs and 0 for walls,
// R* = R_i R_j/(R_i + R_j) (wall: R_i), xi = deltan, F_n = sidata.Fn, k_n = sidata.kn.
#pragma once

#include <cmath>
#include <string>

#include "contact_models.h"
#include "tangential_model_base.h"
#include "global_properties.h"
#include "update.h"
#include "atom.h"
#include "error.h"

#include "contact/tangential/common.h"
#include "contact/tangential/di_renzo.h"
#include "contact/tangential/haff_werner.h"
#include "contact/tangential/linear_spring.h"
#include "contact/tangential/mindlin_deresiewicz.h"
#include "contact/tangential/mindlin_no_slip.h"
#include "contact/tangential/walton_braun_tangential.h"
#include "tdem_liggghts_ids.h"
#include "contact/usual_ranges.h"
#include "tdem_liggghts_properties.h"
#include "tdem_liggghts_settings.h"

namespace tdem {
namespace liggghts {

// Per-law facts: kernel history, which parameters it reads, its name.
template <int ID>
struct TangentialLaw;

template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_HAFF_WERNER> {
  static constexpr const char* caller = "tangential tdem/haff_werner";
  static constexpr const char* prefix = "tdem_hw_";
  static constexpr int history_size = haff_werner::history_size;
  static constexpr const HistorySlot* history = haff_werner::history;
  static constexpr bool damping = true, gstar = false, reset = false;
};
template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_LINEAR_SPRING> {
  static constexpr const char* caller = "tangential tdem/linear_spring";
  static constexpr const char* prefix = "tdem_ls_";
  static constexpr int history_size = linear_spring::history_size;
  static constexpr const HistorySlot* history = linear_spring::history;
  static constexpr bool damping = true, gstar = false, reset = true;
};
template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_WALTON_BRAUN_T> {
  static constexpr const char* caller = "tangential tdem/walton_braun";
  static constexpr const char* prefix = "tdem_wb_";
  static constexpr int history_size = walton_braun_tangential::history_size;
  static constexpr const HistorySlot* history = walton_braun_tangential::history;
  static constexpr bool damping = false, gstar = false, reset = false;
};
template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_MINDLIN_DERESIEWICZ> {
  static constexpr const char* caller = "tangential tdem/mindlin_deresiewicz";
  static constexpr const char* prefix = "tdem_md_";
  static constexpr int history_size = mindlin_deresiewicz::history_size;
  static constexpr const HistorySlot* history = mindlin_deresiewicz::history;
  static constexpr bool damping = false, gstar = true, reset = false;
};
template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_MINDLIN_NO_SLIP> {
  static constexpr const char* caller = "tangential tdem/mindlin_no_slip";
  static constexpr const char* prefix = "tdem_mns_";
  static constexpr int history_size = mindlin_no_slip::history_size;
  static constexpr const HistorySlot* history = mindlin_no_slip::history;
  static constexpr bool damping = true, gstar = true, reset = true;
};
template <>
struct TangentialLaw<LIGGGHTS::ContactModels::TDEM_DI_RENZO> {
  static constexpr const char* caller = "tangential tdem/di_renzo";
  static constexpr const char* prefix = "tdem_dr_";
  static constexpr int history_size = di_renzo::history_size;
  static constexpr const HistorySlot* history = di_renzo::history;
  static constexpr bool damping = false, gstar = true, reset = false;
};

// Applies the tangential force Ft on i (and -Ft on j) with the torques, the same arithmetic as
// LIGGGHTS's tangential models (and tdem/cundall_strack).
inline void apply_tangential_force(const LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, const double* Ft,
                                   LIGGGHTS::ContactModels::ForceData& i_forces,
                                   LIGGGHTS::ContactModels::ForceData& j_forces) {
  const double enx = sidata.en[0], eny = sidata.en[1], enz = sidata.en[2];
  const double tor1 = eny * Ft[2] - enz * Ft[1];
  const double tor2 = enz * Ft[0] - enx * Ft[2];
  const double tor3 = enx * Ft[1] - eny * Ft[0];
  if (sidata.is_wall) {
    const double a = sidata.area_ratio;
    i_forces.delta_F[0] += Ft[0] * a;
    i_forces.delta_F[1] += Ft[1] * a;
    i_forces.delta_F[2] += Ft[2] * a;
    i_forces.delta_torque[0] += -sidata.cri * tor1 * a;
    i_forces.delta_torque[1] += -sidata.cri * tor2 * a;
    i_forces.delta_torque[2] += -sidata.cri * tor3 * a;
  } else {
    i_forces.delta_F[0] += Ft[0];
    i_forces.delta_F[1] += Ft[1];
    i_forces.delta_F[2] += Ft[2];
    j_forces.delta_F[0] += -Ft[0];
    j_forces.delta_F[1] += -Ft[1];
    j_forces.delta_F[2] += -Ft[2];
    i_forces.delta_torque[0] += -sidata.cri * tor1;
    i_forces.delta_torque[1] += -sidata.cri * tor2;
    i_forces.delta_torque[2] += -sidata.cri * tor3;
    j_forces.delta_torque[0] += -sidata.crj * tor1;
    j_forces.delta_torque[1] += -sidata.crj * tor2;
    j_forces.delta_torque[2] += -sidata.crj * tor3;
  }
}

// The kinematics of one contact in the form of src/contact/tangential/common.h.
inline tangential::TangentialKinematics<double> tangential_kinematics(
    const LIGGGHTS::ContactModels::SurfacesIntersectData& sidata, double dt) {
  tangential::TangentialKinematics<double> k;
  const double* n = sidata.en;
  k.n[0] = n[0], k.n[1] = n[1], k.n[2] = n[2];
  k.vt[0] = sidata.vtr1, k.vt[1] = sidata.vtr2, k.vt[2] = sidata.vtr3;
  k.dt = dt;
  k.overlap = sidata.deltan;
  k.meff = sidata.meff;
  k.fn = sidata.Fn;
  k.kn = sidata.kn;
  k.gamman = sidata.gamman;
  const double* wi = sidata.omega_i;
  if (sidata.is_wall) {
    k.reff = sidata.radi;
    k.spin_n = 0.5 * (wi[0] * n[0] + wi[1] * n[1] + wi[2] * n[2]);
  } else {
    const double* wj = sidata.omega_j;
    k.reff = sidata.radi * sidata.radj / (sidata.radi + sidata.radj);
    k.spin_n = 0.5 * ((wi[0] + wj[0]) * n[0] + (wi[1] + wj[1]) * n[1] + (wi[2] + wj[2]) * n[2]);
    const double dv[3] = {sidata.v_i[0] - sidata.v_j[0], sidata.v_i[1] - sidata.v_j[1],
                          sidata.v_i[2] - sidata.v_j[2]};
    const double rinv = sidata.rinv;
    k.omega_t[0] = (n[1] * dv[2] - n[2] * dv[1]) * rinv;
    k.omega_t[1] = (n[2] * dv[0] - n[0] * dv[2]) * rinv;
    k.omega_t[2] = (n[0] * dv[1] - n[1] * dv[0]) * rinv;
  }
  return k;
}

}  // namespace liggghts
}  // namespace tdem

namespace LIGGGHTS {
namespace ContactModels {

// The body shared by the six TangentialModel specialisations.
template <int ID>
class TdemTangentialAdapter : public TangentialModelBase {
  using Law = tdem::liggghts::TangentialLaw<ID>;

 public:
  TdemTangentialAdapter(LAMMPS* lmp, IContactHistorySetup* hsetup,
                    ContactModelBase* c)
      : TangentialModelBase(lmp, hsetup, c) {
    // history values of one model are contiguous; "1" = flips sign with the pair order
    for (int k = 0; k < Law::history_size; ++k) {
      const int off = hsetup->add_history_value(std::string(Law::prefix) + Law::history[k].name,
                                                Law::history[k].flips_sign ? "1" : "0");
      if (k == 0) history_offset_ = off;
    }
  }

  void registerSettings(Settings& settings) {
    tdem::liggghts::register_enum(lmp, settings, Law::caller, "frictionLimit", limit_, {"absolute", "positive_normal"}, 0);
    if (Law::reset)
      tdem::liggghts::register_enum(lmp, settings, Law::caller, "slipReset", reset_, {"spring_only", "spring_and_dashpot"}, 0);
  }

  void postSettings(IContactHistorySetup*, ContactModelBase*) {}

  void connectToProperties(PropertyRegistry& registry) {
    const int n = tdem::liggghts::table_types(registry);  // rows filled for the types present
    registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
    registry.connect("coeffFrict", mu_, Law::caller);
    tdem::liggghts::check_matrix(lmp, mu_, n, "coefficientFriction", Law::caller, 1);
    tdem::liggghts::warn_unusual(lmp, mu_, n, "coefficientFriction", Law::caller, &tdem::usual::friction);
    if (Law::damping) {
      registry.registerProperty(tdem::liggghts::kPropTangentialDampingRatio, &tdem::liggghts::create_tangential_damping_ratio);
      registry.connect(tdem::liggghts::kPropTangentialDampingRatio, ratio_, Law::caller);
    }
    if (Law::gstar) {
      registry.registerProperty("Geff", &MODEL_PARAMS::createGeff);
      registry.connect("Geff", geff_, Law::caller);
      tdem::liggghts::check_matrix(lmp, geff_, n, "youngsModulus/poissonsRatio (effective shear modulus G*)", Law::caller, 0);
    }
  }

  inline void surfacesIntersect(const SurfacesIntersectData& sidata,
                                ForceData& i_forces,
                                ForceData& j_forces) {
    using namespace LIGGGHTS::ContactModels;
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
    const tdem::tangential::TangentialKinematics<double> k = tdem::liggghts::tangential_kinematics(sidata, update->dt);
    const int it = sidata.itype, jt = sidata.jtype;
    const double mu = mu_[it][jt];
    const auto limit = limit_ == 0 ? tdem::tangential::FrictionLimit::absolute : tdem::tangential::FrictionLimit::positive_normal;
    const auto reset = reset_ == 0 ? tdem::tangential::SlipReset::spring_only : tdem::tangential::SlipReset::spring_and_dashpot;
    const bool update_history = sidata.computeflag && sidata.shearupdate;
    double* const hist = Law::history_size > 0 ? &sidata.contact_history[history_offset_] : nullptr;
    double Ft[3] = {0.0, 0.0, 0.0};
    if constexpr (ID == TDEM_HAFF_WERNER) {
      const tdem::haff_werner::Params<double> p{ratio_[it][jt] * sidata.gamman, mu, limit};
      tdem::haff_werner::force(p, k, hist, update_history, Ft);
    } else if constexpr (ID == TDEM_LINEAR_SPRING) {
      const tdem::linear_spring::Params<double> p{sidata.kt, 0.0, ratio_[it][jt] * sidata.gamman, mu, limit, reset};
      tdem::linear_spring::force(p, k, hist, update_history, Ft);
    } else if constexpr (ID == TDEM_WALTON_BRAUN_T) {
      const tdem::walton_braun_tangential::Params<double> p{sidata.kt, 0.0, mu, limit};
      tdem::walton_braun_tangential::force(p, k, hist, update_history, Ft);
    } else if constexpr (ID == TDEM_MINDLIN_DERESIEWICZ) {
      const tdem::mindlin_deresiewicz::Params<double> p{geff_[it][jt], mu, limit};
      tdem::mindlin_deresiewicz::force(p, k, hist, update_history, Ft);
    } else if constexpr (ID == TDEM_MINDLIN_NO_SLIP) {
      const tdem::mindlin_no_slip::Params<double> p{geff_[it][jt], ratio_[it][jt], mu, limit, reset};
      tdem::mindlin_no_slip::force(p, k, hist, update_history, Ft);
    } else {
      const tdem::di_renzo::Params<double> p{geff_[it][jt], mu, limit};
      tdem::di_renzo::force(p, k, hist, update_history, Ft);
    }
    tdem::liggghts::apply_tangential_force(sidata, Ft, i_forces, j_forces);
  }

  void surfacesClose(SurfacesCloseData& scdata, ForceData&,
                     ForceData&) {
    if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
    if (Law::history_size == 0 || !scdata.contact_history) return;
    double* const hist = &scdata.contact_history[history_offset_];
    for (int k = 0; k < Law::history_size; ++k) hist[k] = 0.0;
  }

  void beginPass(SurfacesIntersectData&, ForceData&,
                 ForceData&) {}
  void endPass(SurfacesIntersectData&, ForceData&,
               ForceData&) {}

 private:
  double** mu_ = nullptr;
  double** ratio_ = nullptr;
  double** geff_ = nullptr;
  int history_offset_ = 0;
  int limit_ = 0;
  int reset_ = 0;
};


#define TDEM_TANGENTIAL_SPECIALISATION(ID)                                                  \
  template <>                                                                               \
  class TangentialModel<ID> : public TdemTangentialAdapter<ID> {                \
   public:                                                                                  \
    TangentialModel(LAMMPS* lmp, IContactHistorySetup* hsetup, class ContactModelBase* c) \
        : TdemTangentialAdapter<ID>(lmp, hsetup, c) {}                          \
  };
TDEM_TANGENTIAL_SPECIALISATION(TDEM_HAFF_WERNER)
TDEM_TANGENTIAL_SPECIALISATION(TDEM_LINEAR_SPRING)
TDEM_TANGENTIAL_SPECIALISATION(TDEM_WALTON_BRAUN_T)
TDEM_TANGENTIAL_SPECIALISATION(TDEM_MINDLIN_DERESIEWICZ)
TDEM_TANGENTIAL_SPECIALISATION(TDEM_MINDLIN_NO_SLIP)
TDEM_TANGENTIAL_SPECIALISATION(TDEM_DI_RENZO)
#undef TDEM_TANGENTIAL_SPECIALISATION

}  // namespace ContactModels
}  // namespace LIGGGHTS
