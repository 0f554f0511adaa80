// The contact patch test: two stacked blocks with non-matching meshes. In
// 3-D the grids of both blocks are also distorted in the horizontal plane
// (differently), so that the interface faces are non-matching and
// non-aligned quadrilaterals; the interface and the sides stay plane.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <cmath>

namespace ContactDynamics
{
  namespace
  {
    // x += a sin(2 pi x) sin(pi z), z += a sin(2 pi z) sin(pi x) on the unit
    // square: the sides x, z = 0, 1 stay in place, y is not touched
    template <int dim>
    BodyDefinition<dim>
    distorted(BodyDefinition<dim> body, const double a)
    {
      const auto mesh = body.mesh;
      body.mesh       = [mesh, a]() {
        BodyMesh<dim> m = mesh();
        for (auto &v : m.vertices)
          {
            const double x = v[0], z = v[2];
            v[0] += a * std::sin(2 * M_PI * x) * std::sin(M_PI * z);
            v[2] += a * std::sin(2 * M_PI * z) * std::sin(M_PI * x);
          }
        return m;
      };
      return body;
    }

    template <int dim>
    class PatchTest : public BuiltInScene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

    protected:
      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        if constexpr (dim == 2)
          return {rectangle_body("upper",
                                 Point<2>(0, 0.5),
                                 Point<2>(1, 1),
                                 this->scaled(7),
                                 this->scaled(4)),
                  rectangle_body("lower",
                                 Point<2>(0, 0),
                                 Point<2>(1, 0.5),
                                 this->scaled(5),
                                 this->scaled(3))};
        else
          return {distorted(box_body("upper",
                                     Point<3>(0, 0.5, 0),
                                     Point<3>(1, 1, 1),
                                     {this->scaled(7),
                                      this->scaled(4),
                                      this->scaled(6)},
                                     "upper_"),
                            0.04),
                  distorted(box_body("lower",
                                     Point<3>(0, 0, 0),
                                     Point<3>(1, 0.5, 1),
                                     {this->scaled(5),
                                      this->scaled(3),
                                      this->scaled(4)},
                                     "lower_"),
                            -0.03)};
      }
    };
  } // namespace

  SceneEntry
  patch_test_scene()
  {
    return scene_in_any_dimension<PatchTest>(
      "patch test",
      "two stacked blocks with non-matching meshes (in 3-D also distorted "
      "in the horizontal plane): [0, 1] x [0.5, 1] (x [0, 1]) on [0, 1] x "
      "[0, 0.5] (x [0, 1])");
  }
} // namespace ContactDynamics
