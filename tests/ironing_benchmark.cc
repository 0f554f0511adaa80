// The paper's ironing problem (section 5.2), shipped parameter files at half
// the mesh density, first 0.3 s (first contact and indentation), every
// variant.
// - First contact: the tool's lowest point starts 0.02 above the substrate
//   and its top moves down at 0.5, so a rigid tool touches at t = 0.04;
//   the tool's bottom follows within one wave transit 2/sqrt(6896/0.1)
//   = 0.008 s: contact starts in [0.04, 0.04 + 0.008 + dt].
// - The energy balance closes once the contact work and the frictional
//   dissipation are counted (to 1e-3 of the external work).
// - The mortar run uses MUMPS and runs to t = 1: the contact couplings
//   change the sparsity pattern as the tool slides, which once crashed
//   MUMPS (at t = 0.98 on this mesh).
// - Coulomb's law at every node at the end: |lambda_t| <= mu lambda_n, and
//   the frictional dissipation never decreases.
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>

using namespace dealii;

int
main()
{
  initlog();
  const double dt = 0.01, t_kin = 0.02 / 0.5,
               transit = 2 / std::sqrt(6896 / 0.1);
  for (const std::string variant : {"mortar",
                                    "nts",
                                    "nts_smoothed",
                                    "mortar_friction",
                                    "nts_smoothed_friction"})
    {
      const bool   mumps    = variant == "mortar";
      const double end_time = mumps ? 1.0 : 0.3;
      double       coulomb  = 0; // max of |lambda_t| - mu lambda_n
      const auto   s        = run_shipped<ContactDynamics::Simulator<2>>(
        "prm/ironing/" + variant + ".prm",
        {{"Scene/Refinement factor", "0.5"},
                  {"Time integration/End time", std::to_string(end_time)},
                  {"Nonlinear solver/Linear solver", mumps ? "MUMPS" : "KLU"},
                  {"Output/Output directory", "output_" + variant},
                  {"Output/VTU interval", "0"}},
        [&](const ContactDynamics::Simulator<2> &simulator) {
          const auto *contact =
            dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
              simulator.get_contact());
          for (const auto &node : contact->node_states(0))
            coulomb =
              std::max(coulomb,
                       std::abs(node.tangential) - 0.25 * node.pressure);
        });
      const auto  &time     = s.at("time");
      const double t_c      = first_time_positive(s, "active_contact_nodes");
      const bool   friction = s.count("frictional_dissipation") > 0;
      deallog << variant << ": first contact at " << t_c << std::endl;
      check_true(variant + ": ran to the end",
                 std::abs(time.back() - end_time) < 1e-9);
      check_true(variant + ": first contact in [t_kin, t_kin + L/c + dt]",
                 t_c >= t_kin && t_c <= t_kin + transit + dt);

      double balance = 0, dissipation_drop = 0;
      for (unsigned int i = 0; i < time.size(); ++i)
        {
          const double d = friction ? s.at("frictional_dissipation")[i] : 0.;
          balance        = std::max(balance,
                             std::abs(s.at("energy_balance_error")[i] -
                                      s.at("contact_work")[i] - d));
          if (friction && i > 0)
            dissipation_drop =
              std::max(dissipation_drop,
                       s.at("frictional_dissipation")[i - 1] - d);
        }
      check_true(variant + ": no NaN", std::isfinite(balance + coulomb));
      check_true(variant + ": energy balance closes with contact work",
                 balance < 1e-3 * s.at("external_work").back());
      if (friction)
        {
          check_true(variant + ": |lambda_t| <= mu lambda_n at every node",
                     coulomb <=
                       1e-6 * std::abs(s.at("contact_force_y").back()));
          check_true(variant + ": dissipation never decreases",
                     dissipation_drop <= 0);
        }
    }
}
