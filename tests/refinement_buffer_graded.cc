// The refinement rule on a graded mesh: one row of cells 0.1 high, four
// 0.1 wide and then 0.2, 0.4, 0.8 and 1.6 wide, the contact point at
// (0.05, 0.08) in the first cell, one level, Buffer cells = 2. The buffer
// is counted in the diameters of the contact zone's cells (doc/refinement.md),
// computed here by hand from the cell centres and radii:
// - initial mesh: the zone cell has diameter 0.1414, so the unit of every
//   level-0 cell is 0.1414 and a cell is refined if its distance (centre
//   distance minus radius) is below 0.283. The 0.1-wide cells are at 0,
//   0.034, 0.132, 0.231; the 0.2-wide cell at 0.339 and the wider ones at
//   0.544, 0.947, 1.749: exactly the four small cells are refined. (By
//   their own diameters, the old rule, all eight would be.)
// - after one global refinement: the unit is 0.0707 and a level-1 cell is
//   coarsened if farther than (2 + 1) * 2 * 0.0707 = 0.424. The children
//   of the small cells are within 0.33; of the 0.2-wide cell's children
//   the two at x = 0.55 are at 0.444 and 0.447, the two at x = 0.45 at
//   0.344 and 0.348; the wider cells' 12 children are farther: 14 coarsen
//   flags, no refine flags. (By their own diameters none would be.)
#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/mesh/contact_refinement.h>

#include "tests.h"

using namespace dealii;

int
main()
{
  initlog();
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(
    tria,
    {{0.1, 0.1, 0.1, 0.1, 0.2, 0.4, 0.8, 1.6}, {0.1}},
    Point<2>(0, 0),
    Point<2>(3.4, 0.1));
  DoFHandler<2> dof_handler(tria);
  FESystem<2>   fe(FE_Q<2>(1), 2);

  ContactDynamics::RefinementParameters parameters;
  parameters.maximum_levels = 1;
  parameters.buffer_cells   = 2;
  const std::vector<Point<2>> contact{Point<2>(0.05, 0.08)};

  const auto mark = [&]() {
    dof_handler.distribute_dofs(fe);
    ContactDynamics::VectorType u(dof_handler.locally_owned_dofs(),
                                  MPI_COMM_WORLD);
    const unsigned int          dropped =
      ContactDynamics::mark_cells_near_contact(dof_handler,
                                               u,
                                               contact,
                                               parameters,
                                               0);
    check_true("no refinement dropped", dropped == 0);
  };

  mark();
  unsigned int refined = 0, wrong = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      const bool refine = cell->refine_flag_set();
      refined += refine;
      wrong += refine != (cell->center()[0] < 0.4) || cell->coarsen_flag_set();
    }
  check_close("initial mesh: refined cells", refined, 4, 0);
  check_true("initial mesh: exactly those with x < 0.4", wrong == 0);

  tria.refine_global(1);
  mark();
  unsigned int coarsened = 0;
  wrong                  = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      const double x = cell->center()[0];
      coarsened += cell->coarsen_flag_set();
      wrong +=
        cell->coarsen_flag_set() != (x > 0.5) || bool(cell->refine_flag_set());
    }
  check_close("refined mesh: coarsened cells", coarsened, 14, 0);
  check_true("refined mesh: exactly those with x > 0.5", wrong == 0);
}
