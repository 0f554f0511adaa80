// The checks of the 2-D contact patch test (contact_patch_test and
// contact_patch_test_refined): after the load step, the force balance
// between the contact, the top and the bottom, no tangential force, no gap
// at active nodes and the load E delta; returns the largest nodal pressure
// error relative to E delta = 1000.
#ifndef contact_dynamics_tests_patch_test_checks_h
#define contact_dynamics_tests_patch_test_checks_h

#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

inline double
check_patch_test(const std::string                   &formulation,
                 const ContactDynamics::Simulator<2> &simulator)
{
  using namespace dealii;
  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
      simulator.get_contact());
  const double exact = 1000;
  double       worst = 0, worst_gap = 0;
  unsigned int n_active = 0;
  for (const auto &node : contact->node_states(0))
    {
      worst = std::max(worst, std::abs(node.pressure - exact));
      if (node.active)
        {
          ++n_active;
          worst_gap = std::max(worst_gap, std::abs(node.normalized_gap()));
        }
    }
  const auto stats  = contact_statistics(*contact);
  const auto top    = simulator.reaction_force("upper_top");
  const auto bottom = simulator.reaction_force("lower_bottom");
  deallog << formulation << ": secondary nodes "
          << contact->node_states(0).size() << ", active " << n_active
          << std::endl;
  check_close(formulation + ": contact force on the upper block + reaction "
                            "at its top",
              (stats.at("contact_force_y") + top[1]) / exact,
              0.,
              1e-9);
  check_close(formulation + ": reactions at top and bottom cancel",
              (top[1] + bottom[1]) / exact,
              0.,
              1e-9);
  check_close(formulation + ": tangential contact force",
              stats.at("contact_force_x") / exact,
              0.,
              1e-9);
  check_close(formulation + ": gap at active nodes / delta",
              worst_gap / 1e-3,
              0.,
              1e-9);
  check_close(formulation + ": total load / (E delta)",
              -top[1] / exact,
              1.,
              formulation == "mortar" ? 1e-9 : 0.05);
  return worst / exact;
}

#endif
