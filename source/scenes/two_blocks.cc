// Two blocks, 2-D or 3-D: a narrower block above a wider one, meshes that
// do not match (the scene added as the exercise of issue 13).
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class TwoBlocks : public BuiltInScene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Two blocks");
        prm.declare_entry(
          "Gap",
          "0",
          Patterns::Double(0, 10),
          "Initial distance, in [0, 10], between the upper block "
          "[0.25, 0.75] x [0.5 + gap, 1 + gap] (x [0.25, "
          "0.75] in 3-D) and the lower block [0, 1] x [0, "
          "0.5] (x [0, 1]).");
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Two blocks");
        gap = prm.get_double("Gap");
        prm.leave_subsection();
      }

      // y is the vertical axis (bottom/top) in 2-D and 3-D.
      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        Point<dim> upper0, upper1, lower0, lower1;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != 1)
            {
              upper0[d] = 0.25;
              upper1[d] = 0.75;
              lower1[d] = 1;
            }
        upper0[1] = 0.5 + gap;
        upper1[1] = 1 + gap;
        lower1[1] = 0.5;
        std::vector<unsigned int> n_upper(dim, this->scaled(6)),
          n_lower(dim, this->scaled(5));
        n_lower[1] = this->scaled(3);
        return {box_body("upper", upper0, upper1, n_upper, "upper_"),
                box_body("lower", lower0, lower1, n_lower, "lower_")};
      }

    private:
      double gap;
    };
  } // namespace

  SceneEntry
  two_blocks_scene()
  {
    return scene_in_any_dimension<TwoBlocks>(
      "two blocks",
      "a narrower block above a wider one, see subsection Two blocks");
  }
} // namespace ContactDynamics
