// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-collide: the text of --help. A part of main.cpp (collide_common.h).
#pragma once

#include "collide_common.h"

namespace {

const char* kHelp = R"(tdem-collide: one collision with a tdem normal law (no host engine): head-on, or
oblique with spin and a tangential law.

Usage: tdem-collide --law LAW [law parameters] [bodies] --v0 V [options]
       tdem-collide --law LAW [...] --R1 R [bodies] --v0 V --angle DEG [--spin W]
                    [--tangential TLAW [tangential parameters]] [oblique options]

Bodies (sphere 1 hits sphere 2 or a wall; m* and R* are formed from them):
  --m1 M | --rho RHO      mass of sphere 1 [kg], or its density [kg/m^3] (needs --R1)
  --R1 R                  radius of sphere 1 [m] (needed by hertz --E/--Estar, thornton,
                          continuous_potential without --d, and with --rho)
  --wall                  sphere 1 hits a plane wall (m2 = R2 = infinity)
  --m2 M | --rho2 RHO     mass or density of sphere 2 (default density: --rho)
  --R2 R                  radius of sphere 2 [m]
  --v0 V                  impact velocity (relative normal velocity) [m/s], > 0; with --angle
                          the impact speed |v| (the normal component is V cos(angle))

Laws and their parameters (coefficients, or measurable quantities):
  --law lsd               linear spring-dashpot F = k xi + gamma xi'
      --k K [--gamma G]           stiffness [N/m], damping [kg/s] (default 0)
      --e E --tc T                restitution (0,1] and contact time [s] at this m*
      --e E --k K                 restitution and stiffness
      --end zero_overlap|zero_force   (default zero_overlap)
  --law hertz             F = k~ xi^1.5 + c xi^Theta xi'
      stiffness: --k K~ [N/m^1.5] | --Estar E* [Pa] | --E E --nu NU [--E2 E --nu2 NU]
                 (sphere 2 / wall material, default the same; --E2 inf: rigid) | --tc T
                 (undamped contact time at v0)
      --damping none|linear|kuwabara_kono|tsuji|general   (default none)
        linear: --gamma G [kg/s];  kuwabara_kono: --gamma G~ [kg/(s m^0.5)] | --A T [s];
        tsuji: --alpha A | --e E;  general: --gamma C --theta TH
        linear, kuwabara_kono, general: --e E (< 1) instead of --gamma: the damping that gives
        restitution E at this v0 (root search over the collision)
      --end zero_overlap|zero_force   (default zero_overlap)
  --law walton_braun      hysteretic linear law (contact ends at zero force)
      --kl K [--kul K] [--s S]    loading, unloading stiffness [N/m] (default k_l), slope [1/m]
      --e E --tc T | --e E --kl K constant k_ul from restitution
  --law thornton          elastic-perfectly-plastic (contact ends at zero force)
      modulus as hertz: --Estar | --E --nu [--E2 --nu2]; radius --R1 (and --R2)
      --py P [Pa] | --vy V (yield velocity) [m/s] | --e E (restitution at v0, < 1)
  --law continuous_potential   F = n eps d^n / X^(n+1), X = d - xi
      --eps EPS [J] | --x-min X (closest approach at v0 [m]);  --n N (default 36)
      --d D (default R1 + R2, or R1 with --wall);  --x-cut X (default inf; the collision
      starts at X_cut, or at X = d without cut-off);  --gamma G [kg/s] (default 0);  --end
  --law power_law         power-law hysteresis F = a_l xi^p, unloading a_ul (xi - xi_f)^(p+q)
      --al A --p P  and  --aul A [--q Q]  (default q = 0) | --e E  (q = 0, a_ul from e)
  --law extended_linear   k, gamma from measured e(v0), t_c(v0) at first touch
      --e-fit constant|rational|power --e-coef C0[,C1[,C2]]
            constant e = C0;  rational e = C0 / (C1 + v0^C2);  power e = min(1, (v0/C0)^(-C1))
      --tc-fit constant|power --tc-coef C0[,C1]
            constant t_c = C0;  power t_c = C0 v0^(-C1)
      --v-min V --v-max V     clamp of v0 before the fits (default 1e-3, 1e3 m/s)
      --e-min E               smallest e a fit may give (default 1e-3)
      --end zero_overlap|zero_force   (default zero_overlap)
  --law extended_hertz    Hertz spring (stiffness as hertz: --k | --Estar | --E --nu ...) with
                          Tsuji damping alpha(v0) from e(v0): --e-fit, --e-coef, --v-min, --v-max,
                          --e-min, --end as extended_linear
  --params "WORDS"        for every law: the law's input line as LAMMPS
                          `pair_coeff ... normal LAW WORDS` takes it, instead of the law's own
                          options (walton_braun KL KUL [S], thornton E NU [E2 NU2] PY, power_law
                          AL P AUL [Q], lsd stiffness KN GAMMAN | restitution E TC (GAMMAN per m*),
                          hertz E NU [E2 NU2] [damping linear G | kuwabara_kono G | tsuji E |
                          general THETA C], extended_linear e_fit FORM C.. tc_fit FORM C..
                          [v_min V] [v_max V], extended_hertz E NU [E2 NU2] e_fit FORM C.. ...,
                          continuous_potential EPS N GAMMA with d = X_cut = R1 + R2);
                          --end as limit_force

Oblique impacts (any of --angle > 0, --spin != 0, --spin2 != 0, --tangential other than none;
solid spheres, velocity Verlet as the hosts integrate, end of contact located in the step):
  --angle DEG             impact angle from the normal, [0, 90) degrees (default 0)
  --spin W                initial spin of sphere 1 [1/s] about the axis normal to the impact plane,
                          sign: slip velocity v_s = v_t + R1 W (+ R2 W2), v_s = 0 for rolling
  --spin2 W               initial spin of sphere 2 (not with --wall)
  --tangential TLAW       tangential law (default none: frictionless):
      cundall_strack      spring + Coulomb slider (kernel cundall_strack.h, spring truncated on slip)
          --mu MU  --kt KT | --kappa K (k_t = K k_n; needs lsd, extended_linear or walton_braun)
          [--gammat G] [--friction-limit positive_normal|absolute]  (default absolute: mu |F_n|)
      linear_spring       spring(-dashpot) with Coulomb limit (linear_spring.h)
          --mu MU  --kt KT and/or --kappa K (k_t = KT + K k_n, k_n the normal tangent stiffness)
          [--gammat G] [--slip-reset spring_only|spring_and_dashpot] [--friction-limit ...]
      haff_werner         viscous friction, no memory: --mu MU --gammat G [--friction-limit ...]
      walton_braun        Walton-Braun stiffness k_t0 (1 - x)^(1/3) from the last reversal
                          (walton_braun_tangential.h): --mu MU --kt KT and/or --kappa K [--friction-limit]
      mindlin_no_slip     Tsuji no-slip Mindlin spring 8 G* a with dashpot eta_t = R gamma_n:
          --mu MU  --gstar G | --E E --nu NU [--E2 E --nu2 NU]  [--eta-ratio R] (default 1)
          [--slip-reset ...] [--friction-limit ...]
      di_renzo            2/3 of the no-slip stiffness, no dashpot: --mu MU, G* as mindlin_no_slip
      mindlin_deresiewicz loading/unloading/reloading branches (mindlin_deresiewicz.h): --mu MU, G* as
                          mindlin_no_slip [--friction-limit ...]
  --beta0 B               sticking tangential restitution of the rigid-body (Walton) prediction,
                          [-1, 1] (default 1, marked as assumed)
  --psi-kappa K           kappa of psi_1 = kappa v_s0/(mu v_n0), psi_2 = kappa v_s'/(mu v_n0)
                          (default: k_t/k_n of the linear springs and Walton-Braun (k_t0), 4 G*/E* of
                          the Mindlin laws; none for haff_werner)
  --lever-arm radius|contact_point   lever of the tangential force: R, or R - xi/2 as LIGGGHTS
                          (default radius)

Integration and output:
  --steps N               RK4 steps per estimated contact time, 1 ... 1e6 (default 4000;
                          oblique impacts: velocity Verlet steps, default 100000)
  --dt DT                 fixed time step [s] (overrides --steps)
  --curve FILE            write the samples t,xi,xi_dot,F (CSV, one per step) to FILE
                          (oblique: t,xi,xi_dot,F,Ft,vs,sliding)
  --scheme NAME           integrate a sphere-wall impact (--wall, --R1) in whole steps with the
                          scheme NAME as a host engine does (collision/integrate_impact.h): from
                          free flight at z = R1 + GAP, predict - force - correct per step, the
                          contact ends at the first step with overlap <= 0, results read 10
                          free-flight steps later. NAME: one-evaluation schemes
                          euler|symplectic_euler|taylor2|taylor3|leapfrog|position_verlet|
                          velocity_verlet|velocity_verlet_sync|beeman|ab2|ab3|ab4|ab5|abm4|gear4|
                          gear5|gear6|velocity_verlet_ab2, or the harness-only heun|rk4|vv2|
                          abm4_pece. Step: --dt, or
                          --steps N per estimated contact time (default 1000). Any normal law;
                          --tangential as above; lever arm radius only
  --grid-correction on|off
                          with a one-evaluation --scheme: correct the step in which the contact
                          starts and the step in which it ends for where the touch and the end
                          fall between grid points (contact/grid_correction.h; default off)
  --energy on|off         with a one-evaluation --scheme: account the work of each part of the
                          contact force (contact/energy.h): "energy": the energy each part took
                          out of the motion (normal_elastic, normal_damping, tangential, rolling),
                          their total, the kinetic energy lost, and the balance
                          K~ - K~(0) - W, which closes to round-off for the symplectic schemes:
                          velocity_verlet* (K~ = K - h^2/8 (m|a|^2 + I|alpha|^2)), symplectic_euler,
                          leapfrog, position_verlet (K~ = K + h/2 (m a.v + I alpha.w)); the others'
                          residual is their energy error in that sense; default off
  --gap GAP               with --scheme: the start gap [m], >= 0 (default 0: touch at t = 0)
  --phases P              with --scheme: P runs with gap GAP + (i + 1/2)/P v_n0 dt, i = 0..P-1
                          (the contact start phase on the time grid); prints the means and, where
                          the closed form exists (lsd, tangential none or cundall_strack without
                          --gammat), the mean |error| against it
  --analytic              closed-form solution instead of the integrator (collision/analytic.h):
                          a sphere on a wall or two spheres (contact frame fixed: the turning of the
                          line of centres is neglected), --law lsd (any parameter form, either
                          --end) and --tangential none or cundall_strack (with or without --gammat),
                          lever arm radius; not with --curve, --steps or --dt. "method": "analytic";
                          steps = 0, dt and max_tangential_force null
  --help                  this text

Output: JSON on stdout with law, method (integrated|analytic), end, parameters, m_eff, r_eff, v0, e, contact_time,
max_overlap, max_force, residual_overlap, rebound_velocity, dissipated_energy, steps, dt,
contact_time_estimate, ended, curve; oblique impacts add speed, angle, vn0, vt0, vs0, spin, beta,
e_t, spin_after, rebound angles, psi1, psi2, stick/slip switches and rigid_body (docs/tools/tdem-collide.md).
Exit status 0 ok, 1 the contact did not end (e is null) or FILE could not be written, 2 bad input.
)";

}  // namespace
