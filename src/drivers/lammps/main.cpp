// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-lammps: a drop-in for the LAMMPS `lmp` executable (same command line) that links the
// installed liblammps and adds the tdem styles (pair tdem/gran, fix tdem/wall/gran) and a
// `plugin` command (plugin load FILE..., plugin list) compatible with the LAMMPS PLUGIN
// package, so one input script runs here and in a PLUGIN-enabled LAMMPS.
//
// Registration. The styles are inserted into force->pair_map / modify->fix_map, which LAMMPS
// rebuilds on `clear` (Input::clear calls LAMMPS::destroy, create, post_create). To survive
// `clear`, this executable interposes LAMMPS::post_create (exported through a linker dynamic
// list; liblammps calls it through its PLT): the real function runs first, then the tdem styles
// and every plugin loaded with `plugin load` are registered again. If interposition is not
// available the styles are still registered once after construction.

#include "command.h"
#include "comm.h"
#include "error.h"
#include "exceptions.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "library.h"
#include "modify.h"
#include "version.h"

#include "lammps_compat.h"
#include "tdem_lammps_styles.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <mpi.h>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

struct LoadedPlugin {
  std::string file;
  void *handle;
  lammpsplugin_initfunc init;
};
std::vector<LoadedPlugin> loaded_plugins;
std::vector<std::string> plugin_styles;  // "pair tdem/gran" ... for `plugin list`
bool post_create_hooked = false;
bool version_warned = false;
bool replaying = false;  // re-registering loaded plugins after `clear`: no log, no warnings

void register_one(lammpsplugin_t *p, void *ptr);

// `plugin` command of tdem-lammps (LAMMPS PLUGIN syntax: load, list; unload/clear unsupported)
class PluginCommand : public Command {
 public:
  PluginCommand(LAMMPS *lmp) : Command(lmp) {}
  void command(int narg, char **arg) override
  {
    if (narg < 1)
      error->all(FLERR, "plugin: missing sub-command; allowed: load FILE..., list");
    const std::string cmd = arg[0];
    if (cmd == "load") {
      if (narg < 2) error->all(FLERR, "plugin load: needs at least one FILE");
      for (int i = 1; i < narg; ++i) load(arg[i]);
    } else if (cmd == "list") {
      if (comm->me == 0) {
        utils::logmesg(lmp, "Currently loaded plugins\n");
        for (size_t i = 0; i < plugin_styles.size(); ++i)
          utils::logmesg(lmp, std::to_string(i + 1) + ": " + plugin_styles[i] + "\n");
      }
    } else {
      error->all(FLERR, "plugin: sub-command '" + cmd +
                            "' is not supported by tdem-lammps; allowed: load FILE..., list");
    }
  }

 private:
  void load(const char *file)
  {
    dlerror();
    void *dso = dlopen(file, RTLD_NOW | RTLD_GLOBAL);
    if (!dso) {
      const char *msg = dlerror();
      error->all(FLERR, std::string("plugin load: cannot open '") + file + "': " + (msg ? msg : ""));
    }
    dlerror();
    void *sym = dlsym(dso, "lammpsplugin_init");
    if (!sym) {
      dlclose(dso);
      error->all(FLERR, std::string("plugin load: '") + file + "' has no lammpsplugin_init()");
    }
    auto init = (lammpsplugin_initfunc) sym;
    loaded_plugins.push_back({file, dso, init});
    (*init)((void *) lmp, dso, (void *) &register_one);
  }
};

Command *plugin_command_creator(LAMMPS *lmp)
{
  return new PluginCommand(lmp);
}

// the registration callback handed to lammpsplugin_init (same contract as LAMMPS PLUGIN)
void register_one(lammpsplugin_t *p, void *ptr)
{
  auto lmp = (LAMMPS *) ptr;
  if (!p) return;
  const std::string style = p->style;
  const bool talk = (lmp->comm->me == 0) && !replaying;
  if (talk) {
    utils::logmesg(lmp, std::string("Loading plugin: ") + p->info + " by " + p->author + "\n");
    if (p->version && strcmp(p->version, lmp->version) != 0)
      utils::logmesg(lmp, std::string("  compiled for LAMMPS version ") + p->version +
                              ", loaded into LAMMPS version " + lmp->version + "\n");
  }
  if (style == "pair") {
    auto map = lmp->force->pair_map;
    if (map->find(p->name) != map->end() && talk)
      lmp->error->warning(FLERR, std::string("Overriding built-in pair style ") + p->name +
                                     " from plugin");
    (*map)[p->name] = (Force::PairCreator) p->creator.v1;
  } else if (style == "fix") {
    auto map = lmp->modify->fix_map;
    if (map->find(p->name) != map->end() && talk)
      lmp->error->warning(FLERR, std::string("Overriding built-in fix style ") + p->name +
                                     " from plugin");
    (*map)[p->name] = (Modify::FixCreator) p->creator.v2;
  } else if (style == "compute") {
    (*lmp->modify->compute_map)[p->name] = (Modify::ComputeCreator) p->creator.v2;
  } else if (style == "command") {
    (*lmp->input->command_map)[p->name] = (Input::CommandCreator) p->creator.v1;
  } else {
    if (talk)
      utils::logmesg(lmp, "tdem-lammps: loading plugins for " + style +
                              " styles is not implemented; ignored " + p->name + "\n");
    return;
  }
  const std::string entry = style + " style plugin " + p->name;
  bool known = false;
  for (const auto &s : plugin_styles) known = known || (s == entry);
  if (!known) plugin_styles.push_back(entry);
}

// everything tdem-lammps adds to a (re)created LAMMPS instance
void add_tdem(LAMMPS *lmp)
{
  tdem_lammps::register_styles(lmp);
  if (lmp->input && lmp->input->command_map &&
      lmp->input->command_map->find("plugin") == lmp->input->command_map->end())
    (*lmp->input->command_map)["plugin"] = &plugin_command_creator;
  // plugins loaded before a `clear` are registered again (quietly through the same callback)
  replaying = true;
  for (const auto &p : loaded_plugins) (*p.init)((void *) lmp, p.handle, (void *) &register_one);
  replaying = false;

  if (!version_warned && strcmp(lmp->version, tdem_lammps::compiled_lammps_version()) != 0) {
    version_warned = true;
    if (lmp->comm && lmp->comm->me == 0)
      lmp->error->warning(FLERR, std::string("tdem-lammps was compiled against LAMMPS ") +
                                     tdem_lammps::compiled_lammps_version() +
                                     " but runs with LAMMPS " + lmp->version);
  }
}

}  // namespace

// ------------------------------------------------------------------ post_create interposer
namespace LAMMPS_NS {
void LAMMPS::post_create()
{
  using real_fn = void (*)(LAMMPS *);
  static real_fn real = (real_fn) dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS6LAMMPS11post_createEv");
  if (!real) {
    fprintf(stderr, "tdem-lammps: cannot find LAMMPS::post_create in liblammps: %s\n", dlerror());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  real(this);
  post_create_hooked = true;
  add_tdem(this);
}
}  // namespace LAMMPS_NS

// ------------------------------------------------------------------ main, as LAMMPS main.cpp
namespace {
void finalize_libraries()
{
  lammps_kokkos_finalize();
  lammps_python_finalize();
}
}  // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  MPI_Comm lammps_comm = MPI_COMM_WORLD;
  // -h / -help: LAMMPS prints its compiled style lists and exits inside the constructor; tdem's
  // styles follow them (an exit handler, rank 0)
  int me = 0;
  MPI_Comm_rank(lammps_comm, &me);
  for (int i = 1; i < argc && me == 0; i++)
    if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "-help") == 0) {
      atexit([] { fputs(tdem_lammps::style_listing().c_str(), stdout); });
      break;
    }

  // An ERROR throws LAMMPSException where liblammps was built with exceptions (always since
  // LAMMPS 2023); where it was not, Error::all ends the run itself and nothing is thrown.
  try {
    LAMMPS *lammps = new LAMMPS(argc, argv, lammps_comm);
    if (!post_create_hooked) add_tdem(lammps);  // interposition not active
    lammps->input->file();
    delete lammps;
  } catch (LAMMPSAbortException &ae) {
    finalize_libraries();
    MPI_Abort(tdem_lammps::compat::abort_universe(ae), 1);
  } catch (LAMMPSException &) {
    finalize_libraries();
    MPI_Barrier(lammps_comm);
    MPI_Finalize();
    exit(1);
  } catch (fmt::format_error &fe) {
    fprintf(stderr, "fmt::format_error: %s\n", fe.what());
    finalize_libraries();
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
  } catch (std::exception &e) {
    fprintf(stderr, "Exception: %s\n", e.what());
    finalize_libraries();
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
  }
  finalize_libraries();
  MPI_Barrier(lammps_comm);
  MPI_Finalize();
  return 0;
}
