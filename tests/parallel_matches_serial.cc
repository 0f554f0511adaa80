// The shipped scenes on two MPI processes give the statistics of the same
// run on one process (the reference, computed here on the first process),
// to solver tolerance: energies, contact forces and work, active, stick and
// slip node counts, at every step. The patch test runs with its contact
// surface split between the processes.
#include "parallel_compare.h"


int
main()
{
  initlog();
  check_true("two processes",
             dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2);

  // contact surface split 5 / 3 by METIS
  compare("patch_test_mortar", "prm/examples/patch_test.prm", {});
  compare("patch_test_nts",
          "prm/examples/patch_test.prm",
          {{"Contact/Formulation", "nts"}});
  // pressed, then sliding with Coulomb friction (all nodes slip)
  for (const std::string formulation : {"mortar", "nts"})
    compare("patch_test_friction_" + formulation,
            "prm/examples/patch_test.prm",
            {{"Contact/Formulation", formulation},
             {"Contact/Friction coefficients", "0.3"},
             {"Boundary conditions/Dirichlet",
              "lower_bottom: xy: 0; upper_top: y: -1e-3*min(10*t, 1); "
              "upper_top: x: 0.05*t"},
             {"Time integration/Time step", "0.1"}});
  // (the upper block held in x too: free, it makes the frictionless
  // quasi-static Jacobian singular, which MUMPS did not survive)
  compare("patch_test_mumps",
          "prm/examples/patch_test.prm",
          {{"Nonlinear solver/Linear solver", "MUMPS"},
           {"Boundary conditions/Dirichlet",
            "lower_bottom: xy: 0; upper_top: y: -1e-3*t; upper_top: x: 0"}});
  compare("bar_impact", "prm/examples/bar_impact.prm", {});
  // the multipliers condensed: each process eliminates those of its own
  // secondary nodes (split 5 / 3 here; none on the first process in the
  // bar), the eliminations are gathered
  compare("patch_test_friction_condensed",
          "prm/examples/patch_test.prm",
          {{"Contact/Friction coefficients", "0.3"},
           {"Nonlinear solver/Condense multipliers", "true"},
           {"Boundary conditions/Dirichlet",
            "lower_bottom: xy: 0; upper_top: y: -1e-3*min(10*t, 1); "
            "upper_top: x: 0.05*t"},
           {"Time integration/Time step", "0.1"}});
  compare("bar_impact_nts_condensed",
          "prm/examples/bar_impact.prm",
          {{"Contact/Formulation", "nts"},
           {"Nonlinear solver/Condense multipliers", "true"}});
  compare("bouncing_block_mortar",
          "prm/bouncing_block/mortar_stabilized.prm",
          {{"Time integration/End time", "1.5"}});
  compare("bouncing_block_nts",
          "prm/bouncing_block/nts.prm",
          {{"Time integration/End time", "0.5"}});
  compare("bouncing_block_gmres",
          "prm/bouncing_block/mortar_stabilized.prm",
          {{"Time integration/End time", "0.5"},
           {"Nonlinear solver/Linear solver", "GMRES"}},
          1e-6);
  compare("ironing_mortar",
          "prm/ironing/mortar.prm",
          {{"Time integration/End time", "0.15"}});
  compare("ironing_mortar_friction",
          "prm/ironing/mortar_friction.prm",
          {{"Time integration/End time", "0.12"}});
  // GMRES with ML on the condensed systems, stopped at 1e-6 of the residual
  compare("ironing_mortar_amg",
          "prm/ironing/mortar.prm",
          {{"Time integration/End time", "0.15"},
           {"Nonlinear solver/Linear solver", "AMG"}},
          1e-6);
  compare("ironing_nts_smoothed",
          "prm/ironing/nts_smoothed.prm",
          {{"Time integration/End time", "0.12"}});
}
