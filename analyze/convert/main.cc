// coolgas-convert: frames of a trajectory for other programs' readers.
// All logic is in analyze/convert/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/convert/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-convert", [&] {
    coolgas::watch_interrupts();  // its loop over dumps stops at SIGINT/SIGTERM: exit code 3
    coolgas::ConvertOptions o;
    std::string format = "xyz";
    CLI::App app{
        "Frames (dumps) of a coolgas trajectory on stdout, for other programs:\n"
        "  xyz     extended XYZ (ASE, OVITO, VMD): per frame a count line, then Lattice=\"L 0 0 0 L 0 0 0 L\"\n"
        "          Properties=species:S:1:pos:R:3:velo:R:3[:omega:R:3]:id:I:1[:radius:R:1:mass:R:1] pbc=\"T T T\"\n"
        "          Time=t Step=c (omega: a rough run's angular velocities)\n"
        "          and the provenance as key=\"value\" pairs; species X, ids as in the file (0 .. N-1);\n"
        "  lammps  a LAMMPS text dump (read_dump, OVITO, MDAnalysis LAMMPSDUMP): ITEM: TIMESTEP (the dump's\n"
        "          collision count; the format has no time), BOX BOUNDS pp pp pp, ATOMS id type x y z vx vy vz\n"
        "          ix iy iz [omegax omegay omegaz] [radius mass]; ids are the file's + 1 (LAMMPS ids are\n"
        "          positive), type 1.\n"
        "Ballistic-aggregation files give only the aggregates present, with radius = diameter/2 and mass.\n"
        "Units: lengths in particle diameters sigma, velocities in sigma*omega0, times in 1/omega0, masses in\n"
        "particle masses (reduced units: tell readers that convert units not to, e.g. MDAnalysis'\n"
        "convert_units=False). Positions are wrapped into [0, L), written exactly (shortest round-trip form).\n"
        "An XYZ frame can start a new run: coolgas-simulate with system.init = \"file\", system.from = FILE.\n"
        "A 2D file (disks): z = 0 in both formats; xyz writes Lattice=\"L 0 0 0 L 0 0 0 1\" pbc=\"T T F\" (periodic in\n"
        "the plane, as ASE reads a 2D system), lammps the z bounds -0.5 0.5 of a LAMMPS run with `dimension 2`.\n"
        "A 1D file (rods): xyz only, y = z = 0, Lattice=\"L 0 0 0 1 0 0 0 1\" pbc=\"T F F\" (periodic along x);\n"
        "LAMMPS has no 1D mode, so --format lammps is refused for it."};
    app.add_option("trajectory", o.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--format", format, "xyz or lammps")->check(CLI::IsMember({"xyz", "lammps"}))->capture_default_str();
    auto* time = coolgas::add_dump_selection(app, o.times, o.exact_time, "only the dump nearest this time (default: every dump)");
    app.add_flag("--last", o.last, "only the last dump")->excludes(time);
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    o.format = format == "lammps" ? coolgas::ExportFormat::kLammps : coolgas::ExportFormat::kXyz;
    coolgas::run_convert(o, std::cout);
    return 0;
  });
}
