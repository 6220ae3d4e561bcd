// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: what pair tdem/gran, fix tdem/wall/gran and fix tdem/grate share of the host.
//
// SphereArrays: the per-atom arrays of finite-size spheres, taken in one line with their usual
// names: const auto [x, v, f, omega, torque, radius, rmass, mask, nlocal] = sphere_arrays(atom);
//
// setup_post_force: a post_force fix's setup() under verlet or rRESPA (outermost level).
//
// add_wall_force: a sphere-wall contact's force and torque on the sphere (wall/gran, grate).
//
// RigidMasses: the effective mass of a sphere that belongs to a rigid body (fix rigid, fix
// rigid/small, fix tdem/clump: any fix with rigid_flag) is the body's mass, as in the LAMMPS
// granular styles. One helper for pair tdem/gran, fix tdem/wall/gran and fix tdem/grate.
#pragma once

#include "atom.h"
#include "fix.h"
#include "memory.h"
#include "modify.h"
#include "respa.h"
#include "update.h"
#include "utils.h"

namespace tdem_lammps {

struct SphereArrays {
  double **x, **v, **f, **omega, **torque;
  double *radius, *rmass;
  int *mask;
  int nlocal;
};
inline SphereArrays sphere_arrays(LAMMPS_NS::Atom *atom)
{
  return {atom->x, atom->v, atom->f, atom->omega, atom->torque, atom->radius, atom->rmass, atom->mask, atom->nlocal};
}

// The contact of sphere i with a wall: normal force ccel * d (d from the wall to the centre),
// tangential force fs at the contact point a distance rad from the centre (rinv = 1/|d|); added
// to fi and ti; the force is returned in fw (the wall receives -fw).
__attribute__((always_inline)) inline void add_wall_force(double *fi, double *ti, double dx, double dy, double dz,
                                                          double ccel, const double *fs, double rinv, double rad,
                                                          double *fw)
{
  fw[0] = dx * ccel + fs[0];
  fw[1] = dy * ccel + fs[1];
  fw[2] = dz * ccel + fs[2];
  fi[0] += fw[0];
  fi[1] += fw[1];
  fi[2] += fw[2];
  ti[0] -= rad * (rinv * (dy * fs[2] - dz * fs[1]));
  ti[1] -= rad * (rinv * (dz * fs[0] - dx * fs[2]));
  ti[2] -= rad * (rinv * (dx * fs[1] - dy * fs[0]));
}

template <class FixT>
void setup_post_force(FixT *fix, LAMMPS_NS::Update *update, int vflag, int nlevels_respa)
{
  if (LAMMPS_NS::utils::strmatch(update->integrate_style, "^verlet")) {
    fix->post_force(vflag);
    return;
  }
  auto *respa = (LAMMPS_NS::Respa *) update->integrate;
  respa->copy_flevel_f(nlevels_respa - 1);
  fix->post_force_respa(vflag, nlevels_respa - 1, 0);
  respa->copy_f_flevel(nlevels_respa - 1);
}

struct RigidMasses {
  LAMMPS_NS::Fix *fix = nullptr;  // the first fix with rigid_flag, or none
  double *mass = nullptr;         // per atom: the mass of its body, 0 for a free atom
  int nmax = 0;                   // atoms allocated

  // at init
  void find(LAMMPS_NS::Modify *modify) {
    fix = nullptr;
    for (int i = 0; i < modify->nfix; i++)
      if (modify->fix[i]->rigid_flag) {
        fix = modify->fix[i];
        return;
      }
  }
  // the body masses of the owned atoms (after a re-neighbouring; ghosts: the pair communicates)
  void refresh(LAMMPS_NS::Atom *atom, LAMMPS_NS::Memory *memory, const char *name) {
    if (!fix) return;
    int tmp;
    const int *body = (const int *) fix->extract("body", tmp);
    const double *mass_body = (const double *) fix->extract("masstotal", tmp);
    if (atom->nmax > nmax) {
      memory->destroy(mass);
      nmax = atom->nmax;
      memory->create(mass, nmax, name);
    }
    for (int i = 0; i < atom->nlocal; i++) mass[i] = (body && mass_body && body[i] >= 0) ? mass_body[body[i]] : 0.0;
  }
  void destroy(LAMMPS_NS::Memory *memory) { memory->destroy(mass); }
  // the mass that counts for atom i of mass m
  double of(int i, double m) const { return fix && mass && mass[i] > 0.0 ? mass[i] : m; }
  double memory_usage() const { return (double) nmax * sizeof(double); }
};

}  // namespace tdem_lammps
