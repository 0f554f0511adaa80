// Shared helpers for the .cc unit tests: deallog goes to the file "output"
// that the deal.II test harness compares with the .output file.
#ifndef contact_dynamics_tests_h
#define contact_dynamics_tests_h

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>

#include <fstream>
#include <iomanip>

inline std::ofstream &
initlog()
{
  // the library uses MPI (Trilinos), also in serial
  static int                                      argc   = 1;
  static char                                     name[] = "test";
  static char                                    *args[] = {name, nullptr};
  static char                                   **argv   = args;
  static dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  static std::ofstream                            logfile("output");
  dealii::deallog.attach(logfile);
  dealii::deallog.depth_console(0);
  logfile << std::setprecision(6);
  return logfile;
}

// Prints "name: OK" if |value - expected| <= tolerance, and the numbers
// otherwise, so that a failure shows up as a diff.
inline void
check_close(const std::string &name,
            const double       value,
            const double       expected,
            const double       tolerance)
{
  if (std::abs(value - expected) <= tolerance)
    dealii::deallog << name << ": OK" << std::endl;
  else
    dealii::deallog << name << ": FAILED value=" << std::setprecision(12)
                    << value << " expected=" << expected
                    << " tolerance=" << tolerance << std::endl;
}

inline void
check_true(const std::string &name, const bool condition)
{
  dealii::deallog << name << ": " << (condition ? "OK" : "FAILED") << std::endl;
}


#include <deal.II/base/parameter_handler.h>

#include <contact_dynamics/application.h>

#include <string>

// Mean x velocity (momentum / mass) of the Q1 body with material id `body`,
// with row-sum (lumped) nodal masses, which give the momentum exactly
// (uniform density and parallelogram cells).
template <typename Simulator>
double
mean_velocity_x(const Simulator &simulator, const unsigned int body)
{
  double momentum = 0, mass = 0;
  for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
    if (cell->material_id() == body)
      for (unsigned int v = 0; v < 4; ++v)
        {
          momentum += cell->measure() / 4 *
                      simulator.velocity()(cell->vertex_dof_index(v, 0));
          mass += cell->measure() / 4;
        }
  return momentum / mass;
}

// Writes `text` to `filename` and reads it as the application would.
inline void
read_test_parameters(const std::string        &filename,
                     const std::string        &text,
                     dealii::ParameterHandler &prm)
{
  {
    std::ofstream f(filename);
    f << text;
  }
  ContactDynamics::read_parameters(filename, prm);
}

#endif
