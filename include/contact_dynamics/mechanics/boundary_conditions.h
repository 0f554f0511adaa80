// Prescribed displacements on named surfaces, as functions of time.
#ifndef contact_dynamics_mechanics_boundary_conditions_h
#define contact_dynamics_mechanics_boundary_conditions_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/mapping.h>

#include <contact_dynamics/scenes/scene_layout.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

DEAL_II_NAMESPACE_OPEN
class ParameterHandler;
template <int dim>
class FunctionParser;
DEAL_II_NAMESPACE_CLOSE

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * Dirichlet conditions, written in the parameter file as
   *   surface: components: expression; surface: components: expression; ...
   * where components is any of x, y, z (for example 'xy') and the
   * expression is a FunctionParser formula in x, y (, z) and t, for example
   *   substrate_bottom: xy: 0; block_top: y: 0.2*cos(2*pi/4*t) - 0.19
   */
  template <int dim>
  class DirichletConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const SceneLayout &layout);

    /**
     * Prescribed displacement of every constrained degree of freedom of the
     * first dim (displacement) components at time t. A value that is not
     * finite throws a message naming the entry, the surface and the time.
     */
    std::map<types::global_dof_index, double>
    values(const Mapping<dim>    &mapping,
           const DoFHandler<dim> &dof_handler,
           const double           time) const;

    /**
     * Velocity and acceleration of the prescribed motion at time t, by
     * central differences in time with step h.
     */
    void
    rates(const Mapping<dim>                        &mapping,
          const DoFHandler<dim>                     &dof_handler,
          const double                               time,
          const double                               h,
          std::map<types::global_dof_index, double> &velocity,
          std::map<types::global_dof_index, double> &acceleration) const;

  private:
    /** As values(); `why` adds to the message why the time was asked for. */
    std::map<types::global_dof_index, double>
    values(const Mapping<dim>    &mapping,
           const DoFHandler<dim> &dof_handler,
           const double           time,
           const std::string     &why) const;

    struct Condition
    {
      std::string                          entry; // as written
      std::string                          expression;
      std::string                          surface;
      types::boundary_id                   boundary_id;
      ComponentMask                        mask;
      std::shared_ptr<FunctionParser<dim>> function;
    };
    std::vector<Condition> conditions;
  };
} // namespace ContactDynamics

#endif
