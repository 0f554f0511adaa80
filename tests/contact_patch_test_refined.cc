// The contact patch test (as contact_patch_test: two stacked blocks with
// non-matching meshes, nu = 0, the upper one pressed down by delta = 1e-3,
// exact pressure E delta = 1000 everywhere) on adapted meshes: after the
// load step, in contact, the lower block is refined twice along the left
// half of the contact surface and the upper block once along its right
// part, so both surfaces are graded with hanging nodes next to them (in
// 2-D a hanging node is never on a surface); the state, the multipliers
// and the contact history move to the new mesh and a second step holds
// the load. Dual mortar must reproduce the uniform pressure to 1e-8 at
// every secondary node, with force balance between the contact, the top
// and the bottom (1e-9); node-to-segment is recorded (its one-pass
// error), as in contact_patch_test. On two processes (.mpirun=2) the same.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "patch_test_checks.h"
#include "tests.h"

using namespace dealii;

namespace
{
  double
  run(const std::string &formulation)
  {
    ParameterHandler prm;
    read_test_parameters("patch.prm",
                         patch_test_parameters(formulation,
                                               "-1e-3*min(t, 1)",
                                               "2",
                                               R"(subsection Parallel
  set Mesh = distributed
end
)"),
                         prm);
    std::ostringstream            screen;
    ContactDynamics::Simulator<2> simulator(prm, screen);
    simulator.initialize();
    // a step, halved until it converges (as run() does)
    const auto advance_to = [&](const double end) {
      double dt = end - simulator.current_time();
      while (simulator.current_time() < end - 1e-12)
        if (!simulator.advance(std::min(dt, end - simulator.current_time())))
          dt /= 2;
    };
    advance_to(1);
    // cells at the interface y = 0.5: of the lower block (material 1) left
    // of x = 0.5, twice; of the upper block right of x = 0.4, once
    auto &tria = simulator.get_triangulation();
    for (unsigned int round = 0; round < 2; ++round)
      {
        for (const auto &cell : tria.active_cell_iterators())
          {
            bool at_interface = false;
            for (const unsigned int v : cell->vertex_indices())
              at_interface =
                at_interface || std::abs(cell->vertex(v)[1] - 0.5) < 1e-12;
            const bool lower = cell->material_id() == 1;
            if (cell->is_locally_owned() && at_interface &&
                (lower ? cell->center()[0] < 0.5 :
                         round == 0 && cell->center()[0] > 0.4))
              cell->set_refine_flag();
          }
        check_true(formulation + ": refined", simulator.refine_and_transfer());
      }
    unsigned int hanging = 0;
    for (const auto &line : simulator.get_constraints().get_lines())
      hanging += !line.entries.empty();
    check_true(formulation + ": hanging nodes",
               Utilities::MPI::sum(hanging, MPI_COMM_WORLD) > 0);
    advance_to(2);

    return check_patch_test(formulation, simulator);
  }
} // namespace

int
main()
{
  initlog();
  report_patch_tests(run);
}
