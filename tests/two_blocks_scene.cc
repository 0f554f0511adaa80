// The "two blocks" scene (added in one file and one registry line, issue 13):
// its bodies and surfaces in 2-D and 3-D against the exact volumes, areas
// and gap, and in 2-D the narrow upper block pushed down onto the wide lower
// one with mortar contact (the bounds of the load are derived below).
#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/scene.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;
using namespace ContactDynamics;

namespace
{
  template <int dim>
  void
  check_geometry()
  {
    const Scene<dim> scene =
      make_scene<dim>("two blocks", 1, [](ParameterHandler &prm) {
        prm.enter_subsection("Two blocks");
        prm.set("Gap", "0.1");
        prm.leave_subsection();
      });
    const SceneLayout  layout = scene.layout();
    Triangulation<dim> tria;
    scene.create_triangulation(tria);

    const std::string                    label = std::to_string(dim) + "-D: ";
    std::vector<double>                  volume(2, 0.);
    std::map<types::boundary_id, double> area;
    double lowest_upper = 1e9, highest_lower = -1e9;
    for (const auto &cell : tria.active_cell_iterators())
      {
        volume[cell->material_id()] += cell->measure();
        for (const unsigned int v : cell->vertex_indices())
          {
            const double y = cell->vertex(v)[1];
            if (cell->material_id() == 0)
              lowest_upper = std::min(lowest_upper, y);
            else
              highest_lower = std::max(highest_lower, y);
          }
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            area[face->boundary_id()] += face->measure();
      }
    check_true(label + "bodies upper, lower",
               layout.body_names == std::vector<std::string>{"upper", "lower"});
    check_true(label + "surfaces: 2 bodies x " + std::to_string(2 * dim),
               layout.surfaces.size() == 4 * dim);
    check_close(label + "upper volume", volume[0], std::pow(0.5, dim), 1e-12);
    check_close(label + "lower volume", volume[1], 0.5, 1e-12);
    check_close(label + "upper_bottom area",
                area[layout.surface_id("upper_bottom")],
                std::pow(0.5, dim - 1),
                1e-12);
    check_close(label + "lower_top area",
                area[layout.surface_id("lower_top")],
                1.,
                1e-12);
    check_close(label + "gap", lowest_upper - highest_lower, 0.1, 1e-12);
  }

  // The patch test's file with the other scene (its bodies have the same
  // names): the narrower upper block (E = 1e6, nu = 0, 0.5 x 0.5) pushed
  // down by delta = 1e-3 at its top onto the lower one (1 x 0.5). The load
  // lies between that of the upper block on a rigid base, E delta 0.5 / 0.5
  // = 1000, and that of the upper block on a column as narrow as itself,
  // 500; the supports balance it, and frictionless contact carries a
  // horizontal load no larger than the slope of the deformed surface.
  void
  check_pressed_block()
  {
    run_shipped<Simulator<2>>(
      "prm/examples/patch_test.prm",
      {{"Scene/Scene", "two blocks"},
       {"Boundary conditions/Dirichlet",
        "lower_bottom: xy: 0; upper_top: y: -1e-3*t; upper_left: x: 0"},
       {"Output/Output directory", "output_two_blocks"},
       {"Output/VTU interval", "0"}},
      [&](const Simulator<2> &simulator) {
        const auto top    = simulator.reaction_force("upper_top");
        const auto bottom = simulator.reaction_force("lower_bottom");
        const auto side   = simulator.reaction_force("upper_left");
        deallog << "2-D pressed block: load between 500 and 1000: "
                << (-top[1] > 500 && -top[1] < 1000 ? "OK" : "FAILED")
                << std::endl;
        check_close("2-D pressed block: bottom + top reaction / load",
                    (bottom[1] + top[1]) / top[1],
                    0.,
                    1e-9);
        check_close("2-D pressed block: horizontal reactions / load, at "
                    "most the surface slope delta/0.5",
                    (std::abs(bottom[0]) + std::abs(side[0])) / top[1],
                    0.,
                    2e-3);
      });
  }
} // namespace

int
main()
{
  initlog();
  check_geometry<2>();
  check_geometry<3>();
  check_pressed_block();
}
