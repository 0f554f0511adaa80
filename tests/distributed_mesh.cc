// Parallel/Mesh = distributed (p4est): on three processes, each keeping the
// scene's mesh as its coarse mesh and only its own refined cells and their
// ghosts, with the contact surfaces gathered as surface data, the runs give
// the statistics of the same run on one process (computed here on the first
// process) to solver tolerance: energies, contact forces and work, active,
// stick and slip node counts at every step. The cases have the secondary
// surface split between processes (the patch test with friction, 9 / 6 / 0
// nodes) and processes that own no contact node (the bar, the ironing: the
// weighted partition gives one process all contact cells); the ironing
// runs at refinement factor 0.5 with one global refinement (the mesh of
// factor 1) and the condensed multipliers with AMG.
#include "parallel_compare.h"

int
main()
{
  initlog();
  check_true("three processes",
             dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 3);
  const Changes distributed{{"Parallel/Mesh", "distributed"}};
  Changes       patch = distributed;
  patch.insert(patch.end(),
               {{"Contact/Friction coefficients", "0.3"},
                {"Parallel/Global refinements", "1"},
                {"Boundary conditions/Dirichlet",
                 "lower_bottom: xy: 0; upper_top: y: -1e-3*min(10*t, 1); "
                 "upper_top: x: 0.05*t"},
                {"Time integration/Time step", "0.1"}});
  compare("patch_test_friction_distributed",
          "prm/examples/patch_test.prm",
          patch);
  compare("bar_impact_distributed", "prm/examples/bar_impact.prm", distributed);
  Changes ironing = distributed;
  ironing.insert(ironing.end(),
                 {{"Scene/Refinement factor", "0.5"},
                  {"Parallel/Global refinements", "1"},
                  {"Time integration/End time", "0.05"},
                  {"Nonlinear solver/Linear solver", "AMG"}});
  compare("ironing_distributed_amg", "prm/ironing/mortar.prm", ironing, 1e-6);
}
