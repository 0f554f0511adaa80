// The one-process direct solvers, KLU and UMFPACK (SuiteSparse, on the rows
// of the Trilinos matrix read as the columns of its transpose, with the
// analysis kept while the sparsity pattern does not change and, for KLU,
// the pivot order reused), solve the Newton systems that MUMPS (Trilinos
// Amesos, an independent implementation on the matrix as it is) solves:
// the same energies, work and contact forces to 1e-8 of their scale (measured
// up to 1e-9: MUMPS differs most) and
// the same Newton iterations in all to 10 % (per step they can differ by
// one where the last residual lands at the tolerance: measured on the
// patch test, 1.3e-6 after 4 iterations with one solver, 5 with another),
// on
// - the mortar patch test with Coulomb friction (pressed, then slid:
//   nonsymmetric frictional rows, which a transposed solve would get wrong),
// - 0.3 s of the shipped frictional mortar ironing at refinement factor
//   0.5, where the contact candidates and with them the sparsity pattern
//   change while the tool moves (a stale symbolic analysis would fail).
#include <contact_dynamics/simulator.h>

#include "tests.h"

using namespace dealii;
using Columns = std::map<std::string, std::vector<double>>;

namespace
{
  Columns
  run(const std::string &file,
      ParameterChanges   changes,
      const std::string &solver)
  {
    changes.push_back({"Nonlinear solver/Linear solver", solver});
    changes.push_back({"Output/Output directory",
                       "output_" + solver + "_" + file.substr(4, 7)});
    changes.push_back({"Output/VTU interval", "0"});
    return run_shipped<ContactDynamics::Simulator<2>>(file, changes);
  }

  void
  compare(const std::string      &name,
          const std::string      &file,
          const ParameterChanges &changes)
  {
    const Columns mumps = run(file, changes, "MUMPS");
    for (const std::string solver : {"KLU", "UMFPACK"})
      {
        const Columns other = run(file, changes, solver);
        check_true(name + ", " + solver + ": the same steps as MUMPS",
                   mumps.at("step").size() == other.at("step").size() &&
                     mumps.at("step").size() > 2);
        check_range(name + ": Newton iterations " + solver + " / MUMPS",
                    other.at("cumulative_newton_iterations").back() /
                      mumps.at("cumulative_newton_iterations").back(),
                    0.9,
                    1.1);
        for (const std::vector<std::string> &group :
             std::vector<std::vector<std::string>>{{"kinetic_energy",
                                                    "elastic_energy",
                                                    "external_work",
                                                    "contact_work",
                                                    "frictional_dissipation"},
                                                   {"contact_force_x",
                                                    "contact_force_y"}})
          {
            double scale = 0, largest = 0;
            for (const auto &column : group)
              for (unsigned int i = 0; i < std::min(mumps.at(column).size(),
                                                    other.at(column).size());
                   ++i)
                {
                  scale   = std::max(scale, std::abs(mumps.at(column)[i]));
                  largest = std::max(largest,
                                     std::abs(mumps.at(column)[i] -
                                              other.at(column)[i]));
                }
            check_range(name + ", " + solver + ": " + group[0] +
                          "... against MUMPS, / their scale",
                        largest / scale,
                        0,
                        1e-8);
          }
      }
  }
} // namespace

int
main()
{
  initlog();
  compare("patch test, sliding with friction",
          "prm/examples/patch_test.prm",
          {{"Boundary conditions/Dirichlet",
            "lower_bottom: xy: 0; upper_top: x: if(t <= 1, 0, 0.05*(t - 1)); "
            "upper_top: y: -1e-3*min(t, 1)"},
           {"Time integration/End time", "3"},
           {"Time integration/Time step", "0.25"},
           {"Contact/Friction coefficients", "0.3"}});
  compare("ironing with friction, factor 0.5",
          "prm/ironing/mortar_friction.prm",
          {{"Scene/Refinement factor", "0.5"},
           {"Time integration/End time", "0.3"}});
}
