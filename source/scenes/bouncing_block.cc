// The paper's bouncing block: a unit block above a 5 x 1 substrate; in 3-D
// both extruded by one unit in z.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class BouncingBlock : public BuiltInScene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Bouncing block");
        prm.declare_entry(
          "Depth elements",
          "10",
          Patterns::Integer(1, 1000),
          "3-D only: elements of both bodies across their depth z in "
          "[0, 1], in [1, 1000], at refinement factor 1 (scaled like the "
          "others). With z held on the front and back faces, any number "
          "gives the 2-D plane-strain solution; 1 is the cheapest.");
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Bouncing block");
        depth_elements = prm.get_integer("Depth elements");
        prm.leave_subsection();
      }

      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        if constexpr (dim == 2)
          return {rectangle_body("block",
                                 Point<2>(-2, 0),
                                 Point<2>(-1, 1),
                                 this->scaled(10),
                                 this->scaled(10)),
                  rectangle_body("substrate",
                                 Point<2>(-2.5, -1),
                                 Point<2>(2.5, 0),
                                 this->scaled(49),
                                 this->scaled(10))};
        else
          {
            const unsigned int n_z = this->scaled(depth_elements);
            return {box_body("block",
                             Point<3>(-2, 0, 0),
                             Point<3>(-1, 1, 1),
                             {this->scaled(10), this->scaled(10), n_z},
                             "block_"),
                    box_body("substrate",
                             Point<3>(-2.5, -1, 0),
                             Point<3>(2.5, 0, 1),
                             {this->scaled(49), this->scaled(10), n_z},
                             "substrate_")};
          }
      }

    private:
      unsigned int depth_elements = 10;
    };
  } // namespace

  SceneEntry
  bouncing_block_scene()
  {
    return scene_in_any_dimension<BouncingBlock>(
      "bouncing block",
      "the paper's block falling onto a substrate (in 3-D extruded by one "
      "unit in z), see subsection Bouncing block");
  }
} // namespace ContactDynamics
