// The parameters of the `Contact` subsection that all formulations share:
// the pairs of surfaces, friction, rigid obstacles and monitored points.
#ifndef contact_dynamics_contact_contact_parameters_h
#define contact_dynamics_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <contact_dynamics/contact/rigid_obstacle.h>
#include <contact_dynamics/scenes/scene_layout.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /** One secondary/primary surface pair; a side may join several surfaces. */
  struct ContactPair
  {
    std::vector<types::boundary_id> secondary;
    std::vector<types::boundary_id> primary;
    std::string                     name; // "secondary: primary" as written
    double                          friction_coefficient = 0;
    // the index of the rigid obstacle that is the primary side (`primary`
    // is empty then), or -1
    int obstacle = -1;
  };

  struct ContactParameters
  {
    enum class Formulation
    {
      none,
      mortar,
      node_to_segment
    };
    Formulation              formulation = Formulation::none;
    std::vector<ContactPair> pairs;
    // 'x, y' or 'x, y, z' (create_contact_formulation() checks the count)
    std::vector<std::vector<double>> monitored_points;
    bool                             allow_initial_penetration = false;
    std::vector<std::string>         body_names; // of the scene, for messages
    // per body of body_names (set by create_contact_formulation)
    std::vector<double>                  youngs_moduli;
    std::vector<RigidObstacleParameters> obstacles;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler  &prm,
                     const SceneLayout &layout,
                     const unsigned int dim);
  };

  /**
   * Declares `Contact/Rigid obstacles` only: the first reading of a file
   * learns the obstacles' names from it, to declare their subsections.
   */
  void
  declare_obstacle_names(ParameterHandler &prm);

  /** The names in `Contact/Rigid obstacles` (checked). */
  std::vector<std::string>
  obstacle_names(ParameterHandler &prm);

  /**
   * Declares the `Contact` subsection with every formulation's entries and
   * a subsection per rigid obstacle of `layout`.
   */
  void
  declare_contact_parameters(ParameterHandler  &prm,
                             const SceneLayout &layout,
                             const unsigned int dim);
} // namespace ContactDynamics

#endif
