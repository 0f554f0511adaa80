// Per-body data: material, body force and initial conditions, read from a
// `subsection Body <name>` for every body of the scene.
#ifndef contact_dynamics_mechanics_bodies_h
#define contact_dynamics_mechanics_bodies_h

#include <contact_dynamics/mechanics/material.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  struct BodyParameters
  {
    std::string         name;
    MaterialParameters  material;
    std::vector<double> body_force;           // per unit volume
    std::string         initial_displacement; // dim expressions, ';'-separated
    std::string         initial_velocity;

    static std::string
    subsection_name(const std::string &body_name)
    {
      return "Body " + body_name;
    }

    static void
    declare_parameters(ParameterHandler &prm, const unsigned int dim);
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };

  /**
   * Splits "e1; e2" into dim function expressions for a FunctionParser,
   * checking the count; `parameter` names the entry in error messages.
   */
  std::vector<std::string>
  split_vector_expression(const std::string &text,
                          const unsigned int dim,
                          const std::string &parameter);
} // namespace ContactDynamics

#endif
