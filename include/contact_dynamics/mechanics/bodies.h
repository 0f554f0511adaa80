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

  /**
   * Parses each expression and evaluates it once at the origin (and t = 0):
   * deal.II compiles a FunctionParser expression only at its first
   * evaluation, so a broken one would pass the parameter check and stop the
   * run later with muparser's words only. The variables are x, y (, z) and,
   * if `time_dependent`, t. On failure throws a message that starts with
   * `where` (the parameter and its value) and names the expression and what
   * is allowed. A value that is not finite is no error here: the origin
   * need not lie in the body.
   */
  void
  check_expressions(const std::vector<std::string> &expressions,
                    const unsigned int              dim,
                    const bool                      time_dependent,
                    const std::string              &where);
} // namespace ContactDynamics

#endif
