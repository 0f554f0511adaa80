// Bar impact: an elastic bar hitting a wall or a second bar.
#include <contact_dynamics/parameters.h>
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    // Target: a bar or (the default) a wall
    const Selection<bool> target_names{{false, "wall"}, {true, "bar"}};

    class BarImpact : public BuiltInScene<2>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Bar impact");
        prm.declare_entry(
          "Bar length",
          "1",
          Patterns::Double(1e-12),
          "Length L of the striker [-gap-L, -gap] x [0, height].");
        prm.declare_entry("Bar height",
                          "0.1",
                          Patterns::Double(1e-12),
                          "Height of the bars.");
        prm.declare_entry(
          "Gap",
          "0.01",
          Patterns::Double(0),
          "Initial distance between the striker and the target (at x = 0).");
        prm.declare_entry(
          "Target",
          target_names.name(false),
          target_names.pattern(),
          "'wall': a short block [0, 0.2 L] x [0, height] (make it stiff and "
          "fix its right side); 'bar': a second bar [0, Target length] x "
          "[0, height].");
        prm.declare_entry("Target length",
                          "1",
                          Patterns::Double(1e-12),
                          "Length of the target bar (Target = bar).");
        prm.declare_entry(
          "Elements along bar",
          "40",
          Patterns::Integer(1),
          "Elements along the striker; the height and the target get "
          "elements of the same size.");
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Bar impact");
        length            = prm.get_double("Bar length");
        height            = prm.get_double("Bar height");
        gap               = prm.get_double("Gap");
        target_bar        = target_names.value(prm.get("Target"));
        target_bar_length = prm.get_double("Target length");
        elements          = prm.get_integer("Elements along bar");
        prm.leave_subsection();
      }

      std::vector<BodyDefinition<2>>
      bodies() const override
      {
        const double       L = length, h = height;
        const unsigned int nx      = scaled(elements);
        const unsigned int ny      = MeshSteps::scaled(nx * h / L, 1);
        const double target_length = (target_bar ? target_bar_length : 0.2 * L);
        return {rectangle_body("striker",
                               Point<2>(-gap - L, 0),
                               Point<2>(-gap, h),
                               nx,
                               ny),
                rectangle_body("target",
                               Point<2>(0, 0),
                               Point<2>(target_length, h),
                               MeshSteps::scaled(nx * target_length / L, 1),
                               ny)};
      }

    private:
      double       length;
      double       height;
      double       gap;
      bool         target_bar;
      double       target_bar_length;
      unsigned int elements;
    };
  } // namespace

  SceneEntry
  bar_impact_scene()
  {
    return planar_scene<BarImpact>(
      "bar impact",
      "an elastic bar hitting a wall or a second bar, see subsection Bar impact");
  }
} // namespace ContactDynamics
