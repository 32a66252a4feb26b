// coolgas-simulate: event-driven simulation of a freely cooling granular gas.
#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/tool_main.h"
#include "common/interrupt.h"
#include "simulate/run/run_plan.h"
#include "simulate/scene/scene.h"
#include "simulate/run/scene_file.h"
#include "simulate/run/simulation.h"

namespace {

std::string scene_help() {
  std::ostringstream s;
  s << "\nScene keys (TOML tables [system], [collision], [run], [output]; units: particle diameter, particle mass,\n"
       "initial mean collision time (Enskog with the Carnahan-Starling contact value)):\n";
  s << coolgas::scene_keys_help();
  s << "\nExit codes: 0 done, 2 bad input, 3 interrupted by SIGINT/SIGTERM/SIGHUP (checkpoint written: --resume continues "
       "exactly),\n"
       "4 inelastic collapse (set collision.delta > 0), or an aggregate grown to half the box\n"
       "(aggregation: use more particles); in both cases the state is written as the last dump;\n"
       "5 writing the trajectory failed (disk full, quota, file-size limit, I/O error): the line names the\n"
       "file and the cause, every earlier dump is intact, and --resume FILE completes the run once space is freed.\n"
       "The trajectory can be read while it is written (the analysis tools open it as HDF5 SWMR readers).\n";
  return s.str();
}

// --estimate: the plan of the scene's run (simulate/run/run_plan.h).
int print_estimate(const coolgas::SimulationRequest& req) {
  if (req.scene_path.empty() || !req.resume.empty())
    throw coolgas::InputError("--estimate plans a new run: give a scene file, not --resume (see --help)");
  const coolgas::Scene scene = coolgas::parse_scene(coolgas::read_scene_file(req.scene_path), req.scene_path, req.overrides);
  coolgas::watch_interrupts();
  const coolgas::RunPlan plan = coolgas::plan_run(scene, coolgas::interrupt_flag());
  std::cout << coolgas::plan_header() << "\n" << coolgas::plan_line(plan) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-simulate", [&] {
    coolgas::SimulationRequest req;
    CLI::App app{"Event-driven MD of inelastic hard spheres in a periodic box; writes an H5MD trajectory "
                 "(data-schema/h5md-profile.md, installed as share/doc/coolgas/data-schema/h5md-profile.md)."};
    app.add_option("scene", req.scene_path, "scene file (TOML)");
    auto* output = app.add_option("-o,--output", req.output, "output H5MD file (default: the scene's name with .h5)");
    app.add_option("--set", req.overrides, "override a scene key, e.g. --set collision.r0=0.1 (repeatable)");
    app.add_option("--resume", req.resume, "continue FILE from its last dump (appends to FILE)");
    app.add_flag("--force", req.force, "overwrite an existing output file");
    app.add_flag("-q,--quiet", req.quiet, "no progress line on stderr");
    bool estimate = false;
    app.add_flag("--estimate", estimate,
                 "print the run's plan and simulate nothing: particles, memory and time to request (GB, hours: 1.5 "
                 "times the expected), dumps, disk (GB), peak memory (GB), CPU hours and collisions expected, from a "
                 "pilot run of 10^4 particles to t = 100 (a few seconds)");
    app.footer(scene_help());
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    if (output->count() > 0 && req.output.empty()) throw coolgas::InputError("-o needs a file name, got ''");
    if (estimate) return print_estimate(req);
    if (req.scene_path.empty() == req.resume.empty())
      throw coolgas::InputError("give either a scene file or --resume FILE (see --help)");
    return coolgas::run_simulation(req);
  });
}
