// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the one place where the LAMMPS versions differ (29Sep2021/20220106 of
// Debian 12, 4Feb2025 of Debian 13, 4Jul2026 and the releases in between).
//
// Every difference is a feature macro, set by a compile check against the LAMMPS headers at
// configure time (src/pair_styles/lammps/LammpsFeatures.cmake, which writes them into the
// generated header tdem_lammps_features.h; tools/lammps_dropin.sh writes the same header into a
// LAMMPS source tree), never by a version number:
//
//   TDEM_LMP_ADD_REQUEST          neighbor->add_request(requestor, flags)       (else request())
//   TDEM_LMP_COMM_OVERLOADS       comm->forward_comm(Pair *)                    (else forward_comm_pair)
//   TDEM_LMP_GET_FIX_BY_STYLE     modify->get_fix_by_style() returns a vector   (else find_fix_by_style)
//   TDEM_LMP_GET_REGION_BY_ID     domain->get_region_by_id()                    (else find_region + regions[])
//   TDEM_LMP_MINIMUM_IMAGE_FLERR  domain->minimum_image(FLERR, dx, dy, dz)      (else without FLERR)
//   TDEM_LMP_HISTORY_TYPES        Pair::transfer_history(src, dst, itype, jtype) (else (src, dst))
//   TDEM_LMP_SIZE_CUT             Pair::atom2cut / radii2cut exist              (removed in 2026)
//   TDEM_LMP_ABORT_GET_UNIVERSE   LAMMPSAbortException::get_universe()          (else .universe)
//   TDEM_LMP_HISTORY_TAG_BITS     FixNeighHistory writes partner IDs into restart files as the
//   TDEM_LMP_HISTORY_TAG_VALUE    bits of an integer (since 2023) / as a double's value (2022);
//                                 from the text of fix_neigh_history.cpp; neither: unknown
//
// The styles call the functions below and use the two declaration macros; they contain no
// version test of their own.
#pragma once

#include "tdem_lammps_features.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "exceptions.h"
#include "fix.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "region.h"
#include "utils.h"

#include <string>
#include <vector>

// Pair::transfer_history: the parameter list of the override (LAMMPS 2023 added the types)
#if defined(TDEM_LMP_HISTORY_TYPES)
#define TDEM_LMP_TRANSFER_HISTORY_PARAMS(source, target) double *source, double *target, int, int
#else
#define TDEM_LMP_TRANSFER_HISTORY_PARAMS(source, target) double *source, double *target
#endif

// Pair::atom2cut / radii2cut (the cutoff of a finite-size pair for neighbor multi lists): the
// overrides where the base class still has them; LAMMPS 2026 derives them from finitecutflag
#if defined(TDEM_LMP_SIZE_CUT)
#define TDEM_LMP_SIZE_CUT_OVERRIDES                                                      \
  double atom2cut(int i) override { return atom->radius[i] * 2.0; }                       \
  double radii2cut(double r1, double r2) override { return r1 + r2; }
#else
#define TDEM_LMP_SIZE_CUT_OVERRIDES
#endif

namespace tdem_lammps {
namespace compat {

// How this LAMMPS's FixNeighHistory stores the partner IDs in restart files.
enum class HistoryTags { value = 0, bits = 1, unknown = -1 };
inline constexpr HistoryTags history_tags()
{
#if defined(TDEM_LMP_HISTORY_TAG_BITS)
  return HistoryTags::bits;
#elif defined(TDEM_LMP_HISTORY_TAG_VALUE)
  return HistoryTags::value;
#else
  return HistoryTags::unknown;
#endif
}

// The per-atom restart data of fix (id, style) that read_restart left in atom->extra, before
// the fix is created: rewrite the partner IDs of a FixNeighHistory block (size, npartner, then
// per partner the ID and dnum values) from the encoding `from` into `to`. Returns the number of
// IDs rewritten (0 when the file holds no such fix). Modify's restart lists are protected; they
// are reached through pointers to members of a derived class.
struct ModifyRestartLists : public LAMMPS_NS::Modify {
  static int peratom_index(LAMMPS_NS::Modify *m, const std::string &id, const std::string &style)
  {
    char **LAMMPS_NS::Modify::*ids = &ModifyRestartLists::id_restart_peratom;
    char **LAMMPS_NS::Modify::*styles = &ModifyRestartLists::style_restart_peratom;
    int *LAMMPS_NS::Modify::*index = &ModifyRestartLists::index_restart_peratom;
    for (int i = 0; i < m->nfix_restart_peratom; i++)
      if (id == (m->*ids)[i] && style == (m->*styles)[i]) return (m->*index)[i];
    return -1;
  }
};

inline long convert_history_restart_tags(LAMMPS_NS::Modify *modify, LAMMPS_NS::Atom *atom,
                                         const std::string &id, const std::string &style, int dnum,
                                         HistoryTags from, HistoryTags to)
{
  using LAMMPS_NS::tagint;
  if (from == to) return 0;
  const int nth = ModifyRestartLists::peratom_index(modify, id, style);
  if (nth < 0 || !atom->extra) return 0;
  long n = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    double *x = atom->extra[i];
    int m = 0;
    for (int k = 0; k < nth; k++) m += static_cast<int>(x[m]);
    m++;  // the size of this block
    const int npartner = static_cast<int>(x[m++]);
    for (int p = 0; p < npartner; p++, m += dnum) {
      tagint tag;
      if (from == HistoryTags::value) tag = static_cast<tagint>(x[m]);
      else tag = LAMMPS_NS::ubuf(x[m]).i;
      x[m++] = (to == HistoryTags::value) ? static_cast<double>(tag) : LAMMPS_NS::ubuf(tag).d;
      n++;
    }
  }
  return n;
}

// a size neighbour list (with history when `history`) for a pair style
inline void request_size_list(LAMMPS_NS::Neighbor *neighbor, LAMMPS_NS::Pair *pair, int instance_me,
                              bool history)
{
#if defined(TDEM_LMP_ADD_REQUEST)
  (void) instance_me;
  neighbor->add_request(pair, LAMMPS_NS::NeighConst::REQ_SIZE |
                                  (history ? LAMMPS_NS::NeighConst::REQ_HISTORY : 0));
#else
  const int irequest = neighbor->request(pair, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = history ? 1 : 0;
#endif
}

// forward communication of a pair style's per-atom data (pack/unpack_forward_comm)
inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Pair *pair)
{
#if defined(TDEM_LMP_COMM_OVERLOADS)
  comm->forward_comm(pair);
#else
  comm->forward_comm_pair(pair);
#endif
}

// forward communication of a fix's per-atom data (pack/unpack_forward_comm), size values per atom
// at most (0: the fix's comm_forward)
inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix, int size = 0)
{
#if defined(TDEM_LMP_COMM_OVERLOADS)
  comm->forward_comm(fix, size);
#else
  comm->forward_comm_fix(fix, size);
#endif
}

// reverse communication of a fix's per-atom data of the ghost atoms to their owners
// (pack/unpack_reverse_comm), size values per atom at most (0: the fix's comm_reverse)
inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix, int size = 0)
{
#if defined(TDEM_LMP_COMM_OVERLOADS)
  comm->reverse_comm(fix, size);
#else
  comm->reverse_comm_fix(fix, size);
#endif
}

// the same for a compute's per-atom data
inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Compute *compute, int size = 0)
{
#if defined(TDEM_LMP_COMM_OVERLOADS)
  comm->reverse_comm(compute, size);
#else
  static_cast<void>(size);
  comm->reverse_comm_compute(compute);
#endif
}

// every fix whose style matches the regular expression `style` (utils::strmatch), in fix order
inline std::vector<LAMMPS_NS::Fix *> fixes_by_style(LAMMPS_NS::Modify *modify, const std::string &style)
{
#if defined(TDEM_LMP_GET_FIX_BY_STYLE)
  return modify->get_fix_by_style(style);
#else
  std::vector<LAMMPS_NS::Fix *> out;
  for (int i = 0; i < modify->nfix; i++)
    if (LAMMPS_NS::utils::strmatch(modify->fix[i]->style, style)) out.push_back(modify->fix[i]);
  return out;
#endif
}

// the first fix of that style, or nullptr
inline LAMMPS_NS::Fix *first_fix_by_style(LAMMPS_NS::Modify *modify, const std::string &style)
{
  const auto all = fixes_by_style(modify, style);
  return all.empty() ? nullptr : all.front();
}

// the region with this ID, or nullptr
inline LAMMPS_NS::Region *region_by_id(LAMMPS_NS::Domain *domain, const std::string &id)
{
#if defined(TDEM_LMP_GET_REGION_BY_ID)
  return domain->get_region_by_id(id);
#else
  const int i = domain->find_region(id);
  return i < 0 ? nullptr : domain->regions[i];
#endif
}

// the minimum-image convention applied to a distance vector
inline void minimum_image(LAMMPS_NS::Domain *domain, double &dx, double &dy, double &dz)
{
#if defined(TDEM_LMP_MINIMUM_IMAGE_FLERR)
  domain->minimum_image(FLERR, dx, dy, dz);
#else
  domain->minimum_image(dx, dy, dz);
#endif
}

// the communicator an abort exception names
inline MPI_Comm abort_universe(const LAMMPS_NS::LAMMPSAbortException &e)
{
#if defined(TDEM_LMP_ABORT_GET_UNIVERSE)
  return e.get_universe();
#else
  return e.universe;
#endif
}

}  // namespace compat
}  // namespace tdem_lammps
