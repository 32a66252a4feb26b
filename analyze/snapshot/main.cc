// coolgas-snapshot: picture of a trajectory's particles coloured by cluster.
// All logic is in analyze/snapshot/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/snapshot/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-snapshot", [&] {
    // A 1D file's dumps are read one by one and gnuplot runs for seconds: a
    // signal stops it there (exit code 3) and its temporary folder is removed.
    coolgas::watch_interrupts();
    coolgas::SnapshotToolOptions o;
    CLI::App app{
        "Picture (PNG, PDF or SVG by the extension of -o, drawn by gnuplot) of the particles of a coolgas trajectory at the dump\n"
        "nearest --time, coloured by cluster as in Pathak et al. (2014), Fig. 3: the --colored largest clusters in\n"
        "distinct colours (largest first: blue, red, green, orange, ...), all other particles grey. Clusters are\n"
        "those of coolgas-clusters (floor(L)^3 cells, face neighbours, periodic); in a ballistic-aggregation file\n"
        "they are the aggregates, drawn at their true diameter m^(1/3) and ranked by mass. A key beside the picture\n"
        "gives each coloured cluster's mass. Lengths in particle diameters\n"
        "sigma, times in 1/omega0.\n"
        "Views: slab (default): particles with |z - L/2| < thickness/2 (aggregates of diameter d: < (thickness + d - 1)/2),\n"
        "seen along z, drawn at their true size;\n"
        "3d: all particles in perspective, at most --max-points of them (every k-th particle).\n"
        "A 2D file (disks) is drawn whole in its square, every disk at its true size, clusters from unit\n"
        "squares (coolgas-clusters); --view and --thickness are refused for it.\n"
        "A 1D file (rods on a ring) is drawn as a space-time diagram: x across, one row per dump up the picture\n"
        "from the first dump to the one nearest --time (rows labelled by their times), each rod at its true length\n"
        "coloured by its velocity over the dump's v_rms (blue -2 .. grey 0 .. red +2); --view, --thickness,\n"
        "--colored and --max-points are refused for it, and the table has one row per dump: t [1/omega0],\n"
        "particles [rods or aggregates drawn], v_rms [sigma omega0] (mass-weighted for aggregates).\n"
        "Table on stdout, one row per coloured cluster: rank (1 = largest), mass [particles],\n"
        "fraction = mass/N, shown [particles drawn], rgb (colour as the integer 0xRRGGBB)."};
    app.add_option("trajectory", o.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    coolgas::add_dump_selection(app, o.times, o.exact_time, "draw the dump nearest this time (one time)")->required();
    app.add_option("-o,--output", o.output, "picture to write: .png, .pdf or .svg")->required();
    app.add_flag("--force", o.force, "replace the picture if it exists");
    std::string view = "slab";
    auto* view_opt =
        app.add_option("--view", view, "slab or 3d (3D files)")->check(CLI::IsMember({"slab", "3d"}))->capture_default_str();
    auto* thickness_opt = app.add_option("--thickness", o.scene.thickness, "slab thickness [sigma]")->capture_default_str();
    auto* colored_opt = app.add_option("--colored", o.scene.colored, "number of largest clusters drawn in colour (0-9)")
                            ->capture_default_str();
    auto* max_points_opt =
        app.add_option("--max-points", o.scene.max_points, "3d view: most particles drawn")->capture_default_str();
    app.add_option("--size", o.size_px, "picture height [pixels; PDF: 72 to the inch]; the width adds 30 % for the key")->capture_default_str();
    app.add_option("--gnuplot", o.gnuplot, "gnuplot program to run")->capture_default_str();
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    o.scene.view = view == "3d" ? coolgas::SnapshotView::k3d : coolgas::SnapshotView::kSlab;
    if (view_opt->count() > 0) o.only_3d = "--view " + view;
    else if (thickness_opt->count() > 0) o.only_3d = "--thickness " + thickness_opt->as<std::string>();
    if (colored_opt->count() > 0) o.not_1d = "--colored " + colored_opt->as<std::string>();
    else if (max_points_opt->count() > 0) o.not_1d = "--max-points " + max_points_opt->as<std::string>();
    coolgas::run_snapshot(o, std::cout);
    return 0;
  });
}
