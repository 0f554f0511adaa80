// Hertz: a half-cylinder pressed onto a block graded towards the contact.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    class Hertz : public BuiltInScene<2>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Hertz");
        prm.declare_entry(
          "Radius",
          "1",
          Patterns::Double(1e-12),
          "Radius of the half-cylinder (flat face on top, arc at the "
          "bottom) pressed onto the block.");
        prm.declare_entry(
          "Block width",
          "8",
          Patterns::Double(1e-12),
          "Width of the block [-width/2, width/2] x [0, height].");
        prm.declare_entry("Block height",
                          "4",
                          Patterns::Double(1e-12),
                          "Height of the block.");
        prm.declare_entry(
          "Gap",
          "0",
          Patterns::Double(0),
          "Initial vertical distance between the lowest point of the "
          "cylinder and the top of the block.");
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Hertz");
        radius       = prm.get_double("Radius");
        block_width  = prm.get_double("Block width");
        block_height = prm.get_double("Block height");
        gap          = prm.get_double("Gap");
        prm.leave_subsection();
      }

      std::vector<BodyDefinition<2>>
      bodies() const override
      {
        using namespace MeshSteps;
        const double              R = radius, w = block_width, h = block_height;
        const std::vector<double> half_x = graded(R, w / 2);
        return {half_disc_body("cylinder",
                               Point<2>(0, h + gap + R),
                               R,
                               scaled(32),
                               scaled(20),
                               0,
                               0),
                rectangle_body("block",
                               Point<2>(-w / 2, 0),
                               Point<2>(w / 2, h),
                               concatenate(reversed(half_x), half_x),
                               reversed(graded(R, h)))};
      }

    private:
      // Steps from the contact point outwards over `total`: uniform cells of
      // size R/40 within `fine_length`, geometrically growing (ratio about
      // 1.1) outside.
      std::vector<double>
      graded(const double fine_length, const double total) const
      {
        using namespace MeshSteps;
        const double R    = radius;
        const double size = R / scaled(40);
        const double fine = std::min(fine_length, total);
        if (total - fine <= 2 * R / 40)
          return uniform(total, scaled(total / (R / 40)));
        const unsigned int n_fine =
          std::max(1u, (unsigned int)std::round(fine / size));
        const unsigned int n_grow =
          scaled(n_growing(total - fine, R / 40, 1.1));
        return concatenate(uniform(fine, n_fine),
                           geometric(total - fine, fine / n_fine, n_grow));
      }

      double radius;
      double block_width;
      double block_height;
      double gap;
    };
  } // namespace

  SceneEntry
  hertz_scene()
  {
    return planar_scene<Hertz>(
      "hertz",
      "a half-cylinder pressed onto a block, see subsection Hertz");
  }
} // namespace ContactDynamics
