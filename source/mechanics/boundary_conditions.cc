#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/vector_tools.h>

#include <contact_dynamics/mechanics/bodies.h>
#include <contact_dynamics/mechanics/boundary_conditions.h>
#include <contact_dynamics/parallel.h>

#include <cmath>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    // The displacement function, padded with zeros for the components of
    // further fields (such as Lagrange multipliers) of the finite element.
    template <int dim>
    class PaddedFunction : public Function<dim>
    {
    public:
      PaddedFunction(const Function<dim> &f, const unsigned int n_components)
        : Function<dim>(n_components)
        , f(f)
      {}

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        return component < dim ? f.value(p, component) : 0.;
      }

    private:
      const Function<dim> &f;
    };
  } // namespace

  template <int dim>
  void
  DirichletConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Dirichlet",
      "",
      Patterns::Anything(),
      "Prescribed displacements: a ';'-separated list of "
      "'surface: components: expression', components being any of x, y, z "
      "(e.g. 'xy') and the expression a formula in x, y, (z,) t with "
      "FunctionParser syntax (pi, cos, if(c,a,b), ...). Example: "
      "'substrate_bottom: xy: 0; block_top: x: 0; block_top: y: "
      "0.2*cos(2*pi/4*t) - 0.19'. Later entries win where surfaces share "
      "nodes.");
  }

  template <int dim>
  void
  DirichletConditions<dim>::parse_parameters(ParameterHandler  &prm,
                                             const SceneLayout &layout)
  {
    conditions.clear();
    const std::string text = prm.get("Dirichlet");
    for (const std::string &entry : Utilities::split_string_list(text, ';'))
      {
        const auto error = [&](const std::string &what) {
          return ExcMessage("In 'Boundary conditions/Dirichlet', the entry '" +
                            entry + "' " + what +
                            ". Expected 'surface: components: expression', "
                            "for example 'block_top: y: -0.1*t'.");
        };
        const auto first = entry.find(':');
        AssertThrow(first != std::string::npos, error("has no ':'"));
        const auto second = entry.find(':', first + 1);
        AssertThrow(second != std::string::npos, error("has only one ':'"));
        Condition c;
        c.surface = Utilities::trim(entry.substr(0, first));
        const std::string components =
          Utilities::trim(entry.substr(first + 1, second - first - 1));
        const std::string expression =
          Utilities::trim(entry.substr(second + 1));
        try
          {
            c.boundary_id = layout.surface_id(c.surface);
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream message;
            e.print_info(message);
            AssertThrow(false,
                        ExcMessage("In 'Boundary conditions/Dirichlet': " +
                                   Utilities::trim(message.str())));
          }

        std::vector<bool> mask(dim, false);
        AssertThrow(!components.empty(), error("names no component"));
        for (const char ch : components)
          {
            const int k = (ch == 'x' ? 0 : ch == 'y' ? 1 : ch == 'z' ? 2 : -1);
            AssertThrow(k >= 0 && k < dim,
                        error("has the component '" + std::string(1, ch) +
                              "'; allowed: " + std::string("xyz", dim)));
            mask[k] = true;
          }
        c.mask = ComponentMask(mask);
        AssertThrow(!expression.empty(), error("has no expression"));

        // evaluated once now: deal.II would compile it at the first step
        check_expressions({expression},
                          dim,
                          true,
                          "In 'Boundary conditions/Dirichlet', the entry '" +
                            entry + "'");
        c.entry      = entry;
        c.expression = expression;
        std::vector<std::string> expressions(dim, "0");
        for (unsigned int d = 0; d < dim; ++d)
          if (mask[d])
            expressions[d] = expression;
        c.function = std::make_shared<FunctionParser<dim>>(dim);
        c.function->initialize(FunctionParser<dim>::default_variable_names() +
                                 ",t",
                               expressions,
                               {{"pi", numbers::PI}},
                               true);
        conditions.push_back(c);
      }
  }

  template <int dim>
  std::map<types::global_dof_index, double>
  DirichletConditions<dim>::values(const Mapping<dim>    &mapping,
                                   const DoFHandler<dim> &dof_handler,
                                   const double           time) const
  {
    return values(mapping, dof_handler, time, "");
  }

  template <int dim>
  std::map<types::global_dof_index, double>
  DirichletConditions<dim>::values(const Mapping<dim>    &mapping,
                                   const DoFHandler<dim> &dof_handler,
                                   const double           time,
                                   const std::string     &why) const
  {
    std::map<types::global_dof_index, double> result;
    const unsigned int n_components = dof_handler.get_fe().n_components();
    std::string        failure;
    for (const Condition &c : conditions)
      {
        c.function->set_time(time);
        std::vector<bool> mask(n_components, false);
        for (unsigned int d = 0; d < dim; ++d)
          mask[d] = c.mask[d];
        std::map<types::global_dof_index, double> these;
        const PaddedFunction<dim> padded(*c.function, n_components);
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 c.boundary_id,
                                                 padded,
                                                 these,
                                                 ComponentMask(mask));
        // a NaN here would only show up later as an inverted element
        for (const auto &p : these)
          if (!std::isfinite(p.second))
            {
              std::ostringstream message;
              message << "The prescribed displacement of 'Boundary "
                         "conditions/Dirichlet', entry '"
                      << c.entry << "', is "
                      << (std::isnan(p.second) ? "NaN" :
                          p.second > 0         ? "+infinity" :
                                                 "-infinity")
                      << " on the surface '" << c.surface << "' at t = " << time
                      << why << ": the expression '" << c.expression
                      << "' must be finite at every time of the run on "
                         "every node of the surface.";
              if (failure.empty())
                failure = message.str();
            }
        for (const auto &p : these)
          result[p.first] = p.second;
      }
    // (a process whose part of the surface is finite must stop as well:
    // one message under mpirun, no abort)
    check_collectively(dof_handler.get_communicator(), [&]() {
      AssertThrow(failure.empty(), ExcMessage(failure));
    });
    return result;
  }

  template <int dim>
  void
  DirichletConditions<dim>::rates(
    const Mapping<dim>                        &mapping,
    const DoFHandler<dim>                     &dof_handler,
    const double                               time,
    const double                               h,
    std::map<types::global_dof_index, double> &velocity,
    std::map<types::global_dof_index, double> &acceleration) const
  {
    // central differences reach just outside the run's times
    std::ostringstream why;
    why << " (the velocity and acceleration of the prescribed motion at t = "
        << time << " are taken by central differences with the step " << h
        << ")";
    const auto minus = values(mapping, dof_handler, time - h, why.str());
    const auto mid   = values(mapping, dof_handler, time);
    const auto plus  = values(mapping, dof_handler, time + h, why.str());
    velocity.clear();
    acceleration.clear();
    for (const auto &p : mid)
      {
        const double um = minus.at(p.first), up = plus.at(p.first);
        velocity[p.first]     = (up - um) / (2 * h);
        acceleration[p.first] = (up - 2 * p.second + um) / (h * h);
      }
  }

  template class DirichletConditions<2>;
  template class DirichletConditions<3>;
} // namespace ContactDynamics
