#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/parameters.h>

#include <iostream>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    // Empty if the expression parses and evaluates, otherwise what the
    // parser says.
    template <int dim>
    std::string
    evaluation_error(const std::string &expression, const bool time_dependent)
    {
      std::string variables = FunctionParser<dim>::default_variable_names();
      if (time_dependent)
        variables += ",t";
      const SilencedStdErr silenced;
      try
        {
          FunctionParser<dim> f(1);
          f.initialize(variables,
                       expression,
                       {{"pi", numbers::PI}},
                       time_dependent);
          f.value(Point<dim>());
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          std::string       text = Utilities::trim(info.str());
          const std::string said = "The parser said: ";
          if (text.find(said) != std::string::npos)
            text = text.substr(text.find(said) + said.size());
          while (!text.empty() && text.back() == '.')
            text.pop_back();
          return text.empty() ? "no reason given" : text;
        }
      catch (const std::exception &e)
        {
          return e.what();
        }
      return {};
    }
  } // namespace

  void
  check_expressions(const std::vector<std::string> &expressions,
                    const unsigned int              dim,
                    const bool                      time_dependent,
                    const std::string              &where)
  {
    for (const std::string &expression : expressions)
      {
        const std::string reason =
          (dim == 2 ? evaluation_error<2>(expression, time_dependent) :
                      evaluation_error<3>(expression, time_dependent));
        AssertThrow(reason.empty(),
                    ExcMessage(
                      where + ": the expression '" + expression +
                      "' cannot be evaluated (" + reason +
                      "). An expression may use the variables " +
                      (dim == 2 ? "x, y" : "x, y, z") +
                      (time_dependent ? ", t" :
                                        " (not t: it is the state at t = 0)") +
                      ", the constant pi, numbers such as 1.5e-3, the "
                      "operators + - * / ^ and comparisons, and deal.II's "
                      "FunctionParser functions (sin, cos, exp, log, sqrt, "
                      "abs, min, max, if(c, a, b), ...)."));
      }
  }

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
    for (const auto &[entry, text] :
         {std::make_pair("Initial displacement", initial_displacement),
          std::make_pair("Initial velocity", initial_velocity)})
      check_expressions(split_vector_expression(text, dim, where + entry),
                        dim,
                        false,
                        "The parameter '" + where + entry + "' = '" + text +
                          "'");
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
