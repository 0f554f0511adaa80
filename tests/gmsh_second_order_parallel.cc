// A Gmsh mesh of second order on two processes (issue 41): the curved cells
// come from the file's nodes by coarse cell, so every process must find the
// same nodes for the same cell, also for the refined cells of a distributed
// mesh adapted to the contact. prm/examples/gmsh_hertz_order2.prm (a half
// disc of 548 9-node quadrilaterals on a rigid plane, degree 2, mortar) on
// two processes against one: statistics equal within 1e-7 of their scales,
// uniform (shared mesh) and adapted to the contact (distributed, 2 levels).
#include "parallel_compare.h"

#include <filesystem>

int
main()
{
  initlog();
  // the shipped file names its mesh relative to the repository
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::filesystem::create_directories("prm/examples");
      std::filesystem::remove("prm/examples/half_disc_order2.msh");
      std::filesystem::create_symlink(std::string(SOURCE_DIR) +
                                        "/../prm/examples/half_disc_order2.msh",
                                      "prm/examples/half_disc_order2.msh");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  compare("gmsh_hertz", "prm/examples/gmsh_hertz_order2.prm", {});
  compare("gmsh_hertz_adapted",
          "prm/examples/gmsh_hertz_order2.prm",
          {{"Mesh refinement/Adapt to contact", "true"},
           {"Mesh refinement/Maximum levels", "2"}});
}
