// The contact patch test: two stacked rectangles with non-matching meshes.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    class PatchTest : public BuiltInScene<2>
    {
    protected:
      std::vector<BodyDefinition<2>>
      bodies() const override
      {
        return {rectangle_body("upper",
                               Point<2>(0, 0.5),
                               Point<2>(1, 1),
                               scaled(7),
                               scaled(4)),
                rectangle_body("lower",
                               Point<2>(0, 0),
                               Point<2>(1, 0.5),
                               scaled(5),
                               scaled(3))};
      }
    };
  } // namespace

  SceneEntry
  patch_test_scene()
  {
    return planar_scene<PatchTest>(
      "patch test",
      "two stacked blocks with non-matching meshes");
  }
} // namespace ContactDynamics
