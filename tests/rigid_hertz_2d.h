// Hertz's half-width and peak pressure of a 2-D contact against a rigid
// obstacle (plane strain), from the nodal pressures of the first contact
// pair: shared by rigid_cylinder_hertz.cc and gmsh_second_order_hertz.cc.
#ifndef contact_dynamics_tests_rigid_hertz_2d_h
#define contact_dynamics_tests_rigid_hertz_2d_h

#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

struct HertzResult
{
  double load, half_width, peak, equilibrium; // relative to Hertz, load
};

// Hertz of a cylinder of radius R on a rigid flat (E* = E / (1 - nu^2)) for
// the load P that the run reports on `obstacle`: a = sqrt(4 P R / (pi E*)),
// p0 = 2 P / (pi a). The half-width is measured from the second moment of
// the nodal pressures about x = 0 (a^2 = 4 int p x^2 / int p for the Hertz
// profile), with the weights integral N_j of the current surface.
inline HertzResult
rigid_hertz_2d(const ContactDynamics::Simulator<2> &simulator,
               const std::string                   &obstacle,
               const unsigned int                   degree,
               const double                         R = 1,
               const double E_star                    = 1000 / (1 - 0.3 * 0.3))
{
  const auto *contact =
    dynamic_cast<const ContactDynamics::SurfaceContact<2> *>(
      simulator.get_contact());
  const auto nodes   = contact->secondary_nodes(0);
  const auto surface = contact->secondary_surface(0);
  // integral N_j on the current surface: half of each adjacent face
  // (degree 2: the quadratic N_j on the curved faces)
  std::vector<double> weight(nodes.states.size(), 0.);
  if (degree == 1)
    for (const auto &face : surface.faces)
      {
        const double half =
          nodes.position[face[0]].distance(nodes.position[face[1]]) / 2;
        weight[face[0]] += half;
        weight[face[1]] += half;
      }
  else
    for (unsigned int j = 0; j < weight.size(); ++j)
      weight[j] = surface.current_weight(j, simulator.displacement());
  double force = 0, moment = 0, peak = 0;
  for (unsigned int j = 0; j < nodes.states.size(); ++j)
    {
      const double p = nodes.states[j].pressure;
      const double x = nodes.position[j][0];
      force += p * weight[j];
      moment += p * x * x * weight[j];
      peak = std::max(peak, p);
    }
  // (the load on an obstacle below the body points down)
  const double P =
    std::abs(contact_statistics(*contact).at(obstacle + "_force_y"));
  const double a    = std::sqrt(4 * P * R / (dealii::numbers::PI * E_star));
  const double p0   = 2 * P / (dealii::numbers::PI * a);
  const double a_fe = std::sqrt(4 * moment / force);
  return {P, a_fe / a - 1, peak / p0 - 1, force / P - 1};
}

// Half-width and peak within `bound` of Hertz's, the pressures integrating
// to the load within 0.5 % (equilibrium); `name` begins each line.
inline void
check_rigid_hertz(const std::string &name,
                  const HertzResult &r,
                  const double       bound)
{
  check_range(name + "half-width / Hertz - 1", r.half_width, -bound, bound);
  check_range(name + "peak pressure / Hertz - 1", r.peak, -bound, bound);
  check_range(name + "integral of the pressures / load - 1",
              r.equilibrium,
              -0.005,
              0.005);
}

#endif
