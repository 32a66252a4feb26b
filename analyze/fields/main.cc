// coolgas-fields: coarse-grained fields of a trajectory. All logic is in
// analyze/fields/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/fields/tool.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-fields", [&] {
    coolgas::watch_interrupts();  // its loop over dumps stops at SIGINT/SIGTERM: exit code 3
    coolgas::FieldsOptions opt;
    CLI::App app{
        "Coarse-grained fields of a coolgas trajectory: density, flow velocity and granular temperature on\n"
        "a periodic grid, the flow's energy against the thermal one, and the flow split by FFT into its\n"
        "longitudinal and transverse (vortical, shear) parts. The box is cut into n^d cells (the even n nearest\n"
        "below L/--cell); each particle counts in the cell holding its centre (no further smoothing), with its\n"
        "velocity relative to the centre of mass. Energies are per unit mass (per particle for unit masses;\n"
        "aggregates weighted by their masses).\n\n"
        "Output (TSV on stdout), one row per dump:\n"
        "  t [1/omega0]; cells [1] per side; E = sum m v^2/2M; E_flow = sum_c |p_c|^2/(2 M_c M), the cells' mean\n"
        "  motion; E_thermal = E - E_flow; T = 2 E_thermal M/(d (N - occupied cells)) [m sigma^2 omega0^2];\n"
        "  E_flow_noise = (d/2) T (occupied - 1)/M, E_flow for independent velocities;\n"
        "  E_L, E_T: the momentum field j_c of uniform density M/cells split as j_L(k) = (k.j) k/k^2, j_T = j - j_L,\n"
        "  E_L = sum_{k != 0} |j_L(k)|^2/(2 M^2) (Brito & Ernst 1998); E_L_noise, E_T_noise their values for\n"
        "  independent velocities at T (E_T_noise = (d - 1) E_L_noise; 1D has no transverse part);\n"
        "  density_var [1] = Var(n_c)/<n_c> over the cells (1 for independent positions);\n"
        "  vorticity2 [omega0^2] mean |curl u|^2 over the cells, u = j cells/M.\n"
        "With --spectrum, one block per dump: t; shell [2 pi/L] (|k| L/2pi rounded); k [1/sigma] mean |k|;\n"
        "  E_L, E_T the shell's share of the energies; modes [1] (k and -k apart).\n"
        "With --slab, one block per dump: t; x, y [sigma] cell centres of the middle plane of cells (2D: the plane);\n"
        "  density [sigma^-d]; vorticity [omega0] its component normal to the plane (central differences).\n"
        "With --vti DIR, also DIR/fields_<dump>.vti per dump (VTK ImageData: density, velocity, temperature,\n"
        "  vorticity per cell; opens in ParaView and VisIt)."};
    app.add_option("trajectory", opt.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--cell", opt.cell, "cell side wanted [sigma], >= 1; the grid takes the even n nearest below L/cell")
        ->capture_default_str();
    app.add_flag("--spectrum", opt.spectrum, "blocks of E_L(k) and E_T(k) per dump instead of one row per dump");
    app.add_flag("--slab", opt.slab, "blocks of the middle plane's cells (density, vorticity) per dump, for pictures");
    app.add_option("--vti", opt.vti, "directory (existing) for one VTK ImageData file per dump");
    coolgas::add_dump_selection(app, opt.times, opt.exact_time, "analyse only the dump nearest this time");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    coolgas::run_fields(opt, std::cout);
    return 0;
  });
}
