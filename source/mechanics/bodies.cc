#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/mechanics/bodies.h>

namespace ContactDynamics
{
  void
  BodyParameters::declare_parameters(ParameterHandler  &prm,
                                     const unsigned int dim)
  {
    MaterialParameters::declare_parameters(prm);
    const std::string zeros = (dim == 2 ? "0, 0" : "0, 0, 0");
    prm.declare_entry("Body force",
                      zeros,
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Body force per unit volume, one number per coordinate "
                      "direction (for gravity: density times g).");
    const std::string zero_expr = (dim == 2 ? "0; 0" : "0; 0; 0");
    prm.declare_entry(
      "Initial displacement",
      zero_expr,
      Patterns::Anything(),
      "Displacement at t = 0, one expression per coordinate direction "
      "separated by ';', in the reference coordinates x, y (, z); for example "
      "'0; 0.01'. Functions and constants of deal.II's FunctionParser (pi, "
      "sin, if(c,a,b), ...) are available.");
    prm.declare_entry("Initial velocity",
                      zero_expr,
                      Patterns::Anything(),
                      "Velocity at t = 0, as 'Initial displacement'.");
  }

  void
  BodyParameters::parse_parameters(ParameterHandler  &prm,
                                   const unsigned int dim)
  {
    material.parse_parameters(prm);
    body_force = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Body force")));
    initial_displacement    = prm.get("Initial displacement");
    initial_velocity        = prm.get("Initial velocity");
    const std::string where = subsection_name(name) + "/";
    split_vector_expression(initial_displacement,
                            dim,
                            where + "Initial displacement");
    split_vector_expression(initial_velocity, dim, where + "Initial velocity");
  }

  std::vector<std::string>
  split_vector_expression(const std::string &text,
                          const unsigned int dim,
                          const std::string &parameter)
  {
    std::vector<std::string> parts = Utilities::split_string_list(text, ';');
    AssertThrow(parts.size() == dim,
                ExcMessage("The parameter '" + parameter + "' = '" + text +
                           "' has " + std::to_string(parts.size()) +
                           " expression(s); it needs exactly " +
                           std::to_string(dim) +
                           ", one per coordinate direction, separated by "
                           "';'."));
    for (const auto &p : parts)
      AssertThrow(!p.empty(),
                  ExcMessage("The parameter '" + parameter + "' = '" + text +
                             "' has an empty expression."));
    return parts;
  }
} // namespace ContactDynamics
