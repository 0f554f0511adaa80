// Hertz: a half-cylinder (2-D) or a sphere (3-D, a quarter by symmetry)
// pressed onto a block graded towards the contact.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class Hertz : public BuiltInScene<dim>
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
          "bottom) pressed onto the block; in 3-D of the sphere whose cap "
          "(a quarter: x, z in [0, 0.4 R], 0.5 R high above its lowest "
          "point) is pressed onto the block.");
        prm.declare_entry(
          "Block width",
          "8",
          Patterns::Double(1e-12),
          "Width of the block [-width/2, width/2] x [0, height]; in 3-D "
          "the quarter [0, width/2] x [0, height] x [0, width/2], with the "
          "symmetry planes x = 0 and z = 0 (the surfaces *_left and "
          "*_front).");
        prm.declare_entry("Block height",
                          "4",
                          Patterns::Double(1e-12),
                          "Height of the block.");
        prm.declare_entry(
          "Gap",
          "0",
          Patterns::Double(0),
          "Initial vertical distance between the lowest point of the "
          "cylinder (3-D: the sphere) and the top of the block.");
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

      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        using namespace MeshSteps;
        const double R = radius, w = block_width, h = block_height;
        if constexpr (dim == 2)
          {
            const std::vector<double> half_x = graded(R, w / 2, 1.1);
            return {half_disc_body("cylinder",
                                   Point<2>(0, h + gap + R),
                                   R,
                                   this->scaled(32),
                                   this->scaled(20),
                                   0,
                                   0),
                    rectangle_body("block",
                                   Point<2>(-w / 2, 0),
                                   Point<2>(w / 2, h),
                                   concatenate(reversed(half_x), half_x),
                                   reversed(graded(R, h, 1.1)))};
          }
        else
          {
            // fine cells within 0.2 R of the axis (a/R = 0.1 to 0.15),
            // growing faster than in 2-D: the cell count grows with the cube
            const double              fine = 0.2 * R, ratio = 1.4;
            const std::vector<double> block_x = graded(fine, w / 2, ratio);
            const double cap_width = 0.4 * R, cap_height = 0.5 * R,
                         y0        = h + gap;
            AssertThrow(w / 2 >= cap_width && h >= cap_height,
                        ExcMessage(
                          "Scene/Hertz: in 3-D the block (Block width / 2 = " +
                          std::to_string(w / 2) + ", Block height = " +
                          std::to_string(h) +
                          ") must be at least as wide as the sphere's cap "
                          "(0.4 Radius = " +
                          std::to_string(cap_width) + ") and as high as it "
                          "(0.5 Radius = " +
                          std::to_string(cap_height) +
                          "); Hertz's half-space wants it much larger."));
            const std::vector<double> cap_x = graded(fine, cap_width, ratio);
            return {sphere_cap_body("sphere",
                                    Point<3>(0, y0, 0),
                                    {cap_x,
                                     graded(fine, cap_height, ratio),
                                     cap_x},
                                    Point<3>(0, y0, 0),
                                    R),
                    box_body<3>("block",
                                Point<3>(0, 0, 0),
                                {block_x, reversed(graded(fine, h, ratio)), block_x},
                                "block_")};
          }
      }

    private:
      // Steps from the contact point outwards over `total`: uniform cells of
      // size R/40 within `fine_length`, geometrically growing (ratio about
      // `ratio`) outside.
      std::vector<double>
      graded(const double fine_length,
             const double total,
             const double ratio) const
      {
        using namespace MeshSteps;
        const double R    = radius;
        const double size = R / this->scaled(40);
        const double fine = std::min(fine_length, total);
        if (total - fine <= 2 * R / 40)
          return uniform(total, this->scaled(total / (R / 40)));
        const unsigned int n_fine =
          std::max(1u, (unsigned int)std::round(fine / size));
        const unsigned int n_grow =
          this->scaled(n_growing(total - fine, R / 40, ratio));
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
    return scene_in_any_dimension<Hertz>(
      "hertz",
      "a half-cylinder (3-D: a quarter of a sphere) pressed onto a block, "
      "see subsection Hertz");
  }
} // namespace ContactDynamics
