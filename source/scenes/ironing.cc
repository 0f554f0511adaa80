// The paper's ironing problem: a half-disc tool on a long substrate; in
// 3-D a spherical tool on a slab (half of both by symmetry, z >= 0).
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class Ironing : public BuiltInScene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Ironing");
        prm.declare_entry(
          "Tool",
          "elastic",
          Patterns::Selection("elastic|none"),
          "'elastic': the meshed tool (a body 'tool'); 'none': the substrate "
          "only, for a rigid obstacle in its place (Contact/Rigid "
          "obstacles: in 2-D a cylinder of radius 1 with Point 1.2, 5.02; "
          "in 3-D a sphere of radius 1 with Point 1.2, 2.52, 0), which has "
          "no unknowns.");
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Ironing");
        with_tool = prm.get("Tool") == "elastic";
        prm.leave_subsection();
      }

      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        std::vector<BodyDefinition<dim>> all;
        if constexpr (dim == 2)
          all = bodies_2d();
        else
          all = bodies_3d();
        if (!with_tool)
          all.erase(all.begin());
        return all;
      }

    private:
      bool with_tool = true;

      std::vector<BodyDefinition<2>>
      bodies_2d() const
      {
        using namespace MeshSteps;
        const auto scaled = [this](const double n) {
          return this->scaled(n);
        };
        // 200 elements along the top; vertically a geometric progression
        // from the top element length down to coarser cells.
        const unsigned int nx = scaled(200);
        return {half_disc_body("tool",
                               Point<2>(1.2, 5.02),
                               1.0,
                               scaled(16),
                               scaled(12),
                               1.0,
                               scaled(16)),
                rectangle_body("substrate",
                               Point<2>(0, 0),
                               Point<2>(12, 4),
                               uniform(12, nx),
                               reversed(geometric(4, 12.0 / nx, scaled(30))))};
      }

      // A sphere of radius 1 (its cap: x in [0.6, 1.8], z in [0, 0.6],
      // 0.8 high above its lowest point (1.2, 1.52, 0)) on the slab
      // [0, 6] x [0, 1.5] x [0, 1.5]; the plane z = 0 (the *_front
      // surfaces) is a symmetry plane. Cells of 0.1 along the slab's top
      // and on the cap, growing downwards and sideways.
      std::vector<BodyDefinition<3>>
      bodies_3d() const
      {
        using namespace MeshSteps;
        const double h = 0.1 / this->refinement_factor;
        const auto   n = [h](const double length) {
          return std::max(1u, (unsigned int)std::round(length / h));
        };
        const std::vector<double> depth = geometric(1.5, h, n(0.5));
        return {sphere_cap_body("tool",
                                Point<3>(0.6, 1.52, 0),
                                {uniform(1.2, n(1.2)),
                                 geometric(0.8, h, n(0.4)),
                                 uniform(0.6, n(0.6))},
                                Point<3>(1.2, 1.52, 0),
                                1.0),
                box_body<3>("substrate",
                            Point<3>(0, 0, 0),
                            {uniform(6, n(6)), reversed(depth), depth},
                            "substrate_")};
      }
    };
  } // namespace

  SceneEntry
  ironing_scene()
  {
    return scene_in_any_dimension<Ironing>(
      "ironing",
      "the paper's half-disc tool pressed into and sliding along a "
      "substrate (3-D: a spherical tool on a slab, half by symmetry)");
  }
} // namespace ContactDynamics
