// Nonlinear solver/Condense multipliers: the Newton systems with the contact
// multipliers eliminated node by node give the Newton iterates of the full
// saddle-point systems (an independent path: a different linear system,
// solved by the same direct solver). Compared per step, condensed against
// uncondensed, on the elastic bar impact (dynamic, persistency) and on the
// patch-test blocks pressed and then slid with Coulomb friction (mu = 0.3,
// quasi-static, stick and slip, tangential multipliers):
// - node-to-segment (nodal multipliers: each appears only in its node's
//   rows): the same number of Newton iterations at every step, energies,
//   contact work and frictional dissipation equal to 1e-6 of their scale;
// - three blocks where a node is secondary in one pair and on the primary
//   surface of the other (tests/three_bodies_contact.prm): that node is not
//   eliminated, and both formulations give the same Newton iterations
//   (NTS: the same Newton iterations; mortar: within the bound below;
//   before this rule, the condensed runs stalled with hundreds of cuts);
// - mortar: the variationally consistent force
//   -sum lambda_j w_j d(g_j/w_j)/du couples a node's rows to its
//   neighbours' multipliers by terms of the size of the gap times the
//   rotation of the normals (measured up to 10 % of the diagonal at the
//   first iteration of an impact), which the node-wise elimination leaves
//   out: the Newton iteration is then inexact, converges to the same states
//   (energies to 1e-6 of their scale) and takes at most 40 % more
//   iterations (measured +12 % and +24 %; the count moves by several
//   per cent with the round-off of the linear solve, which decides the
//   active set of the bar's corner nodes in some steps: the same matrix
//   stored with the Jacobian's sparsity pattern or with its own gave 294
//   and 262 iterations).
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <filesystem>

using namespace dealii;
using Columns = std::map<std::string, std::vector<double>>;

namespace
{
  Columns
  run(const std::string &file, ParameterChanges changes, const bool condense)
  {
    changes.push_back(
      {"Nonlinear solver/Condense multipliers", condense ? "true" : "false"});
    changes.push_back({"Output/Output directory",
                       std::string("output_") + (condense ? "c" : "u")});
    changes.push_back({"Output/VTU interval", "0"});
    return run_shipped<ContactDynamics::Simulator<2>>(file, changes);
  }

  void
  compare(const std::string      &name,
          const std::string      &file,
          const ParameterChanges &changes,
          const bool              same_iterations)
  {
    const Columns full = run(file, changes, false);
    const Columns cond = run(file, changes, true);
    check_true(name + ": the same number of steps",
               full.at("step").size() == cond.at("step").size());
    double scale = 0, largest = 0;
    for (const auto *column :
         {"kinetic_energy", "elastic_energy", "external_work", "contact_work"})
      if (full.count(column))
        for (unsigned int i = 0; i < full.at(column).size(); ++i)
          {
            scale = std::max(scale, std::abs(full.at(column)[i]));
            largest =
              std::max(largest,
                       std::abs(full.at(column)[i] - cond.at(column)[i]));
          }
    if (full.count("frictional_dissipation"))
      for (unsigned int i = 0; i < full.at("step").size(); ++i)
        largest = std::max(largest,
                           std::abs(full.at("frictional_dissipation")[i] -
                                    cond.at("frictional_dissipation")[i]));
    check_close(name + ": energies and work equal, relative to their scale",
                largest / scale,
                0,
                1e-6);
    record_measured(name + ": largest difference / scale",
                    largest / scale,
                    0,
                    1e-6);
    const double n_full = full.at("cumulative_newton_iterations").back();
    const double n_cond = cond.at("cumulative_newton_iterations").back();
    if (same_iterations)
      check_true(name + ": the same Newton iterations at every step",
                 full.at("newton_iterations") == cond.at("newton_iterations"));
    else
      check_range(name + ": Newton iterations condensed / full",
                  n_cond / n_full,
                  0.8,
                  1.4);
  }
} // namespace

int
main()
{
  initlog();
  const std::string      bar   = "prm/examples/bar_impact.prm";
  const std::string      patch = "prm/examples/patch_test.prm";
  const ParameterChanges sliding{
    {"Boundary conditions/Dirichlet",
     "lower_bottom: xy: 0; upper_top: x: if(t <= 1, 0, 0.05*(t - 1)); "
     "upper_top: y: -1e-3*min(t, 1)"},
    {"Time integration/End time", "3"},
    {"Time integration/Time step", "0.25"},
    {"Contact/Friction coefficients", "0.3"}};
  ParameterChanges sliding_nts = sliding;
  sliding_nts.push_back({"Contact/Formulation", "nts"});

  compare("nts, bar impact", bar, {{"Contact/Formulation", "nts"}}, true);
  compare("nts, sliding with friction", patch, sliding_nts, true);
  // a node that is secondary in one pair and on the primary surface of
  // another is not eliminated (its rows hold other nodes' multipliers)
  // (the mesh is read with the parameter file, from the working directory)
  std::filesystem::copy_file(std::string(SOURCE_DIR) + "/three_bodies.msh",
                             "three_bodies.msh",
                             std::filesystem::copy_options::overwrite_existing);
  const ParameterChanges three;
  ParameterChanges       three_mortar = three;
  three_mortar.push_back({"Contact/Formulation", "mortar"});
  compare("nts, shared node of two pairs",
          "tests/three_bodies_contact.prm",
          three,
          true);
  compare("mortar, shared node of two pairs",
          "tests/three_bodies_contact.prm",
          three_mortar,
          false);
  compare("mortar, bar impact", bar, {}, false);
  compare("mortar, sliding with friction", patch, sliding, false);
}
