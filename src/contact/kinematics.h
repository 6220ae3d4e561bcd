// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: plain data that flows between a host adapter and the force laws.
//
// Conventions (written down once, used everywhere):
//  * overlap xi > 0 while in contact; overlap_rate = d(xi)/dt > 0 while approaching.
//  * meff is the effective mass of the pair, 1/m* = 1/m_i + 1/m_j; a wall or a frozen
//    partner has infinite mass, so m* is the mass of the moving sphere. Adapters compute it
//    (and may pass a body or local mass for clumps); laws never look it up themselves.
//  * reff is the effective radius, 1/R* = 1/R_i + 1/R_j (a plane wall has R_j -> infinity).
#pragma once

// Force kernels run billions of times inside the hosts' contact loops: make sure they are
// inlined into the adapter even when the compiler's size heuristics would say no.
#if defined(__GNUC__) || defined(__clang__)
#define TDEM_KERNEL inline __attribute__((always_inline))
#else
#define TDEM_KERNEL inline
#endif

namespace tdem {

template <class T>
struct NormalKinematics {
  T overlap;       // xi [m]
  T overlap_rate;  // d xi / dt [m/s], > 0 approaching
  T meff;          // m* [kg]
  T reff;          // R* [m]
};

// What a normal law hands to the tangential law and to the adapter.
template <class T>
struct NormalResult {
  T force;      // normal force on particle i along the normal pointing from j to i, > 0 repulsive
  T elastic;    // conservative part of the force before any clipping
  T stiffness;  // k used (tangent stiffness dF/dxi for non-linear laws)
  T damping;    // gamma used [kg/s]
};

// One named per-contact history value. `flips_sign` says whether the value changes sign
// when the pair is seen from the other particle (vectors in the contact plane do, scalars
// such as a maximum overlap do not). Adapters map the slots onto the host storage
// (LIGGGHTS contact history, LAMMPS FixNeighHistory / wall history).
struct HistorySlot {
  const char* name;
  bool flips_sign;
};

// How a contact ends: where the overlap returns to zero, or where the force does (the force
// is clipped at zero; the contact may end with an overlap left).
enum class ContactEnd { zero_overlap, zero_force };

inline const char* to_string(ContactEnd e) {
  return e == ContactEnd::zero_overlap ? "zero_overlap" : "zero_force";
}

}  // namespace tdem
