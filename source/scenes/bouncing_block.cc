// The paper's bouncing block: a unit block above a 5 x 1 substrate.
#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    class BouncingBlock : public BuiltInScene<2>
    {
    protected:
      std::vector<BodyDefinition<2>>
      bodies() const override
      {
        return {rectangle_body("block",
                               Point<2>(-2, 0),
                               Point<2>(-1, 1),
                               scaled(10),
                               scaled(10)),
                rectangle_body("substrate",
                               Point<2>(-2.5, -1),
                               Point<2>(2.5, 0),
                               scaled(49),
                               scaled(10))};
      }
    };
  } // namespace

  SceneEntry
  bouncing_block_scene()
  {
    return planar_scene<BouncingBlock>(
      "bouncing block",
      "the paper's block falling onto a substrate");
  }
} // namespace ContactDynamics
