// 3-D contact on two MPI processes gives the statistics of the same run on
// one process (computed here on the first process), to solver tolerance, at
// every step: the contact patches are computed in equal shares by the
// processes and their sums sent to the owners of the nodes
// (doc/contact.md, "Parallel assembly"), so this also covers a contact
// surface that lies on one process's part of the mesh (the bouncing
// block's bottom); mortar and node-to-segment.
#include "parallel_compare.h"


int
main()
{
  initlog();
  check_true("two processes",
             dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 2);

  compare<3>("patch_test_3d", "prm/examples/patch_test_3d.prm", {});
  // pressed, then sliding with Coulomb friction along an oblique direction
  compare<3>("patch_test_3d_friction",
             "prm/examples/patch_test_3d.prm",
             {{"Contact/Friction coefficients", "0.3"},
              {"Boundary conditions/Dirichlet",
               "lower_bottom: xyz: 0; upper_top: y: -1e-3*min(10*t, 1); "
               "upper_top: x: 0.04*t; upper_top: z: 0.02*t"},
              {"Time integration/Time step", "0.1"}});
  // the whole contact surface on the first process, persistency, dynamics
  compare<3>("bouncing_block_3d",
             "prm/bouncing_block/mortar_3d.prm",
             {{"Scene/Refinement factor", "0.5"},
              {"Scene/Bouncing block/Depth elements", "2"},
              {"Time integration/End time", "1"},
              {"Nonlinear solver/Linear solver", "auto"}});
  // node-to-segment with smoothed normals and friction, sliding
  compare<3>("patch_test_3d_nts_friction",
             "prm/examples/patch_test_3d.prm",
             {{"Contact/Formulation", "nts"},
              {"Contact/Node to segment/Normal smoothing distance", "0.3"},
              {"Contact/Friction coefficients", "0.3"},
              {"Boundary conditions/Dirichlet",
               "lower_bottom: xyz: 0; upper_top: y: -1e-3*min(10*t, 1); "
               "upper_top: x: 0.04*t; upper_top: z: 0.02*t"},
              {"Time integration/Time step", "0.1"}});
}
